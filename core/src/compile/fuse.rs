//! Choices behind the fused instructions: which conditions become one compare-and-branch,
//! and which expressions are *pure* (can neither fault nor change anything), so that an
//! element store may check its bounds after computing them without changing what a program
//! observes. Only decides and emits jumps; element addressing itself is in `emit.rs`.

use super::emit::Emitter;
use super::CompileError;
use crate::semantic::ir::{BinOp, Expr, ExprKind, Place, UnOp};
use crate::semantic::types::{Elem, Type};
use crate::vm::op::{Branch, Op};

/// The compare-and-branch instruction that jumps when `op` on cells of `elem` is FALSE,
/// if there is one (integers, bit strings, time and enumerations in the i64 order;
/// `=`/`<>` on every non-real cell, as the typed compare instructions).
fn jump_when_false(op: BinOp, elem: Elem) -> Option<fn(Branch) -> Op> {
    let ordered = !matches!(elem, Elem::ULInt | Elem::LWord | Elem::Real | Elem::LReal);
    Some(match op {
        BinOp::Eq if !elem.is_real() => Op::JumpNe,
        BinOp::Ne if !elem.is_real() => Op::JumpEq,
        BinOp::Lt if ordered => Op::JumpGe,
        BinOp::Le if ordered => Op::JumpGt,
        BinOp::Gt if ordered => Op::JumpLe,
        BinOp::Ge if ordered => Op::JumpLt,
        _ => return None,
    })
}

impl Emitter<'_> {
    /// Compiles the BOOL `cond` and a jump taken when it is FALSE; returns the jump's index
    /// for [`Emitter::patch`]. `IF a > b` becomes one `JumpLe`, `IF NOT x` one `JumpIf`.
    pub fn jump_unless(&mut self, cond: &Expr) -> Result<u32, CompileError> {
        match &cond.kind {
            ExprKind::Binary(op, a, b) if a.ty.is_scalar() && a.ty == b.ty => {
                let elem = self.elem_of(a.ty)?;
                if let Some(f) = jump_when_false(*op, elem) {
                    let ra = self.expr(a, None)?;
                    let rb = self.expr(b, None)?;
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
            ExprKind::Call { .. } | ExprKind::Builtin { .. } => false,
        }
    }

    fn is_pure_place(&self, place: &Place) -> bool {
        match place {
            Place::Local(_) | Place::Global(_) => true,
            Place::Field(b, _) | Place::Bit(b, ..) => self.is_pure_place(b),
            Place::Element(b, arr, idx) => {
                let Some(def) = self.p.types.arrays.get(*arr as usize) else { return false };
                let in_range = idx.iter().zip(&def.dims).all(|(i, &(lo, hi))| {
                    matches!(i.kind, ExprKind::Const(k) if lo <= k as i64 && k as i64 <= hi)
                });
                in_range && idx.len() == def.dims.len() && self.is_pure_place(b)
            }
        }
    }
}
