//! The inner loop of the VM: the simple, frequent instructions (moves, loads and stores,
//! array elements, typed arithmetic and comparisons, jumps, the FOR step) in a tight loop
//! of its own, so that the compiler keeps the loop's state in registers. It stops, without
//! consuming it, at the first instruction it does not handle (calls, CASE, strings, the
//! generic operators, …) or when the watchdog budget is spent; the outer loop in
//! `machine` handles that instruction and comes back.
//!
//! Like the outer loop it never allocates and never panics (every index is checked; a bad
//! one is `Fault::Internal`). It charges the watchdog budget per loop iteration rather than
//! per instruction: a jump back costs the number of instructions it jumps back over (the
//! instructions of one pass of the loop on its straight path), so straight code costs
//! nothing here and an endless loop still exhausts any budget.

use super::trace::Hook;
use crate::program::op::{outer_loop_ops, Branch, DimInfo, ElemSite, Op, R3};
use crate::semantic::types::Elem;
use crate::values::arith;
use crate::values::Fault;

const BAD: Fault = Fault::Internal("register address out of range");

/// The code and tables the inner loop reads.
#[derive(Clone, Copy)]
pub(super) struct Tables<'a> {
    /// The instructions.
    pub code: &'a [Op],
    /// Element-access sites.
    pub sites: &'a [ElemSite],
    /// Array dimensions.
    pub dims: &'a [DimInfo],
}

/// Why [`run`] stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Exit {
    /// At an instruction it does not handle, or at a jump back the budget cannot pay (then
    /// the fuel is 0).
    Slow,
    /// At an instruction that faults: [`diagnose`] tells which fault.
    Fault,
}

/// Runs simple instructions from `*pc` in the frame at `base`. Whatever makes it stop, the
/// instruction at `*pc` has not run (a faulting one has written nothing).
///
/// With `TRUSTED`, the instruction fetch, register operands and element sites are not
/// bounds-checked: the caller guarantees that `*pc` is inside a region [`crate::program::verify::verify`] accepted,
/// for a frame at `base` that lies inside `cells` (computed addresses — pointers, elements
/// — are still checked, they depend on data).
///
/// `hook` sees every instruction before and after it runs (the traced scans of "why");
/// with [`super::trace::NoHook`] those calls are compiled out.
#[inline(never)]
#[cfg_attr(plc_speed, optimize(speed))]
pub(super) fn run<const TRUSTED: bool, H: Hook>(
    t: Tables<'_>,
    cells: &mut [u64],
    base: u32,
    pc: &mut usize,
    fuel: &mut u64,
    hook: &mut H,
) -> Exit {
    let Tables { code, sites, dims } = t;
    // The program counter and the fuel live in locals (registers) while the loop runs and
    // are written back on the way out. Every failed check leaves through the one `Fault`
    // exit, which keeps the loop small.
    let (mut p, mut f) = (*pc, *fuel);
    macro_rules! ok {
        ($e:expr) => {
            match $e {
                Some(v) => v,
                None => {
                    p -= 1;
                    break Exit::Fault;
                }
            }
        };
    }
    macro_rules! r {
        ($x:expr) => {{
            let i = base.wrapping_add($x) as usize;
            if TRUSTED {
                // SAFETY: `verify` checked every register operand of this region against
                // the frame, and the caller checked that the frame lies inside `cells`.
                unsafe { *cells.get_unchecked(i) }
            } else {
                *ok!(cells.get(i))
            }
        }};
    }
    macro_rules! w {
        ($x:expr, $v:expr) => {{
            let v = $v;
            let i = base.wrapping_add($x) as usize;
            if TRUSTED {
                // SAFETY: as for `r!`.
                unsafe { *cells.get_unchecked_mut(i) = v }
            } else {
                *ok!(cells.get_mut(i)) = v;
            }
        }};
    }
    macro_rules! at {
        ($a:expr) => {
            *ok!(cells.get_mut(($a) as usize))
        };
    }
    macro_rules! elem {
        ($k:expr, $idx:expr) => {{
            let k = $k as usize;
            let s = if TRUSTED {
                // SAFETY: `verify` checked the site indices of this region.
                unsafe { sites.get_unchecked(k) }
            } else {
                ok!(sites.get(k))
            };
            u64::from(base.wrapping_add(s.start)) + ok!(s.offset(r!($idx)).ok())
        }};
    }
    // A jump: a backward one (a loop) costs the instructions it jumps back over; when the
    // budget cannot pay, the jump is left undone for the outer loop to report.
    macro_rules! goto {
        ($t:expr) => {{
            let t = $t as usize;
            if t < p {
                let cost = (p - t) as u64;
                if f < cost {
                    p -= 1;
                    f = 0;
                    break Exit::Slow;
                }
                f -= cost;
            }
            p = t;
        }};
    }
    macro_rules! branch {
        ($o:expr, |$x:ident, $y:ident| $e:expr) => {{
            let Branch { a, b, target } = $o;
            let ($x, $y) = (r!(a), r!(b));
            if $e {
                taken();
                goto!(target);
            }
        }};
    }
    macro_rules! bin {
        ($o:expr, |$x:ident, $y:ident| $e:expr) => {{
            let R3 { dst, a, b } = $o;
            let ($x, $y) = (r!(a), r!(b));
            w!(dst, $e)
        }};
    }
    let exit = loop {
        let op = if TRUSTED {
            // SAFETY: in a verified region every jump and CASE target lies inside the
            // region and the region ends with Ret or Halt (which this loop never runs), so
            // `p` never leaves it; `verify` checked that the region lies inside `code`.
            unsafe { code.get_unchecked(p) }
        } else {
            let Some(op) = code.get(p) else { break Exit::Slow };
            op
        };
        p += 1;
        if H::ON {
            hook.before(op, p - 1, base, cells);
        }
        match *op {
            Op::Const { dst, bits } => w!(dst, bits),
            Op::Move { dst, a } => w!(dst, r!(a)),
            Op::LoadAbs { dst, addr } => w!(dst, at!(addr)),
            Op::StoreAbs { addr, a } => at!(addr) = r!(a),
            Op::LoadInd { dst, ptr, off } => w!(dst, at!(r!(ptr).wrapping_add(u64::from(off)))),
            Op::StoreInd { ptr, off, a } => at!(r!(ptr).wrapping_add(u64::from(off))) = r!(a),
            Op::AddrOf { dst, off } => w!(dst, u64::from(base.wrapping_add(off))),
            Op::PtrAdd { dst, ptr, off } => w!(dst, r!(ptr).wrapping_add(u64::from(off))),
            Op::LoadElem { dst, idx, site } => w!(dst, at!(elem!(site, idx))),
            Op::StoreElem { idx, site, a } => at!(elem!(site, idx)) = r!(a),
            Op::MoveElem { didx, sidx, site } => {
                let to = elem!(site, didx);
                let from = elem!(site.wrapping_add(1), sidx);
                at!(to) = at!(from);
            }
            Op::ElemAddr { dst, idx, site } => w!(dst, elem!(site, idx)),
            Op::Index { ptr, idx, dim } => {
                let d = ok!(dims.get(dim as usize));
                let i = r!(idx) as i64;
                ok!((d.low <= i && i <= d.high).then_some(()));
                let step = (i as i128 - d.low as i128) as u64 * u64::from(d.stride);
                w!(ptr, r!(ptr).wrapping_add(step));
            }
            Op::AddI64(o) => bin!(o, |x, y| (x as i64).wrapping_add(y as i64) as u64),
            Op::SubI64(o) => bin!(o, |x, y| (x as i64).wrapping_sub(y as i64) as u64),
            Op::MulI64(o) => bin!(o, |x, y| (x as i64).wrapping_mul(y as i64) as u64),
            Op::AddI32(o) => bin!(o, |x, y| (x as i32).wrapping_add(y as i32) as i64 as u64),
            Op::SubI32(o) => bin!(o, |x, y| (x as i32).wrapping_sub(y as i32) as i64 as u64),
            Op::MulI32(o) => bin!(o, |x, y| (x as i32).wrapping_mul(y as i32) as i64 as u64),
            Op::AddI16(o) => bin!(o, |x, y| (x as i16).wrapping_add(y as i16) as i64 as u64),
            Op::SubI16(o) => bin!(o, |x, y| (x as i16).wrapping_sub(y as i16) as i64 as u64),
            Op::AddF64(o) => bin!(o, |x, y| (f64::from_bits(x) + f64::from_bits(y)).to_bits()),
            Op::SubF64(o) => bin!(o, |x, y| (f64::from_bits(x) - f64::from_bits(y)).to_bits()),
            Op::MulF64(o) => bin!(o, |x, y| (f64::from_bits(x) * f64::from_bits(y)).to_bits()),
            Op::DivF64(o) => bin!(o, |x, y| (f64::from_bits(x) / f64::from_bits(y)).to_bits()),
            Op::AddF32(o) => bin!(o, |x, y| f32r(f64::from_bits(x) + f64::from_bits(y))),
            Op::SubF32(o) => bin!(o, |x, y| f32r(f64::from_bits(x) - f64::from_bits(y))),
            Op::MulF32(o) => bin!(o, |x, y| f32r(f64::from_bits(x) * f64::from_bits(y))),
            Op::DivF32(o) => bin!(o, |x, y| f32r(f64::from_bits(x) / f64::from_bits(y))),
            Op::EqCell(o) => bin!(o, |x, y| u64::from(x == y)),
            Op::NeCell(o) => bin!(o, |x, y| u64::from(x != y)),
            Op::LtI64(o) => bin!(o, |x, y| u64::from((x as i64) < (y as i64))),
            Op::LeI64(o) => bin!(o, |x, y| u64::from((x as i64) <= (y as i64))),
            Op::GtI64(o) => bin!(o, |x, y| u64::from((x as i64) > (y as i64))),
            Op::GeI64(o) => bin!(o, |x, y| u64::from((x as i64) >= (y as i64))),
            Op::And(o) => bin!(o, |x, y| x & y),
            Op::Or(o) => bin!(o, |x, y| x | y),
            Op::Xor(o) => bin!(o, |x, y| x ^ y),
            Op::AndNot(o) => bin!(o, |x, y| x & !y),
            Op::Not { elem, dst, a } => w!(dst, arith::complement(elem, r!(a))),
            Op::Neg { elem, dst, a } => w!(dst, arith::negate(elem, r!(a))),
            Op::RealToDint { dst, a } => w!(dst, real_to_dint(r!(a))),
            Op::MulRealToDint(o) => {
                bin!(o, |x, y| real_to_dint(f32r(f64::from_bits(x) * f64::from_bits(y))))
            }
            Op::GetBit { dst, a, n } => w!(dst, arith::get_bit(r!(a), n)),
            Op::Jump { target } => goto!(target),
            Op::JumpIf { c, target } => {
                if r!(c) != 0 {
                    taken();
                    goto!(target);
                }
            }
            Op::JumpIfNot { c, target } => {
                if r!(c) == 0 {
                    taken();
                    goto!(target);
                }
            }
            Op::JumpLt(o) => branch!(o, |x, y| (x as i64) < (y as i64)),
            Op::JumpLe(o) => branch!(o, |x, y| (x as i64) <= (y as i64)),
            Op::JumpGt(o) => branch!(o, |x, y| (x as i64) > (y as i64)),
            Op::JumpGe(o) => branch!(o, |x, y| (x as i64) >= (y as i64)),
            Op::JumpEq(o) => branch!(o, |x, y| x == y),
            Op::JumpNe(o) => branch!(o, |x, y| x != y),
            Op::ForNext32 { bits, signed, v, lim, target } => {
                // Values of at most 32 bits: the sum cannot overflow i64.
                let (x, end, step) = (r!(v) as i64, r!(lim) as i64, r!(lim.wrapping_add(1)) as i64);
                let next = x + step;
                let sh = 64 - u32::from(bits);
                let wrapped =
                    if signed { (next << sh) >> sh } else { ((next as u64) << sh >> sh) as i64 };
                w!(v, wrapped as u64);
                if if step > 0 { next <= end } else { next >= end } {
                    goto!(target);
                } else {
                    taken();
                }
            }
            Op::ForInc32 { bits, signed, v, lim, target } => {
                let (x, end) = (r!(v) as i64, r!(lim) as i64);
                let next = x + 1;
                let sh = 64 - u32::from(bits);
                let wrapped =
                    if signed { (next << sh) >> sh } else { ((next as u64) << sh >> sh) as i64 };
                w!(v, wrapped as u64);
                if next <= end {
                    goto!(target);
                } else {
                    taken();
                }
            }
            // Not ours: give it back to the outer loop.
            outer_loop_ops!() => {
                p -= 1;
                break Exit::Slow;
            }
        }
        if H::ON {
            hook.after(cells);
        }
    };
    *pc = p;
    *fuel = f;
    exit
}

/// The fault of an instruction [`run`] stopped at with [`Exit::Fault`], found by checking
/// its operands in the order `run` does.
#[cold]
#[inline(never)]
pub(super) fn diagnose(op: &Op, t: Tables<'_>, cells: &[u64], base: u32) -> Fault {
    let reg = |x: u32| cells.get(base.wrapping_add(x) as usize).copied().ok_or(BAD);
    let site = |k: u32, idx: u32| -> Result<u64, Fault> {
        let s = t.sites.get(k as usize).ok_or(BAD)?;
        let off = s.offset(reg(idx)?)?;
        let addr = u64::from(base.wrapping_add(s.start)) + off;
        cells.get(addr as usize).ok_or(BAD)?;
        Ok(addr)
    };
    let found = match *op {
        Op::LoadElem { idx, site: k, .. }
        | Op::StoreElem { idx, site: k, .. }
        | Op::ElemAddr { idx, site: k, .. } => site(k, idx).map(|_| ()),
        Op::MoveElem { didx, sidx, site: k } => {
            site(k, didx).and_then(|_| site(k.wrapping_add(1), sidx)).map(|_| ())
        }
        Op::Index { idx, dim, .. } => (|| {
            let d = t.dims.get(dim as usize).ok_or(BAD)?;
            let i = reg(idx)? as i64;
            if i < d.low || i > d.high {
                return Err(Fault::IndexOutOfRange { index: i, low: d.low, high: d.high });
            }
            Ok(())
        })(),
        _ => Ok(()),
    };
    // Anything else that stops the inner loop is an address outside memory: a compiler bug.
    found.err().unwrap_or(BAD)
}

/// `arith::convert(Real, DInt, x)`, inlined: round half to even, wrap to 32 bits.
/// Below 2^51, adding 1.5 * 2^52 rounds to an integer half to even (the default IEEE
/// rounding, exactly as `round_ties_even`) and leaves that integer in the low mantissa
/// bits, so no libm call and no saturating float-to-int conversion is needed.
#[inline]
fn real_to_dint(x: u64) -> u64 {
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    let f = f64::from_bits(x);
    if f.abs() < 2_251_799_813_685_248.0 {
        let k = (f + MAGIC).to_bits().wrapping_sub(MAGIC.to_bits()) as i64;
        k as i32 as i64 as u64
    } else {
        arith::convert(Elem::Real, Elem::DInt, x)
    }
}

/// Marks the rare path of a branch, so that the compiler keeps a predictable jump there
/// instead of a conditional move (which would chain the next dispatch on the data).
#[cold]
#[inline(never)]
fn taken() {}

/// Rounds an f64 result to REAL precision, as `arith::from_f64(Elem::Real, _)` does.
#[inline]
fn f32r(v: f64) -> u64 {
    (v as f32 as f64).to_bits()
}
