//! Lowering: a resolved chart → hidden declarations and ordinary statements that the
//! checker, compiler and VM handle like any ST body. The evolution rules implemented here
//! are the ones `docs/sfc.md` explains; keep the two in step.
//!
//! Per scan the generated body does, in this order:
//! 1. `SFC__Dt` := virtual time since the previous scan of this POU (0 on its first scan and
//!    after the clock went back, i.e. after a restart);
//! 2. from the second scan on: every active step's `T` grows by `SFC__Dt`; every transition
//!    whose steps are all active is tested (by priority, then source order; a step already
//!    claimed by a firing transition cannot be left twice); then the firing transitions
//!    deactivate their source steps and activate their target steps (`T := T#0s`);
//! 3. every action control is updated from the step flags as they now stand;
//! 4. boolean actions copy their control's `Q`; action bodies run while their `A` is TRUE.

use super::build::At;
use super::chart::{Action, ActionKind, Chart, Transition};
use super::{Reword, Rewrite, DT, LAST, STARTED, STEP_TYPE};
use crate::diagnostics::Code;
use crate::syntax::ast::sfc::{Qualifier, TransitionCondition};
use crate::syntax::ast::*;

/// What one chart becomes.
pub(super) struct Lowered {
    /// The action control structure types.
    pub types: Vec<TypeDef>,
    /// The hidden variables (steps, action controls, transition flags, timing).
    pub vars: VarBlock,
    /// The statements that replace the chart.
    pub body: Vec<Stmt>,
}

/// The variable holding transition `t`'s decision of this scan.
fn fire_var(chart: &Chart, t: usize) -> String {
    match &chart.transitions[t].ast.name {
        Some(n) => format!("SFC__Fire_{}", n.name),
        None => format!("SFC__Fire_{}", t + 1),
    }
}

/// Lowers `chart`; problems the checker will find in generated code are reworded through
/// `rewrites` so they name the chart's elements.
pub(super) fn lower(chart: &Chart, rewrites: &mut Vec<Rewrite>) -> Lowered {
    let pre = At(chart.pou.name.span);
    let mut decls = vec![
        pre.decl(STARTED, "BOOL", None),
        pre.decl(DT, "TIME", None),
        pre.decl(LAST, "TIME", None),
    ];
    for s in &chart.steps {
        let at = At(s.header);
        let init = s.initial.then(|| Initializer::Struct {
            fields: vec![(at.ident("X"), Initializer::Expr(at.bool(true)))],
            span: s.header,
        });
        decls.push(At(s.name.span).decl(&s.name.name, STEP_TYPE, init));
    }
    for (i, t) in chart.transitions.iter().enumerate() {
        if !t.valid {
            continue;
        }
        decls.push(At(t.ast.header).decl(&fire_var(chart, i), "BOOL", None));
        if let (TransitionCondition::Body(_), Some(name)) = (&t.ast.condition, &t.ast.name) {
            decls.push(At(name.span).decl(&name.name, "BOOL", None));
        }
    }
    let mut types = Vec::new();
    let mut controls = Vec::new();
    for a in &chart.actions {
        let control = ActionControl::new(a);
        let type_name = format!("SFC_ACTION__{}__{}", chart.pou.name.name, a.name.name);
        types.push(control.at.struct_type(&type_name, control.fields()));
        decls.push(At(a.name.span).decl(&control.var, &type_name, None));
        controls.push(control);
    }

    let mut evolution = step_times(chart);
    evolution.extend(decisions(chart, rewrites));
    evolution.extend(firing(chart));
    let mut body = vec![
        pre.assign(pre.name(DT), pre.bin(BinaryOp::Sub, pre.name("SYS_CLOCK"), pre.name(LAST))),
        pre.if_then(
            pre.or(
                pre.bin(BinaryOp::Cmp(Cmp::Lt), pre.name(DT), pre.time(0)),
                pre.not(pre.name(STARTED)),
            ),
            vec![pre.assign(pre.name(DT), pre.time(0))],
        ),
        pre.assign(pre.name(LAST), pre.name("SYS_CLOCK")),
        pre.if_then(pre.name(STARTED), evolution),
        pre.assign(pre.name(STARTED), pre.bool(true)),
    ];
    for (c, a) in controls.iter().zip(&chart.actions) {
        body.extend(c.update(chart, a, rewrites));
    }
    for (c, a) in controls.iter().zip(&chart.actions) {
        if let ActionKind::Boolean = a.kind {
            if let Some(first) = a.uses.first() {
                let at = At(first.assoc.action.span);
                body.push(at.assign(at.name(&a.name.name), at.field(&c.var, "Q")));
                rewrites.push(Rewrite {
                    span: first.assoc.action.span,
                    codes: &[Code::TypeMismatch],
                    code: Code::SfcBooleanActionNotBool,
                    reword: Reword::Wrap(crate::msg!(NotBooleanAction, name = &a.name.name)),
                });
            }
        }
    }
    for (c, a) in controls.iter().zip(&chart.actions) {
        if let (ActionKind::Declared(decl), false) = (&a.kind, a.uses.is_empty()) {
            let at = At(decl.header);
            body.push(at.if_then(at.field(&c.var, "A"), decl.body.clone()));
        }
    }
    let vars =
        VarBlock { section: VarSection::Var, retain: false, constant: false, decls, span: pre.0 };
    Lowered { types, vars, body }
}

/// `IF S.X THEN S.T := S.T + SFC__Dt; END_IF;` for every step.
fn step_times(chart: &Chart) -> Vec<Stmt> {
    chart
        .steps
        .iter()
        .map(|s| {
            let at = At(s.header);
            let name = s.name.name.as_str();
            let grown = at.bin(BinaryOp::Add, at.field(name, "T"), at.name(DT));
            at.if_then(at.field(name, "X"), vec![at.assign(at.field(name, "T"), grown)])
        })
        .collect()
}

/// The transitions in the order they are tested: by PRIORITY (lower first, unwritten
/// last), then in source order.
fn test_order(chart: &Chart) -> Vec<usize> {
    let mut order: Vec<usize> =
        (0..chart.transitions.len()).filter(|&t| chart.transitions[t].valid).collect();
    crate::order::sort_by_key(&mut order, |&t| {
        let p = chart.transitions[t].ast.priority.map(|(p, _)| p);
        (p.is_none(), p, t)
    });
    order
}

fn all_active(at: At, chart: &Chart, steps: &[usize]) -> Vec<Expr> {
    steps.iter().map(|&s| at.field(&chart.steps[s].name.name, "X")).collect()
}

/// Decides which transitions fire this scan, from the step flags at the start of the scan.
fn decisions(chart: &Chart, rewrites: &mut Vec<Rewrite>) -> Vec<Stmt> {
    let order = test_order(chart);
    let mut out = Vec::new();
    for (k, &t) in order.iter().enumerate() {
        let tr: &Transition = &chart.transitions[t];
        let at = At(tr.ast.header);
        let fire = fire_var(chart, t);
        out.push(at.assign(at.name(&fire), at.bool(false)));
        let mut guard = all_active(at, chart, &tr.from);
        for &u in &order[..k] {
            if chart.transitions[u].from.iter().any(|s| tr.from.contains(s)) {
                guard.push(at.not(at.name(&fire_var(chart, u))));
            }
        }
        let inner = match &tr.ast.condition {
            TransitionCondition::Expr(cond) => {
                rewrites.push(Rewrite {
                    span: cond.span,
                    codes: &[Code::ConditionNotBool],
                    code: Code::SfcConditionNotBool,
                    reword: Reword::Condition(tr.describe()),
                });
                vec![at.if_then(cond.clone(), vec![at.assign(at.name(&fire), at.bool(true))])]
            }
            TransitionCondition::Body(stmts) => {
                let Some(name) = &tr.ast.name else { continue };
                let mut v = vec![at.assign(at.name(&name.name), at.bool(false))];
                v.extend(stmts.iter().cloned());
                v.push(at.assign(at.name(&fire), at.name(&name.name)));
                v
            }
        };
        out.push(at.if_then(at.all(guard), inner));
    }
    out
}

/// Deactivates the source steps of every firing transition, then activates the targets
/// (so a step both left and entered in one scan stays active, its time restarted).
fn firing(chart: &Chart) -> Vec<Stmt> {
    let valid = || chart.transitions.iter().enumerate().filter(|(_, t)| t.valid);
    let mut out = Vec::new();
    for (i, t) in valid() {
        let at = At(t.ast.header);
        let body = t
            .from
            .iter()
            .map(|&s| at.assign(at.field(&chart.steps[s].name.name, "X"), at.bool(false)))
            .collect();
        out.push(at.if_then(at.name(&fire_var(chart, i)), body));
    }
    for (i, t) in valid() {
        let at = At(t.ast.header);
        let mut body = Vec::new();
        for &s in &t.to {
            let name = chart.steps[s].name.name.as_str();
            body.push(at.assign(at.field(name, "X"), at.bool(true)));
            body.push(at.assign(at.field(name, "T"), at.time(0)));
        }
        out.push(at.if_then(at.name(&fire_var(chart, i)), body));
    }
    out
}

/// The action control of one action (the standard's ACTION_CONTROL block, specialised to
/// the qualifiers the action is used with).
struct ActionControl {
    /// Where its generated code points.
    at: At,
    /// The variable holding its state.
    var: String,
    /// For each qualifier used, the steps (indices) and associations using it.
    used: Vec<(Qualifier, Vec<usize>)>,
}

/// Internal fields (besides Q and A) each qualifier needs.
fn fields_of(q: Qualifier) -> &'static [(&'static str, &'static str)] {
    match q {
        Qualifier::N | Qualifier::R => &[],
        Qualifier::S => &[("S_FF", "BOOL")],
        Qualifier::P => &[("P_M", "BOOL")],
        Qualifier::P1 => &[("P1_M", "BOOL")],
        Qualifier::P0 => &[("P0_M", "BOOL")],
        Qualifier::L => &[("L_M", "BOOL"), ("L_ET", "TIME"), ("L_PT", "TIME")],
        Qualifier::D => &[("D_M", "BOOL"), ("D_ET", "TIME"), ("D_PT", "TIME")],
        Qualifier::SD => {
            &[("SD_FF", "BOOL"), ("SD_M", "BOOL"), ("SD_ET", "TIME"), ("SD_PT", "TIME")]
        }
        Qualifier::DS => {
            &[("DS_M", "BOOL"), ("DS_ET", "TIME"), ("DS_PT", "TIME"), ("DS_FF", "BOOL")]
        }
        Qualifier::SL => {
            &[("SL_FF", "BOOL"), ("SL_M", "BOOL"), ("SL_ET", "TIME"), ("SL_PT", "TIME")]
        }
    }
}

impl ActionControl {
    fn new(a: &Action) -> Self {
        let (at, var) = match &a.kind {
            ActionKind::Declared(decl) => (At(decl.header), a.name.name.clone()),
            ActionKind::Boolean => (At(a.name.span), format!("SFC__{}", a.name.name)),
        };
        let mut used: Vec<(Qualifier, Vec<usize>)> = Vec::new();
        for q in Qualifier::ALL {
            let mut steps: Vec<usize> = Vec::new();
            for u in a.uses.iter().filter(|u| u.assoc.qualifier == q) {
                if !steps.contains(&u.step) {
                    steps.push(u.step);
                }
            }
            if !steps.is_empty() {
                used.push((q, steps));
            }
        }
        ActionControl { at, var, used }
    }

    fn uses(&self, q: Qualifier) -> bool {
        self.used.iter().any(|(u, _)| *u == q)
    }

    fn has_pulses(&self) -> bool {
        self.uses(Qualifier::P1) || self.uses(Qualifier::P0)
    }

    /// The structure fields: Q and A first (what users read), then the internals.
    fn fields(&self) -> Vec<(String, &'static str)> {
        let mut out = vec![("Q".to_string(), "BOOL"), ("A".to_string(), "BOOL")];
        if self.has_pulses() {
            out.push(("Qn".to_string(), "BOOL"));
            out.push(("Hold".to_string(), "BOOL"));
        }
        for (q, _) in &self.used {
            out.extend(fields_of(*q).iter().map(|(f, t)| (f.to_string(), *t)));
        }
        out
    }

    fn f(&self, field: &str) -> Expr {
        self.at.field(&self.var, field)
    }

    /// The OR of the step flags of the associations with qualifier `q`.
    fn input(&self, chart: &Chart, q: Qualifier) -> Expr {
        let steps = self.used.iter().find(|(u, _)| *u == q).map(|(_, s)| s.as_slice());
        let flags = all_active(self.at, chart, steps.unwrap_or(&[]));
        self.at.any(flags)
    }

    /// `NOT R AND (e)` when the action has an R association: R wins over everything.
    fn gate(&self, chart: &Chart, e: Expr) -> Expr {
        if self.uses(Qualifier::R) {
            self.at.and(self.at.not(self.input(chart, Qualifier::R)), e)
        } else {
            e
        }
    }

    /// An on-delay timer (TON) on `input` with the fields `<q>_M`, `<q>_ET`, `<q>_PT`:
    /// ET is 0 on the scan the input rises and grows by the scan time after.
    fn timer(&self, input: Expr, q: &str) -> Vec<Stmt> {
        let at = self.at;
        let (m, et, pt) = (format!("{q}_M"), format!("{q}_ET"), format!("{q}_PT"));
        let grow = at.if_then(
            self.f(&m),
            vec![at.assign(self.f(&et), at.bin(BinaryOp::Add, self.f(&et), at.name(DT)))],
        );
        let cap = at.if_then(
            at.bin(BinaryOp::Cmp(Cmp::Gt), self.f(&et), self.f(&pt)),
            vec![at.assign(self.f(&et), self.f(&pt))],
        );
        vec![
            at.if_else(input.clone(), vec![grow, cap], vec![at.assign(self.f(&et), at.time(0))]),
            at.assign(self.f(&m), input),
        ]
    }

    /// `ET >= PT` of timer `q`.
    fn elapsed(&self, q: &str) -> Expr {
        self.at.bin(BinaryOp::Cmp(Cmp::Ge), self.f(&format!("{q}_ET")), self.f(&format!("{q}_PT")))
    }

    /// `ET < PT` of timer `q`.
    fn running(&self, q: &str) -> Expr {
        self.at.bin(BinaryOp::Cmp(Cmp::Lt), self.f(&format!("{q}_ET")), self.f(&format!("{q}_PT")))
    }

    /// Latches each timed qualifier's duration from the first active step using it.
    fn latches(&self, chart: &Chart, a: &Action, rewrites: &mut Vec<Rewrite>) -> Vec<Stmt> {
        let mut out = Vec::new();
        for q in [Qualifier::L, Qualifier::D, Qualifier::SD, Qualifier::DS, Qualifier::SL] {
            let mut branches = Vec::new();
            let mut seen_steps = Vec::new();
            for use_ in &a.uses {
                if use_.assoc.qualifier != q || seen_steps.contains(&use_.step) {
                    continue;
                }
                let Some(duration) = &use_.assoc.duration else { continue };
                seen_steps.push(use_.step);
                let at = At(use_.assoc.span);
                let flag = at.field(&chart.steps[use_.step].name.name, "X");
                let field = at.field(&self.var, &format!("{}_PT", q.name()));
                branches.push((flag, vec![at.assign(field, duration.clone())]));
                rewrites.push(Rewrite {
                    span: duration.span,
                    codes: &[Code::TypeMismatch, Code::ConstantOutOfRange],
                    code: Code::SfcDurationNotTime,
                    reword: Reword::Wrap(crate::msg!(
                        DurationMustBeTime,
                        action = &use_.assoc.action.name,
                        q = q.name()
                    )),
                });
            }
            out.extend(self.at.if_chain(branches));
        }
        out
    }

    /// The statements that update this control for one scan.
    fn update(&self, chart: &Chart, a: &Action, rewrites: &mut Vec<Rewrite>) -> Vec<Stmt> {
        if self.used.is_empty() {
            return Vec::new();
        }
        let at = self.at;
        let x = |q| self.input(chart, q);
        let mut out = self.latches(chart, a, rewrites);
        let mut qn = Vec::new();
        let mut qp = Vec::new();
        for (q, _) in &self.used {
            match q {
                Qualifier::R => {}
                Qualifier::N => qn.push(x(Qualifier::N)),
                Qualifier::S => {
                    let set = at.or(x(Qualifier::S), self.f("S_FF"));
                    out.push(at.assign(self.f("S_FF"), self.gate(chart, set)));
                    qn.push(self.f("S_FF"));
                }
                Qualifier::L => {
                    out.extend(self.timer(x(Qualifier::L), "L"));
                    qn.push(at.and(x(Qualifier::L), self.running("L")));
                }
                Qualifier::D => {
                    out.extend(self.timer(x(Qualifier::D), "D"));
                    qn.push(at.and(x(Qualifier::D), self.elapsed("D")));
                }
                Qualifier::SD => {
                    let set = at.or(x(Qualifier::SD), self.f("SD_FF"));
                    out.push(at.assign(self.f("SD_FF"), self.gate(chart, set)));
                    out.extend(self.timer(self.f("SD_FF"), "SD"));
                    qn.push(at.and(self.f("SD_FF"), self.elapsed("SD")));
                }
                Qualifier::DS => {
                    out.extend(self.timer(x(Qualifier::DS), "DS"));
                    let done = at.and(x(Qualifier::DS), self.elapsed("DS"));
                    let set = at.or(done, self.f("DS_FF"));
                    out.push(at.assign(self.f("DS_FF"), self.gate(chart, set)));
                    qn.push(self.f("DS_FF"));
                }
                Qualifier::SL => {
                    let set = at.or(x(Qualifier::SL), self.f("SL_FF"));
                    out.push(at.assign(self.f("SL_FF"), self.gate(chart, set)));
                    out.extend(self.timer(self.f("SL_FF"), "SL"));
                    qn.push(at.and(self.f("SL_FF"), self.running("SL")));
                }
                Qualifier::P => qn.push(at.and(x(Qualifier::P), at.not(self.f("P_M")))),
                Qualifier::P1 => qp.push(at.and(x(Qualifier::P1), at.not(self.f("P1_M")))),
                Qualifier::P0 => qp.push(at.and(at.not(x(Qualifier::P0)), self.f("P0_M"))),
            }
        }
        if self.has_pulses() {
            // A final scan follows only a Q period held by a non-pulse qualifier.
            out.push(at.assign(self.f("A"), at.and(self.f("Q"), self.f("Hold"))));
            out.push(at.assign(self.f("Qn"), self.gate(chart, at.any(qn))));
            let pulses = self.gate(chart, at.any(qp));
            out.push(at.assign(self.f("Q"), at.or(self.f("Qn"), pulses)));
            let held = at.and(self.f("Q"), at.or(self.f("Hold"), self.f("Qn")));
            out.push(at.assign(self.f("Hold"), held));
        } else {
            out.push(at.assign(self.f("A"), self.f("Q")));
            out.push(at.assign(self.f("Q"), self.gate(chart, at.any(qn))));
        }
        out.push(at.assign(self.f("A"), at.or(self.f("Q"), self.f("A"))));
        for (q, field) in [(Qualifier::P, "P_M"), (Qualifier::P1, "P1_M"), (Qualifier::P0, "P0_M")]
        {
            if self.uses(q) {
                out.push(at.assign(self.f(field), x(q)));
            }
        }
        out
    }
}
