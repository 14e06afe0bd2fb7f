//! The operand types and side tables of the instruction set (see `op`): register
//! triples, built-in selectors, array dimensions, element-access sites and CASE tables.

use crate::values::Fault;
pub use crate::values::{MathFn, StrFunc};

/// A frame-relative cell offset.
pub type Reg = u32;

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

/// The operands of a compare-and-branch instruction: jump to `target` when `a` and `b`
/// stand in the instruction's relation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Branch {
    /// Left operand.
    pub a: Reg,
    /// Right operand.
    pub b: Reg,
    /// Jump target.
    pub target: u32,
}

/// One access to an element of a one-dimensional array that lives in the frame, for
/// [`Op::LoadElem`] and its kin: the index is `x + add` wrapped in the type of the index
/// expression (`arr[j + 1]` with `j : DINT` wraps in DINT, exactly as the separate
/// addition would), bounds-checked against `low..=low + span`.
///
/// The compiler folds `add` into a site only when the array's bounds lie inside the range
/// of the index type, so a sum that lands inside the bounds cannot have wrapped: the hot
/// path adds and compares once, and only an out-of-range sum takes the (cold) wrapping
/// path, which decides between the wrapped index and the fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ElemSite {
    /// The constant added to the index register minus the lowest index (wrapping): the
    /// element's position is `x + bias`.
    pub bias: i64,
    /// Lowest index.
    pub low: i64,
    /// Highest index minus lowest index (an array has fewer than 2^32 cells).
    pub span: u32,
    /// Frame offset of the accessed cell of the array's first element.
    pub start: u32,
    /// Cells per index step.
    pub stride: u32,
    /// 64 minus the width of the type the sum wraps in (0 for LINT).
    pub shift: u8,
    /// The sum wraps as a signed type (sign-extended) rather than an unsigned one.
    pub signed: bool,
}

impl ElemSite {
    /// A site for index `x + add` into `low..=low + span` from frame cell `start`.
    pub fn new(add: i64, low: i64, span: u32, start: u32, stride: u32) -> ElemSite {
        ElemSite { bias: add.wrapping_sub(low), low, span, start, stride, shift: 0, signed: true }
    }

    /// The constant added to the index register.
    pub fn add(&self) -> i64 {
        self.bias.wrapping_add(self.low)
    }

    /// The highest index.
    pub fn high(&self) -> i64 {
        self.low.wrapping_add(i64::from(self.span))
    }

    /// The offset in cells from the site's `start` of the element that index register
    /// value `x` selects, or the out-of-range fault.
    #[inline(always)]
    pub fn offset(&self, x: u64) -> Result<u64, Fault> {
        let d = (x as i64).wrapping_add(self.bias) as u64;
        if d > u64::from(self.span) {
            return self.wrapped_offset(x);
        }
        Ok(d.wrapping_mul(u64::from(self.stride)))
    }

    /// [`ElemSite::offset`] for a sum outside the bounds: wraps it in the index type and
    /// checks again.
    #[cold]
    #[inline(never)]
    fn wrapped_offset(&self, x: u64) -> Result<u64, Fault> {
        let sum = (x as i64).wrapping_add(self.add());
        let sh = u32::from(self.shift);
        let i = if self.signed {
            sum.wrapping_shl(sh).wrapping_shr(sh)
        } else {
            ((sum as u64).wrapping_shl(sh).wrapping_shr(sh)) as i64
        };
        let d = i.wrapping_sub(self.low) as u64;
        if d > u64::from(self.span) {
            return Err(Fault::IndexOutOfRange { index: i, low: self.low, high: self.high() });
        }
        Ok(d.wrapping_mul(u64::from(self.stride)))
    }
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
