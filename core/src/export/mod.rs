//! Values as text for the UI and files for download: the IEC literal of a value, the
//! children of an aggregate (for an expandable variables table), a CSV snapshot of every
//! variable, a trace as CSV or as an IEEE 1364 VCD file (for GTKWave), and ZIP archives
//! (an exercise's SCORM package).
//!
//! Everything here is pure: it reads a [`Simulator`](crate::sim::Simulator) or a
//! [`Trace`](crate::sim::Trace) and returns text, so it is tested natively.

mod browse;
mod csv;
#[cfg(test)]
mod tests;
mod vcd;
mod zip;

pub use browse::{children, is_expandable, snapshot, Child, SnapshotRow, MAX_CHILDREN};
pub use csv::{csv_field, trace_csv, variables_csv};
pub use vcd::trace_vcd;
pub use zip::{crc32, zip, ZipError};

use std::fmt::Write;

use crate::vm::{
    decode_bytes, format_date, format_dt, format_real, format_time, format_tod, Value,
};

/// The IEC literal of a value (`TRUE`, `42`, `1.5`, `T#1s500ms`, `'text'`, `Red`);
/// aggregates as `[1, 2]` and `(a := 1, b := TRUE)`. Scalars read back with
/// `Simulator::write`.
pub fn value_text(v: &Value) -> String {
    let mut out = String::new();
    push_value(&mut out, v);
    out
}

fn push_value(out: &mut String, v: &Value) {
    match v {
        Value::Bool(b) => out.push_str(if *b { "TRUE" } else { "FALSE" }),
        Value::Int(i, _) => {
            let _ = write!(out, "{i}");
        }
        Value::Real(f, e) => out.push_str(&format_real(*e, *f)),
        Value::Str(b) => push_quoted(out, &decode_bytes(b), '\''),
        Value::WStr(u) => push_quoted(out, &String::from_utf16_lossy(u), '"'),
        Value::Time(t) => out.push_str(&format_time(*t)),
        Value::Date(t) => out.push_str(&format_date(*t)),
        Value::Tod(t) => out.push_str(&format_tod(*t)),
        Value::Dt(t) => out.push_str(&format_dt(*t)),
        Value::Enum { value, name } => match name {
            Some(n) => out.push_str(n),
            None => {
                let _ = write!(out, "{value}");
            }
        },
        Value::Ref(None) => out.push_str("NULL"),
        Value::Ref(Some(path)) => {
            let _ = write!(out, "REF({path})");
        }
        Value::Array(items) => {
            out.push('[');
            for (k, x) in items.iter().enumerate() {
                if k > 0 {
                    out.push_str(", ");
                }
                push_value(out, x);
            }
            out.push(']');
        }
        Value::Struct(fields) => {
            out.push('(');
            for (k, (name, x)) in fields.iter().enumerate() {
                if k > 0 {
                    out.push_str(", ");
                }
                out.push_str(name);
                out.push_str(" := ");
                push_value(out, x);
            }
            out.push(')');
        }
    }
}

/// A string literal with `$` escapes.
fn push_quoted(out: &mut String, s: &str, quote: char) {
    out.push(quote);
    for c in s.chars() {
        match c {
            '$' => out.push_str("$$"),
            '\n' => out.push_str("$N"),
            '\r' => out.push_str("$R"),
            '\t' => out.push_str("$T"),
            '\x0c' => out.push_str("$P"),
            c if c == quote => {
                out.push('$');
                out.push(c);
            }
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "${:02X}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push(quote);
}

/// A value as a number for charts: BOOL as 0/1, integers and reals as themselves,
/// enumerations by value, TIME in milliseconds. `None` for strings, dates and aggregates.
pub fn value_number(v: &Value) -> Option<f64> {
    match v {
        Value::Bool(b) => Some(if *b { 1.0 } else { 0.0 }),
        Value::Int(i, _) => Some(*i as f64),
        Value::Real(f, _) => Some(*f),
        Value::Time(t) => Some(*t as f64 / 1e6),
        Value::Enum { value, .. } => Some(*value as f64),
        _ => None,
    }
}

/// Nanoseconds as milliseconds text without trailing zeros (`10`, `2.5`, `0.001`).
pub fn ms_text(ns: i64) -> String {
    let whole = ns / 1_000_000;
    let frac = (ns % 1_000_000).unsigned_abs();
    if frac == 0 {
        return whole.to_string();
    }
    let sign = if ns < 0 && whole == 0 { "-" } else { "" };
    let digits = format!("{frac:06}");
    format!("{sign}{whole}.{}", digits.trim_end_matches('0'))
}
