//! Literal text → values: integers in any base, reals, strings with `$` escapes,
//! durations, dates, times of day, directly represented addresses and type prefixes.
//!
//! Every function takes the literal's text as the lexer found it and returns the value or a
//! problem (a code and a message for the student). Nothing here knows about spans: the
//! parser places the problem on the literal's token.

use super::ast::{AddressArea, AddressSize, LiteralValue};
use crate::diagnostics::{Arg, Code, Said};
use crate::{msg, phrase};

/// A problem with a literal: its code and a message.
pub(crate) type LitError = (Code, Said);

type LitResult<T> = Result<T, LitError>;

const NS_PER_US: i128 = 1_000;
const NS_PER_MS: i128 = 1_000_000;
const NS_PER_S: i128 = 1_000_000_000;
const NS_PER_MIN: i128 = 60 * NS_PER_S;
const NS_PER_H: i128 = 60 * NS_PER_MIN;
const NS_PER_DAY: i128 = 24 * NS_PER_H;

/// The value of an integer literal: `123_456`, `2#1110_0000`, `8#377`, `16#e5`.
pub(crate) fn parse_integer(text: &str) -> LitResult<i128> {
    let bad = || (Code::InvalidNumber, msg!(InvalidInteger, text = text));
    let (base, digits) = match text.split_once('#') {
        Some((b, d)) => {
            let base: u32 = match b.replace('_', "").as_str() {
                "2" => 2,
                "8" => 8,
                "16" => 16,
                _ => return Err((Code::InvalidNumber, msg!(InvalidBase, base = b))),
            };
            (base, d)
        }
        None => (10, text),
    };
    check_underscores(digits).map_err(|_| bad())?;
    let mut value: i128 = 0;
    for c in digits.chars().filter(|&c| c != '_') {
        let Some(d) = c.to_digit(base) else {
            return Err((
                Code::InvalidNumber,
                msg!(InvalidDigit, digit = c, base = base, text = text),
            ));
        };
        value = value * i128::from(base) + i128::from(d);
        if value > i128::from(u64::MAX) {
            return Err((Code::IntegerLiteralTooLarge, msg!(IntegerTooLarge, text = text)));
        }
    }
    Ok(value)
}

/// `_` may only stand between two digits.
fn check_underscores(digits: &str) -> Result<(), ()> {
    if digits.is_empty()
        || digits.starts_with('_')
        || digits.ends_with('_')
        || digits.contains("__")
    {
        return Err(());
    }
    Ok(())
}

/// The value of a real literal: `1.5`, `3.14159_26`, `1.234e-6`, `1.0E+3`.
pub(crate) fn parse_real(text: &str) -> LitResult<f64> {
    let bad = || (Code::InvalidNumber, msg!(InvalidReal, text = text));
    let (mantissa, _) = text.split_once(['e', 'E']).unwrap_or((text, ""));
    for part in mantissa.split('.') {
        check_underscores(part).map_err(|_| bad())?;
    }
    let cleaned: String = text.chars().filter(|&c| c != '_').collect();
    match cleaned.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(bad()),
    }
}

/// The bytes of a `'…'` string (text with quotes). Non-ASCII characters are kept as their
/// UTF-8 bytes.
pub(crate) fn parse_string(text: &str) -> LitResult<Vec<u8>> {
    let inner = strip_quotes(text, '\'');
    let mut out = Vec::with_capacity(inner.len());
    let mut chars = inner.char_indices();
    while let Some((_, c)) = chars.next() {
        if c == '\'' {
            break;
        }
        if c != '$' {
            let mut buf = [0u8; 4];
            out.extend_from_slice(c.encode_utf8(&mut buf).as_bytes());
            continue;
        }
        let Some((_, e)) = chars.next() else {
            return Err(escape_error("$"));
        };
        if let Some(b) = simple_escape(e) {
            out.push(b);
        } else if e.is_ascii_hexdigit() {
            let Some((_, e2)) = chars.next().filter(|(_, c)| c.is_ascii_hexdigit()) else {
                return Err(escape_error(&format!("${e}")));
            };
            let hex: String = [e, e2].iter().collect();
            let byte =
                u8::from_str_radix(&hex, 16).map_err(|_| escape_error(&format!("${hex}")))?;
            out.push(byte);
        } else {
            return Err(escape_error(&format!("${e}")));
        }
    }
    Ok(out)
}

/// The UTF-16 code units of a `"…"` wide string (text with quotes); `$hhhh` is one unit.
pub(crate) fn parse_wstring(text: &str) -> LitResult<Vec<u16>> {
    let inner = strip_quotes(text, '"');
    let mut out = Vec::with_capacity(inner.len());
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        if c == '"' {
            break;
        }
        if c != '$' {
            let mut buf = [0u16; 2];
            out.extend_from_slice(c.encode_utf16(&mut buf));
            continue;
        }
        let Some(e) = chars.next() else {
            return Err(escape_error("$"));
        };
        if let Some(b) = simple_escape(e) {
            out.push(u16::from(b));
        } else if e.is_ascii_hexdigit() {
            let mut hex = String::from(e);
            for _ in 0..3 {
                match chars.next() {
                    Some(h) if h.is_ascii_hexdigit() => hex.push(h),
                    _ => return Err((Code::InvalidEscape, msg!(InvalidWideEscape, hex = hex))),
                }
            }
            let unit =
                u16::from_str_radix(&hex, 16).map_err(|_| escape_error(&format!("${hex}")))?;
            out.push(unit);
        } else {
            return Err(escape_error(&format!("${e}")));
        }
    }
    Ok(out)
}

/// The text after the opening quote. The lexer ends a string token at its first
/// unescaped quote, so decoding stops at an unescaped quote; an unterminated string (already
/// reported by the lexer) has none.
fn strip_quotes(text: &str, quote: char) -> &str {
    text.strip_prefix(quote).unwrap_or(text)
}

fn simple_escape(e: char) -> Option<u8> {
    Some(match e {
        '$' => b'$',
        '\'' => b'\'',
        '"' => b'"',
        'L' | 'l' | 'N' | 'n' => b'\n',
        'R' | 'r' => b'\r',
        'T' | 't' => b'\t',
        'P' | 'p' => 0x0c,
        _ => return None,
    })
}

fn escape_error(found: &str) -> LitError {
    (Code::InvalidEscape, msg!(InvalidEscape, found = found))
}

/// The text after the first `#` (the whole text if there is none).
fn after_hash(text: &str) -> &str {
    text.split_once('#').map_or(text, |(_, b)| b)
}

/// The value in nanoseconds of a duration literal with its prefix: `T#5d14h12m18s3.5ms`.
pub(crate) fn parse_duration(text: &str) -> LitResult<i64> {
    let body = after_hash(text);
    let bad = |why: Arg| (Code::InvalidTimeLiteral, msg!(InvalidDuration, text = text, why = why));
    let (negative, rest) = match body.as_bytes().first() {
        Some(b'-') => (true, &body[1..]),
        Some(b'+') => (false, &body[1..]),
        _ => (false, body),
    };
    let rest = rest.trim_start_matches('_');
    if rest.is_empty() {
        return Err(bad(phrase!(WhyWriteNumberAndUnitT1sOr).into()));
    }
    const UNITS: [(&str, i128, i128); 7] = [
        ("d", NS_PER_DAY, 0),
        ("h", NS_PER_H, 24),
        ("m", NS_PER_MIN, 60),
        ("s", NS_PER_S, 60),
        ("ms", NS_PER_MS, 1000),
        ("us", NS_PER_US, 1000),
        ("ns", 1, 1000),
    ];
    let bytes = rest.as_bytes();
    let mut i = 0;
    let mut total: i128 = 0;
    let mut last_unit: Option<usize> = None;
    let mut had_fraction = false;
    while i < bytes.len() {
        if bytes[i] == b'_' {
            i += 1;
            continue;
        }
        if had_fraction {
            return Err(bad(phrase!(WhyOnlyLastUnitMayHaveFraction).into()));
        }
        // The number.
        let num_start = i;
        while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'_') {
            i += 1;
        }
        let int_text = &rest[num_start..i];
        if int_text.is_empty() {
            return Err(bad(phrase!(WhyNumberMustComeBeforeUnit).into()));
        }
        let mut frac_text = "";
        if i < bytes.len() && bytes[i] == b'.' {
            i += 1;
            let f_start = i;
            while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'_') {
                i += 1;
            }
            frac_text = &rest[f_start..i];
            if frac_text.is_empty() {
                return Err(bad(phrase!(WhyDigitMustFollowDecimalPoint).into()));
            }
            had_fraction = true;
        }
        // The unit.
        let u_start = i;
        while i < bytes.len() && bytes[i].is_ascii_alphabetic() {
            i += 1;
        }
        let unit_text = rest[u_start..i].to_ascii_lowercase();
        let Some(unit_index) = UNITS.iter().position(|(u, _, _)| *u == unit_text) else {
            return Err(if unit_text.is_empty() {
                bad(phrase!(WhyNumberNeedsUnitDHM).into())
            } else {
                bad(Arg::Text(format!("`{unit_text}` is not a unit; use d, h, m, s, ms, us or ns")))
            });
        };
        if let Some(prev) = last_unit {
            if unit_index <= prev {
                return Err(bad(phrase!(WhyUnitsMustGoFromLargestTo).into()));
            }
        }
        let (unit_name, unit_ns, limit) = UNITS[unit_index];
        let whole =
            digits_value(int_text).ok_or_else(|| bad(phrase!(WhyNumberIsTooLarge).into()))?;
        if last_unit.is_some() && whole >= limit {
            return Err(bad(Arg::Text(format!(
                "`{whole}{unit_name}` is too large after a larger unit (must be below {limit})"
            ))));
        }
        let mut part =
            whole.checked_mul(unit_ns).ok_or_else(|| bad(phrase!(WhyDurationIsTooLong).into()))?;
        part += fraction_ns(frac_text, unit_ns);
        total = total.checked_add(part).ok_or_else(|| bad(phrase!(WhyDurationIsTooLong).into()))?;
        last_unit = Some(unit_index);
    }
    if negative {
        total = -total;
    }
    i64::try_from(total).map_err(|_| bad(phrase!(WhyDurationIsTooLongAtMost).into()))
}

/// Decimal digits with `_` separators as a number (None when absurdly long).
fn digits_value(text: &str) -> Option<i128> {
    let mut v: i128 = 0;
    for c in text.chars().filter(|&c| c != '_') {
        v = v.checked_mul(10)?.checked_add(i128::from(c.to_digit(10)?))?;
        if v > i128::from(u64::MAX) {
            return None;
        }
    }
    Some(v)
}

/// `0.frac` of `unit_ns` rounded to the nearest nanosecond.
fn fraction_ns(frac: &str, unit_ns: i128) -> i128 {
    let digits: Vec<i128> =
        frac.chars().filter_map(|c| c.to_digit(10)).take(20).map(i128::from).collect();
    let mut num: i128 = 0;
    let mut den: i128 = 1;
    for d in digits {
        num = num * 10 + d;
        den *= 10;
    }
    (num * unit_ns * 2 + den) / (den * 2)
}

/// Days since 1970-01-01 of a civil date (proleptic Gregorian calendar).
fn days_from_civil(year: i64, month: i64, day: i64) -> i64 {
    let y = if month <= 2 { year - 1 } else { year };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (month + 9) % 12;
    let doy = (153 * mp + 2) / 5 + day - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

fn days_in_month(year: i64, month: i64) -> i64 {
    match month {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        _ if (year % 4 == 0 && year % 100 != 0) || year % 400 == 0 => 29,
        _ => 28,
    }
}

fn date_error(text: &str, why: impl Into<Arg>) -> LitError {
    (Code::InvalidDateLiteral, msg!(InvalidDate, text = text, why = why.into()))
}

/// A field of digits (with `_`), at most 9 digits.
fn field(s: &str) -> Option<i64> {
    let digits: String = s.chars().filter(|&c| c != '_').collect();
    if digits.is_empty() || digits.len() > 9 || !digits.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// Days since 1970 of `YYYY-MM-DD`.
fn date_days(full: &str, body: &str) -> LitResult<i64> {
    let parts: Vec<&str> = body.split('-').collect();
    let [y, m, d] = parts.as_slice() else {
        return Err(date_error(full, phrase!(WhyWriteDateAsYearMonthDay)));
    };
    let (Some(year), Some(month), Some(day)) = (field(y), field(m), field(d)) else {
        return Err(date_error(full, phrase!(WhyWriteDateAsYearMonthDay)));
    };
    if !(1..=12).contains(&month) {
        return Err(date_error(full, format!("there is no month {month}")));
    }
    if day < 1 || day > days_in_month(year, month) {
        return Err(date_error(full, format!("month {month} of {year} has no day {day}")));
    }
    Ok(days_from_civil(year, month, day))
}

/// Nanoseconds since midnight of `HH:MM:SS[.fff]` (seconds may be left out).
fn daytime_ns(full: &str, body: &str) -> LitResult<i64> {
    let parts: Vec<&str> = body.split(':').collect();
    let (h, m, s) = match parts.as_slice() {
        [h, m, s] => (*h, *m, *s),
        [h, m] => (*h, *m, "0"),
        _ => return Err(date_error(full, phrase!(WhyWriteTimeAsHoursMinutesSeconds))),
    };
    let (sec_text, frac_text) = s.split_once('.').unwrap_or((s, ""));
    let (Some(hour), Some(minute), Some(second)) = (field(h), field(m), field(sec_text)) else {
        return Err(date_error(full, phrase!(WhyWriteTimeAsHoursMinutesSeconds)));
    };
    let frac_ok = frac_text.chars().all(|c| c.is_ascii_digit() || c == '_')
        && (!s.contains('.') || frac_text.chars().any(|c| c.is_ascii_digit()));
    if !frac_ok {
        return Err(date_error(full, phrase!(WhySecondsAreNotNumber)));
    }
    if hour > 23 {
        return Err(date_error(full, format!("there is no hour {hour} (0–23)")));
    }
    if minute > 59 {
        return Err(date_error(full, format!("there is no minute {minute} (0–59)")));
    }
    if second > 59 {
        return Err(date_error(full, format!("there is no second {second} (0–59)")));
    }
    let ns = i128::from(hour) * NS_PER_H
        + i128::from(minute) * NS_PER_MIN
        + i128::from(second) * NS_PER_S
        + fraction_ns(frac_text, NS_PER_S);
    i64::try_from(ns).map_err(|_| date_error(full, phrase!(WhyOutOfRange)))
}

/// Microseconds in a day: DATE and DT count microseconds since 1970-01-01 (`values::arith`).
const US_PER_DAY: i64 = 86_400_000_000;

/// The microseconds since 1970-01-01 of a day's start, for days of the years 1 to 9999
/// (the range of IEC 61131-3's date literals, `D#0001-01-01` to `D#9999-12-31`).
fn days_to_us(full: &str, days: i64) -> LitResult<i64> {
    const FIRST: i64 = -719_162; // 0001-01-01
    const LAST: i64 = 2_932_896; // 9999-12-31
    if !(FIRST..=LAST).contains(&days) {
        return Err(date_error(full, phrase!(WhyDatesMustLieBetween000101)));
    }
    Ok(days * US_PER_DAY)
}

/// `D#2006-03-20` → microseconds since 1970-01-01.
pub(crate) fn parse_date(text: &str) -> LitResult<i64> {
    let days = date_days(text, after_hash(text))?;
    days_to_us(text, days)
}

/// `TOD#10:42:23.78` → nanoseconds since midnight.
pub(crate) fn parse_time_of_day(text: &str) -> LitResult<i64> {
    daytime_ns(text, after_hash(text))
}

/// `DT#2006-03-20-10:42:23.78` → microseconds since 1970-01-01 00:00 (digits of the
/// seconds past the microsecond are dropped).
pub(crate) fn parse_date_time(text: &str) -> LitResult<i64> {
    let body = after_hash(text);
    // The date has exactly two `-`; the third separates the time of day.
    let split = body.match_indices('-').nth(2).map(|(i, _)| i);
    let Some(split) = split else {
        return Err(date_error(text, phrase!(WhyWriteDateAndTimeAsDt20060320104223)));
    };
    let days = date_days(text, &body[..split])?;
    let tod = daytime_ns(text, &body[split + 1..])?;
    let us = days_to_us(text, days)?;
    Ok(us + tod / NS_PER_US as i64)
}

/// A parsed directly represented address: area, size and the dotted numbers.
pub(crate) type ParsedAddress = (AddressArea, AddressSize, Vec<u32>);

/// `%IX0.0`, `%QW4`, `%MD10`, `%I0.0`, `%I*` → area, size and path.
pub(crate) fn parse_direct_address(text: &str) -> LitResult<ParsedAddress> {
    let bad = |why: Arg| (Code::InvalidDirectAddress, msg!(InvalidAddress, text = text, why = why));
    let rest = text.strip_prefix('%').unwrap_or(text);
    let mut chars = rest.chars();
    let area = match chars.next().map(|c| c.to_ascii_uppercase()) {
        Some('I') => AddressArea::Input,
        Some('Q') => AddressArea::Output,
        Some('M') => AddressArea::Memory,
        _ => return Err(bad(phrase!(WhyItMustStartWithIQ).into())),
    };
    let rest = &rest[1..];
    let (size, rest) = match rest.chars().next().map(|c| c.to_ascii_uppercase()) {
        Some('X') => (AddressSize::Bit, &rest[1..]),
        Some('B') => (AddressSize::Byte, &rest[1..]),
        Some('W') => (AddressSize::Word, &rest[1..]),
        Some('D') => (AddressSize::DWord, &rest[1..]),
        Some('L') => (AddressSize::LWord, &rest[1..]),
        Some(c) if c.is_ascii_digit() || c == '*' => (AddressSize::Bit, rest),
        _ => return Err(bad(phrase!(WhySizeLetterMustBeXB).into())),
    };
    if rest == "*" {
        return Ok((area, size, Vec::new()));
    }
    let mut path = Vec::new();
    for part in rest.split('.') {
        if part.is_empty() || !part.chars().all(|c| c.is_ascii_digit()) {
            return Err(bad(phrase!(WhyWriteNumbersSeparatedByDotsAfter).into()));
        }
        path.push(part.parse::<u32>().map_err(|_| bad(phrase!(WhyNumberIsTooLarge2).into()))?);
    }
    Ok((area, size, path))
}

/// The bit number of a `.%X3` bit access (the text of the `%X3` token).
pub(crate) fn parse_bit_address(text: &str) -> Option<u32> {
    let rest = text.strip_prefix('%')?;
    let digits = rest.strip_prefix('X').or_else(|| rest.strip_prefix('x'))?;
    if digits.is_empty() || !digits.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// A partial access after a `.`: `%B1`, `%W0`, `%D1`, `%L0` → (width in bits, index).
pub(crate) fn parse_part_address(text: &str) -> Option<(u32, u32)> {
    let rest = text.strip_prefix('%')?;
    let mut chars = rest.chars();
    let width = match chars.next()?.to_ascii_uppercase() {
        'B' => 8,
        'W' => 16,
        'D' => 32,
        'L' => 64,
        _ => return None,
    };
    let digits = chars.as_str();
    if digits.is_empty() || !digits.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    Some((width, digits.parse().ok()?))
}

/// What kind of value a type prefix such as `DINT#` or `REAL#` accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum PrefixClass {
    /// Integer and bit-string types: an integer.
    Integer,
    /// REAL, LREAL: a real or an integer.
    Real,
    /// BOOL: `TRUE`, `FALSE`, `0`, `1`.
    Bool,
    /// STRING, CHAR: a `'…'` string.
    String,
    /// WSTRING, WCHAR: a `"…"` string.
    WString,
}

/// The class of a type prefix (any case), or `None` when the name is not an elementary type
/// that can prefix a literal (then `Name#Value` is an enumerator).
pub(crate) fn prefix_class(name: &str) -> Option<PrefixClass> {
    Some(match name.to_ascii_uppercase().as_str() {
        "SINT" | "INT" | "DINT" | "LINT" | "USINT" | "UINT" | "UDINT" | "ULINT" | "BYTE"
        | "WORD" | "DWORD" | "LWORD" => PrefixClass::Integer,
        "REAL" | "LREAL" => PrefixClass::Real,
        "BOOL" => PrefixClass::Bool,
        "STRING" | "CHAR" => PrefixClass::String,
        "WSTRING" | "WCHAR" => PrefixClass::WString,
        _ => return None,
    })
}

/// Converts `value` to what `prefix` (of class `class`) asks for, or explains why not.
pub(crate) fn apply_prefix(
    prefix: &str,
    class: PrefixClass,
    value: LiteralValue,
) -> LitResult<LiteralValue> {
    let mismatch = |what: Arg| {
        (Code::InvalidTypedLiteral, msg!(TypedLiteralNeeds, prefix = prefix, what = what))
    };
    match (class, value) {
        (PrefixClass::Integer, v @ LiteralValue::Int(_)) => Ok(v),
        (PrefixClass::Integer, _) => Err(mismatch(phrase!(WhatInteger).into())),
        (PrefixClass::Real, v @ LiteralValue::Real(_)) => Ok(v),
        (PrefixClass::Real, LiteralValue::Int(i)) => Ok(LiteralValue::Real(i as f64)),
        (PrefixClass::Real, _) => Err(mismatch(phrase!(WhatNumber).into())),
        (PrefixClass::Bool, v @ LiteralValue::Bool(_)) => Ok(v),
        (PrefixClass::Bool, LiteralValue::Int(0)) => Ok(LiteralValue::Bool(false)),
        (PrefixClass::Bool, LiteralValue::Int(1)) => Ok(LiteralValue::Bool(true)),
        (PrefixClass::Bool, _) => Err(mismatch(phrase!(WhatTrueFalse0Or1).into())),
        (PrefixClass::String, v @ LiteralValue::String(_)) => Ok(v),
        (PrefixClass::String, _) => Err(mismatch(phrase!(WhatStringInSingleQuotes).into())),
        (PrefixClass::WString, v @ LiteralValue::WString(_)) => Ok(v),
        (PrefixClass::WString, _) => Err(mismatch(phrase!(WhatStringInDoubleQuotes).into())),
    }
}

#[cfg(test)]
mod tests;
