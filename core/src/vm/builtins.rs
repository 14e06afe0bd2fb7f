//! The less frequent instructions: numeric built-ins (ABS, SQRT, …, shifts), selection
//! (SEL, MAX, MIN, LIMIT, MUX), strings, text conversion and BCD. Called from the
//! dispatch loop for every instruction it does not handle itself.

use super::strings::{self, Scratch};
use super::text;
use crate::program::memory::{read_str_into, write_str};
use crate::program::op::{MathFn, Op};
use crate::program::Executable;
use crate::semantic::ir::{BinOp, Cmp};
use crate::semantic::types::Elem;
use crate::values::arith::{self, ShiftKind};
use crate::values::math;
use crate::values::Fault;

const BAD: Fault = Fault::Internal("register address out of range");

/// Executes one of the instructions listed in the module comment; returns how many string
/// bytes it read and wrote (the watchdog charges them).
pub(crate) fn exec(
    op: Op,
    cells: &mut [u64],
    base: u32,
    exe: &Executable,
    s: &mut Scratch,
) -> Result<u64, Fault> {
    let reg = |x: u32| base.wrapping_add(x) as usize;
    let get = |cells: &[u64], x: u32| cells.get(reg(x)).copied().ok_or(BAD);
    macro_rules! w {
        ($x:expr, $v:expr) => {{
            let v = $v;
            *cells.get_mut(reg($x)).ok_or(BAD)? = v;
        }};
    }
    match op {
        Op::StrCmp { op, dst, a, b } => {
            s.a.clear();
            s.b.clear();
            read_str_into(cells, get(cells, a)? as usize, &mut s.a)?;
            read_str_into(cells, get(cells, b)? as usize, &mut s.b)?;
            let BinOp::Cmp(c) = op else { return Err(Fault::Internal("string operator")) };
            w!(dst, u64::from(c.holds(s.a.cmp(&s.b))));
            return Ok((s.a.len() + s.b.len()) as u64);
        }
        Op::Str { f, n, wide, dst, args } => {
            return strings::exec(f, n, wide, dst, args, cells, base, s);
        }
        Op::Math { f, elem, dst, a, b } => {
            let x = get(cells, a)?;
            let y = get(cells, b)?;
            w!(dst, math(f, elem, x, y));
        }
        Op::Select { dst, g, a } => {
            let k = u32::from(get(cells, g)? != 0);
            w!(dst, get(cells, a.wrapping_add(k))?);
        }
        Op::MinMax { max, elem, n, dst, args } => {
            let mut best = get(cells, args)?;
            for k in 1..u32::from(n) {
                let v = get(cells, args.wrapping_add(k))?;
                let better = if max {
                    arith::compare(BinOp::Cmp(Cmp::Gt), elem, v, best)
                } else {
                    arith::compare(BinOp::Cmp(Cmp::Lt), elem, v, best)
                };
                if better {
                    best = v;
                }
            }
            w!(dst, best);
        }
        Op::Limit { elem, check, dst, args } => {
            let mn = get(cells, args)?;
            let x = get(cells, args.wrapping_add(1))?;
            let mx = get(cells, args.wrapping_add(2))?;
            let outside = arith::compare(BinOp::Cmp(Cmp::Lt), elem, x, mn)
                || arith::compare(BinOp::Cmp(Cmp::Gt), elem, x, mx);
            if check && outside {
                return Err(Fault::SubrangeViolation {
                    value: x as i64,
                    low: mn as i64,
                    high: mx as i64,
                });
            }
            let v = if arith::compare(BinOp::Cmp(Cmp::Lt), elem, x, mn) {
                mn
            } else if arith::compare(BinOp::Cmp(Cmp::Gt), elem, x, mx) {
                mx
            } else {
                x
            };
            w!(dst, v);
        }
        Op::Mux { n, dst, args } => {
            let k = get(cells, args)? as i64;
            if k < 0 || k >= i64::from(n) {
                return Err(Fault::IndexOutOfRange { index: k, low: 0, high: i64::from(n) - 1 });
            }
            w!(dst, get(cells, args.wrapping_add(1 + k as u32))?);
        }
        Op::ToStr { ty, dst, a } => {
            let t = *exe.out.types.get(ty as usize).ok_or(BAD)?;
            s.text.clear();
            text::format_cell(&mut s.text, &exe.type_table, t, get(cells, a)?);
            let d = get(cells, dst)? as usize;
            write_str(cells, d, s.text.as_bytes(), 1)?;
        }
        Op::FromStr { elem, dst, a } => {
            s.a.clear();
            read_str_into(cells, get(cells, a)? as usize, &mut s.a)?;
            w!(dst, text::parse_cell(&s.a, elem)?);
            return Ok(s.a.len() as u64);
        }
        Op::Bcd { encode, from, to, dst, a } => {
            let x = get(cells, a)?;
            w!(dst, if encode { to_bcd(from, to, x)? } else { from_bcd(from, to, x)? });
        }
        _ => return Err(Fault::Internal("unknown instruction")),
    }
    Ok(0)
}

/// A numeric built-in on cells of type `elem`.
pub(crate) fn math(f: MathFn, elem: Elem, x: u64, y: u64) -> u64 {
    let real = |g: fn(f64) -> f64| arith::from_f64(elem, g(arith::to_f64(elem, x)));
    match f {
        MathFn::Abs => {
            if elem.is_real() {
                arith::from_f64(elem, f64::from_bits(x).abs())
            } else {
                arith::norm(elem, arith::to_i128(elem, x).abs())
            }
        }
        MathFn::Sqrt => real(math::sqrt),
        MathFn::Ln => real(math::ln),
        MathFn::Log => real(math::log10),
        MathFn::Exp => real(math::exp),
        MathFn::Sin => real(math::sin),
        MathFn::Cos => real(math::cos),
        MathFn::Tan => real(math::tan),
        MathFn::Asin => real(math::asin),
        MathFn::Acos => real(math::acos),
        MathFn::Atan => real(math::atan),
        MathFn::Expt => {
            arith::from_f64(elem, math::pow(arith::to_f64(elem, x), arith::to_f64(elem, y)))
        }
        MathFn::Shl => arith::shift(ShiftKind::Shl, elem, x, y as i64),
        MathFn::Shr => arith::shift(ShiftKind::Shr, elem, x, y as i64),
        MathFn::Rol => arith::shift(ShiftKind::Rol, elem, x, y as i64),
        MathFn::Ror => arith::shift(ShiftKind::Ror, elem, x, y as i64),
    }
}

fn bad_bcd(x: u64, target: Elem) -> Fault {
    Fault::BadConversion { text: format!("16#{x:X}"), target: target.name() }
}

/// Decodes packed BCD in the width of `from` into `to`.
pub(crate) fn from_bcd(from: Elem, to: Elem, x: u64) -> Result<u64, Fault> {
    let bits = from.bits().clamp(4, 64);
    let v = if bits >= 64 { x } else { x & ((1u64 << bits) - 1) };
    let mut r: i128 = 0;
    for k in (0..bits / 4).rev() {
        let d = (v >> (k * 4)) & 0xF;
        if d > 9 {
            return Err(bad_bcd(v, to));
        }
        r = r * 10 + d as i128;
    }
    Ok(arith::norm(to, r))
}

/// Encodes a value of `from` as packed BCD of type `to`.
pub(crate) fn to_bcd(from: Elem, to: Elem, x: u64) -> Result<u64, Fault> {
    let v = arith::to_i128(from, x);
    let digits = to.bits().clamp(4, 64) / 4;
    if v < 0 || v >= 10i128.pow(digits) {
        return Err(Fault::BadConversion { text: v.to_string(), target: to.name() });
    }
    let (mut n, mut r, mut k) = (v as u128, 0u64, 0);
    while n > 0 {
        r |= ((n % 10) as u64) << (k * 4);
        n /= 10;
        k += 1;
    }
    Ok(r)
}
