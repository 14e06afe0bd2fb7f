//! References initialised in their declaration: `r : REF_TO INT := REF(counter);`
//! (IEC 61131-3 ed. 3: a reference's initial value is `NULL` or `REF()` of a variable of
//! the same POU or a global).
//!
//! Declaration order does not matter, as for other initial values, so `REF(x)` in an
//! initial value is not checked where it is met: [`Checker::ref_init`] keeps it as a
//! pending entry ([`RefRoot::Pending`]) and [`Checker::resolve_ref_inits`] checks it once
//! every POU's variables and every global are declared, in the scope of the declaring POU
//! (the globals' scope for VAR_GLOBAL). The target must have one place for the whole run,
//! fixed relative to the instance holding the declaration, or a global: a temporary (a
//! VAR_TEMP, a FUNCTION's variable), a VAR_IN_OUT, an element chosen by a variable index
//! and a dereference are refused (E0181), besides what `REF()` refuses anywhere. The place
//! becomes a [`RefInit`] path that the compiler turns into an address for every instance
//! (`compile/layout.rs`).

use super::check::{BodyState, Checker, PendingRefInit};
use super::ir::{ExprKind, InitValue, Place};
use super::types::{PouId, RefInit, RefRoot, RefStep, Type};
use crate::diagnostics::Code;
use crate::syntax::{self as ast, PouKind, VarSection};

impl Checker<'_> {
    /// `Some` when the initial value `e` of a `ty` is `REF(…)`: its pending value (or
    /// `None` after an error); `None` for any other initial value.
    pub(super) fn ref_init(&mut self, e: &ast::Expr, ty: Type) -> Option<Option<InitValue>> {
        let mut inner = e;
        while let ast::ExprKind::Paren(x) = &inner.kind {
            inner = x;
        }
        let ast::ExprKind::Call { callee, .. } = &inner.kind else { return None };
        if !self.is_ref_call(callee) {
            return None;
        }
        let Some(scope) = self.ref_scope else {
            self.error(
                Code::NotConstant,
                e.span,
                "`REF()` can be the initial value of a variable declared in a POU or in \
                 VAR_GLOBAL, not of a TYPE, a struct field or a VAR_CONFIG entry",
            );
            return Some(None);
        };
        let k = self.ref_inits.len() as u32;
        self.ref_inits.push(PendingRefInit { scope, expr: inner.clone(), ty });
        Some(Some(InitValue::Ref(RefInit { root: RefRoot::Pending(k), steps: Vec::new() })))
    }

    /// Checks every pending `REF()` initial value and puts its path (or NULL, after an
    /// error) in place of the pending entry, in every variable's initial value.
    pub(super) fn resolve_ref_inits(&mut self) {
        let pending = std::mem::take(&mut self.ref_inits);
        if pending.is_empty() {
            return;
        }
        let saved = std::mem::take(&mut self.body);
        let resolved: Vec<Option<RefInit>> =
            pending.iter().map(|p| self.resolve_ref_init(p)).collect();
        self.body = saved;
        let vars = self.globals.iter_mut().chain(self.pous.iter_mut().flat_map(|p| &mut p.vars));
        for v in vars {
            if let Some(init) = &mut v.init {
                replace_pending(init, &resolved);
            }
        }
    }

    fn resolve_ref_init(&mut self, p: &PendingRefInit) -> Option<RefInit> {
        self.body = BodyState { pou: p.scope.pou, loop_depth: 0, read_only: false };
        let typed = self.expr(&p.expr, Some(p.ty))?;
        let value = self.coerce(typed, p.ty, p.expr.span)?;
        let ExprKind::RefOf(place) = &value.kind else {
            return None;
        };
        let span = ref_argument(&p.expr).map_or(p.expr.span, |a| a.span);
        match self.static_path(place, p.scope.pou) {
            Ok(path) => Some(path),
            Err(why) => {
                let msg = crate::msg!(ReferenceSInitialValueMust, why = why);
                self.error(Code::RefNotAVariable, span, msg);
                None
            }
        }
    }

    /// The path of `place` (checked in POU `pou`'s scope) from a variable of `pou` or a
    /// global, or why it has no place fixed before the program runs.
    fn static_path(&self, place: &Place, pou: PouId) -> Result<RefInit, String> {
        // The chain from `place` down to its root variable, walked back up.
        let mut chain = vec![place];
        let mut at = place;
        loop {
            at = match at {
                Place::Field(b, _) | Place::Element(b, _, _) => b,
                Place::Bit(b, _, _) | Place::Slice(b, _, _) => b,
                Place::Local(_) | Place::Global(_) | Place::Deref(_) => break,
            };
            chain.push(at);
        }
        let mut steps = Vec::new();
        let mut root = None;
        let mut ty = Type::Void;
        for p in chain.iter().rev() {
            match p {
                Place::Local(i) => {
                    let owner = self.pous.get(pou as usize).ok_or("not a variable")?;
                    let var = owner.vars.get(*i as usize).ok_or("not a variable")?;
                    if owner.kind == PouKind::Function {
                        return Err(format!(
                            "`{}` is a variable of FUNCTION `{}`, which exists only while the function runs",
                            var.name, owner.name
                        ));
                    }
                    lives_on(var, &owner.name)?;
                    root = Some(RefRoot::Own(pou, *i));
                    ty = var.ty;
                }
                Place::Global(g) => {
                    let var = self.globals.get(*g as usize).ok_or("not a variable")?;
                    root = Some(RefRoot::Global(*g));
                    ty = var.ty;
                }
                Place::Field(_, i) => match ty {
                    Type::Struct(s) => {
                        let def = self.types.structs.get(s as usize).ok_or("not a field")?;
                        ty = def.fields.get(*i as usize).ok_or("not a field")?.ty;
                        steps.push(RefStep::Field(s, *i));
                    }
                    Type::Fb(q) => {
                        let fb = self.pous.get(q as usize).ok_or("not a member")?;
                        let var = fb.vars.get(*i as usize).ok_or("not a member")?;
                        lives_on(var, &fb.name)?;
                        ty = var.ty;
                        steps.push(RefStep::Member(q, *i));
                    }
                    _ => return Err("not a field".to_string()),
                },
                Place::Element(_, a, idx) => {
                    let def = self.types.arrays.get(*a as usize).ok_or("not an element")?;
                    let mut flat: u64 = 0;
                    for (e, &(lo, hi)) in idx.iter().zip(&def.dims) {
                        let i = match e.kind {
                            ExprKind::Const(bits) => bits as i64,
                            _ => return Err("the element is chosen by a variable index; give constant indexes (`REF(a[2])`)".to_string()),
                        };
                        if i < lo || i > hi {
                            return Err(format!("index {i} is outside the array's {lo}..{hi}"));
                        }
                        let n = super::types::dim_len(lo, hi);
                        flat = flat.saturating_mul(n).saturating_add((i - lo) as u64);
                    }
                    ty = def.element;
                    steps.push(RefStep::Element(*a, flat));
                }
                Place::Deref(_) => {
                    return Err(
                        "a dereference `r^` points where `r` points when it runs".to_string()
                    )
                }
                Place::Bit(..) | Place::Slice(..) => {
                    return Err("a bit or a located variable has no address of its own".to_string())
                }
            }
        }
        let root = root.ok_or("not a variable")?;
        Ok(RefInit { root, steps })
    }
}

/// Whether variable `var` of POU `pou` keeps its place between calls (not a VAR_TEMP, not
/// a VAR_IN_OUT, which is another variable on every call).
fn lives_on(var: &super::ir::Var, pou: &str) -> Result<(), String> {
    match var.section {
        VarSection::Temp => Err(format!(
            "`{}` is a VAR_TEMP of `{pou}`, which exists only while `{pou}` runs",
            var.name
        )),
        VarSection::InOut => Err(format!(
            "`{}` is a VAR_IN_OUT of `{pou}`, a different variable on every call",
            var.name
        )),
        _ => Ok(()),
    }
}

/// The argument of the `REF(…)` call `e`.
fn ref_argument(e: &ast::Expr) -> Option<&ast::Expr> {
    let ast::ExprKind::Call { args, .. } = &e.kind else { return None };
    match args.first()? {
        ast::Arg::Positional(a) | ast::Arg::Input { value: a, .. } => Some(a),
        _ => None,
    }
}

/// Puts the resolved paths (NULL for those that failed) in place of pending entries.
fn replace_pending(init: &mut InitValue, resolved: &[Option<RefInit>]) {
    let mut stack = vec![init];
    while let Some(v) = stack.pop() {
        match v {
            InitValue::Ref(RefInit { root: RefRoot::Pending(k), .. }) => {
                *v = match resolved.get(*k as usize).cloned().flatten() {
                    Some(r) => InitValue::Ref(r),
                    None => InitValue::Scalar(0),
                };
            }
            InitValue::Array(items) => stack.extend(items.iter_mut()),
            InitValue::Struct(fields) => stack.extend(fields.iter_mut().flatten()),
            InitValue::Scalar(_) | InitValue::Str(_) | InitValue::Ref(_) => {}
        }
    }
}
