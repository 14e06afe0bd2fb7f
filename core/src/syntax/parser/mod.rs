//! The parser: tokens → [`SourceFile`], with error recovery.
//!
//! A recursive-descent parser over the token list from `lexer.rs`. Each `parse_*` method
//! returns `PResult`: `Err(Fail)` means a diagnostic has already been reported and the
//! caller must recover (skip to the next `;`, statement keyword or END_ keyword). One bad
//! line gives one diagnostic. Every loop consumes a token or stops, and nesting is capped,
//! so no input makes the parser panic, loop forever or overflow the stack.
//!
//! Files: `mod.rs` (cursor, diagnostics, top level and POUs), `decl.rs` (VAR blocks,
//! types, initial values), `stmt.rs` (statements), `expr.rs` (expressions), `il.rs`
//! (Instruction List bodies).

mod config;
mod decl;
mod expr;
mod il;
mod sfc;

pub(crate) use il::il_operator_names;
pub(super) use il::{is_il_operator, starts_operand};
mod stmt;

use super::ast::sfc::{SfcBody, SfcElement};
use super::ast::*;
use super::lexer::{lex, Comment, Token, TokenKind};
use crate::diagnostics::{Arg as MsgArg, Code, Diagnostic, Span};
use crate::{msg, phrase};

/// Marks a failed parse whose diagnostic has already been reported.
#[derive(Debug, Clone, Copy)]
pub(super) struct Fail;

/// The result of a parsing step.
pub(super) type PResult<T> = Result<T, Fail>;

// The deepest nesting of expressions, statements and initializers accepted (this parser
// takes about 7 KiB of stack per level in a debug build, 1.5 KiB optimised).
use crate::limits::{MAX_EXPR_HEIGHT, MAX_NESTING};

/// Parses a whole source file; diagnostics come back in source order.
pub(crate) fn parse_source(source: &str) -> (SourceFile, Vec<Diagnostic>) {
    let mut p = Parser::new(source);
    let file = p.parse_file();
    (file, p.finish())
}

/// Parses one expression; anything after it is an error.
pub(crate) fn parse_single_expression(source: &str) -> Result<Expr, Vec<Diagnostic>> {
    let mut p = Parser::new(source);
    let result = p.parse_expr();
    if result.is_ok() && !p.at(TokenKind::Eof) {
        let tok = p.tok();
        let found = p.describe(tok);
        p.error(
            Code::UnexpectedToken,
            tok.span,
            msg!(ExpectedFound, what = phrase!(ExpectEndOfExpression), found = found),
        );
    }
    let diags = p.finish();
    match result {
        Ok(e) if !diags.iter().any(Diagnostic::is_error) => Ok(e),
        _ => Err(diags),
    }
}

/// The parser's cursor over the tokens, and the diagnostics found so far.
pub(super) struct Parser<'a> {
    src: &'a str,
    tokens: Vec<Token>,
    comments: Vec<Comment>,
    pos: usize,
    diags: Vec<Diagnostic>,
    depth: usize,
    /// The END_ keywords the enclosing statements wait for (innermost last).
    open_ends: Vec<TokenKind>,
}

impl<'a> Parser<'a> {
    fn new(source: &'a str) -> Self {
        let lexed = lex(source);
        Parser {
            src: source,
            tokens: lexed.tokens,
            comments: lexed.comments,
            pos: 0,
            diags: lexed.diagnostics,
            depth: 0,
            open_ends: Vec::new(),
        }
    }

    fn finish(mut self) -> Vec<Diagnostic> {
        crate::order::sort_by_key(&mut self.diags, |d| (d.span.start, d.span.end));
        self.diags
    }

    // ---- cursor ----

    /// The current token (the final `Eof` once past the end).
    pub(super) fn tok(&self) -> Token {
        self.nth(0)
    }

    /// The token `n` places ahead.
    pub(super) fn nth(&self, n: usize) -> Token {
        let eof = Token { kind: TokenKind::Eof, span: Span::new(self.src.len(), self.src.len()) };
        self.tokens.get(self.pos + n).or(self.tokens.last()).copied().unwrap_or(eof)
    }

    pub(super) fn peek(&self) -> TokenKind {
        self.tok().kind
    }

    pub(super) fn peek_at(&self, n: usize) -> TokenKind {
        self.nth(n).kind
    }

    pub(super) fn at(&self, kind: TokenKind) -> bool {
        self.peek() == kind
    }

    /// Consumes and returns the current token (never moves past `Eof`).
    pub(super) fn bump(&mut self) -> Token {
        let t = self.tok();
        if t.kind != TokenKind::Eof {
            self.pos += 1;
        }
        t
    }

    pub(super) fn eat(&mut self, kind: TokenKind) -> Option<Token> {
        if self.at(kind) {
            Some(self.bump())
        } else {
            None
        }
    }

    /// The span of the last consumed token (the first token's when none is consumed yet).
    pub(super) fn prev_span(&self) -> Span {
        match self.pos.checked_sub(1).and_then(|i| self.tokens.get(i)) {
            Some(t) => t.span,
            None => self.tok().span,
        }
    }

    /// The text of a token as written.
    pub(super) fn text(&self, tok: Token) -> &'a str {
        self.src.get(tok.span.start as usize..tok.span.end as usize).unwrap_or("")
    }

    /// A token as shown in a message: `` `END_IF` `` or "the end of the text".
    pub(super) fn describe(&self, tok: Token) -> MsgArg {
        if tok.kind == TokenKind::Eof {
            return MsgArg::Msg(phrase!(EndOfText));
        }
        let text = self.text(tok);
        MsgArg::Text(if text.chars().count() > 40 {
            let short: String = text.chars().take(40).collect();
            format!("`{short}…`")
        } else {
            format!("`{text}`")
        })
    }

    pub(super) fn ident(&self, tok: Token) -> Ident {
        Ident { name: self.text(tok).to_string(), span: tok.span }
    }

    // ---- diagnostics ----

    /// Reports a problem, unless one is already reported at the same place.
    pub(super) fn error(
        &mut self,
        code: Code,
        span: Span,
        msg: impl Into<crate::diagnostics::Said>,
    ) {
        if self.diags.iter().any(|d| d.span.start == span.start) {
            return;
        }
        self.diags.push(Diagnostic::error(code, span, msg));
    }

    /// Reports "expected WHAT, found …" at the current token and fails.
    pub(super) fn expected(&mut self, what: impl Into<MsgArg>) -> Fail {
        let tok = self.tok();
        let found = self.describe(tok);
        self.error(
            Code::UnexpectedToken,
            tok.span,
            msg!(ExpectedFound, what = what.into(), found = found),
        );
        Fail
    }

    /// Consumes a token of `kind` or reports "expected WHAT".
    pub(super) fn expect(&mut self, kind: TokenKind, what: impl Into<MsgArg>) -> PResult<Token> {
        match self.eat(kind) {
            Some(t) => Ok(t),
            None => Err(self.expected(what)),
        }
    }

    /// Runs `f` one nesting level deeper, failing when the input nests too deeply.
    pub(super) fn nested<T>(&mut self, f: impl FnOnce(&mut Self) -> PResult<T>) -> PResult<T> {
        if self.depth >= MAX_NESTING {
            let span = self.tok().span;
            self.error(
                Code::TooComplex,
                span,
                format!("this is nested too deeply (more than {MAX_NESTING} levels); simplify it"),
            );
            return Err(Fail);
        }
        self.depth += 1;
        let r = f(self);
        self.depth -= 1;
        r
    }

    /// Fails with a located error when an expression tree grown by a chain of operators
    /// or postfix steps (at `span`) would be taller than [`MAX_EXPR_HEIGHT`]: the later
    /// passes recurse once per level.
    pub(super) fn check_height(&mut self, height: usize, span: Span) -> PResult<()> {
        if height <= MAX_EXPR_HEIGHT {
            return Ok(());
        }
        self.error(
            Code::TooComplex,
            span,
            format!(
                "this expression is too long: more than {MAX_EXPR_HEIGHT} operators, calls, \
                 indices or members in a row; split it over several statements"
            ),
        );
        Err(Fail)
    }

    /// The text of a comment that starts on the same line right after byte `end`.
    pub(super) fn trailing_comment(&self, end: u32) -> Option<String> {
        let i = self.comments.partition_point(|c| c.span.start < end);
        let c = self.comments.get(i)?;
        let gap = self.src.get(end as usize..c.span.start as usize)?;
        if gap.chars().all(|ch| ch == ' ' || ch == '\t') {
            Some(c.text.clone())
        } else {
            None
        }
    }

    // ---- top level ----

    fn parse_file(&mut self) -> SourceFile {
        let mut items = Vec::new();
        loop {
            let before = self.pos;
            match self.peek() {
                TokenKind::Eof => break,
                TokenKind::Type => items.push(Item::Types(self.parse_type_block())),
                TokenKind::VarGlobal => {
                    if let Some(block) = self.parse_var_block() {
                        items.push(Item::Globals(block));
                    }
                }
                TokenKind::Program | TokenKind::Function | TokenKind::FunctionBlock => {
                    items.push(Item::Pou(self.parse_pou()));
                }
                TokenKind::Configuration => {
                    items.push(Item::Configuration(self.parse_configuration()));
                }
                TokenKind::Resource => self.skip_configuration(),
                k if is_var_keyword(k) => {
                    let tok = self.tok();
                    let text = self.text(tok);
                    self.error(
                        Code::UnexpectedToken,
                        tok.span,
                        format!("`{text}` must stand inside a PROGRAM, FUNCTION or FUNCTION_BLOCK (only VAR_GLOBAL may stand alone)"),
                    );
                    let _ = self.parse_var_block();
                }
                _ => {
                    self.expected(phrase!(ExpectProgramFunctionFunctionBlockTypeOrVarGlobal));
                    while !is_top_level_start(self.peek()) {
                        self.bump();
                    }
                }
            }
            if self.pos == before {
                self.bump();
            }
        }
        SourceFile { items }
    }

    /// A `RESOURCE` outside any configuration: reported and skipped.
    fn skip_configuration(&mut self) {
        let opener = self.bump();
        let (end, name) = (TokenKind::EndResource, "END_RESOURCE");
        let text = self.text(opener);
        self.error(
            Code::UnexpectedToken,
            opener.span,
            format!("`{text}` must stand inside a CONFIGURATION; it is skipped up to `{name}`"),
        );
        while !self.at(end) && !self.at(TokenKind::Eof) {
            self.bump();
        }
        if self.eat(end).is_some() {
            self.eat(TokenKind::Semicolon);
        }
    }

    fn parse_pou(&mut self) -> Pou {
        let opener = self.bump();
        let (kind, end, end_name) = match opener.kind {
            TokenKind::Program => (PouKind::Program, TokenKind::EndProgram, "END_PROGRAM"),
            TokenKind::Function => (PouKind::Function, TokenKind::EndFunction, "END_FUNCTION"),
            _ => (PouKind::FunctionBlock, TokenKind::EndFunctionBlock, "END_FUNCTION_BLOCK"),
        };
        let kw_text = self.text(opener).to_string();
        let name = match self.eat(TokenKind::Ident) {
            Some(t) => self.ident(t),
            None => {
                self.expected(format!("a name after `{kw_text}`"));
                Ident { name: String::new(), span: self.tok().span }
            }
        };
        let mut return_type = None;
        if kind == PouKind::Function && self.eat(TokenKind::Colon).is_some() {
            match self.parse_type_spec() {
                Ok(t) => return_type = Some(t),
                Err(Fail) => self.skip_to_line_end_or_var(),
            }
        }
        self.eat(TokenKind::Semicolon);
        let mut var_blocks = Vec::new();
        while is_var_keyword(self.peek()) {
            if let Some(b) = self.parse_var_block() {
                var_blocks.push(b);
            }
        }
        let il = if self.at_il_body() { Some(self.parse_il_body()) } else { None };
        let mut body = Vec::new();
        let mut sfc: Option<SfcBody> = None;
        let mut mixed_reported = false;
        loop {
            let before = self.pos;
            let stmts = self.parse_stmts(false);
            if sfc.is_some() && !stmts.is_empty() {
                self.report_mixed_body(&stmts, &mut mixed_reported);
            } else {
                body.extend(stmts);
            }
            if self.at_sfc_element() {
                if sfc.is_none() && !body.is_empty() {
                    let stray = std::mem::take(&mut body);
                    self.report_mixed_body(&stray, &mut mixed_reported);
                }
                let element = self.parse_sfc_element();
                let span = element_span(&element);
                let chart = sfc.get_or_insert(SfcBody { elements: Vec::new(), span });
                chart.span = chart.span.to(span);
                chart.elements.push(element);
                continue;
            }
            let tok = self.tok();
            match tok.kind {
                k if k == end => {
                    self.bump();
                    self.eat(TokenKind::Semicolon);
                    break;
                }
                TokenKind::EndProgram | TokenKind::EndFunction | TokenKind::EndFunctionBlock => {
                    let found = self.describe(tok);
                    self.error(
                        Code::UnexpectedToken,
                        tok.span,
                        msg!(
                            ExpectedEndToClose,
                            end = end_name,
                            kind = kw_text,
                            name = &name.name,
                            found = found
                        ),
                    );
                    self.bump();
                    self.eat(TokenKind::Semicolon);
                    break;
                }
                k if is_var_keyword(k) => {
                    self.error(Code::UnexpectedToken, tok.span, msg!(DeclarationsAfterStatements));
                    if let Some(b) = self.parse_var_block() {
                        var_blocks.push(b);
                    }
                }
                k if is_stray_end(k) => {
                    let found = self.text(tok);
                    self.error(Code::UnexpectedToken, tok.span, msg!(StrayEnd, found = found));
                    self.bump();
                }
                _ => {
                    let found = self.describe(tok);
                    self.error(
                        Code::MissingEnd,
                        opener.span,
                        msg!(
                            EndMissing,
                            end = end_name,
                            kind = kw_text,
                            name = &name.name,
                            found = found
                        ),
                    );
                    break;
                }
            }
            if self.pos == before {
                self.bump();
            }
        }
        let span = opener.span.to(self.prev_span());
        Pou { kind, name, return_type, var_blocks, body, sfc, il, span }
    }

    /// Reports statements that stand outside the steps, transitions and actions of an SFC
    /// body (once per POU).
    fn report_mixed_body(&mut self, stmts: &[Stmt], reported: &mut bool) {
        if let (Some(first), false) = (stmts.first(), *reported) {
            *reported = true;
            self.error(
                Code::SfcNotAllowedHere,
                first.span,
                "a body written as an SFC holds only steps, transitions and actions; put these statements inside an ACTION",
            );
        }
    }

    /// After a bad FUNCTION result type: skip to the declarations or the body.
    fn skip_to_line_end_or_var(&mut self) {
        while !is_var_keyword(self.peek())
            && !is_block_end(self.peek())
            && !self.at(TokenKind::Semicolon)
        {
            self.bump();
        }
    }
}

/// The span of a step, transition or action.
fn element_span(e: &SfcElement) -> Span {
    match e {
        SfcElement::Step(s) => s.span,
        SfcElement::Transition(t) => t.span,
        SfcElement::Action(a) => a.span,
    }
}

/// `VAR`, `VAR_INPUT`, … (every keyword that opens a declaration block).
pub(super) fn is_var_keyword(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(k, Var | VarInput | VarOutput | VarInOut | VarGlobal | VarExternal | VarTemp)
}

/// Tokens that start a top-level item (or end the text).
fn is_top_level_start(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(
        k,
        Eof | Type | VarGlobal | Program | Function | FunctionBlock | Configuration | Resource
    )
}

/// END_ keywords (and ELSE/ELSIF/UNTIL) that close a statement or a non-POU block.
pub(super) fn is_stray_end(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(
        k,
        EndIf
            | Elsif
            | Else
            | EndCase
            | EndFor
            | EndWhile
            | Until
            | EndRepeat
            | EndVar
            | EndType
            | EndStruct
            | EndConfiguration
            | EndResource
            | EndStep
            | EndTransition
            | EndAction
    )
}

/// Tokens at which a statement list stops: any END_ keyword, ELSE/ELSIF/UNTIL, and
/// keywords that open a new declaration or top-level block.
pub(super) fn is_block_end(k: TokenKind) -> bool {
    use TokenKind::*;
    is_stray_end(k)
        || is_var_keyword(k)
        || matches!(
            k,
            Eof | EndProgram
                | EndFunction
                | EndFunctionBlock
                | Program
                | Function
                | FunctionBlock
                | Type
                | Struct
                | Configuration
                | Resource
                | InitialStep
        )
}

#[cfg(test)]
mod tests;
