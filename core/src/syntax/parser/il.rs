//! Instruction List bodies (IEC 61131-3 ed. 2 §3.2): one instruction per line.
//!
//! A body is IL when its first line is an IL operator followed on the same line by an
//! operand (`LD A`), or a label (`Start:`): no ST statement can begin either way, so every
//! ST body parses as before. Each instruction's tokens are cut at the end of its line (a
//! call's argument list in parentheses may go on over several lines) and parsed by a parser
//! over those tokens alone, so an operand never swallows the next line's `AND`. Operands are
//! single values (a variable, member, element, direct address or literal); anything longer
//! is a located error.

use super::{is_block_end, PResult, Parser};
use crate::diagnostics::{Code, Span};
use crate::syntax::ast::il::*;
use crate::syntax::ast::*;
use crate::syntax::lexer::{Token, TokenKind};

/// The operators of IL (upper case), the input operators of the standard blocks excepted.
const OPERATORS: &[&str] = &[
    "LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "OR", "ORN", "XOR", "XORN", "NOT", "ADD",
    "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LT", "LE", "JMP", "JMPC", "JMPCN", "CAL",
    "CALC", "CALCN", "RET", "RETC", "RETCN",
];

/// The input operators of the standard function blocks (`S1 FF1` sets `FF1.S1`).
pub(crate) const INPUT_OPERATORS: &[&str] = &["S1", "R1", "CLK", "CU", "CD", "PV", "IN", "PT"];

/// Every IL operator, the input operators last (for `did you mean`).
pub(crate) fn il_operator_names() -> impl Iterator<Item = &'static str> {
    OPERATORS.iter().chain(INPUT_OPERATORS).copied()
}

/// Whether `upper` is an IL operator or input operator (not a function name).
pub(crate) fn is_il_operator(upper: &str) -> bool {
    OPERATORS.contains(&upper) || INPUT_OPERATORS.contains(&upper)
}

/// Tokens that can begin an operand.
pub(crate) fn starts_operand(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(
        k,
        Ident
            | Integer
            | Real
            | String
            | WString
            | Duration
            | Date
            | TimeOfDay
            | DateTime
            | Direct
            | True
            | False
            | Minus
            | Plus
    )
}

/// The binary operation of an operator that acts on the CR with an operand.
fn operation(upper: &str) -> Option<(BinaryOp, bool)> {
    Some(match upper {
        "AND" | "&" => (BinaryOp::And, false),
        "ANDN" | "&N" => (BinaryOp::And, true),
        "OR" => (BinaryOp::Or, false),
        "ORN" => (BinaryOp::Or, true),
        "XOR" => (BinaryOp::Xor, false),
        "XORN" => (BinaryOp::Xor, true),
        "ADD" => (BinaryOp::Add, false),
        "SUB" => (BinaryOp::Sub, false),
        "MUL" => (BinaryOp::Mul, false),
        "DIV" => (BinaryOp::Div, false),
        "MOD" => (BinaryOp::Mod, false),
        other => (BinaryOp::Cmp(Cmp::from_function(other)?), false),
    })
}

/// The condition an operator's C / CN suffix gives (`JMPCN` → `IfFalse`).
fn condition(upper: &str, base: &str) -> IlCondition {
    match &upper[base.len()..] {
        "C" => IlCondition::IfTrue,
        "CN" => IlCondition::IfFalse,
        _ => IlCondition::Always,
    }
}

impl<'a> Parser<'a> {
    /// The text between two tokens.
    fn gap(&self, a: Token, b: Token) -> &'a str {
        self.src.get(a.span.end as usize..b.span.start as usize).unwrap_or("")
    }

    /// Whether `b` stands on the same line as `a` (which comes before it).
    fn same_line(&self, a: Token, b: Token) -> bool {
        !self.gap(a, b).contains('\n')
    }

    /// Whether the body at the cursor is written in IL (see the module comment).
    pub(super) fn at_il_body(&self) -> bool {
        let (t0, t1) = (self.tok(), self.nth(1));
        if t0.kind != TokenKind::Ident {
            return false;
        }
        if t1.kind == TokenKind::Colon {
            return true;
        }
        let op = self.text(t0).to_ascii_uppercase();
        if !is_il_operator(&op) {
            return false;
        }
        if self.same_line(t0, t1) {
            starts_operand(t1.kind)
        } else {
            matches!(op.as_str(), "RET" | "RETC" | "RETCN")
        }
    }

    /// Parses an IL body up to the END_ keyword of its POU.
    pub(super) fn parse_il_body(&mut self) -> IlBody {
        let start = self.tok().span;
        let mut instructions = Vec::new();
        let mut labels: Vec<(Ident, usize)> = Vec::new();
        while !is_block_end(self.peek()) {
            let before = self.pos;
            if self.at(TokenKind::Ident) && self.peek_at(1) == TokenKind::Colon {
                let label_tok = self.bump();
                let label = self.ident(label_tok);
                let colon = self.bump();
                if labels.iter().any(|(l, _)| l.key() == label.key()) {
                    self.error(
                        Code::IlUndefinedLabel,
                        label.span,
                        format!("the label `{}` is defined twice", label.name),
                    );
                } else {
                    labels.push((label, instructions.len()));
                }
                if !self.same_line(colon, self.tok()) {
                    continue;
                }
                if is_block_end(self.peek()) {
                    break;
                }
            }
            let end = self.instruction_end();
            let at = self.tok();
            let instruction = self.parse_instruction(end).unwrap_or_else(|| IlInstruction {
                kind: IlKind::Invalid,
                operator: self.ident(at),
                span: at.span,
            });
            instructions.push(instruction);
            self.pos = end.max(self.pos);
            if self.pos == before {
                self.bump();
            }
        }
        let span = start.to(self.prev_span());
        IlBody { instructions, labels, span }
    }

    /// The index one past the last token of the instruction at the cursor: the end of its
    /// line, or of the line that closes a parenthesis opened after the operator's own `(`.
    fn instruction_end(&self) -> usize {
        let first = self.pos;
        let head = self.tok();
        let deferrable = match head.kind {
            TokenKind::Ident => operation(&self.text(head).to_ascii_uppercase()).is_some(),
            k => matches!(
                k,
                TokenKind::And
                    | TokenKind::Or
                    | TokenKind::Xor
                    | TokenKind::Mod
                    | TokenKind::Ampersand
            ),
        };
        let mut depth = 0i32;
        let mut i = first;
        while let Some(&t) = self.tokens.get(i) {
            if t.kind == TokenKind::Eof || (i > first && is_block_end(t.kind)) {
                break;
            }
            if i > first {
                let prev = self.tokens[i - 1];
                if depth <= 0 && !self.same_line(prev, t) {
                    break;
                }
            }
            // A `(` right after an operator is the deferral modifier, closed by a `)` line.
            let modifier = deferrable
                && t.kind == TokenKind::LParen
                && (i == first + 1
                    || (i == first + 2 && self.tokens[first].kind == TokenKind::Ampersand));
            match t.kind {
                TokenKind::LParen if !modifier => depth += 1,
                TokenKind::RParen if i > first => depth -= 1,
                _ => {}
            }
            i += 1;
        }
        i
    }

    /// Parses the instruction in tokens `self.pos..end` with a parser over those tokens.
    fn parse_instruction(&mut self, end: usize) -> Option<IlInstruction> {
        let mut tokens: Vec<Token> = self.tokens.get(self.pos..end).unwrap_or(&[]).to_vec();
        while tokens.last().is_some_and(|t| t.kind == TokenKind::Semicolon) {
            tokens.pop();
        }
        let last = tokens.last().map_or(self.tok().span.start, |t| t.span.end) as usize;
        tokens.push(Token { kind: TokenKind::Eof, span: Span::new(last, last) });
        let mut line = Parser {
            src: self.src,
            tokens,
            comments: Vec::new(),
            pos: 0,
            diags: Vec::new(),
            depth: self.depth,
            open_ends: Vec::new(),
        };
        let result = line.instruction();
        for mut d in line.diags {
            d.message = d.message.replace("the end of the text", "the end of the line");
            self.error(d.code, d.span, d.message);
        }
        result.ok()
    }

    /// One instruction (this parser holds its tokens only).
    fn instruction(&mut self) -> PResult<IlInstruction> {
        let op_tok = self.bump();
        let mut operator = self.ident(op_tok);
        let upper = match op_tok.kind {
            TokenKind::Ident => operator.name.to_ascii_uppercase(),
            TokenKind::And => "AND".into(),
            TokenKind::Or => "OR".into(),
            TokenKind::Xor => "XOR".into(),
            TokenKind::Not => "NOT".into(),
            TokenKind::Mod => "MOD".into(),
            TokenKind::RParen => ")".into(),
            TokenKind::Ampersand => {
                let n = self.tok();
                if n.kind == TokenKind::Ident
                    && n.span.start == op_tok.span.end
                    && self.text(n).eq_ignore_ascii_case("N")
                {
                    self.bump();
                    operator =
                        Ident { name: format!("&{}", self.text(n)), span: op_tok.span.to(n.span) };
                    "&N".into()
                } else {
                    "&".into()
                }
            }
            _ => {
                let found = self.describe(op_tok);
                self.error(
                    Code::IlUnknownOperator,
                    op_tok.span,
                    crate::msg!(ExpectedIlOperatorFound, found = found),
                );
                return Err(super::Fail);
            }
        };
        let kind = self.instruction_kind(&upper, &operator)?;
        if !self.at(TokenKind::Eof) {
            let tok = self.tok();
            let found = self.describe(tok);
            self.error(
                Code::IlBadInstruction,
                tok.span,
                format!("expected the end of the line after `{}`, found {found}: one instruction per line", operator.name),
            );
        }
        let span = op_tok.span.to(self.prev_span());
        Ok(IlInstruction { kind, operator, span })
    }

    fn instruction_kind(&mut self, upper: &str, operator: &Ident) -> PResult<IlKind> {
        Ok(match upper {
            "LD" | "LDN" => {
                IlKind::Load { negated: upper == "LDN", operand: self.il_operand(operator)? }
            }
            "ST" | "STN" => {
                IlKind::Store { negated: upper == "STN", target: self.il_operand(operator)? }
            }
            "S" | "R" => IlKind::SetReset { set: upper == "S", target: self.il_operand(operator)? },
            "NOT" => IlKind::Not,
            ")" => IlKind::Close,
            "JMP" | "JMPC" | "JMPCN" => {
                let label = match self.eat(TokenKind::Ident) {
                    Some(t) => self.ident(t),
                    None => {
                        return Err(
                            self.il_expected(Code::IlBadInstruction, "a label after the jump")
                        )
                    }
                };
                IlKind::Jump { condition: condition(upper, "JMP"), label }
            }
            "CAL" | "CALC" | "CALCN" => {
                let e = self.parse_expr()?;
                let (instance, args) = match e.kind {
                    ExprKind::Call { callee, args } => (*callee, args),
                    _ => (e, Vec::new()),
                };
                IlKind::Call { condition: condition(upper, "CAL"), instance, args }
            }
            "RET" | "RETC" | "RETCN" => IlKind::Return { condition: condition(upper, "RET") },
            _ if INPUT_OPERATORS.contains(&upper) => {
                IlKind::Input { input: operator.clone(), instance: self.il_operand(operator)? }
            }
            _ => match operation(upper) {
                Some((op, negated)) => {
                    let deferred = self.eat(TokenKind::LParen).is_some();
                    let operand = if deferred && self.at(TokenKind::Eof) {
                        None
                    } else {
                        Some(self.il_operand(operator)?)
                    };
                    IlKind::Operate { op, negated, deferred, operand }
                }
                None => self.function_instruction(operator)?,
            },
        })
    }

    /// `NAME op, op, …` or `NAME(formal list)`: a function call on the CR.
    fn function_instruction(&mut self, operator: &Ident) -> PResult<IlKind> {
        if operator.name.is_empty() || !crate::syntax::is_identifier(&operator.name) {
            self.error(
                Code::IlUnknownOperator,
                operator.span,
                crate::msg!(NotIlOperator, name = &operator.name),
            );
            return Err(super::Fail);
        }
        if self.at(TokenKind::LParen) {
            self.pos = 0;
            let e = self.parse_expr()?;
            let ExprKind::Call { args, .. } = e.kind else {
                return Err(self.il_expected(Code::IlBadInstruction, "a formal argument list"));
            };
            return Ok(IlKind::Function { name: operator.clone(), args, formal: true });
        }
        let mut args = Vec::new();
        if !self.at(TokenKind::Eof) {
            loop {
                args.push(Arg::Positional(self.il_operand(operator)?));
                if self.eat(TokenKind::Comma).is_none() {
                    break;
                }
            }
        }
        Ok(IlKind::Function { name: operator.clone(), args, formal: false })
    }

    /// One operand: a variable, member, element, direct address or (signed) literal.
    fn il_operand(&mut self, operator: &Ident) -> PResult<Expr> {
        if self.at(TokenKind::Eof) {
            return Err(self.il_expected(
                Code::IlBadInstruction,
                &format!("an operand after `{}`", operator.name),
            ));
        }
        let e = self.parse_expr()?;
        let single = !matches!(
            &e.kind,
            ExprKind::Binary(..)
                | ExprKind::Paren(_)
                | ExprKind::Call { .. }
                | ExprKind::Unary(UnaryOp::Not, _)
        );
        if !single {
            self.error(
                Code::IlBadInstruction,
                e.span,
                "an IL operand is one variable or constant: write each operation as its own instruction",
            );
            return Err(super::Fail);
        }
        Ok(e)
    }

    fn il_expected(&mut self, code: Code, what: &str) -> super::Fail {
        let tok = self.tok();
        let found = self.describe(tok);
        self.error(code, tok.span, format!("expected {what}, found {found}"));
        super::Fail
    }
}
