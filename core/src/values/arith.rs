//! Arithmetic on memory cells: the one definition of how values wrap, round, convert and
//! compare. The VM and the checker's constant folder both call these, so a folded constant
//! and a computed value can never differ.
//!
//! Cell encoding (one `u64` per scalar):
//! - BOOL: 0 or 1;
//! - signed integers, TIME, DATE, TOD, DT, enumerations: the value sign-extended to 64 bits
//!   (TIME and TOD in nanoseconds, DATE and DT in microseconds since 1970-01-01, which
//!   covers the years 1 to 9999 of IEC's date literals and far beyond);
//! - unsigned integers and bit strings: the value zero-extended;
//! - REAL: the f64 bits of a value already rounded to f32 precision; LREAL: its f64 bits.

use super::{BinOp, Cmp, Elem, Fault};

const NS_PER_MS: i64 = 1_000_000;
const NS_PER_US: i64 = 1_000;
const US_PER_S: i64 = 1_000_000;
const US_PER_DAY: i64 = 86_400 * US_PER_S;

/// A temporal cell in nanoseconds (DATE and DT count microseconds), without overflow.
fn temporal_ns(e: Elem, bits: u64) -> i128 {
    let v = i128::from(bits as i64);
    if matches!(e, Elem::Date | Elem::Dt) {
        v * i128::from(NS_PER_US)
    } else {
        v
    }
}

/// Nanoseconds as a cell of temporal type `e`: DATE and DT drop the part below a
/// microsecond (toward zero); every type wraps in its 64 bits, as integers do.
fn temporal_from_ns(e: Elem, ns: i128) -> u64 {
    if matches!(e, Elem::Date | Elem::Dt) {
        (ns / i128::from(NS_PER_US)) as i64 as u64
    } else {
        ns as i64 as u64
    }
}

/// Wraps an integer to `elem` (two's complement) and encodes it.
pub fn norm(elem: Elem, v: i128) -> u64 {
    match elem {
        Elem::Bool => u64::from(v != 0),
        Elem::SInt => v as i8 as i64 as u64,
        Elem::Int => v as i16 as i64 as u64,
        Elem::DInt => v as i32 as i64 as u64,
        Elem::USInt | Elem::Byte => v as u8 as u64,
        Elem::UInt | Elem::Word => v as u16 as u64,
        Elem::UDInt | Elem::DWord => v as u32 as u64,
        Elem::Real | Elem::LReal => from_f64(elem, v as f64),
        _ => v as i64 as u64,
    }
}

/// Decodes an integral cell (any non-real type) as a wide integer.
pub fn to_i128(elem: Elem, bits: u64) -> i128 {
    match elem {
        Elem::ULInt | Elem::LWord => bits as i128,
        Elem::Real | Elem::LReal => f64::from_bits(bits) as i128,
        _ if elem.is_zero_extended() => bits as i128,
        _ => bits as i64 as i128,
    }
}

/// Encodes a float as `elem` (REAL rounds to f32 precision).
pub fn from_f64(elem: Elem, f: f64) -> u64 {
    match elem {
        Elem::Real => (f as f32 as f64).to_bits(),
        Elem::LReal => f.to_bits(),
        _ => norm(elem, f as i128),
    }
}

/// Decodes any numeric cell as a float.
pub fn to_f64(elem: Elem, bits: u64) -> f64 {
    if elem.is_real() {
        f64::from_bits(bits)
    } else {
        to_i128(elem, bits) as f64
    }
}

/// Rounds half to even, the rule of `REAL_TO_INT` (docs/semantics.md).
pub fn round_half_even(f: f64) -> f64 {
    f.round_ties_even()
}

/// Converts a cell of type `from` to type `to` (the `*_TO_*` functions and implicit
/// widening). Out-of-range values wrap; reals round half to even; TIME counts milliseconds
/// when converted to or from a number; DATE and DT count seconds, TOD milliseconds.
/// Between temporal types the value keeps its meaning (DT_TO_TIME is the time since
/// 1970, TIME_TO_DT drops the nanoseconds below a microsecond).
pub fn convert(from: Elem, to: Elem, bits: u64) -> u64 {
    if from == to {
        return bits;
    }
    if to == Elem::Bool {
        return u64::from(if from.is_real() { f64::from_bits(bits) != 0.0 } else { bits != 0 });
    }
    let temporal_unit = |e: Elem| match e {
        Elem::Time | Elem::Tod => NS_PER_MS,
        Elem::Date | Elem::Dt => US_PER_S,
        _ => 1,
    };
    if from.is_temporal() && to.is_temporal() {
        // DT_TO_TOD keeps the time within the day, DT_TO_DATE the day's start (both
        // count from midnight, also before 1970).
        let us = bits as i64;
        return match (from, to) {
            (Elem::Dt | Elem::Date, Elem::Tod) => (us.rem_euclid(US_PER_DAY) * NS_PER_US) as u64,
            (Elem::Dt, Elem::Date) => (us - us.rem_euclid(US_PER_DAY)) as u64,
            _ => temporal_from_ns(to, temporal_ns(from, bits)),
        };
    }
    if from.is_temporal() {
        let ns = bits as i64;
        let unit = temporal_unit(from);
        return if to.is_real() {
            from_f64(to, ns as f64 / unit as f64)
        } else {
            norm(to, (ns / unit) as i128)
        };
    }
    if to.is_temporal() {
        let unit = temporal_unit(to) as i128;
        return if from.is_real() {
            let f = f64::from_bits(bits) * unit as f64;
            norm(to, round_half_even(f) as i128)
        } else {
            norm(to, to_i128(from, bits).wrapping_mul(unit))
        };
    }
    if from.is_real() {
        let f = f64::from_bits(bits);
        if to.is_real() {
            return from_f64(to, f);
        }
        let r = round_half_even(f);
        return norm(to, if r.is_nan() { 0 } else { r as i128 });
    }
    if to.is_real() {
        return from_f64(to, to_i128(from, bits) as f64);
    }
    norm(to, to_i128(from, bits))
}

/// `TRUNC`: a real to an integer type, toward zero, wrapping when out of range.
pub fn trunc(from: Elem, to: Elem, bits: u64) -> u64 {
    let f = to_f64(from, bits).trunc();
    norm(to, if f.is_nan() { 0 } else { f as i128 })
}

/// Applies an arithmetic or logical operator to two cells of the same type `elem`.
/// Comparisons are handled by [`compare`]; short-circuit operators never reach here.
pub fn binary(op: BinOp, elem: Elem, a: u64, b: u64) -> Result<u64, Fault> {
    if elem.is_real() {
        let (x, y) = (f64::from_bits(a), f64::from_bits(b));
        let r = match op {
            BinOp::Add => x + y,
            BinOp::Sub => x - y,
            BinOp::Mul => x * y,
            BinOp::Div => x / y,
            BinOp::Pow => super::math::pow(x, y),
            BinOp::Mod => {
                if y == 0.0 {
                    0.0
                } else {
                    x % y
                }
            }
            _ => return Err(Fault::Internal("logical operator on REAL")),
        };
        return Ok(from_f64(elem, r));
    }
    match op {
        BinOp::And => return Ok(a & b),
        BinOp::Or => return Ok(a | b),
        BinOp::Xor => return Ok(a ^ b),
        _ => {}
    }
    let (x, y) = (to_i128(elem, a), to_i128(elem, b));
    let r = match op {
        BinOp::Add => x.wrapping_add(y),
        BinOp::Sub => x.wrapping_sub(y),
        BinOp::Mul => x.wrapping_mul(y),
        BinOp::Div => {
            if y == 0 {
                return Err(Fault::DivisionByZero);
            }
            x / y
        }
        BinOp::Mod => {
            if y == 0 {
                0
            } else {
                x % y
            }
        }
        BinOp::Pow => return Ok(norm(elem, super::math::pow(x as f64, y as f64) as i128)),
        _ => return Err(Fault::Internal("comparison in binary()")),
    };
    Ok(norm(elem, r))
}

/// TIME (or TOD/DT) scaled by a number: `T#1s * 2`, `T#1s / 2.5`. `factor` is a LINT
/// when `real` is false, else an LREAL.
pub fn scale_time(op: BinOp, elem: Elem, t: u64, factor: u64, real: bool) -> Result<u64, Fault> {
    let t = t as i64;
    if real {
        let f = f64::from_bits(factor);
        let r = match op {
            BinOp::Mul => t as f64 * f,
            _ if f == 0.0 => return Err(Fault::DivisionByZero),
            _ => t as f64 / f,
        };
        return Ok(norm(elem, round_half_even(r) as i128));
    }
    let k = factor as i64;
    let r = match op {
        BinOp::Mul => t.wrapping_mul(k),
        _ if k == 0 => return Err(Fault::DivisionByZero),
        _ => t.wrapping_div(k),
    };
    Ok(r as u64)
}

/// Compares two cells of the same type with `op` (one of Eq, Ne, Lt, Le, Gt, Ge).
pub fn compare(op: BinOp, elem: Elem, a: u64, b: u64) -> bool {
    let ord = if elem.is_real() {
        f64::from_bits(a).partial_cmp(&f64::from_bits(b))
    } else {
        Some(to_i128(elem, a).cmp(&to_i128(elem, b)))
    };
    match (op, ord) {
        (BinOp::Cmp(c), Some(o)) => c.holds(o),
        // NaN is unordered: only `<>` holds.
        (BinOp::Cmp(c), None) => c == Cmp::Ne,
        _ => false,
    }
}

/// Arithmetic negation in `elem` (wraps: `-(-128)` is -128 in SINT).
pub fn negate(elem: Elem, a: u64) -> u64 {
    if elem.is_real() {
        from_f64(elem, -f64::from_bits(a))
    } else {
        norm(elem, to_i128(elem, a).wrapping_neg())
    }
}

/// NOT: logical on BOOL, bitwise complement within the type's width otherwise.
pub fn complement(elem: Elem, a: u64) -> u64 {
    if elem == Elem::Bool {
        a ^ 1
    } else {
        norm(elem, !(a as i64) as i128)
    }
}

/// Shifts and rotations within the width of `elem` (SHL, SHR, ROL, ROR).
pub fn shift(kind: ShiftKind, elem: Elem, a: u64, n: i64) -> u64 {
    let width = elem.bits().max(1);
    let mask: u64 = if width >= 64 { u64::MAX } else { (1u64 << width) - 1 };
    let v = a & mask;
    let n = n.max(0) as u64;
    let r = match kind {
        ShiftKind::Shl => {
            if n >= width as u64 {
                0
            } else {
                v << n
            }
        }
        ShiftKind::Shr => {
            if n >= width as u64 {
                0
            } else {
                v >> n
            }
        }
        ShiftKind::Rol | ShiftKind::Ror => {
            let k = (n % width as u64) as u32;
            if k == 0 {
                v
            } else {
                let (l, r) = if kind == ShiftKind::Rol { (k, width - k) } else { (width - k, k) };
                (v << l) | (v >> r)
            }
        }
    };
    norm(elem, (r & mask) as i128)
}

/// Which shift [`shift`] does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShiftKind {
    /// Shift left, filling with zeros.
    Shl,
    /// Shift right, filling with zeros.
    Shr,
    /// Rotate left.
    Rol,
    /// Rotate right.
    Ror,
}

/// Reads bit `n` of an integral cell.
pub fn get_bit(a: u64, n: u32) -> u64 {
    (a >> n.min(63)) & 1
}

/// Writes bit `n` of an integral cell of type `elem` and re-normalises it.
pub fn set_bit(elem: Elem, a: u64, n: u32, value: bool) -> u64 {
    let n = n.min(63);
    let r = if value { a | (1 << n) } else { a & !(1 << n) };
    norm(elem, r as i64 as i128)
}

/// Reads a value of type `elem` stored as its raw bits (its width, from bit `shift`) in
/// a 64-bit cell of the process image (a located variable): integers sign- or
/// zero-extended as their cells are, REAL from its 32 IEEE bits.
pub fn get_slice(cell: u64, shift: u32, elem: Elem) -> u64 {
    let width = elem.bits().min(64);
    let raw = if width >= 64 { cell } else { (cell >> shift.min(63)) & ((1u64 << width) - 1) };
    match elem {
        Elem::Real => f64::from(f32::from_bits(raw as u32)).to_bits(),
        Elem::LReal => raw,
        _ if elem.is_zero_extended() || width >= 64 => norm(elem, raw as i128),
        _ => {
            // Sign-extend from the value's width.
            let up = 64 - width;
            norm(elem, i128::from(((raw << up) as i64) >> up))
        }
    }
}

/// Writes the value `v` (a cell of type `elem`) as its raw bits into a 64-bit image cell
/// from bit `shift` (see [`get_slice`]); the other bits keep their values.
pub fn set_slice(cell: u64, shift: u32, elem: Elem, v: u64) -> u64 {
    let width = elem.bits().min(64);
    let raw = match elem {
        Elem::Real => u64::from((f64::from_bits(v) as f32).to_bits()),
        _ => v,
    };
    if width >= 64 {
        return raw;
    }
    let shift = shift.min(64 - width);
    let mask = ((1u64 << width) - 1) << shift;
    (cell & !mask) | ((raw << shift) & mask)
}

/// Writes `bits`, a value of type `ty`, at bit `n` of a cell of type `cell_elem`: the one
/// bit of a BOOL (a bit access, or a located BOOL), or the raw bits of a wider located
/// variable ([`set_slice`]).
pub fn put_at_bit(cell_elem: Elem, cell: u64, n: u32, ty: Elem, bits: u64) -> u64 {
    if ty == Elem::Bool {
        set_bit(cell_elem, cell, n, bits != 0)
    } else {
        set_slice(cell, n, ty, bits)
    }
}

/// True when converting `from` to `to` leaves a cell's bits unchanged (see the cell
/// encoding above): signed values are kept sign-extended and unsigned values and
/// bit strings zero-extended, so widening within those families is free.
pub fn identity_widening(from: Elem, to: Elem) -> bool {
    if from == to {
        return true;
    }
    let integral = |e: Elem| e.is_integral() || e == Elem::Bool;
    if !integral(from) || !integral(to) || to == Elem::Bool {
        return false;
    }
    if from.is_signed_int() {
        return to.is_signed_int() && to.bits() >= from.bits();
    }
    // Zero-extended sources (unsigned, bit strings, BOOL).
    if to.is_signed_int() {
        to.bits() > from.bits()
    } else {
        to.bits() >= from.bits()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn int(e: Elem, v: i128) -> u64 {
        norm(e, v)
    }

    #[test]
    fn dates_count_microseconds_and_convert_by_meaning() {
        let (dt, time, tod, date) = (Elem::Dt, Elem::Time, Elem::Tod, Elem::Date);
        // 1.5 s after 1970 as a DT is 1,500,000 µs; as a TIME 1.5e9 ns.
        assert_eq!(convert(dt, time, 1_500_000), 1_500_000_000);
        assert_eq!(convert(time, dt, 1_500_000_999), 1_500_000, "below a µs is dropped");
        assert_eq!(convert(time, dt, -999i64 as u64), 0, "toward zero");
        // 1969-12-31-23:00 is -3,600 s: its time of day 23:00, its date the day before.
        let before = (-3_600_000_000i64) as u64;
        assert_eq!(convert(dt, tod, before), 23 * 3_600_000_000_000);
        assert_eq!(convert(dt, date, before) as i64, -86_400_000_000);
        assert_eq!(convert(date, tod, 86_400_000_000), 0);
        // As numbers DATE and DT count seconds, whatever the representation.
        assert_eq!(convert(dt, Elem::LInt, 1_500_000), 1);
        assert_eq!(convert(Elem::LInt, date, 86_400), 86_400_000_000);
        // A DT far from 1970 as a TIME wraps like any overflow.
        let far = 300 * 365 * 86_400_000_000i64;
        assert_eq!(convert(dt, time, far as u64), (i128::from(far) * 1000) as i64 as u64);
    }

    #[test]
    fn integer_overflow_wraps_in_the_type() {
        let r = binary(BinOp::Add, Elem::Int, int(Elem::Int, 32767), int(Elem::Int, 1));
        assert_eq!(r.map(|b| to_i128(Elem::Int, b)), Ok(-32768));
        let r = binary(BinOp::Sub, Elem::USInt, 0, 1);
        assert_eq!(r.map(|b| to_i128(Elem::USInt, b)), Ok(255));
    }

    #[test]
    fn division_truncates_toward_zero_and_mod_follows_the_dividend() {
        let d = binary(BinOp::Div, Elem::DInt, int(Elem::DInt, -7), int(Elem::DInt, 3));
        assert_eq!(d.map(|b| to_i128(Elem::DInt, b)), Ok(-2));
        let m = binary(BinOp::Mod, Elem::DInt, int(Elem::DInt, -7), int(Elem::DInt, 2));
        assert_eq!(m.map(|b| to_i128(Elem::DInt, b)), Ok(-1));
        assert_eq!(binary(BinOp::Mod, Elem::DInt, 5, 0), Ok(0));
        assert_eq!(binary(BinOp::Div, Elem::DInt, 5, 0), Err(Fault::DivisionByZero));
    }

    #[test]
    fn real_to_int_rounds_half_to_even() {
        for (f, want) in [(2.5, 2), (-2.5, -2), (1.6, 2), (3.5, 4), (-0.4, 0)] {
            let r = convert(Elem::LReal, Elem::Int, from_f64(Elem::LReal, f));
            assert_eq!(to_i128(Elem::Int, r), want, "{f}");
        }
        assert_eq!(to_i128(Elem::Int, trunc(Elem::LReal, Elem::Int, (-2.7f64).to_bits())), -2);
    }

    #[test]
    fn out_of_range_conversion_wraps() {
        let r = convert(Elem::DInt, Elem::SInt, int(Elem::DInt, 300));
        assert_eq!(to_i128(Elem::SInt, r), 44);
    }

    #[test]
    fn rotations_stay_in_the_width() {
        assert_eq!(shift(ShiftKind::Rol, Elem::Byte, 0x81, 1), 0x03);
        assert_eq!(shift(ShiftKind::Ror, Elem::Byte, 0x01, 1), 0x80);
        assert_eq!(shift(ShiftKind::Shl, Elem::Byte, 0x81, 1), 0x02);
        assert_eq!(complement(Elem::Byte, 0x0F), 0xF0);
    }

    #[test]
    fn real_values_are_rounded_to_single_precision() {
        let r = from_f64(Elem::Real, 0.1);
        assert_eq!(f64::from_bits(r), 0.1f32 as f64);
    }
}

#[cfg(test)]
mod identity_tests {
    use super::identity_widening;
    use crate::values::{arith, Elem};

    #[test]
    fn identity_widenings_really_leave_the_bits_alone() {
        let elems = [
            Elem::Bool,
            Elem::SInt,
            Elem::Int,
            Elem::DInt,
            Elem::LInt,
            Elem::USInt,
            Elem::UInt,
            Elem::UDInt,
            Elem::ULInt,
            Elem::Byte,
            Elem::Word,
            Elem::DWord,
            Elem::LWord,
        ];
        for from in elems {
            for to in elems {
                if !identity_widening(from, to) {
                    continue;
                }
                let (lo, hi) = from.int_range();
                for v in [lo, hi, 0, 1, lo / 2, hi / 2] {
                    let bits = arith::norm(from, v);
                    assert_eq!(arith::convert(from, to, bits), bits, "{from:?} -> {to:?} of {v}");
                }
            }
        }
    }
}
