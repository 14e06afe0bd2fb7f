//! Statements: assignments, calls, IF, CASE, FOR, WHILE, REPEAT, EXIT, CONTINUE, RETURN.
//!
//! Recovery: a statement that fails is skipped up to its `;` (or the next statement
//! keyword or END_ keyword); a missing `;` is reported without skipping anything; a missing
//! END_ keyword is reported at the statement's opening keyword.

use super::{is_block_end, Fail, PResult, Parser};
use crate::diagnostics::{Code, Span};
use crate::phrase;
use crate::syntax::ast::*;
use crate::syntax::lexer::{Token, TokenKind};

/// Keywords that start a statement.
fn is_statement_keyword(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(k, If | Case | For | While | Repeat | Exit | Continue | Return)
}

/// END_ keywords of statements.
fn is_statement_end(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(k, EndIf | EndCase | EndFor | EndWhile | EndRepeat)
}

/// A stand-in for an expression that failed to parse (its error is already reported).
fn placeholder(value: LiteralValue, span: Span) -> Expr {
    Expr { kind: ExprKind::Literal(Literal { value, type_prefix: None }), span }
}

impl Parser<'_> {
    /// Statements up to an END_ keyword, ELSE/ELSIF/UNTIL, a new block or, inside a CASE
    /// (`in_case`), the next case label.
    pub(super) fn parse_stmts(&mut self, in_case: bool) -> Vec<Stmt> {
        let mut stmts = Vec::new();
        loop {
            let k = self.peek();
            if is_block_end(k) || (in_case && self.looks_like_case_label()) {
                return stmts;
            }
            if self.open_ends.is_empty() && self.at_sfc_element() {
                return stmts;
            }
            let before = self.pos;
            match self.nested(|p| p.parse_stmt()) {
                Ok(s) => stmts.push(s),
                Err(Fail) => self.skip_statement(),
            }
            if self.pos == before {
                self.bump();
            }
        }
    }

    /// Skips a broken statement: up to and including its `;`, or up to the next statement
    /// keyword or END_ keyword.
    fn skip_statement(&mut self) {
        loop {
            let k = self.peek();
            if k == TokenKind::Semicolon {
                self.bump();
                return;
            }
            if is_block_end(k) || is_statement_keyword(k) {
                return;
            }
            self.bump();
        }
    }

    /// Skips the rest of a broken header expression up to `stop` (not consumed).
    fn skip_to(&mut self, stop: &[TokenKind]) {
        loop {
            let k = self.peek();
            if stop.contains(&k)
                || k == TokenKind::Semicolon
                || is_block_end(k)
                || is_statement_keyword(k)
            {
                return;
            }
            self.bump();
        }
    }

    /// An expression in a statement header, followed by `stop` (THEN, DO, OF, TO, …). On
    /// a broken expression, skips to `stop` and returns a stand-in.
    fn header_expr(&mut self, stop: &[TokenKind], fallback: LiteralValue) -> Expr {
        match self.parse_expr() {
            Ok(e) => e,
            Err(Fail) => {
                let span = self.tok().span;
                self.skip_to(stop);
                placeholder(fallback, span)
            }
        }
    }

    /// Consumes keyword `kind` (named `name`) or reports it missing without skipping.
    fn expect_keyword(&mut self, kind: TokenKind, name: &str, context: &str) {
        if self.eat(kind).is_none() {
            self.expected(format!("`{name}` {context}"));
        }
    }

    /// The `;` ending a simple statement. When missing, reports it at the statement's last
    /// token and goes on (nothing is skipped).
    pub(super) fn end_statement(&mut self, start: Span) -> Span {
        if let Some(semi) = self.eat(TokenKind::Semicolon) {
            return start.to(semi.span);
        }
        if self.at(TokenKind::Error) {
            // A stray character the lexer reported: skip the rest of the line quietly.
            self.skip_statement();
            return start.to(self.prev_span());
        }
        let last = self.prev_span();
        let found = self.describe(self.tok());
        self.error(
            Code::UnexpectedToken,
            last,
            format!("expected `;` after the statement, found {found}"),
        );
        start.to(last)
    }

    fn parse_stmt(&mut self) -> PResult<Stmt> {
        let tok = self.tok();
        let start = tok.span;
        let kind = match tok.kind {
            TokenKind::Semicolon => {
                self.bump();
                return Ok(Stmt { kind: StmtKind::Empty, span: start });
            }
            TokenKind::If => return Ok(self.parse_if()),
            TokenKind::Case => return Ok(self.parse_case()),
            TokenKind::For => return Ok(self.parse_for()),
            TokenKind::While => return Ok(self.parse_while()),
            TokenKind::Repeat => return Ok(self.parse_repeat()),
            TokenKind::Exit => StmtKind::Exit,
            TokenKind::Continue => StmtKind::Continue,
            TokenKind::Return => StmtKind::Return,
            TokenKind::Ident | TokenKind::Direct | TokenKind::LParen => {
                return self.parse_assign_or_call()
            }
            _ => return Err(self.expected(phrase!(ExpectStatement))),
        };
        self.bump();
        let span = self.end_statement(start);
        Ok(Stmt { kind, span })
    }

    fn parse_assign_or_call(&mut self) -> PResult<Stmt> {
        let start = self.tok().span;
        let target = self.parse_postfix()?;
        let kind = if self.eat(TokenKind::Assign).is_some() {
            let value = self.parse_expr()?;
            StmtKind::Assign { target, value }
        } else if matches!(target.kind, ExprKind::Call { .. }) {
            StmtKind::Call(target)
        } else if self.at(TokenKind::Eq) {
            let span = self.tok().span;
            self.error(
                Code::UnexpectedToken,
                span,
                "expected `:=` to assign, found `=` (`=` compares two values; `:=` assigns)",
            );
            return Err(Fail);
        } else {
            let what =
                self.src.get(target.span.start as usize..target.span.end as usize).unwrap_or("");
            let what: String = what.chars().take(40).collect();
            return Err(self.expected(format!("`:=` or a call `(…)` after `{what}`")));
        };
        let span = self.end_statement(start);
        Ok(Stmt { kind, span })
    }

    /// Closes a compound statement: its END_ keyword and an optional `;`. A missing END_ is
    /// reported at `opener`.
    fn close_block(&mut self, opener: Token, end: TokenKind, end_name: &str) -> Span {
        let what = self.text(opener).to_string();
        let tok = self.tok();
        if tok.kind == end {
            self.bump();
            self.eat(TokenKind::Semicolon);
        } else if is_statement_end(tok.kind) && !self.open_ends.contains(&tok.kind) {
            // A wrong END_ that nothing around expects: take it as a misspelled close.
            let found = self.describe(tok);
            self.error(
                Code::UnexpectedToken,
                tok.span,
                format!("expected `{end_name}` to close this {what}, found {found}"),
            );
            self.bump();
            self.eat(TokenKind::Semicolon);
        } else {
            let found = self.describe(tok);
            self.error(
                Code::MissingEnd,
                opener.span,
                format!("`{end_name}` is missing for this {what} (found {found})"),
            );
        }
        opener.span.to(self.prev_span())
    }

    /// Statements of a compound statement's body, waiting for `end`.
    fn body(&mut self, end: TokenKind, in_case: bool) -> Vec<Stmt> {
        self.open_ends.push(end);
        let stmts = self.parse_stmts(in_case);
        self.open_ends.pop();
        stmts
    }

    fn parse_if(&mut self) -> Stmt {
        let opener = self.bump();
        let mut branches = Vec::new();
        let mut else_body = None;
        let cond = self.header_expr(&[TokenKind::Then], LiteralValue::Bool(false));
        self.expect_keyword(TokenKind::Then, "THEN", "after the IF condition");
        branches.push((cond, self.body(TokenKind::EndIf, false)));
        loop {
            if self.eat(TokenKind::Elsif).is_some() {
                let cond = self.header_expr(&[TokenKind::Then], LiteralValue::Bool(false));
                self.expect_keyword(TokenKind::Then, "THEN", "after the ELSIF condition");
                branches.push((cond, self.body(TokenKind::EndIf, false)));
            } else if self.eat(TokenKind::Else).is_some() {
                else_body = Some(self.body(TokenKind::EndIf, false));
                break;
            } else {
                break;
            }
        }
        let span = self.close_block(opener, TokenKind::EndIf, "END_IF");
        Stmt { kind: StmtKind::If { branches, else_body }, span }
    }

    fn parse_case(&mut self) -> Stmt {
        let opener = self.bump();
        let selector = self.header_expr(&[TokenKind::Of], LiteralValue::Int(0));
        self.expect_keyword(TokenKind::Of, "OF", "after the CASE selector");
        let mut arms = Vec::new();
        let mut else_body = None;
        loop {
            let k = self.peek();
            if k == TokenKind::Else {
                self.bump();
                else_body = Some(self.body(TokenKind::EndCase, false));
                break;
            }
            if is_block_end(k) {
                break;
            }
            let before = self.pos;
            match self.parse_case_arm() {
                Ok(arm) => arms.push(arm),
                Err(Fail) => self.skip_statement(),
            }
            if self.pos == before {
                self.bump();
            }
        }
        let span = self.close_block(opener, TokenKind::EndCase, "END_CASE");
        Stmt { kind: StmtKind::Case { selector, arms, else_body }, span }
    }

    fn parse_case_arm(&mut self) -> PResult<CaseArm> {
        let start = self.tok().span;
        let mut labels = Vec::new();
        loop {
            let low = self.parse_expr()?;
            if self.eat(TokenKind::DotDot).is_some() {
                let high = self.parse_expr()?;
                labels.push(CaseLabel::Range(low, high));
            } else {
                labels.push(CaseLabel::Value(low));
            }
            if self.eat(TokenKind::Comma).is_none() {
                break;
            }
        }
        let colon = self.expect(TokenKind::Colon, phrase!(ExpectColonAfterCaseLabel))?;
        let body = self.body(TokenKind::EndCase, true);
        Ok(CaseArm { labels, body, span: start.to(colon.span) })
    }

    /// True when the tokens ahead read like `label, label..label :` (a new CASE branch).
    fn looks_like_case_label(&self) -> bool {
        use TokenKind::*;
        for i in 0..64 {
            match self.peek_at(i) {
                Colon => return i > 0,
                Ident | Integer | Real | Hash | Minus | Plus | Comma | DotDot | Dot | LParen
                | RParen | Star | Slash | True | False | Mod => {}
                _ => return false,
            }
        }
        false
    }

    fn parse_for(&mut self) -> Stmt {
        let opener = self.bump();
        let var = match self.eat(TokenKind::Ident) {
            Some(t) => self.ident(t),
            None => {
                self.expected(phrase!(ExpectNameOfLoopVariableAfterFor));
                Ident { name: String::new(), span: self.tok().span }
            }
        };
        let stops = [TokenKind::To, TokenKind::By, TokenKind::Do];
        let from = if self.eat(TokenKind::Assign).is_some() {
            self.header_expr(&stops, LiteralValue::Int(0))
        } else {
            self.expected(phrase!(ExpectAssignAndStartValueAfterLoopVariable));
            let span = self.tok().span;
            self.skip_to(&stops);
            placeholder(LiteralValue::Int(0), span)
        };
        self.expect_keyword(TokenKind::To, "TO", "and the end value");
        let to = self.header_expr(&stops, LiteralValue::Int(0));
        let by = if self.eat(TokenKind::By).is_some() {
            Some(self.header_expr(&[TokenKind::Do], LiteralValue::Int(1)))
        } else {
            None
        };
        self.expect_keyword(TokenKind::Do, "DO", "after the FOR header");
        let body = self.body(TokenKind::EndFor, false);
        let span = self.close_block(opener, TokenKind::EndFor, "END_FOR");
        Stmt { kind: StmtKind::For { var, from, to, by, body }, span }
    }

    fn parse_while(&mut self) -> Stmt {
        let opener = self.bump();
        let cond = self.header_expr(&[TokenKind::Do], LiteralValue::Bool(false));
        self.expect_keyword(TokenKind::Do, "DO", "after the WHILE condition");
        let body = self.body(TokenKind::EndWhile, false);
        let span = self.close_block(opener, TokenKind::EndWhile, "END_WHILE");
        Stmt { kind: StmtKind::While { cond, body }, span }
    }

    fn parse_repeat(&mut self) -> Stmt {
        let opener = self.bump();
        let body = self.body(TokenKind::EndRepeat, false);
        let until = if self.eat(TokenKind::Until).is_some() {
            self.header_expr(&[TokenKind::EndRepeat], LiteralValue::Bool(true))
        } else {
            let found = self.describe(self.tok());
            self.error(
                Code::MissingEnd,
                opener.span,
                format!("`UNTIL` is missing for this REPEAT (found {found})"),
            );
            placeholder(LiteralValue::Bool(true), self.tok().span)
        };
        let span = self.close_block(opener, TokenKind::EndRepeat, "END_REPEAT");
        Stmt { kind: StmtKind::Repeat { body, until }, span }
    }
}
