//! The operand types and side tables of the instruction set (see `op`): register
//! triples, built-in selectors, array dimensions and CASE tables.

use super::op::Reg;

/// The three registers of a typed binary instruction: `dst := a op b`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct R3 {
    /// Destination.
    pub dst: Reg,
    /// Left operand.
    pub a: Reg,
    /// Right operand.
    pub b: Reg,
}

/// Numeric built-ins executed by [`Op::Math`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MathFn {
    /// ABS (wraps for integers).
    Abs,
    /// SQRT
    Sqrt,
    /// LN
    Ln,
    /// LOG
    Log,
    /// EXP
    Exp,
    /// SIN
    Sin,
    /// COS
    Cos,
    /// TAN
    Tan,
    /// ASIN
    Asin,
    /// ACOS
    Acos,
    /// ATAN
    Atan,
    /// EXPT with an exponent of the same real type as the base.
    Expt,
    /// SHL with the count as LINT in `b`.
    Shl,
    /// SHR
    Shr,
    /// ROL
    Rol,
    /// ROR
    Ror,
}

/// String built-ins executed by [`Op::Str`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StrFunc {
    /// LEN(s) → INT
    Len,
    /// LEFT(s, n)
    Left,
    /// RIGHT(s, n)
    Right,
    /// MID(s, n, p)
    Mid,
    /// CONCAT(a, b, …)
    Concat,
    /// INSERT(s1, s2, p)
    Insert,
    /// DELETE(s, n, p)
    Delete,
    /// REPLACE(s1, s2, n, p)
    Replace,
    /// FIND(s1, s2) → INT
    Find,
    /// STRING → WSTRING (each byte a Latin-1 character).
    Widen,
    /// WSTRING → STRING (characters above 255 become `?`).
    Narrow,
}

/// One array dimension for [`Op::Index`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DimInfo {
    /// Lowest index.
    pub low: i64,
    /// Highest index.
    pub high: i64,
    /// Cells per index step.
    pub stride: u32,
}

/// A CASE dispatch table for [`Op::Case`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CaseTable {
    /// Dense labels: `targets[sel - low]`, `default` outside.
    Dense {
        /// Selector value of `targets[0]`.
        low: i64,
        /// One target per selector value.
        targets: Vec<u32>,
        /// The ELSE (or end) target.
        default: u32,
    },
    /// Sparse labels: sorted, non-overlapping `(lo, hi, target)` ranges searched binarily.
    Sparse {
        /// The ranges.
        ranges: Vec<(i64, i64, u32)>,
        /// The ELSE (or end) target.
        default: u32,
    },
}

impl CaseTable {
    /// The jump target for selector value `v`.
    pub fn target(&self, v: i128) -> u32 {
        match self {
            CaseTable::Dense { low, targets, default } => {
                let i = v - *low as i128;
                if i >= 0 && (i as u128) < targets.len() as u128 {
                    targets.get(i as usize).copied().unwrap_or(*default)
                } else {
                    *default
                }
            }
            CaseTable::Sparse { ranges, default } => {
                let k = ranges.partition_point(|&(_, hi, _)| (hi as i128) < v);
                match ranges.get(k) {
                    Some(&(lo, _, t)) if lo as i128 <= v => t,
                    _ => *default,
                }
            }
        }
    }
}
