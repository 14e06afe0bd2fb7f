//! One IL body → statements. See the module comment of `il` for the scheme.
//!
//! The CR is an expression (`cr`) read where it is used. Before anything that could change
//! what that expression reads (a store, a set or reset, a call) while the CR is still
//! needed afterwards, the CR is copied into the temporary of its type ("materialised").
//! A CR made of constants and temporaries only is never copied: reading it again gives
//! the same value. Deferred operations (`AND(`) keep the CR before the `(` on a stack of
//! at most [`MAX_DEFERRED`] levels; a chain longer than [`MAX_CHAIN`] operations is
//! materialised, so no expression the checker walks grows past the parser's limits.

use std::collections::BTreeMap;

use super::{temp_name, Typing, ValueType, PC};
use crate::diagnostics::{Code, Diagnostic, Span};
use crate::syntax::ast::il::*;
use crate::syntax::ast::*;

/// The deepest nesting of `(` deferred operations.
const MAX_DEFERRED: usize = 32;
/// The height at which a CR expression is copied into its temporary.
const MAX_CHAIN: usize = 32;

/// What one body becomes.
pub(super) struct Lowered {
    /// The statements.
    pub body: Vec<Stmt>,
    /// The temporaries used, with their types.
    pub temps: Vec<(String, &'static str)>,
    /// The body jumps: it needs the state variable.
    pub jumps: bool,
    /// Problems found.
    pub diagnostics: Vec<Diagnostic>,
}

/// An operation waiting for its `)`.
struct Deferred {
    op: BinaryOp,
    negated: bool,
    saved: Expr,
    span: Span,
}

struct Lowering<'a, T: Typing> {
    il: &'a IlBody,
    pou: &'a str,
    typer: &'a mut T,
    out: Vec<Stmt>,
    cr: Option<Expr>,
    deferred: Vec<Deferred>,
    temps: BTreeMap<String, &'static str>,
    diags: Vec<Diagnostic>,
    /// A problem already reported made the CR unknown: do not also report it missing.
    poisoned: bool,
    /// The segments (state machine arms) start at these instruction indices; empty when
    /// the body does not jump.
    starts: Vec<usize>,
    /// Per segment: the temporary through which the CR enters it, once known.
    entry: Vec<Option<Expr>>,
}

/// Lowers `il`, the body of POU `pou`.
pub(super) fn lower<T: Typing>(il: &IlBody, pou: &str, typer: &mut T) -> Lowered {
    let jumps = il.instructions.iter().any(|i| matches!(i.kind, IlKind::Jump { .. }));
    let mut starts = vec![0];
    if jumps {
        for (_, at) in &il.labels {
            if !starts.contains(at) && *at < il.instructions.len() {
                starts.push(*at);
            }
        }
        starts.sort_unstable();
    }
    let mut l = Lowering {
        il,
        pou,
        typer,
        out: Vec::new(),
        cr: None,
        deferred: Vec::new(),
        temps: BTreeMap::new(),
        diags: Vec::new(),
        poisoned: false,
        entry: vec![None; starts.len()],
        starts,
    };
    let body = if jumps { l.state_machine() } else { l.straight() };
    Lowered { body, temps: l.temps.into_iter().collect(), jumps, diagnostics: l.diags }
}

// ---- small constructors ----

fn expr(kind: ExprKind, span: Span) -> Expr {
    Expr { kind, span }
}

fn name(n: &str, span: Span) -> Expr {
    expr(ExprKind::Name(Ident { name: n.to_string(), span }), span)
}

fn not(e: Expr, span: Span) -> Expr {
    expr(ExprKind::Unary(UnaryOp::Not, Box::new(e)), span)
}

fn int(v: i128, span: Span) -> Expr {
    expr(ExprKind::Literal(Literal { value: LiteralValue::Int(v), type_prefix: None }), span)
}

fn boolean(v: bool, span: Span) -> Expr {
    expr(ExprKind::Literal(Literal { value: LiteralValue::Bool(v), type_prefix: None }), span)
}

fn stmt(kind: StmtKind, span: Span) -> Stmt {
    Stmt { kind, span }
}

fn assign(target: Expr, value: Expr, span: Span) -> Stmt {
    stmt(StmtKind::Assign { target, value }, span)
}

fn if_then(cond: Expr, body: Vec<Stmt>, span: Span) -> Stmt {
    stmt(StmtKind::If { branches: vec![(cond, body)], else_body: None }, span)
}

/// Whether reading `e` again later gives the same value whatever runs in between:
/// constants and the lowering's own temporaries.
fn is_stable(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Literal(_) | ExprKind::EnumValue { .. } => true,
        ExprKind::Name(id) => super::is_hidden_name(&id.name),
        ExprKind::Unary(_, a) | ExprKind::Paren(a) => is_stable(a),
        ExprKind::Binary(_, a, b) => is_stable(a) && is_stable(b),
        _ => false,
    }
}

/// The condition an IL condition puts on the CR (`None` for always).
fn guard(condition: IlCondition, cr: Expr, span: Span) -> Option<Expr> {
    match condition {
        IlCondition::Always => None,
        IlCondition::IfTrue => Some(cr),
        IlCondition::IfFalse => Some(not(cr, span)),
    }
}

impl<T: Typing> Lowering<'_, T> {
    fn error(&mut self, code: Code, span: Span, msg: impl Into<crate::diagnostics::Said>) {
        self.diags.push(Diagnostic::error(code, span, msg));
    }

    /// The CR, or a located error when none is loaded.
    fn need_cr(&mut self, at: &IlInstruction) -> Option<Expr> {
        match &self.cr {
            Some(cr) => Some(cr.clone()),
            None => {
                if !self.poisoned {
                    self.error(
                        Code::IlNoCurrentResult,
                        at.span,
                        crate::msg!(NeedsCurrentResultButNone, name = at.operator.name),
                    );
                }
                self.poisoned = true;
                None
            }
        }
    }

    /// The type of `e` in the POU, when the checker can tell it.
    fn type_of(&mut self, e: &Expr) -> Result<ValueType, Vec<Diagnostic>> {
        self.typer.type_of(self.pou, e)
    }

    /// Copies a CR that is not stable into the temporary of its type.
    fn materialise(&mut self, at: Span) {
        self.keep(at, false);
    }

    /// Copies a CR that grew taller than [`MAX_CHAIN`] into its temporary, stable or not.
    fn bound_height(&mut self, at: Span) {
        if self.cr.as_ref().is_some_and(|e| e.height() > MAX_CHAIN) {
            self.keep(at, true);
        }
    }

    /// Copies the CR into the temporary of its type, unless it is stable and not `force`d.
    fn keep(&mut self, at: Span, force: bool) {
        let Some(cr) = self.cr.take() else { return };
        if is_stable(&cr) && !force {
            self.cr = Some(cr);
            return;
        }
        if let Some(temp) = self.temp_for(&cr, at) {
            self.out.push(assign(temp.clone(), cr, at));
            self.cr = Some(temp);
        } else {
            self.poisoned = true;
        }
    }

    /// The temporary for a value like `e` (declared on first use), or a reported problem.
    /// Inside `(` each level has its own temporaries (`IL__CR_BOOL_2`), so keeping a CR
    /// there never overwrites one that a deferred operation still reads.
    fn temp_for(&mut self, e: &Expr, at: Span) -> Option<Expr> {
        match self.type_of(&typing_view(e)) {
            Ok(ValueType::Elementary(ty)) => {
                let mut n = temp_name(ty);
                if !self.deferred.is_empty() {
                    n = format!("{n}_{}", self.deferred.len());
                }
                self.temps.insert(n.clone(), ty);
                Some(name(&n, at))
            }
            Ok(other) => {
                let shown = match other {
                    ValueType::Other(n) => n,
                    _ => "function block instance".to_string(),
                };
                self.error(
                    Code::IlResultType,
                    at,
                    crate::msg!(CurrentResultHereIlKeeps, shown = shown),
                );
                None
            }
            Err(diags) => {
                self.diags.extend(diags.into_iter().filter(Diagnostic::is_error));
                None
            }
        }
    }

    /// Whether the CR is read after instruction `i` (by the next instruction, or on
    /// entry to the segment that follows).
    fn read_after(&self, i: usize) -> bool {
        let next = i + 1;
        if let Some(seg) = self.starts.iter().position(|&s| s == next) {
            return self.needs_entry(seg);
        }
        self.il.instructions.get(next).is_some_and(|n| n.kind.reads_result())
    }

    /// Whether segment `seg` reads the CR before loading one.
    fn needs_entry(&self, seg: usize) -> bool {
        let start = self.starts[seg];
        self.il.instructions.get(start).is_some_and(|n| n.kind.reads_result())
    }

    /// Lowers instructions `start..end`; returns whether the code after them can run. The
    /// instructions after an unconditional JMP or RET are reported (once) and left out.
    fn run(&mut self, start: usize, end: usize) -> bool {
        for i in start..end {
            if !self.instruction(i) {
                if let Some(next) = self.il.instructions.get(i + 1..end).and_then(|r| r.first()) {
                    self.diags.push(Diagnostic::warning(
                        Code::UnreachableCode,
                        next.span,
                        crate::msg!(InstructionCanNeverRunJmp),
                    ));
                }
                return false;
            }
        }
        true
    }

    /// Lowers a body without jumps.
    fn straight(&mut self) -> Vec<Stmt> {
        self.run(0, self.il.instructions.len());
        self.close_check();
        std::mem::take(&mut self.out)
    }

    /// Reports `(` left open at the end of a body or segment.
    fn close_check(&mut self) {
        for d in std::mem::take(&mut self.deferred) {
            self.error(Code::IlBadInstruction, d.span, crate::msg!(NeverClosed));
        }
    }

    /// Lowers a body with jumps: `IL__Pc := 0; WHILE IL__Pc >= 0 DO CASE IL__Pc OF …`.
    fn state_machine(&mut self) -> Vec<Stmt> {
        let at = self.il.span;
        let mut arms = Vec::new();
        for seg in 0..self.starts.len() {
            let start = self.starts[seg];
            let end = self.starts.get(seg + 1).copied().unwrap_or(self.il.instructions.len());
            self.cr = self.entry[seg].clone();
            self.poisoned = false;
            let live = self.run(start, end);
            self.close_check();
            if live {
                let next = if seg + 1 < self.starts.len() { seg as i128 + 1 } else { -1 };
                if next >= 0 {
                    let last = end.checked_sub(1).and_then(|i| self.il.instructions.get(i));
                    self.transfer(seg + 1, last.map_or(at, |l| l.span));
                }
                self.out.push(assign(name(PC, at), int(next, at), at));
            }
            let label = CaseLabel::Value(int(seg as i128, at));
            arms.push(CaseArm {
                labels: vec![label],
                body: std::mem::take(&mut self.out),
                span: at,
            });
        }
        let case = stmt(
            StmtKind::Case {
                selector: name(PC, at),
                arms,
                else_body: Some(vec![assign(name(PC, at), int(-1, at), at)]),
            },
            at,
        );
        let cond = expr(
            ExprKind::Binary(BinaryOp::Cmp(Cmp::Ge), Box::new(name(PC, at)), Box::new(int(0, at))),
            at,
        );
        vec![
            assign(name(PC, at), int(0, at), at),
            stmt(StmtKind::While { cond, body: vec![case] }, at),
        ]
    }

    /// Carries the CR into segment `seg` (through its entry temporary) when it reads it.
    fn transfer(&mut self, seg: usize, at: Span) {
        if !self.needs_entry(seg) {
            return;
        }
        let Some(cr) = self.cr.clone() else { return };
        let Some(temp) = self.temp_for(&cr, at) else { return };
        match &self.entry[seg] {
            Some(existing)
                if name_of(existing).map(Ident::key) != name_of(&temp).map(Ident::key) =>
            {
                let (ExprKind::Name(a), ExprKind::Name(b)) = (&existing.kind, &temp.kind) else {
                    return;
                };
                let label = self.label_of(seg);
                self.error(
                    Code::IlResultType,
                    at,
                    crate::msg!(
                        CurrentResultReachesHereBut,
                        label = label,
                        here = (b.name.trim_start_matches("IL__CR_")).to_string(),
                        there = (a.name.trim_start_matches("IL__CR_")).to_string()
                    ),
                );
                return;
            }
            _ => {}
        }
        if name_of(&cr).map(|n| n.key()) != name_of(&temp).map(|n| n.key()) {
            self.out.push(assign(temp.clone(), cr, at));
        }
        self.cr = Some(temp.clone());
        self.entry[seg].get_or_insert(temp);
    }

    /// The first label of segment `seg`, as written.
    fn label_of(&self, seg: usize) -> String {
        let start = self.starts[seg];
        self.il
            .labels
            .iter()
            .find(|(_, at)| *at == start)
            .map_or_else(String::new, |(l, _)| l.name.clone())
    }

    /// The segment a label starts, or a reported problem.
    fn segment_of(&mut self, label: &Ident) -> Option<usize> {
        let at = self.il.labels.iter().find(|(l, _)| l.key() == label.key()).map(|(_, at)| *at);
        match at {
            Some(at) if at >= self.il.instructions.len() => Some(usize::MAX),
            Some(at) => self.starts.iter().position(|&s| s == at),
            None => {
                self.error(
                    Code::IlUndefinedLabel,
                    label.span,
                    crate::msg!(LabelNotDefinedBody, name = label.name),
                );
                None
            }
        }
    }

    /// Lowers instruction `i`; returns whether the code after it can run.
    fn instruction(&mut self, i: usize) -> bool {
        let il = self.il;
        let ins = &il.instructions[i];
        let at = ins.span;
        if !self.deferred.is_empty()
            && !matches!(
                ins.kind,
                IlKind::Load { .. }
                    | IlKind::Invalid
                    | IlKind::Operate { .. }
                    | IlKind::Not
                    | IlKind::Close
                    | IlKind::Function { .. }
            )
        {
            self.error(
                Code::IlBadInstruction,
                at,
                crate::msg!(CannotStandInsideParenthesesOnly, name = ins.operator.name),
            );
            return true;
        }
        match &ins.kind {
            IlKind::Invalid => {
                self.cr = None;
                self.poisoned = true;
            }
            IlKind::Load { negated, operand } => {
                let v = operand.clone();
                self.cr = Some(if *negated { not(v, at) } else { v });
                self.poisoned = false;
            }
            IlKind::Store { negated, target } => {
                if self.cr.is_some() && self.read_after(i) {
                    self.materialise(at);
                }
                let Some(cr) = self.need_cr(ins) else { return true };
                let value = if *negated { not(cr, at) } else { cr };
                self.out.push(assign(target.clone(), value, at));
            }
            IlKind::SetReset { set, target } => {
                if matches!(self.type_of(target), Ok(ValueType::Instance)) {
                    let input = Ident {
                        name: if *set { "S" } else { "R" }.into(),
                        span: ins.operator.span,
                    };
                    self.input(i, ins, input, target);
                } else {
                    if self.cr.is_some() && self.read_after(i) {
                        self.materialise(at);
                    }
                    let Some(cr) = self.need_cr(ins) else { return true };
                    let write = assign(target.clone(), boolean(*set, at), at);
                    self.out.push(if_then(cr, vec![write], at));
                }
            }
            IlKind::Not => {
                let Some(cr) = self.need_cr(ins) else { return true };
                self.cr = Some(not(cr, at));
            }
            IlKind::Operate { op, negated, deferred, operand } => {
                let Some(cr) = self.need_cr(ins) else { return true };
                let operand =
                    operand.clone().map(|o| if *negated && !*deferred { not(o, at) } else { o });
                if *deferred {
                    if self.deferred.len() >= MAX_DEFERRED {
                        self.error(
                            Code::TooComplex,
                            at,
                            crate::msg!(MoreThanOpenOnce, MAX_DEFERRED = MAX_DEFERRED),
                        );
                        self.poisoned = true;
                        self.cr = None;
                        return true;
                    }
                    self.deferred.push(Deferred {
                        op: *op,
                        negated: *negated,
                        saved: cr,
                        span: at,
                    });
                    self.cr = operand;
                } else if let Some(operand) = operand {
                    self.cr =
                        Some(expr(ExprKind::Binary(*op, Box::new(cr), Box::new(operand)), at));
                    self.bound_height(at);
                }
            }
            IlKind::Close => {
                let Some(d) = self.deferred.pop() else {
                    self.error(Code::IlBadInstruction, at, crate::msg!(WithoutOperationBefore));
                    return true;
                };
                let Some(inner) = self.need_cr(ins) else { return true };
                let inner = if d.negated { not(inner, at) } else { inner };
                self.cr =
                    Some(expr(ExprKind::Binary(d.op, Box::new(d.saved), Box::new(inner)), at));
                self.bound_height(at);
            }
            IlKind::Jump { condition, label } => {
                let Some(target) = self.segment_of(label) else { return true };
                let cond = match condition {
                    IlCondition::Always => None,
                    _ => {
                        if self.read_after(i) || (target != usize::MAX && self.needs_entry(target))
                        {
                            self.materialise(at);
                        }
                        let Some(cr) = self.need_cr(ins) else { return true };
                        guard(*condition, cr, at)
                    }
                };
                let mut body = Vec::new();
                let saved_out = std::mem::take(&mut self.out);
                let next = if target == usize::MAX { -1 } else { target as i128 };
                if target != usize::MAX {
                    self.transfer(target, at);
                }
                body.append(&mut self.out);
                self.out = saved_out;
                body.push(assign(name(PC, at), int(next, at), at));
                body.push(stmt(StmtKind::Continue, at));
                match cond {
                    Some(c) => self.out.push(if_then(c, body, at)),
                    None => {
                        self.out.extend(body);
                        self.cr = None;
                        return false;
                    }
                }
            }
            IlKind::Call { condition, instance, args } => {
                if self.cr.is_some() && self.read_after(i) {
                    self.materialise(at);
                }
                let call = expr(
                    ExprKind::Call { callee: Box::new(instance.clone()), args: args.clone() },
                    at,
                );
                let call = stmt(StmtKind::Call(call), at);
                if *condition == IlCondition::Always {
                    self.out.push(call);
                } else {
                    let Some(cr) = self.need_cr(ins) else { return true };
                    if let Some(c) = guard(*condition, cr, at) {
                        self.out.push(if_then(c, vec![call], at));
                    }
                }
            }
            IlKind::Return { condition } => {
                let ret = stmt(StmtKind::Return, at);
                if *condition == IlCondition::Always {
                    self.out.push(ret);
                    self.cr = None;
                    return false;
                }
                if self.read_after(i) {
                    self.materialise(at);
                }
                let Some(cr) = self.need_cr(ins) else { return true };
                if let Some(c) = guard(*condition, cr, at) {
                    self.out.push(if_then(c, vec![ret], at));
                }
            }
            IlKind::Input { input, instance } => self.input(i, ins, input.clone(), instance),
            IlKind::Function { name: f, args, formal } => self.function(ins, f, args, *formal),
        }
        true
    }

    /// An input operator: `instance(input := CR);`.
    fn input(&mut self, i: usize, ins: &IlInstruction, input: Ident, instance: &Expr) {
        let at = ins.span;
        if self.cr.is_some() && self.read_after(i) {
            self.materialise(at);
        }
        let Some(cr) = self.need_cr(ins) else { return };
        let args = vec![Arg::Input { name: input, value: cr }];
        let call = expr(ExprKind::Call { callee: Box::new(instance.clone()), args }, at);
        self.out.push(stmt(StmtKind::Call(call), at));
    }

    /// A function instruction: CR := f(CR, operands…) or f(formal list). The result of a
    /// function of the file is kept in its temporary at once, so it runs exactly once, here;
    /// a standard function (no side effects) stays an expression, so untyped constants in
    /// it take the type expected where the CR is used, as in ST.
    fn function(&mut self, ins: &IlInstruction, f: &Ident, args: &[Arg], formal: bool) {
        let at = ins.span;
        let Some(standard) = self.typer.function(&f.name) else {
            let msg = crate::msg!(NeitherIlOperatorNorFunction, name = &f.name);
            let hint =
                crate::diagnostics::suggest::closest(&f.name, crate::syntax::il_operator_names());
            self.diags
                .push(Diagnostic::error(Code::IlUnknownOperator, f.span, msg).suggesting(hint));
            self.poisoned = true;
            self.cr = None;
            return;
        };
        let mut all = Vec::with_capacity(args.len() + 1);
        if !formal {
            let Some(cr) = self.need_cr(ins) else { return };
            all.push(Arg::Positional(cr));
        }
        all.extend(args.iter().cloned());
        let callee = name(&f.name, f.span);
        self.cr = Some(expr(ExprKind::Call { callee: Box::new(callee), args: all }, at));
        if !standard {
            self.materialise(at);
        }
    }
}

/// `e` with every level temporary (`IL__CR_BOOL_2`) named as its level-0 one, which the
/// declarations the types come from know (same type, so the same answer).
fn typing_view(e: &Expr) -> Expr {
    let mut e = e.clone();
    rename_levels(&mut e);
    e
}

fn rename_levels(e: &mut Expr) {
    match &mut e.kind {
        ExprKind::Name(id) if super::is_hidden_name(&id.name) => {
            if let Some((base, level)) = id.name.rsplit_once('_') {
                if !level.is_empty() && level.bytes().all(|b| b.is_ascii_digit()) {
                    id.name = base.to_string();
                }
            }
        }
        ExprKind::Unary(_, a) | ExprKind::Paren(a) => rename_levels(a),
        ExprKind::Binary(_, a, b) => {
            rename_levels(a);
            rename_levels(b);
        }
        ExprKind::Call { args, .. } => {
            for a in args {
                if let Arg::Positional(v) | Arg::Input { value: v, .. } = a {
                    rename_levels(v);
                }
            }
        }
        _ => {}
    }
}

/// The identifier of a name expression.
fn name_of(e: &Expr) -> Option<&Ident> {
    match &e.kind {
        ExprKind::Name(n) => Some(n),
        _ => None,
    }
}
