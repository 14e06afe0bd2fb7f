//! Values as IEC text and back: `*_TO_STRING`, `STRING_TO_*`, and the canonical literals
//! used by the JSON renderer (`T#1s500ms`, `D#2006-03-20`, `TOD#10:42:23.78`,
//! `DT#2006-03-20-10:42:23.78`).

use std::fmt::Write;

use crate::semantic::types::{Elem, Type, TypeTable};
use crate::values::arith;
use crate::values::Fault;

const NS_PER_DAY: i64 = 86_400_000_000_000;
/// DATE and DT count microseconds since 1970-01-01 (`values::arith`).
const US_PER_DAY: i64 = 86_400_000_000;

/// The canonical TIME literal of `ns` nanoseconds: largest unit first among d, h, m, s,
/// ms, us, ns, zero units left out (`T#1s500ms`, `T#0s`, `T#-14ms`).
pub fn format_time(ns: i64) -> String {
    let mut s = String::from("T#");
    if ns < 0 {
        s.push('-');
    }
    let mut v = ns.unsigned_abs();
    if v == 0 {
        s.push_str("0s");
        return s;
    }
    const UNITS: [(u64, &str); 7] = [
        (86_400_000_000_000, "d"),
        (3_600_000_000_000, "h"),
        (60_000_000_000, "m"),
        (1_000_000_000, "s"),
        (1_000_000, "ms"),
        (1_000, "us"),
        (1, "ns"),
    ];
    for (size, name) in UNITS {
        let k = v / size;
        if k > 0 {
            let _ = write!(s, "{k}{name}");
            v -= k * size;
        }
    }
    s
}

/// (year, month, day) of a day number counted from 1970-01-01.
pub fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let y = yoe + era * 400;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (if m <= 2 { y + 1 } else { y }, m, d)
}

/// The day number (from 1970-01-01) of a civil date.
pub fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y.rem_euclid(400);
    let m = i64::from(m);
    let doy = (153 * (if m > 2 { m - 3 } else { m + 9 }) + 2) / 5 + i64::from(d) - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

/// The date of `us` microseconds since 1970-01-01 (a year past 9999, which only
/// arithmetic reaches, is written with its digits; one before 1 as astronomers count it).
fn push_date(s: &mut String, us: i64) {
    let (y, m, d) = civil_from_days(us.div_euclid(US_PER_DAY));
    let _ = write!(s, "{y:04}-{m:02}-{d:02}");
}

fn push_tod(s: &mut String, ns: i64) {
    let t = ns.rem_euclid(NS_PER_DAY);
    let secs = t / 1_000_000_000;
    let frac = t % 1_000_000_000;
    let _ = write!(s, "{:02}:{:02}:{:02}", secs / 3600, secs / 60 % 60, secs % 60);
    if frac > 0 {
        let f = format!("{frac:09}");
        s.push('.');
        s.push_str(f.trim_end_matches('0'));
    }
}

/// The literal of a DATE (`D#2006-03-20`) of `us` microseconds since 1970-01-01.
pub fn format_date(us: i64) -> String {
    let mut s = String::from("D#");
    push_date(&mut s, us);
    s
}

/// The literal of a TIME_OF_DAY (`TOD#10:42:23.78`).
pub fn format_tod(ns: i64) -> String {
    let mut s = String::from("TOD#");
    push_tod(&mut s, ns);
    s
}

/// The literal of a DATE_AND_TIME (`DT#2006-03-20-10:42:23.78`) of `us` microseconds
/// since 1970-01-01.
pub fn format_dt(us: i64) -> String {
    let mut s = String::from("DT#");
    push_date(&mut s, us);
    s.push('-');
    push_tod(&mut s, us.rem_euclid(US_PER_DAY) * 1000);
    s
}

/// Shortest text that reads back as the same REAL (f32) or LREAL value.
pub fn format_real(elem: Elem, f: f64) -> String {
    if elem == Elem::Real {
        format!("{}", f as f32)
    } else {
        format!("{f}")
    }
}

/// Appends the text of a scalar cell of type `ty` (`*_TO_STRING`).
pub(crate) fn format_cell(out: &mut String, types: &TypeTable, ty: Type, bits: u64) {
    match ty {
        Type::Enum(e) => {
            let v = bits as i64;
            match types.enums.get(e as usize).and_then(|d| d.values.iter().find(|x| x.1 == v)) {
                Some((name, _)) => out.push_str(name),
                None => {
                    let _ = write!(out, "{v}");
                }
            }
        }
        Type::Elem(e) => match e {
            Elem::Bool => out.push_str(if bits != 0 { "TRUE" } else { "FALSE" }),
            Elem::Real | Elem::LReal => out.push_str(&format_real(e, f64::from_bits(bits))),
            Elem::Time => out.push_str(&format_time(bits as i64)),
            Elem::Date => out.push_str(&format_date(bits as i64)),
            Elem::Tod => out.push_str(&format_tod(bits as i64)),
            Elem::Dt => out.push_str(&format_dt(bits as i64)),
            _ => {
                let _ = write!(out, "{}", arith::to_i128(e, bits));
            }
        },
        _ => {}
    }
}

/// Parses a TIME literal or duration text (`T#1h2m`, `TIME#-5s`, `1.5s`) to nanoseconds.
pub fn parse_time(text: &str) -> Option<i64> {
    let t = text.trim().to_ascii_lowercase().replace('_', "");
    let body = ["ltime#", "time#", "t#"].iter().find_map(|p| t.strip_prefix(p)).unwrap_or(&t);
    let (neg, mut rest) = match body.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, body.strip_prefix('+').unwrap_or(body)),
    };
    if rest.is_empty() {
        return None;
    }
    let mut total: i128 = 0;
    while !rest.is_empty() {
        let num_end = rest.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(rest.len());
        let (num, r) = rest.split_at(num_end);
        let unit_end = r.find(|c: char| c.is_ascii_digit()).unwrap_or(r.len());
        let (unit, r) = r.split_at(unit_end);
        let scale: i128 = match unit {
            "d" => 86_400_000_000_000,
            "h" => 3_600_000_000_000,
            "m" => 60_000_000_000,
            "s" => 1_000_000_000,
            "ms" => 1_000_000,
            "us" => 1_000,
            "ns" => 1,
            _ => return None,
        };
        let value: f64 = num.parse().ok()?;
        if num.contains('.') && !r.is_empty() {
            return None;
        }
        total += if num.contains('.') {
            (value * scale as f64).round() as i128
        } else {
            num.parse::<i128>().ok()?.checked_mul(scale)?
        };
        rest = r;
    }
    let v = if neg { -total } else { total };
    i64::try_from(v).ok()
}

fn parse_date(t: &str) -> Option<i64> {
    let mut it = t.splitn(3, '-');
    let y: i64 = it.next()?.trim().parse().ok()?;
    let m: u32 = it.next()?.trim().parse().ok()?;
    let d: u32 = it.next()?.trim().parse().ok()?;
    if !(1..=12).contains(&m) || !(1..=31).contains(&d) || !(1..=9999).contains(&y) {
        return None;
    }
    days_from_civil(y, m, d).checked_mul(US_PER_DAY)
}

fn parse_tod(t: &str) -> Option<i64> {
    let mut it = t.trim().splitn(3, ':');
    let h: i64 = it.next()?.parse().ok()?;
    let m: i64 = it.next()?.parse().ok()?;
    let s: f64 = it.next().unwrap_or("0").parse().ok()?;
    if !(0..24).contains(&h) || !(0..60).contains(&m) || !(0.0..60.0).contains(&s) {
        return None;
    }
    Some((h * 3600 + m * 60) * 1_000_000_000 + (s * 1e9).round() as i64)
}

fn strip_prefix_ci<'a>(t: &'a str, prefixes: &[&str]) -> &'a str {
    for p in prefixes {
        if t.len() >= p.len() && t[..p.len()].eq_ignore_ascii_case(p) {
            return &t[p.len()..];
        }
    }
    t
}

/// Parses text as a value of `elem` (`STRING_TO_*`); `None` when it is not one.
pub fn parse_text(text: &str, elem: Elem) -> Option<u64> {
    let t = text.trim();
    match elem {
        Elem::Bool => match t.to_ascii_uppercase().as_str() {
            "TRUE" | "1" => Some(1),
            "FALSE" | "0" => Some(0),
            _ => None,
        },
        Elem::Real | Elem::LReal => {
            let v: f64 = t.replace('_', "").parse().ok()?;
            Some(arith::from_f64(elem, v))
        }
        Elem::Time => parse_time(t).map(|v| v as u64),
        Elem::Date => parse_date(strip_prefix_ci(t, &["DATE#", "D#"])).map(|v| v as u64),
        Elem::Tod => parse_tod(strip_prefix_ci(t, &["TIME_OF_DAY#", "TOD#"])).map(|v| v as u64),
        Elem::Dt => {
            let b = strip_prefix_ci(t, &["DATE_AND_TIME#", "DT#"]);
            let (d, tod) = b.rsplit_once('-').filter(|(d, _)| d.matches('-').count() == 2)?;
            Some(parse_date(d)?.checked_add(parse_tod(tod)? / 1000)? as u64)
        }
        _ => {
            let s = t.replace('_', "");
            let (neg, s) = match s.strip_prefix('-') {
                Some(r) => (true, r.to_string()),
                None => (false, s.strip_prefix('+').unwrap_or(&s).to_string()),
            };
            let v = match s.split_once('#') {
                Some((b, digits)) => {
                    let radix = b.parse::<u32>().ok().filter(|r| [2, 8, 16].contains(r))?;
                    i128::from_str_radix(digits, radix).ok()?
                }
                None => s.parse::<i128>().ok()?,
            };
            let v = if neg { -v } else { v };
            let (lo, hi) = elem.int_range();
            (lo..=hi).contains(&v).then(|| arith::norm(elem, v))
        }
    }
}

/// `STRING_TO_*` on bytes: the value or `Fault::BadConversion`.
pub(crate) fn parse_cell(bytes: &[u8], elem: Elem) -> Result<u64, Fault> {
    let text = String::from_utf8_lossy(bytes);
    parse_text(&text, elem)
        .ok_or_else(|| Fault::BadConversion { text: text.into_owned(), target: elem.name() })
}
