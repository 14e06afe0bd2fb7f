//! Statements: assignments, calls, IF, CASE, loops and jumps.

use super::check::Checker;
use super::consts;
use super::ir::{Builtin, Expr, ExprKind, Place, Stmt, StmtKind};
use super::types::Type;
use crate::diagnostics::{Code, Span};
use crate::syntax::{self as ast};

impl<'a> Checker<'a> {
    /// Checks a list of statements; statements with errors are left out. The first
    /// statement after a RETURN, EXIT or CONTINUE of the same list gets warning W0002.
    pub fn stmts(&mut self, list: &[ast::Stmt]) -> Vec<Stmt> {
        use ast::StmtKind as K;
        let leaving = list.iter().position(|s| matches!(s.kind, K::Return | K::Exit | K::Continue));
        if let Some(i) = leaving {
            if let Some(next) = list[i + 1..].iter().find(|s| !matches!(s.kind, K::Empty)) {
                let why = match list[i].kind {
                    K::Return => "the RETURN before it always leaves the POU",
                    K::Exit => "the EXIT before it always leaves the loop",
                    _ => "the CONTINUE before it always goes on with the loop's next pass",
                };
                let msg = crate::msg!(StatementCanNeverRun, why = why);
                self.warning(Code::UnreachableCode, next.span, msg);
            }
        }
        list.iter().filter_map(|s| self.stmt(s)).collect()
    }

    /// The target at `span` of an assignment was not declared: the value `t` stored into
    /// it tells the type its `Declare NAME` fix declares.
    fn imply_type(&mut self, span: Span, t: &super::expr::Typed) {
        let implied = self.implied_by(t);
        if let Some(d) =
            self.diags.iter_mut().rev().find(|d| {
                d.code == Code::UndeclaredName && d.span == span && d.implied_type.is_none()
            })
        {
            d.implied_type = implied;
        }
    }

    pub(super) fn condition(&mut self, e: &ast::Expr, what: &str) -> Option<Expr> {
        let t = self.expr(e, Some(Type::BOOL))?;
        // A condition is a BOOL context: an untyped `0` or `1` is FALSE or TRUE.
        let t = self.bool_literal(t, Type::BOOL);
        if !t.e.ty.is_bool() {
            let msg = crate::msg!(
                ConditionMustBoolNot,
                what = what,
                ty = (self.tname(t.e.ty)).to_string()
            );
            self.error(Code::ConditionNotBool, e.span, msg);
            return None;
        }
        Some(t.e)
    }

    fn stmt(&mut self, s: &ast::Stmt) -> Option<Stmt> {
        use ast::StmtKind as K;
        let span = s.span;
        let kind = match &s.kind {
            K::Empty => return None,
            K::Assign { target, value } if matches!(target.kind, ast::ExprKind::Part { .. }) => {
                self.part_assign(target, value)?
            }
            K::Assign { target, value } => {
                let place = self.place(target, true);
                let t = self.expr(value, place.as_ref().map(|p| p.1));
                if let (None, Some(t), ast::ExprKind::Name(_)) = (&place, &t, &target.kind) {
                    self.imply_type(target.span, t);
                }
                let ((place, ty), t) = (place?, t?);
                if let Type::Fb(_) = ty {
                    self.error(
                        Code::NotAssignable,
                        target.span,
                        crate::msg!(FunctionBlockInstanceCannotAssigned),
                    );
                    return None;
                }
                let v = self.coerce(t, ty, value.span)?;
                self.check_subrange(&place, &v);
                let v = self.guard_subrange(&place, v);
                if let (Type::Array(_) | Type::Struct(_), false) =
                    (ty, matches!(v.kind, ExprKind::Load(_)))
                {
                    self.error(
                        Code::NotAssignable,
                        value.span,
                        crate::msg!(ArraysStructuresCanOnlyCopied),
                    );
                    return None;
                }
                StmtKind::Assign(place, v)
            }
            K::Call(call) => {
                let ast::ExprKind::Call { callee, args } = &call.kind else {
                    self.error(Code::UnexpectedToken, span, crate::msg!(ExpectedCall));
                    return None;
                };
                self.call_stmt(callee, args, span)?
            }
            K::If { branches, else_body } => {
                let mut out = Vec::new();
                for (cond, body) in branches {
                    let c = self.condition(cond, "IF");
                    let b = self.stmts(body);
                    if let Some(c) = c {
                        out.push((c, b));
                    }
                }
                let else_body = else_body.as_ref().map(|b| self.stmts(b)).unwrap_or_default();
                StmtKind::If { branches: out, else_body }
            }
            K::Case { selector, arms, else_body } => {
                self.case(selector, arms, else_body.as_deref())?
            }
            K::For { var, from, to, by, body } => {
                let var_expr = ast::Expr { kind: ast::ExprKind::Name(var.clone()), span: var.span };
                let place = self.place(&var_expr, true);
                let ty = place.as_ref().map(|p| p.1);
                let el = ty.and_then(Type::elem).filter(|e| e.is_int());
                if place.is_some() && el.is_none() {
                    let msg = crate::msg!(VariableMustIntegerVariable, name = var.name);
                    self.error(Code::ForVariableNotInteger, var.span, msg);
                }
                let vty = el.map(Type::Elem);
                let f = self
                    .expr(from, vty)
                    .and_then(|t| vty.and_then(|ty| self.coerce(t, ty, from.span)));
                let t =
                    self.expr(to, vty).and_then(|t| vty.and_then(|ty| self.coerce(t, ty, to.span)));
                let b = match by {
                    Some(b) => self
                        .expr(b, vty)
                        .and_then(|t| vty.and_then(|ty| self.coerce(t, ty, b.span))),
                    None => el.map(|e| Expr {
                        kind: ExprKind::Const(1),
                        ty: Type::Elem(e),
                        span: var.span,
                    }),
                };
                if let Some(step) = &b {
                    if consts::int_value(step) == Some(0) {
                        self.error(Code::ZeroForStep, step.span, crate::msg!(LoopStep0NeverEnds));
                    }
                }
                self.body.loop_depth += 1;
                let body = self.stmts(body);
                self.body.loop_depth -= 1;
                let ((place, _), el, from, to, by) = (place?, el?, f?, t?, b?);
                let (from, to) = self.guard_for_limits(&place, from, to);
                StmtKind::For { var: place, ty: el, from, to, by, body }
            }
            K::While { cond, body } => {
                let c = self.condition(cond, "WHILE");
                self.body.loop_depth += 1;
                let body = self.stmts(body);
                self.body.loop_depth -= 1;
                StmtKind::While { cond: c?, body }
            }
            K::Repeat { body, until } => {
                self.body.loop_depth += 1;
                let body = self.stmts(body);
                self.body.loop_depth -= 1;
                let c = self.condition(until, "UNTIL");
                StmtKind::Repeat { body, until: c? }
            }
            K::Exit | K::Continue => {
                if self.body.loop_depth == 0 {
                    let kw = if matches!(s.kind, K::Exit) { "EXIT" } else { "CONTINUE" };
                    self.error(
                        Code::ExitOutsideLoop,
                        span,
                        crate::msg!(CanOnlyUsedInsideWhile, kw = kw),
                    );
                    return None;
                }
                if matches!(s.kind, K::Exit) {
                    StmtKind::Exit
                } else {
                    StmtKind::Continue
                }
            }
            K::Return => StmtKind::Return,
        };
        Some(Stmt { kind, span })
    }

    /// The subrange a place is declared with, if any.
    pub(super) fn place_range(&self, place: &Place) -> Option<(i64, i64)> {
        match place {
            Place::Local(i) => self.pous.get(self.body.pou as usize)?.vars.get(*i as usize)?.range,
            Place::Global(i) => self.globals.get(*i as usize)?.range,
            Place::Field(_, _) | Place::Bit(..) | Place::Slice(..) | Place::Deref(_) => None,
            Place::Element(_, id, _) => self.types.arrays.get(*id as usize)?.element_range,
        }
    }

    /// `w.%B1 := v` as `w := (w AND NOT 16#FF00) OR SHL(v, 8)` (its own function: `stmt`
    /// recurses through nested statements, so its frame stays small).
    #[inline(never)]
    fn part_assign(&mut self, target: &ast::Expr, value: &ast::Expr) -> Option<StmtKind> {
        let ast::ExprKind::Part { base, width, index } = &target.kind else { return None };
        let place = self.place(base, true);
        let part = place.as_ref().and_then(|p| self.part_of(p.1, *width, *index, target.span));
        let t = self.expr(value, part.map(Type::Elem));
        let ((place, ty), part, t) = (place?, part?, t?);
        let v = self.coerce(t, Type::Elem(part), value.span)?;
        let current = Expr { kind: ExprKind::Load(place.clone()), ty, span: target.span };
        let whole = self.write_part(current, part, *index, v, target.span);
        Some(StmtKind::Assign(place, whole))
    }

    /// A value stored into a subrange variable, checked when the scan stores it (a FAULT
    /// outside the limits, located at the assignment); constants are checked here already.
    fn guard_subrange(&self, place: &Place, value: Expr) -> Expr {
        self.guard_range(self.place_range(place), value)
    }

    /// `value` checked against `range` when the scan computes it (see
    /// [`Checker::guard_subrange`]): a variable's subrange, or a parameter's.
    pub(super) fn guard_range(&self, range: Option<(i64, i64)>, value: Expr) -> Expr {
        let Some((lo, hi)) = range else { return value };
        if consts::int_value(&value).is_some() {
            return value;
        }
        let (ty, span) = (value.ty, value.span);
        let limit = |v: i64| Expr { kind: ExprKind::Const(v as u64), ty, span };
        Expr {
            kind: ExprKind::Builtin {
                func: Builtin::Subrange,
                args: vec![limit(lo), value, limit(hi)],
            },
            ty,
            span,
        }
    }

    /// The limits of a FOR loop over a subrange variable, checked against its subrange
    /// (constants here, others when the loop starts): the first value is stored in the
    /// variable, and the last one the body sees is `to`. The value that ends the loop
    /// (one step past `to`) is not checked, as no statement of the body sees it.
    #[inline(never)]
    fn guard_for_limits(&mut self, place: &Place, from: Expr, to: Expr) -> (Expr, Expr) {
        let range = self.place_range(place);
        self.check_range(range, &from);
        self.check_range(range, &to);
        (self.guard_range(range, from), self.guard_range(range, to))
    }

    /// Reports a constant stored into a subrange variable outside its limits.
    fn check_subrange(&mut self, place: &Place, value: &Expr) {
        self.check_range(self.place_range(place), value);
    }

    /// Reports a constant outside `range` (a variable's or a parameter's subrange).
    pub(super) fn check_range(&mut self, range: Option<(i64, i64)>, value: &Expr) {
        let (Some((lo, hi)), Some(v)) = (range, consts::int_value(value)) else {
            return;
        };
        if v < lo || v > hi {
            self.error(
                Code::SubrangeViolation,
                value.span,
                crate::msg!(OutsideSubrangeVariable, v = v, lo = lo, hi = hi),
            );
        }
    }

    fn case(
        &mut self,
        selector: &ast::Expr,
        arms: &[ast::CaseArm],
        else_body: Option<&[ast::Stmt]>,
    ) -> Option<StmtKind> {
        let sel = self.expr(selector, None);
        let sel_ty = sel.as_ref().map(|s| s.e.ty);
        let ok_selector =
            |t: Type| matches!(t, Type::Enum(_)) || t.elem().is_some_and(|e| e.is_integral());
        if let Some(t) = sel_ty {
            if !ok_selector(t) {
                let msg = crate::msg!(
                    CaseSelectorMustIntegerEnumeration,
                    value = (self.tname(t)).to_string()
                );
                self.error(Code::TypeMismatch, selector.span, msg);
            }
        }
        let label_ty = sel_ty.filter(|t| ok_selector(*t));
        // The labels accepted so far, disjoint, by their lower end: an overlap test is one
        // lookup (a CASE of 200,000 labels checked in quadratic time took minutes).
        let mut seen: std::collections::BTreeMap<i64, i64> = std::collections::BTreeMap::new();
        let mut out = Vec::new();
        for arm in arms {
            let mut ranges = Vec::new();
            for label in &arm.labels {
                let (lo_e, hi_e) = match label {
                    ast::CaseLabel::Value(v) => (v, v),
                    ast::CaseLabel::Range(a, b) => (a, b),
                };
                let (Some(lo), Some(hi)) =
                    (self.case_label(lo_e, label_ty), self.case_label(hi_e, label_ty))
                else {
                    continue;
                };
                let span = lo_e.span.to(hi_e.span);
                if lo > hi {
                    self.error(Code::InvalidRange, span, crate::msg!(RangeEmpty, lo = lo, hi = hi));
                    continue;
                }
                if seen.range(..=hi).next_back().is_some_and(|(_, &end)| end >= lo) {
                    self.error(
                        Code::DuplicateCaseLabel,
                        span,
                        crate::msg!(CaseLabelAlreadyCoveredEarlier),
                    );
                    continue;
                }
                seen.insert(lo, hi);
                ranges.push((lo, hi));
            }
            let body = self.stmts(&arm.body);
            out.push((ranges, body));
        }
        let else_body = else_body.map(|b| self.stmts(b)).unwrap_or_default();
        let sel = sel?;
        label_ty?;
        Some(StmtKind::Case { selector: sel.e, arms: out, else_body })
    }

    fn case_label(&mut self, e: &ast::Expr, sel: Option<Type>) -> Option<i64> {
        let t = self.expr(e, sel)?;
        let sel = sel?;
        let value = match sel {
            Type::Enum(_) => {
                if t.e.ty != sel {
                    let msg = crate::msg!(LabelNotValue, sel = (self.tname(sel)).to_string());
                    self.error(Code::CaseLabelType, e.span, msg);
                    return None;
                }
                consts::int_value(&t.e)
            }
            _ => {
                if !t.e.ty.elem().is_some_and(|el| el.is_integral()) {
                    let msg = crate::msg!(
                        CaseLabelMustIntegerConstant,
                        ty = (self.tname(t.e.ty)).to_string()
                    );
                    self.error(Code::CaseLabelType, e.span, msg);
                    return None;
                }
                consts::int_value(&t.e)
            }
        };
        if value.is_none() {
            self.error(Code::NotConstant, e.span, crate::msg!(CaseLabelMustConstant));
        }
        if let (Some(v), Some(el)) = (value, sel.elem()) {
            let (lo, hi) = el.int_range();
            if (v as i128) < lo || (v as i128) > hi {
                let msg =
                    crate::msg!(LabelCanNeverMatchSelector, v = v, name = (el.name()).to_string());
                self.warning(Code::CaseWithoutMatch, e.span, msg);
            }
        }
        value
    }
}
