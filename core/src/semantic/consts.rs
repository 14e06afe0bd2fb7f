//! Constant values: folding checked expressions, reading constants back, and the default
//! value of every type.

use super::ir::{Expr, ExprKind, InitValue, Pou};
use super::types::{Type, TypeTable};
use crate::values::arith;

/// The integer value of a constant integral or enumeration expression.
pub fn int_value(e: &Expr) -> Option<i64> {
    match (&e.kind, e.ty) {
        (ExprKind::Const(bits), Type::Elem(el)) if el.is_integral() || el == super::Elem::Bool => {
            i64::try_from(arith::to_i128(el, *bits)).ok()
        }
        (ExprKind::Const(bits), Type::Enum(_)) => Some(*bits as i64),
        _ => None,
    }
}

/// The initial value a constant expression stands for, if it is constant.
pub fn to_init_value(e: &Expr) -> Option<InitValue> {
    match &e.kind {
        ExprKind::Const(bits) => Some(InitValue::Scalar(*bits)),
        ExprKind::ConstStr(bytes) => Some(InitValue::Str(bytes.clone())),
        _ => None,
    }
}

/// The value a variable of type `ty` starts with when nothing is declared.
pub fn default_value(types: &TypeTable, pous: &[Pou], ty: Type) -> InitValue {
    match ty {
        Type::Elem(_) | Type::Ref(_) | Type::Void => InitValue::Scalar(0),
        Type::Str { .. } => InitValue::Str(Vec::new()),
        Type::Enum(id) => InitValue::Scalar(
            types.enums.get(id as usize).and_then(|e| e.values.first()).map_or(0, |v| v.1 as u64),
        ),
        Type::Array(_) => InitValue::Array(Vec::new()),
        Type::Struct(id) => {
            InitValue::Struct(vec![
                None;
                types.structs.get(id as usize).map_or(0, |s| s.fields.len())
            ])
        }
        Type::Fb(id) => {
            InitValue::Struct(vec![None; pous.get(id as usize).map_or(0, |p| p.vars.len())])
        }
    }
}
