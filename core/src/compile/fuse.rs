//! Choices behind the fused instructions: which conditions become one compare-and-branch,
//! which expressions are *pure* (can neither fault nor change anything), so that an
//! element store may check its bounds after computing them without changing what a program
//! observes, and the reuse of array elements a comparison has just loaded
//! (`IF a[j] > a[j + 1] THEN t := a[j]; …` reads `a[j]` once). Element addressing itself
//! is in `emit.rs`.

use super::emit::Emitter;
use super::CompileError;
use crate::program::op::{Branch, Op};
use crate::semantic::ir::{BinOp, Cmp, Expr, ExprKind, Place, Stmt, StmtKind, UnOp};
use crate::semantic::types::{Elem, Type};
use crate::syntax::VarSection;

/// The compare-and-branch instruction that jumps when `op` on cells of `elem` is FALSE,
/// if there is one (integers, bit strings, time and enumerations in the i64 order;
/// `=`/`<>` on every non-real cell, as the typed compare instructions).
fn jump_when_false(op: BinOp, elem: Elem) -> Option<fn(Branch) -> Op> {
    let ordered = !matches!(elem, Elem::ULInt | Elem::LWord | Elem::Real | Elem::LReal);
    Some(match op {
        BinOp::Cmp(Cmp::Eq) if !elem.is_real() => Op::JumpNe,
        BinOp::Cmp(Cmp::Ne) if !elem.is_real() => Op::JumpEq,
        BinOp::Cmp(Cmp::Lt) if ordered => Op::JumpGe,
        BinOp::Cmp(Cmp::Le) if ordered => Op::JumpGt,
        BinOp::Cmp(Cmp::Gt) if ordered => Op::JumpLe,
        BinOp::Cmp(Cmp::Ge) if ordered => Op::JumpLt,
        _ => return None,
    })
}

/// Whether evaluating `e` writes no variable: anything but a call of a FUNCTION (which may
/// write through VAR_IN_OUT, globals or its own FB instances). It may still fault; that
/// ends the scan, so nothing after it observes a stale value.
fn writes_nothing(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Const(_) | ExprKind::ConstStr(_) | ExprKind::Sys(_) => true,
        ExprKind::Load(place) => place_writes_nothing(place),
        ExprKind::Unary(_, a) | ExprKind::Convert(a) | ExprKind::Trunc(a) => writes_nothing(a),
        ExprKind::Binary(_, a, b) => writes_nothing(a) && writes_nothing(b),
        ExprKind::Builtin { args, .. } => args.iter().all(writes_nothing),
        ExprKind::RefOf(place) => place_writes_nothing(place),
        ExprKind::Call { .. } => false,
    }
}

/// Whether computing the address of `place` writes nothing (its indices call nothing).
fn place_writes_nothing(place: &Place) -> bool {
    match place {
        Place::Local(_) | Place::Global(_) => true,
        Place::Field(b, _) | Place::Bit(b, ..) | Place::Slice(b, ..) => place_writes_nothing(b),
        Place::Element(b, _, idx) => place_writes_nothing(b) && idx.iter().all(writes_nothing),
        Place::Deref(r) => writes_nothing(r),
    }
}

impl Emitter<'_> {
    /// Compiles the BOOL `cond` and a jump taken when it is FALSE; returns the jump's index
    /// for [`Emitter::patch`]. `IF a > b` becomes one `JumpLe`, `IF NOT x` one `JumpIf`.
    pub fn jump_unless(&mut self, cond: &Expr) -> Result<u32, CompileError> {
        self.compared.clear();
        match &cond.kind {
            ExprKind::Binary(op, a, b) if a.ty.is_scalar() && a.ty == b.ty => {
                let elem = self.elem_of(a.ty)?;
                if let Some(f) = jump_when_false(*op, elem) {
                    let ra = self.expr(a, None)?;
                    let rb = self.expr(b, None)?;
                    self.compared.clear();
                    // The left operand's element was loaded before the right operand ran:
                    // it is still the element's value only if the right operand changes
                    // nothing (a call may write the array or the index through VAR_IN_OUT
                    // or a global).
                    let a_still_current = writes_nothing(b);
                    let loaded = [(a, ra)].into_iter().filter(|_| a_still_current);
                    for (e, r) in loaded.chain([(b, rb)]) {
                        if let ExprKind::Load(place @ Place::Element(_, _, idx)) = &e.kind {
                            if idx.iter().all(|i| self.is_pure(i)) {
                                self.compared.push((place.clone(), r));
                            }
                        }
                    }
                    return Ok(self.emit(f(Branch { a: ra, b: rb, target: 0 })));
                }
            }
            ExprKind::Unary(UnOp::Not, x) if x.ty == Type::BOOL => {
                let c = self.expr(x, None)?;
                return Ok(self.emit(Op::JumpIf { c, target: 0 }));
            }
            _ => {}
        }
        let c = self.expr(cond, None)?;
        Ok(self.emit(Op::JumpIfNot { c, target: 0 }))
    }

    /// Compiles the leading statements of the branch a compare-and-branch guards that copy
    /// an element the comparison loaded (`t := a[j]`, `a[j] := a[j + 1]`) from the register
    /// that holds it; returns how many statements it compiled. Exact: nothing ran since
    /// the load (so the element and its bounds check are as they were), and each write
    /// drops what it may change: a local scalar the elements whose indices read it, any
    /// other place everything. The caller keeps the comparison's registers allocated
    /// meanwhile and clears [`Emitter::compared`] afterwards.
    pub fn reuse_compared(&mut self, body: &[Stmt]) -> Result<usize, CompileError> {
        let mut done = 0;
        for s in body {
            let StmtKind::Assign(dst, e) = &s.kind else { break };
            let ExprKind::Load(src) = &e.kind else { break };
            let Some(&(_, r)) = self.compared.iter().find(|(p, _)| same_place(p, src)) else {
                break;
            };
            let local = match dst {
                Place::Local(i) => self
                    .p
                    .pou(self.pou)
                    .vars
                    .get(*i as usize)
                    .filter(|v| v.section != VarSection::InOut && v.ty.is_scalar())
                    .map(|_| *i),
                _ => None,
            };
            if local.is_none() && !matches!(dst, Place::Element(..)) {
                break;
            }
            if matches!(dst, Place::Element(..)) && !e.ty.is_scalar() {
                break;
            }
            self.mark(s.span);
            let saved = self.top;
            // The value cannot fault, so checking the destination's bounds at the store
            // keeps the order of effects (as for any pure right-hand side).
            let a = self.place_addr(dst)?;
            self.store(a, r);
            self.top = saved;
            match local {
                Some(i) => self.compared.retain(|(p, _)| !place_reads_local(p, i)),
                None => self.compared.clear(),
            }
            done += 1;
        }
        Ok(done)
    }

    /// Whether evaluating `e` can neither fault nor have an effect: constants, variables,
    /// elements at constant in-range indices, and operators that wrap (everything but an
    /// integer or time division). Calls and built-ins count as impure.
    pub fn is_pure(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Const(_) | ExprKind::ConstStr(_) | ExprKind::Sys(_) => true,
            ExprKind::Load(place) => self.is_pure_place(place),
            ExprKind::Unary(_, a) | ExprKind::Convert(a) | ExprKind::Trunc(a) => self.is_pure(a),
            ExprKind::Binary(op, a, b) => {
                let divides = *op == BinOp::Div && !a.ty.elem().is_some_and(Elem::is_real);
                !divides && self.is_pure(a) && self.is_pure(b)
            }
            ExprKind::RefOf(place) => self.is_pure_place(place),
            ExprKind::Call { .. } | ExprKind::Builtin { .. } => false,
        }
    }

    fn is_pure_place(&self, place: &Place) -> bool {
        match place {
            Place::Local(_) | Place::Global(_) => true,
            Place::Field(b, _) | Place::Bit(b, ..) | Place::Slice(b, ..) => self.is_pure_place(b),
            Place::Element(b, arr, idx) => {
                let Some(def) = self.p.types.arrays.get(*arr as usize) else { return false };
                let in_range = idx.iter().zip(&def.dims).all(|(i, &(lo, hi))| {
                    matches!(i.kind, ExprKind::Const(k) if lo <= k as i64 && k as i64 <= hi)
                });
                in_range && idx.len() == def.dims.len() && self.is_pure_place(b)
            }
            // NULL faults.
            Place::Deref(_) => false,
        }
    }
}

/// Whether two places are the same place written twice (spans ignored).
fn same_place(a: &Place, b: &Place) -> bool {
    match (a, b) {
        (Place::Local(x), Place::Local(y)) | (Place::Global(x), Place::Global(y)) => x == y,
        (Place::Field(p, x), Place::Field(q, y)) => x == y && same_place(p, q),
        (Place::Bit(p, x, e), Place::Bit(q, y, f))
        | (Place::Slice(p, x, e), Place::Slice(q, y, f)) => x == y && e == f && same_place(p, q),
        (Place::Element(p, x, i), Place::Element(q, y, j)) => {
            x == y
                && same_place(p, q)
                && i.len() == j.len()
                && i.iter().zip(j).all(|(a, b)| same_expr(a, b))
        }
        _ => false,
    }
}

/// Whether two pure expressions compute the same value (spans ignored).
fn same_expr(a: &Expr, b: &Expr) -> bool {
    a.ty == b.ty
        && match (&a.kind, &b.kind) {
            (ExprKind::Const(x), ExprKind::Const(y)) => x == y,
            (ExprKind::Load(p), ExprKind::Load(q)) => same_place(p, q),
            (ExprKind::Unary(o, x), ExprKind::Unary(p, y)) => o == p && same_expr(x, y),
            (ExprKind::Convert(x), ExprKind::Convert(y)) => same_expr(x, y),
            (ExprKind::Binary(o, x1, x2), ExprKind::Binary(p, y1, y2)) => {
                o == p && same_expr(x1, y1) && same_expr(x2, y2)
            }
            _ => false,
        }
}

/// Whether `place` reads local variable `i` (in its indices or as its base).
fn place_reads_local(place: &Place, i: u32) -> bool {
    match place {
        Place::Local(x) => *x == i,
        Place::Global(_) => false,
        Place::Field(p, _) | Place::Bit(p, ..) | Place::Slice(p, ..) => place_reads_local(p, i),
        Place::Element(p, _, idx) => {
            place_reads_local(p, i) || idx.iter().any(|e| expr_reads_local(e, i))
        }
        // The reference may point at local `i`.
        Place::Deref(_) => true,
    }
}

fn expr_reads_local(e: &Expr, i: u32) -> bool {
    match &e.kind {
        ExprKind::Load(p) => place_reads_local(p, i),
        ExprKind::Unary(_, a) | ExprKind::Convert(a) | ExprKind::Trunc(a) => expr_reads_local(a, i),
        ExprKind::Binary(_, a, b) => expr_reads_local(a, i) || expr_reads_local(b, i),
        ExprKind::Const(_) | ExprKind::ConstStr(_) | ExprKind::Sys(_) => false,
        ExprKind::RefOf(p) => place_reads_local(p, i),
        // Not pure, never cached; answer conservatively.
        ExprKind::Call { .. } | ExprKind::Builtin { .. } => true,
    }
}
