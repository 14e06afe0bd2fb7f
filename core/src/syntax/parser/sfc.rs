//! Textual SFC (IEC 61131-3 §6.7): `INITIAL_STEP`/`STEP … END_STEP` with action
//! associations, `TRANSITION … FROM … TO … END_TRANSITION` and `ACTION … END_ACTION` as the
//! body of a PROGRAM or FUNCTION_BLOCK.
//!
//! `STEP`, `TRANSITION`, `ACTION`, `FROM` and `PRIORITY` are not reserved words: they are
//! recognised from what follows them (`STEP name`, `TRANSITION FROM`, …), so programs that
//! use them as variable names keep working. Only `INITIAL_STEP`, `END_STEP`,
//! `END_TRANSITION` and `END_ACTION` are keywords. Checking the chart (unknown steps,
//! initial steps, …) is not done here but in `crate::sfc`.

use super::{is_block_end, Fail, PResult, Parser};
use crate::diagnostics::{Code, Span};
use crate::phrase;
use crate::syntax::ast::sfc::*;
use crate::syntax::ast::*;
use crate::syntax::lexer::{Token, TokenKind};

impl Parser<'_> {
    /// True when the token `n` places ahead is the name `word` (any case).
    fn word_at(&self, n: usize, word: &str) -> bool {
        let t = self.nth(n);
        t.kind == TokenKind::Ident && self.text(t).eq_ignore_ascii_case(word)
    }

    /// True when the cursor stands on the start of a step, transition or action.
    pub(super) fn at_sfc_element(&self) -> bool {
        match self.peek() {
            TokenKind::InitialStep => true,
            TokenKind::Ident if self.word_at(0, "STEP") || self.word_at(0, "ACTION") => {
                // `Step Name` is never a statement; `Step := 1;` and `Action(…);` are.
                self.peek_at(1) == TokenKind::Ident
            }
            TokenKind::Ident if self.word_at(0, "TRANSITION") => match self.peek_at(1) {
                TokenKind::Ident => true,
                // `TRANSITION (PRIORITY := n) FROM`, not a call `Transition(PRIORITY := n);`
                TokenKind::LParen => self.word_at(2, "PRIORITY") && self.word_at(6, "FROM"),
                _ => false,
            },
            _ => false,
        }
    }

    /// Parses one step, transition or action (the cursor is on its first word).
    pub(super) fn parse_sfc_element(&mut self) -> SfcElement {
        if self.at(TokenKind::InitialStep) || self.word_at(0, "STEP") {
            SfcElement::Step(self.parse_step())
        } else if self.word_at(0, "ACTION") {
            SfcElement::Action(self.parse_action())
        } else {
            SfcElement::Transition(self.parse_transition())
        }
    }

    /// Skips a broken SFC element up to `end` (consumed) or the start of the next element.
    fn skip_sfc(&mut self, end: TokenKind) {
        loop {
            if self.at(end) {
                self.bump();
                self.eat(TokenKind::Semicolon);
                return;
            }
            if self.at_sfc_element() || sfc_stop(self.peek()) {
                return;
            }
            self.bump();
        }
    }

    /// The name after `STEP`, `ACTION` or `TRANSITION`.
    fn sfc_name(&mut self, what: &str) -> PResult<Ident> {
        let tok = self.expect(TokenKind::Ident, what)?;
        Ok(self.ident(tok))
    }

    /// Closes an element with `end` (and an optional `;`); reports it missing at `opener`.
    fn close_sfc(&mut self, opener: Token, end: TokenKind, end_name: &str, what: &str) -> Span {
        if self.eat(end).is_some() {
            self.eat(TokenKind::Semicolon);
        } else {
            let found = self.describe(self.tok());
            self.error(
                Code::MissingEnd,
                opener.span,
                format!("`{end_name}` is missing for {what} (found {found})"),
            );
            if !self.at_sfc_element() {
                self.skip_sfc(end);
            }
        }
        opener.span.to(self.prev_span())
    }

    fn parse_step(&mut self) -> SfcStep {
        let opener = self.bump();
        let initial = opener.kind == TokenKind::InitialStep;
        let kw = self.text(opener).to_string();
        let name = match self.sfc_name(&format!("a step name after `{kw}`")) {
            Ok(n) => n,
            Err(Fail) => {
                self.skip_sfc(TokenKind::EndStep);
                let name = Ident { name: String::new(), span: opener.span };
                let span = opener.span.to(self.prev_span());
                return SfcStep { name, initial, associations: Vec::new(), header: span, span };
            }
        };
        let header = opener.span.to(name.span);
        if self.eat(TokenKind::Colon).is_none() {
            self.expected(format!("`:` after the step name `{}`", name.name));
        }
        let mut associations = Vec::new();
        while !self.at(TokenKind::EndStep)
            && !self.at_sfc_element()
            && !sfc_stop(self.peek())
            && !is_block_end(self.peek())
        {
            let before = self.pos;
            match self.parse_association() {
                Ok(a) => associations.push(a),
                Err(Fail) => self.skip_association(),
            }
            if self.pos == before {
                self.bump();
            }
        }
        let what = format!("step `{}`", name.name);
        let span = self.close_sfc(opener, TokenKind::EndStep, "END_STEP", &what);
        SfcStep { name, initial, associations, header, span }
    }

    /// Skips a broken association up to and including its `;` (or to `END_STEP`).
    fn skip_association(&mut self) {
        loop {
            let k = self.peek();
            if k == TokenKind::Semicolon {
                self.bump();
                return;
            }
            if k == TokenKind::EndStep || sfc_stop(k) || self.at_sfc_element() {
                return;
            }
            self.bump();
        }
    }

    /// `Action(qualifier[, duration][, indicator…]);`
    fn parse_association(&mut self) -> PResult<ActionAssociation> {
        let action = self.sfc_name("an action association such as `Fill(N);` or `END_STEP`")?;
        if self.eat(TokenKind::LParen).is_none() {
            let name = action.name.clone();
            return Err(self.expected(format!(
                "`(` and a qualifier after the action name, as in `{name}(N);`"
            )));
        }
        let mut qualifier = Qualifier::N;
        let mut qualifier_span = action.span;
        if self.at(TokenKind::Ident) {
            let tok = self.bump();
            let text = self.text(tok);
            match Qualifier::from_name(text) {
                Some(q) => {
                    qualifier = q;
                    qualifier_span = tok.span;
                }
                None => {
                    // Reported, then read as N so the association still counts as a use.
                    self.error(
                        Code::SfcUnknownQualifier,
                        tok.span,
                        crate::msg!(NotActionQualifier, name = text),
                    );
                }
            }
        }
        let mut duration = None;
        let mut indicators = Vec::new();
        while self.eat(TokenKind::Comma).is_some() {
            if qualifier.is_timed() && duration.is_none() {
                duration = Some(self.parse_expr()?);
            } else if self.at(TokenKind::Ident) {
                let tok = self.bump();
                indicators.push(self.ident(tok));
            } else if matches!(self.peek(), TokenKind::Duration) {
                let tok = self.bump();
                let name = qualifier.name();
                self.error(
                    Code::SfcUnexpectedDuration,
                    tok.span,
                    crate::msg!(QualifierTakesNoDuration, name = name),
                );
            } else {
                return Err(self.expected(phrase!(ExpectIndicatorVariableName)));
            }
        }
        self.expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParenInActionAssociation))?;
        if qualifier.is_timed() && duration.is_none() {
            let name = qualifier.name();
            self.error(
                Code::SfcMissingDuration,
                qualifier_span,
                crate::msg!(QualifierNeedsDuration, name = name, action = &action.name),
            );
        }
        let span = self.end_statement(action.span);
        Ok(ActionAssociation { action, qualifier, qualifier_span, duration, indicators, span })
    }

    /// A step name or a parenthesised list of step names.
    fn step_list(&mut self, what: &str) -> PResult<Vec<Ident>> {
        if self.eat(TokenKind::LParen).is_some() {
            let mut names = vec![self.sfc_name(what)?];
            while self.eat(TokenKind::Comma).is_some() {
                names.push(self.sfc_name(what)?);
            }
            self.expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParenInListOfSteps))?;
            Ok(names)
        } else {
            Ok(vec![self.sfc_name(what)?])
        }
    }

    /// `(PRIORITY := n)` (the cursor is on the `(`).
    fn parse_priority(&mut self) -> PResult<(u32, Span)> {
        let open = self.bump();
        if !self.word_at(0, "PRIORITY") {
            return Err(self.expected(phrase!(ExpectPriorityN)));
        }
        self.bump();
        self.expect(TokenKind::Assign, phrase!(ExpectAssignAfterPriority))?;
        let value = self.parse_expr()?;
        let close = self.expect(TokenKind::RParen, phrase!(ExpectCloseParenAfterPriority))?;
        let n = match &value.kind {
            ExprKind::Literal(Literal { value: LiteralValue::Int(n), type_prefix: None }) => {
                u32::try_from(*n).ok()
            }
            _ => None,
        };
        match n {
            Some(n) => Ok((n, open.span.to(close.span))),
            None => {
                self.error(
                    Code::UnexpectedToken,
                    value.span,
                    "PRIORITY takes a whole number written as a literal (0 is the highest priority)",
                );
                Err(Fail)
            }
        }
    }

    fn parse_transition(&mut self) -> SfcTransition {
        let opener = self.bump();
        match self.transition_header(opener) {
            Ok((name, priority, from, to)) => {
                let header = opener.span.to(self.prev_span());
                let condition = self.transition_condition();
                let what = match &name {
                    Some(n) => format!("transition `{}`", n.name),
                    None => "this transition".to_string(),
                };
                let span =
                    self.close_sfc(opener, TokenKind::EndTransition, "END_TRANSITION", &what);
                SfcTransition { name, priority, from, to, condition, header, span }
            }
            Err(Fail) => {
                self.skip_sfc(TokenKind::EndTransition);
                let span = opener.span.to(self.prev_span());
                let condition = TransitionCondition::Body(Vec::new());
                SfcTransition {
                    name: None,
                    priority: None,
                    from: Vec::new(),
                    to: Vec::new(),
                    condition,
                    header: span,
                    span,
                }
            }
        }
    }

    /// `[name] [(PRIORITY := n)] FROM steps TO steps`
    #[allow(clippy::type_complexity)]
    fn transition_header(
        &mut self,
        opener: Token,
    ) -> PResult<(Option<Ident>, Option<(u32, Span)>, Vec<Ident>, Vec<Ident>)> {
        let mut name = None;
        if self.at(TokenKind::Ident) && !self.word_at(0, "FROM") {
            let tok = self.bump();
            name = Some(self.ident(tok));
        }
        let priority = if self.at(TokenKind::LParen) { Some(self.parse_priority()?) } else { None };
        if !self.word_at(0, "FROM") {
            let kw = self.text(opener).to_string();
            return Err(self.expected(format!("`FROM` and the steps this {kw} leaves")));
        }
        self.bump();
        let from = self.step_list("a step name after FROM")?;
        self.expect(TokenKind::To, phrase!(ExpectToAndStepsThisTransitionActivates))?;
        let to = self.step_list("a step name after TO")?;
        Ok((name, priority, from, to))
    }

    /// `:= condition;` or `: statements`.
    fn transition_condition(&mut self) -> TransitionCondition {
        if self.eat(TokenKind::Assign).is_some() {
            let start = self.tok().span;
            match self.parse_expr() {
                Ok(e) => {
                    self.end_statement(e.span);
                    TransitionCondition::Expr(e)
                }
                Err(Fail) => {
                    while !self.at(TokenKind::EndTransition)
                        && !self.at(TokenKind::Semicolon)
                        && !sfc_stop(self.peek())
                        && !self.at_sfc_element()
                    {
                        self.bump();
                    }
                    self.eat(TokenKind::Semicolon);
                    let bad = Literal { value: LiteralValue::Bool(false), type_prefix: None };
                    TransitionCondition::Expr(Expr { kind: ExprKind::Literal(bad), span: start })
                }
            }
        } else if self.eat(TokenKind::Colon).is_some() {
            TransitionCondition::Body(self.parse_stmts(false))
        } else {
            self.expected(phrase!(ExpectAssignAndTransitionCondition));
            TransitionCondition::Body(Vec::new())
        }
    }

    fn parse_action(&mut self) -> SfcAction {
        let opener = self.bump();
        let name = match self.sfc_name("an action name after `ACTION`") {
            Ok(n) => n,
            Err(Fail) => Ident { name: String::new(), span: opener.span },
        };
        let header = opener.span.to(name.span);
        if self.eat(TokenKind::Colon).is_none() {
            self.expected(format!("`:` after the action name `{}`", name.name));
        }
        let body = self.parse_stmts(false);
        let what = format!("action `{}`", name.name);
        let span = self.close_sfc(opener, TokenKind::EndAction, "END_ACTION", &what);
        SfcAction { name, body, header, span }
    }
}

/// Tokens at which every SFC element stops: the end of the POU or of the text.
fn sfc_stop(k: TokenKind) -> bool {
    use TokenKind::*;
    matches!(
        k,
        Eof | EndProgram | EndFunction | EndFunctionBlock | Program | Function | FunctionBlock
    )
}
