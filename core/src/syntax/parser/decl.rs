//! Declarations: `VAR…` blocks, `TYPE` blocks, type references and initial values.
//!
//! Recovery: a broken declaration is skipped up to its `;` (or `END_VAR`); a missing
//! `END_VAR`/`END_TYPE`/`END_STRUCT` is reported at the opening keyword.

use super::{is_block_end, is_var_keyword, Fail, PResult, Parser};
use crate::diagnostics::{Code, Span};
use crate::phrase;
use crate::syntax::ast::*;
use crate::syntax::lexer::{Token, TokenKind};

/// One enumerator with its optional explicit value.
type Enumerator = (Ident, Option<Expr>);

impl Parser<'_> {
    /// A `VAR… END_VAR` block (the cursor is on its opening keyword). `None` only when the
    /// opening keyword is not a VAR keyword.
    pub(super) fn parse_var_block(&mut self) -> Option<VarBlock> {
        let opener = self.tok();
        let section = match opener.kind {
            TokenKind::Var => VarSection::Var,
            TokenKind::VarInput => VarSection::Input,
            TokenKind::VarOutput => VarSection::Output,
            TokenKind::VarInOut => VarSection::InOut,
            TokenKind::VarGlobal => VarSection::Global,
            TokenKind::VarExternal => VarSection::External,
            TokenKind::VarTemp => VarSection::Temp,
            _ => return None,
        };
        self.bump();
        let mut retain = false;
        let mut constant = false;
        loop {
            match self.peek() {
                TokenKind::Retain | TokenKind::Persistent => retain = true,
                TokenKind::NonRetain => retain = false,
                TokenKind::Constant => constant = true,
                _ => break,
            }
            self.bump();
        }
        let mut decls = Vec::new();
        loop {
            let before = self.pos;
            let tok = self.tok();
            match tok.kind {
                TokenKind::EndVar => {
                    self.bump();
                    break;
                }
                TokenKind::Ident | TokenKind::At => match self.parse_var_decl(true) {
                    Ok(Some(d)) => decls.push(d),
                    Ok(None) => {
                        self.missing_end(opener, "END_VAR");
                        break;
                    }
                    Err(Fail) => self.skip_declaration(TokenKind::EndVar),
                },
                k if is_block_end(k) || is_statement_start(k) => {
                    self.missing_end(opener, "END_VAR");
                    break;
                }
                _ => {
                    self.expected(phrase!(ExpectVariableDeclarationXIntOrEndVar));
                    self.skip_declaration(TokenKind::EndVar);
                }
            }
            if self.pos == before {
                self.bump();
            }
        }
        let span = opener.span.to(self.prev_span());
        Some(VarBlock { section, retain, constant, decls, span })
    }

    fn missing_end(&mut self, opener: Token, end_name: &str) {
        let what = self.text(opener).to_string();
        let found = self.describe(self.tok());
        self.error(
            Code::MissingEnd,
            opener.span,
            format!("`{end_name}` is missing for this {what} (found {found})"),
        );
    }

    /// Skips a broken declaration up to and including its `;`, or up to `end`.
    fn skip_declaration(&mut self, end: TokenKind) {
        loop {
            let k = self.peek();
            if k == TokenKind::Semicolon {
                self.bump();
                return;
            }
            if k == end || is_block_end(k) {
                return;
            }
            self.bump();
        }
    }

    /// `a, b AT %IX0.0 : TYPE := init;` plus a trailing same-line comment. `Ok(None)` when
    /// the line reads like a statement (the `END_VAR` before it is missing); only checked
    /// when `may_be_statement`.
    fn parse_var_decl(&mut self, may_be_statement: bool) -> PResult<Option<VarDecl>> {
        let start_pos = self.pos;
        let start = self.tok().span;
        let mut names = Vec::new();
        if self.at(TokenKind::Ident) {
            loop {
                let t = self.expect(TokenKind::Ident, phrase!(ExpectVariableName))?;
                names.push(self.ident(t));
                if self.eat(TokenKind::Comma).is_none() {
                    break;
                }
            }
        }
        if may_be_statement
            && names.len() == 1
            && matches!(
                self.peek(),
                TokenKind::Assign | TokenKind::LParen | TokenKind::Dot | TokenKind::LBracket
            )
        {
            self.pos = start_pos;
            return Ok(None);
        }
        let mut location = None;
        if self.eat(TokenKind::At).is_some() {
            let tok = self.expect(TokenKind::Direct, phrase!(ExpectAddressIx00AfterAt))?;
            location = self.direct_address(tok);
        }
        self.expect(TokenKind::Colon, phrase!(ExpectColonAndTypeAfterName))?;
        let ty = self.parse_type_spec()?;
        let init = if self.eat(TokenKind::Assign).is_some() {
            Some(self.parse_initializer()?)
        } else {
            None
        };
        let mut span = start.to(self.prev_span());
        let mut comment = None;
        if let Some(semi) = self.eat(TokenKind::Semicolon) {
            span = span.to(semi.span);
            comment = self.trailing_comment(semi.span.end);
        } else if self.at(TokenKind::Error) {
            // A stray character the lexer reported: skip the rest quietly.
            self.skip_declaration(TokenKind::EndVar);
        } else {
            let found = self.describe(self.tok());
            let shown = names.first().map_or("it".to_string(), |n| format!("`{}`", n.name));
            self.error(
                Code::UnexpectedToken,
                self.prev_span(),
                format!("expected `;` after the declaration of {shown}, found {found}"),
            );
        }
        Ok(Some(VarDecl { names, location, ty, init, comment, span }))
    }

    /// A type: a name, `STRING[n]`, `ARRAY[…] OF T`, `T(lo..hi)`, `(A, B)`, `STRUCT…`.
    pub(super) fn parse_type_spec(&mut self) -> PResult<TypeRef> {
        self.nested(|p| p.parse_type_spec_inner())
    }

    fn parse_type_spec_inner(&mut self) -> PResult<TypeRef> {
        let tok = self.tok();
        match tok.kind {
            TokenKind::Array => self.parse_array_type(),
            TokenKind::Struct => self.parse_struct_type(),
            TokenKind::LParen => {
                let (values, close) = self.parse_enum_values()?;
                Ok(TypeRef::Enum { values, span: tok.span.to(close) })
            }
            TokenKind::Ident => {
                self.bump();
                let name = self.ident(tok);
                let upper = name.key();
                if upper == "STRING" || upper == "WSTRING" {
                    return self.parse_string_type(tok, upper == "WSTRING");
                }
                if upper == "REF_TO" && !self.at(TokenKind::Semicolon) {
                    let target = self.parse_type_spec()?;
                    let span = tok.span.to(target.span());
                    return Ok(TypeRef::Ref { target: Box::new(target), span });
                }
                if !self.at(TokenKind::LParen) {
                    return Ok(TypeRef::Named(name));
                }
                let enum_follows = self.peek_at(1) == TokenKind::Ident
                    && matches!(
                        self.peek_at(2),
                        TokenKind::Comma | TokenKind::RParen | TokenKind::Assign
                    );
                if enum_follows {
                    // `INT (A, B)`: an enumeration with a base type (the base is ignored).
                    let (values, close) = self.parse_enum_values()?;
                    return Ok(TypeRef::Enum { values, span: tok.span.to(close) });
                }
                self.bump();
                let low = self.parse_expr()?;
                self.expect(TokenKind::DotDot, phrase!(ExpectDotdotBetweenLimitsOfSubrange))?;
                let high = self.parse_expr()?;
                let close =
                    self.expect(TokenKind::RParen, phrase!(ExpectCloseParenAfterSubrange))?;
                Ok(TypeRef::Subrange {
                    base: name,
                    low: Box::new(low),
                    high: Box::new(high),
                    span: tok.span.to(close.span),
                })
            }
            _ => Err(self.expected(phrase!(ExpectTypeName))),
        }
    }

    fn parse_string_type(&mut self, tok: Token, wide: bool) -> PResult<TypeRef> {
        let close_kind = match self.peek() {
            TokenKind::LBracket => TokenKind::RBracket,
            TokenKind::LParen => TokenKind::RParen,
            _ => return Ok(TypeRef::String { wide, length: None, span: tok.span }),
        };
        self.bump();
        let length = self.parse_expr()?;
        let what = if close_kind == TokenKind::RBracket { "`]`" } else { "`)`" };
        let close = self.expect(close_kind, format!("{what} after the string length"))?;
        Ok(TypeRef::String { wide, length: Some(Box::new(length)), span: tok.span.to(close.span) })
    }

    /// `ARRAY [lo..hi, lo..hi] OF T`; `[a..b][c..d]` is read as `[a..b, c..d]`.
    fn parse_array_type(&mut self) -> PResult<TypeRef> {
        let opener = self.bump();
        let mut ranges = Vec::new();
        self.expect(TokenKind::LBracket, phrase!(ExpectBracketAndIndexRangeAfterArray))?;
        loop {
            let low = self.parse_expr()?;
            self.expect(TokenKind::DotDot, phrase!(ExpectDotdotBetweenArrayBounds))?;
            let high = self.parse_expr()?;
            ranges.push((low, high));
            if self.eat(TokenKind::Comma).is_some() {
                continue;
            }
            self.expect(TokenKind::RBracket, phrase!(ExpectCommaOrCloseBracketAfterArrayBounds))?;
            if self.eat(TokenKind::LBracket).is_none() {
                break;
            }
        }
        self.expect(TokenKind::Of, phrase!(ExpectOfAndElementTypeAfterArrayBounds))?;
        let element = self.parse_type_spec()?;
        let span = opener.span.to(element.span());
        Ok(TypeRef::Array { ranges, element: Box::new(element), span })
    }

    fn parse_struct_type(&mut self) -> PResult<TypeRef> {
        let opener = self.bump();
        let mut fields = Vec::new();
        loop {
            let before = self.pos;
            match self.peek() {
                TokenKind::EndStruct => {
                    self.bump();
                    break;
                }
                TokenKind::Ident => match self.parse_var_decl(false) {
                    Ok(Some(d)) => fields.push(d),
                    Ok(None) => {}
                    Err(Fail) => self.skip_declaration(TokenKind::EndStruct),
                },
                k if is_block_end(k) || is_statement_start(k) => {
                    self.missing_end(opener, "END_STRUCT");
                    break;
                }
                _ => {
                    self.expected(phrase!(ExpectFieldDeclarationXIntOrEndStruct));
                    self.skip_declaration(TokenKind::EndStruct);
                }
            }
            if self.pos == before {
                self.bump();
            }
        }
        Ok(TypeRef::Struct { fields, span: opener.span.to(self.prev_span()) })
    }

    /// `(A, B := 5, C)` — returns the values and the span of `)`.
    fn parse_enum_values(&mut self) -> PResult<(Vec<Enumerator>, Span)> {
        self.expect(TokenKind::LParen, phrase!(ExpectParen))?;
        let mut values = Vec::new();
        loop {
            let t = self.expect(TokenKind::Ident, phrase!(ExpectNameOfEnumerationValue))?;
            let value =
                if self.eat(TokenKind::Assign).is_some() { Some(self.parse_expr()?) } else { None };
            values.push((self.ident(t), value));
            if self.eat(TokenKind::Comma).is_none() {
                break;
            }
        }
        let close =
            self.expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParenInEnumeration))?;
        Ok((values, close.span))
    }

    /// An initial value: an expression, `[1, 2, 3(0)]` or `(field := value, …)`.
    pub(super) fn parse_initializer(&mut self) -> PResult<Initializer> {
        self.nested(|p| p.parse_initializer_inner())
    }

    fn parse_initializer_inner(&mut self) -> PResult<Initializer> {
        let tok = self.tok();
        if tok.kind == TokenKind::LBracket {
            self.bump();
            let mut elements = Vec::new();
            if !self.at(TokenKind::RBracket) {
                loop {
                    elements.push(self.parse_array_element()?);
                    if self.eat(TokenKind::Comma).is_none() {
                        break;
                    }
                }
            }
            let close = self
                .expect(TokenKind::RBracket, phrase!(ExpectCommaOrCloseBracketInArraySInitial))?;
            return Ok(Initializer::Array { elements, span: tok.span.to(close.span) });
        }
        if tok.kind == TokenKind::LParen
            && self.peek_at(1) == TokenKind::Ident
            && self.peek_at(2) == TokenKind::Assign
        {
            self.bump();
            let mut fields = Vec::new();
            loop {
                let name = self.expect(TokenKind::Ident, phrase!(ExpectFieldName))?;
                self.expect(TokenKind::Assign, phrase!(ExpectAssignAfterFieldName))?;
                let value = self.parse_initializer()?;
                fields.push((self.ident(name), value));
                if self.eat(TokenKind::Comma).is_none() {
                    break;
                }
            }
            let close = self
                .expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParenInStructureSInitial))?;
            return Ok(Initializer::Struct { fields, span: tok.span.to(close.span) });
        }
        Ok(Initializer::Expr(self.parse_expr()?))
    }

    /// `value` or `n(value)` or `n()`.
    fn parse_array_element(&mut self) -> PResult<ArrayInitElement> {
        let tok = self.tok();
        if tok.kind == TokenKind::Integer && self.peek_at(1) == TokenKind::LParen {
            let count = self.parse_primary_literal()?;
            self.bump(); // `(`
            let value = if self.at(TokenKind::RParen) {
                None
            } else {
                Some(Box::new(self.parse_initializer()?))
            };
            let close =
                self.expect(TokenKind::RParen, phrase!(ExpectCloseParenAfterRepeatedValue))?;
            return Ok(ArrayInitElement::Repeat { count, value, span: tok.span.to(close.span) });
        }
        Ok(ArrayInitElement::Single(self.parse_initializer()?))
    }

    /// The integer literal of a repeat count.
    fn parse_primary_literal(&mut self) -> PResult<Expr> {
        let tok = self.tok();
        let value = match crate::syntax::literal::parse_integer(self.text(tok)) {
            Ok(v) => v,
            Err((code, msg)) => {
                self.error(code, tok.span, msg);
                0
            }
        };
        self.bump();
        Ok(Expr {
            kind: ExprKind::Literal(Literal { value: LiteralValue::Int(value), type_prefix: None }),
            span: tok.span,
        })
    }

    /// `TYPE name : spec [:= init]; … END_TYPE`.
    pub(super) fn parse_type_block(&mut self) -> Vec<TypeDef> {
        let opener = self.bump();
        let mut defs = Vec::new();
        loop {
            let before = self.pos;
            match self.peek() {
                TokenKind::EndType => {
                    self.bump();
                    self.eat(TokenKind::Semicolon);
                    break;
                }
                TokenKind::Ident => match self.parse_type_def() {
                    Ok(d) => defs.push(d),
                    Err(Fail) => self.skip_declaration(TokenKind::EndType),
                },
                k if is_block_end(k) || is_statement_start(k) => {
                    self.missing_end(opener, "END_TYPE");
                    break;
                }
                _ => {
                    self.expected(phrase!(ExpectTypeDefinitionSpeedIntOrEndType));
                    self.skip_declaration(TokenKind::EndType);
                }
            }
            if self.pos == before {
                self.bump();
            }
        }
        defs
    }

    fn parse_type_def(&mut self) -> PResult<TypeDef> {
        let name_tok = self.bump();
        let name = self.ident(name_tok);
        self.expect(TokenKind::Colon, format!("`:` and a type after `{}`", name.name))?;
        let ty = self.parse_type_spec()?;
        let init = if self.eat(TokenKind::Assign).is_some() {
            Some(self.parse_initializer()?)
        } else {
            None
        };
        let is_struct = matches!(ty, TypeRef::Struct { .. });
        let mut span = name_tok.span.to(self.prev_span());
        if let Some(semi) = self.eat(TokenKind::Semicolon) {
            span = span.to(semi.span);
        } else if !is_struct {
            let found = self.describe(self.tok());
            self.error(
                Code::UnexpectedToken,
                self.prev_span(),
                format!("expected `;` after the definition of `{}`, found {found}", name.name),
            );
        }
        Ok(TypeDef { name, ty, init, span })
    }
}

/// Tokens that can only start a statement (so a declaration block before them is unclosed).
fn is_statement_start(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(k, If | Case | For | While | Repeat | Exit | Continue | Return) || is_var_keyword(k)
}
