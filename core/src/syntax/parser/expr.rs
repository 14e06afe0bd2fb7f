//! Expressions: precedence climbing over the IEC operator table, unary operators, postfix
//! calls, indexing, member and bit access, literals (with type prefixes) and addresses.

use super::{Fail, PResult, Parser};
use crate::diagnostics::Code;
use crate::phrase;
use crate::syntax::ast::*;
use crate::syntax::lexer::{Token, TokenKind};
use crate::syntax::literal;

/// The operator of an infix token and its binding power (higher binds tighter).
fn infix(kind: TokenKind) -> Option<(BinaryOp, u8)> {
    use TokenKind as T;
    Some(match kind {
        T::Or => (BinaryOp::Or, 1),
        T::OrElse => (BinaryOp::OrElse, 1),
        T::Xor => (BinaryOp::Xor, 2),
        T::And | T::Ampersand => (BinaryOp::And, 3),
        T::AndThen => (BinaryOp::AndThen, 3),
        T::Eq => (BinaryOp::Cmp(Cmp::Eq), 4),
        T::Ne => (BinaryOp::Cmp(Cmp::Ne), 4),
        T::Lt => (BinaryOp::Cmp(Cmp::Lt), 5),
        T::Le => (BinaryOp::Cmp(Cmp::Le), 5),
        T::Gt => (BinaryOp::Cmp(Cmp::Gt), 5),
        T::Ge => (BinaryOp::Cmp(Cmp::Ge), 5),
        T::Plus => (BinaryOp::Add, 6),
        T::Minus => (BinaryOp::Sub, 6),
        T::Star => (BinaryOp::Mul, 7),
        T::Slash => (BinaryOp::Div, 7),
        T::Mod => (BinaryOp::Mod, 7),
        T::Power => (BinaryOp::Pow, 8),
        _ => return None,
    })
}

impl Parser<'_> {
    /// Parses a whole expression.
    pub(super) fn parse_expr(&mut self) -> PResult<Expr> {
        let e = self.nested(|p| p.parse_binary(1))?;
        // Chains are checked as they grow; this catches height built by nesting
        // (parentheses and unary operators around a long chain).
        self.check_height(e.height(), e.span)?;
        Ok(e)
    }

    /// Binary operators of binding power `min` or more; all are left-associative.
    fn parse_binary(&mut self, min: u8) -> PResult<Expr> {
        let mut lhs = self.parse_unary()?;
        let mut height = None;
        while let Some((op, bp)) = infix(self.peek()) {
            if bp < min {
                break;
            }
            let tok = self.bump();
            let rhs = self.nested(|p| p.parse_binary(bp + 1))?;
            let h = 1 + height.unwrap_or_else(|| lhs.height()).max(rhs.height());
            self.check_height(h, tok.span)?;
            height = Some(h);
            let span = lhs.span.to(rhs.span);
            lhs = Expr { kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)), span };
        }
        Ok(lhs)
    }

    fn parse_unary(&mut self) -> PResult<Expr> {
        let op = match self.peek() {
            TokenKind::Minus => UnaryOp::Neg,
            TokenKind::Plus => UnaryOp::Plus,
            TokenKind::Not => UnaryOp::Not,
            _ => return self.parse_postfix(),
        };
        let tok = self.bump();
        let operand = self.nested(|p| p.parse_unary())?;
        let span = tok.span.to(operand.span);
        Ok(Expr { kind: ExprKind::Unary(op, Box::new(operand)), span })
    }

    /// A primary expression followed by calls, `[…]`, `.member` and `.bit`.
    pub(super) fn parse_postfix(&mut self) -> PResult<Expr> {
        let mut e = self.parse_primary()?;
        let mut height = None;
        loop {
            if !matches!(
                self.peek(),
                TokenKind::LParen | TokenKind::LBracket | TokenKind::Dot | TokenKind::Caret
            ) {
                return Ok(e);
            }
            let h = 1 + height.unwrap_or_else(|| e.height());
            self.check_height(h, self.tok().span)?;
            height = Some(h);
            match self.peek() {
                TokenKind::LParen => {
                    self.bump();
                    let args = self.parse_args()?;
                    let close =
                        self.expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParenInCall))?;
                    let span = e.span.to(close.span);
                    e = Expr { kind: ExprKind::Call { callee: Box::new(e), args }, span };
                }
                TokenKind::LBracket => {
                    self.bump();
                    let mut indices = vec![self.parse_expr()?];
                    while self.eat(TokenKind::Comma).is_some() {
                        indices.push(self.parse_expr()?);
                    }
                    let close = self.expect(
                        TokenKind::RBracket,
                        phrase!(ExpectCommaOrCloseBracketAfterIndex),
                    )?;
                    let span = e.span.to(close.span);
                    e = Expr { kind: ExprKind::Index(Box::new(e), indices), span };
                }
                TokenKind::Dot => e = self.parse_member(e)?,
                TokenKind::Caret => {
                    let caret = self.bump();
                    let span = e.span.to(caret.span);
                    e = Expr { kind: ExprKind::Deref(Box::new(e)), span };
                }
                _ => return Ok(e),
            }
        }
    }

    /// `.member`, `.3` or `.%X3` after `base` (the cursor is on the `.`).
    #[inline(never)]
    fn parse_member(&mut self, base: Expr) -> PResult<Expr> {
        self.bump();
        let tok = self.tok();
        let span = base.span.to(tok.span);
        let kind = match tok.kind {
            TokenKind::Ident => ExprKind::Member(Box::new(base), self.ident(tok)),
            TokenKind::Integer => {
                let bit = self.bit_number(tok, self.text(tok).parse().ok())?;
                ExprKind::Bit(Box::new(base), bit)
            }
            TokenKind::Direct => match literal::parse_part_address(self.text(tok)) {
                Some((width, index)) => ExprKind::Part { base: Box::new(base), width, index },
                None => {
                    let bit = self.bit_number(tok, literal::parse_bit_address(self.text(tok)))?;
                    ExprKind::Bit(Box::new(base), bit)
                }
            },
            _ => return Err(self.expected(phrase!(ExpectMemberNameOrBitNumberAfterDot))),
        };
        self.bump();
        Ok(Expr { kind, span })
    }

    fn bit_number(&mut self, tok: Token, bit: Option<u32>) -> PResult<u32> {
        match bit {
            Some(b) => Ok(b),
            None => {
                let found = self.describe(tok);
                self.error(
                    Code::UnexpectedToken,
                    tok.span,
                    format!(
                        "expected a bit number such as `.3` or `.%X3` (or a part such as `.%B1`), found {found}"
                    ),
                );
                Err(Fail)
            }
        }
    }

    /// Call arguments up to (not including) the `)`.
    fn parse_args(&mut self) -> PResult<Vec<Arg>> {
        let mut args = Vec::new();
        if self.at(TokenKind::RParen) {
            return Ok(args);
        }
        loop {
            args.push(self.parse_arg()?);
            if self.eat(TokenKind::Comma).is_none() {
                return Ok(args);
            }
        }
    }

    fn parse_arg(&mut self) -> PResult<Arg> {
        let first = self.tok();
        match (first.kind, self.peek_at(1), self.peek_at(2)) {
            (TokenKind::Ident, TokenKind::Assign, _) => {
                self.bump();
                self.bump();
                let value = self.parse_expr()?;
                Ok(Arg::Input { name: self.ident(first), value })
            }
            (TokenKind::Ident, TokenKind::Arrow, _) => {
                self.bump();
                self.bump();
                let target = self.parse_expr()?;
                Ok(Arg::Output { name: self.ident(first), target, negated: false })
            }
            (TokenKind::Not, TokenKind::Ident, TokenKind::Arrow) => {
                self.bump();
                let name_tok = self.bump();
                self.bump();
                let target = self.parse_expr()?;
                Ok(Arg::Output { name: self.ident(name_tok), target, negated: true })
            }
            _ => Ok(Arg::Positional(self.parse_expr()?)),
        }
    }

    fn parse_primary(&mut self) -> PResult<Expr> {
        let tok = self.tok();
        let span = tok.span;
        match tok.kind {
            TokenKind::Direct => {
                self.bump();
                let addr = self.direct_address(tok).ok_or(Fail)?;
                Ok(Expr { kind: ExprKind::Direct(addr), span })
            }
            TokenKind::LParen => {
                self.bump();
                let inner = Box::new(self.parse_expr()?);
                let close =
                    self.expect(TokenKind::RParen, phrase!(ExpectCloseParenToCloseParenthesis))?;
                Ok(Expr { kind: ExprKind::Paren(inner), span: span.to(close.span) })
            }
            TokenKind::Ident if self.peek_at(1) == TokenKind::Hash => self.parse_hash_prefixed(),
            TokenKind::Ident => {
                self.bump();
                Ok(Expr { kind: ExprKind::Name(self.ident(tok)), span })
            }
            // The operators that are also standard functions: `MOD(a, b)`, `AND(a, b, c)`.
            TokenKind::Mod | TokenKind::And | TokenKind::Or | TokenKind::Xor
                if self.peek_at(1) == TokenKind::LParen =>
            {
                self.bump();
                Ok(Expr { kind: ExprKind::Name(self.ident(tok)), span })
            }
            _ => match self.literal_token(tok) {
                Some(e) => Ok(e),
                None => Err(self.expected(phrase!(ExpectExpression))),
            },
        }
    }

    /// A literal token as an expression (`None` when `tok` is not a literal). Kept out of
    /// `parse_primary` so the recursive path stays light on stack.
    #[inline(never)]
    fn literal_token(&mut self, tok: Token) -> Option<Expr> {
        let text = self.text(tok);
        let value = match tok.kind {
            TokenKind::Integer => {
                self.literal_value(tok, literal::parse_integer(text).map(LiteralValue::Int))
            }
            TokenKind::Real => {
                self.literal_value(tok, literal::parse_real(text).map(LiteralValue::Real))
            }
            TokenKind::String => {
                self.literal_value(tok, literal::parse_string(text).map(LiteralValue::String))
            }
            TokenKind::WString => {
                self.literal_value(tok, literal::parse_wstring(text).map(LiteralValue::WString))
            }
            TokenKind::True => LiteralValue::Bool(true),
            TokenKind::False => LiteralValue::Bool(false),
            TokenKind::Duration => {
                self.literal_value(tok, literal::parse_duration(text).map(LiteralValue::Time))
            }
            TokenKind::Date => {
                self.literal_value(tok, literal::parse_date(text).map(LiteralValue::Date))
            }
            TokenKind::TimeOfDay => self
                .literal_value(tok, literal::parse_time_of_day(text).map(LiteralValue::TimeOfDay)),
            TokenKind::DateTime => {
                self.literal_value(tok, literal::parse_date_time(text).map(LiteralValue::DateTime))
            }
            _ => return None,
        };
        self.bump();
        // Duration and date literals carry no `type_prefix`: the value kind already says
        // TIME, DATE, TOD or DT (`LTIME#` is read as TIME).
        Some(Expr { kind: ExprKind::Literal(Literal { value, type_prefix: None }), span: tok.span })
    }

    /// The value of a literal, or a zero of the same kind after reporting the problem.
    fn literal_value(
        &mut self,
        tok: Token,
        r: Result<LiteralValue, literal::LitError>,
    ) -> LiteralValue {
        match r {
            Ok(v) => v,
            Err((code, msg)) => {
                self.error(code, tok.span, msg);
                match tok.kind {
                    TokenKind::Real => LiteralValue::Real(0.0),
                    TokenKind::String => LiteralValue::String(Vec::new()),
                    TokenKind::WString => LiteralValue::WString(Vec::new()),
                    TokenKind::Duration => LiteralValue::Time(0),
                    TokenKind::Date => LiteralValue::Date(0),
                    TokenKind::TimeOfDay => LiteralValue::TimeOfDay(0),
                    TokenKind::DateTime => LiteralValue::DateTime(0),
                    _ => LiteralValue::Int(0),
                }
            }
        }
    }

    /// `DINT#5`, `INT#-5`, `UINT#16#FE`, `BOOL#1`, `STRING#'OK'` or `Color#Red`.
    #[inline(never)]
    fn parse_hash_prefixed(&mut self) -> PResult<Expr> {
        let prefix_tok = self.bump();
        self.bump(); // `#`
        let prefix = self.ident(prefix_tok);
        let Some(class) = literal::prefix_class(&prefix.name) else {
            let value_tok =
                self.expect(TokenKind::Ident, format!("an enumerator after `{}#`", prefix.name))?;
            let value = self.ident(value_tok);
            let span = prefix_tok.span.to(value_tok.span);
            return Ok(Expr { kind: ExprKind::EnumValue { type_name: prefix, value }, span });
        };
        let negative = match self.peek() {
            TokenKind::Minus => {
                self.bump();
                true
            }
            TokenKind::Plus => {
                self.bump();
                false
            }
            _ => false,
        };
        let tok = self.tok();
        let text = self.text(tok);
        let value = match tok.kind {
            TokenKind::Integer => {
                self.literal_value(tok, literal::parse_integer(text).map(LiteralValue::Int))
            }
            TokenKind::Real => {
                self.literal_value(tok, literal::parse_real(text).map(LiteralValue::Real))
            }
            TokenKind::String if !negative => {
                self.literal_value(tok, literal::parse_string(text).map(LiteralValue::String))
            }
            TokenKind::WString if !negative => {
                self.literal_value(tok, literal::parse_wstring(text).map(LiteralValue::WString))
            }
            TokenKind::True if !negative => LiteralValue::Bool(true),
            TokenKind::False if !negative => LiteralValue::Bool(false),
            _ => return Err(self.expected(format!("a value after `{}#`", prefix.name))),
        };
        self.bump();
        let value = match (negative, value) {
            (true, LiteralValue::Int(i)) => LiteralValue::Int(-i),
            (true, LiteralValue::Real(r)) => LiteralValue::Real(-r),
            (_, v) => v,
        };
        let span = prefix_tok.span.to(tok.span);
        let value = match literal::apply_prefix(&prefix.name, class, value) {
            Ok(v) => v,
            Err((code, msg)) => {
                self.error(code, span, msg);
                LiteralValue::Int(0)
            }
        };
        Ok(Expr { kind: ExprKind::Literal(Literal { value, type_prefix: Some(prefix) }), span })
    }

    /// Decodes a `%…` token, reporting E0009 when it is malformed.
    pub(super) fn direct_address(&mut self, tok: Token) -> Option<DirectAddress> {
        let text = self.text(tok);
        match literal::parse_direct_address(text) {
            Ok((area, size, path)) => {
                Some(DirectAddress { area, size, path, text: text.to_string(), span: tok.span })
            }
            Err((code, msg)) => {
                self.error(code, tok.span, msg);
                None
            }
        }
    }
}
