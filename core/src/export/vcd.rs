//! A trace as an IEEE 1364 Value Change Dump (opens in GTKWave).

use std::fmt::Write;

use crate::sim::Trace;
use crate::vm::Value;

/// How one traced variable is dumped.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    /// `wire 1`.
    Bit,
    /// `integer <width>` (two's complement).
    Int(u32),
    /// `real 64`.
    Real,
    /// Not dumpable (strings, dates, aggregates).
    Skip,
}

fn kind(v: &Value) -> Kind {
    match v {
        Value::Bool(_) => Kind::Bit,
        Value::Int(_, e) => Kind::Int(e.bits().clamp(8, 64)),
        Value::Enum { .. } => Kind::Int(32),
        Value::Time(_) => Kind::Int(64),
        Value::Real(..) => Kind::Real,
        _ => Kind::Skip,
    }
}

/// The short identifier of variable `n`: printable ASCII from `!`.
fn ident(mut n: usize) -> String {
    let mut s = String::new();
    loop {
        s.push(char::from(b'!' + (n % 94) as u8));
        n /= 94;
        if n == 0 {
            return s;
        }
        n -= 1;
    }
}

/// A reference name without characters VCD readers split on.
fn vcd_name(path: &str) -> String {
    path.chars()
        .map(|c| match c {
            '[' => '(',
            ']' => ')',
            ',' => '_',
            c if c.is_whitespace() => '_',
            c => c,
        })
        .collect()
}

fn push_change(out: &mut String, kind: Kind, v: &Value, id: &str) {
    match kind {
        Kind::Bit => {
            let on = matches!(v, Value::Bool(true));
            let _ = writeln!(out, "{}{id}", if on { '1' } else { '0' });
        }
        Kind::Int(width) => {
            let n: i128 = match v {
                Value::Int(i, _) => *i,
                Value::Enum { value, .. } => i128::from(*value),
                Value::Time(t) => i128::from(*t / 1_000_000),
                _ => 0,
            };
            let bits = if n >= 0 {
                format!("{n:b}")
            } else {
                let mask: u128 = if width >= 128 { u128::MAX } else { (1u128 << width) - 1 };
                format!("{:0w$b}", (n as u128) & mask, w = width as usize)
            };
            let _ = writeln!(out, "b{bits} {id}");
        }
        Kind::Real => {
            let f = match v {
                Value::Real(f, _) => *f,
                _ => 0.0,
            };
            let f = if f.is_finite() { f } else { 0.0 };
            let _ = writeln!(out, "r{f} {id}");
        }
        Kind::Skip => {}
    }
}

/// The largest of 1 ms, 1 µs and 1 ns that divides every sample time:
/// (nanoseconds per unit, unit text).
fn timescale(trace: &Trace) -> (i64, &'static str) {
    for (ns, text) in [(1_000_000, "1 ms"), (1_000, "1 us")] {
        if trace.samples().all(|s| s.time_ns % ns == 0) {
            return (ns, text);
        }
    }
    (1, "1 ns")
}

/// A trace as VCD: `$timescale 1 ms $end` (or µs/ns when the cycle needs it), BOOL as
/// `wire 1`, integers as `integer`, REAL/LREAL as `real 64`, TIME as an integer of
/// milliseconds; only value changes are written. Strings, dates and aggregates are left
/// out. `Elem` widths: SINT 8 … LINT 64.
pub fn trace_vcd(trace: &Trace) -> String {
    let paths: Vec<&str> = trace.paths().collect();
    let first = trace.samples().next();
    let kinds: Vec<Kind> = paths
        .iter()
        .enumerate()
        .map(|(i, _)| first.and_then(|s| s.values.get(i)).map_or(Kind::Skip, kind))
        .collect();
    let ids: Vec<String> = (0..paths.len()).map(ident).collect();
    let (unit, unit_text) = timescale(trace);
    let mut out = String::new();
    out.push_str("$version PLC trainer $end\n");
    let _ = writeln!(out, "$timescale {unit_text} $end");
    out.push_str("$scope module plc $end\n");
    for ((p, k), id) in paths.iter().zip(&kinds).zip(&ids) {
        let decl = match k {
            Kind::Bit => "wire 1".to_string(),
            Kind::Int(w) => format!("integer {w}"),
            Kind::Real => "real 64".to_string(),
            Kind::Skip => continue,
        };
        let _ = writeln!(out, "$var {decl} {id} {} $end", vcd_name(p));
    }
    out.push_str("$upscope $end\n$enddefinitions $end\n");
    let mut last: Vec<Option<&Value>> = vec![None; paths.len()];
    let mut last_time: Option<i64> = None;
    for s in trace.samples() {
        let t = s.time_ns / unit;
        if last_time.is_some_and(|lt| t < lt) {
            continue;
        }
        let mut body = String::new();
        for (i, v) in s.values.iter().enumerate() {
            let (Some(k), Some(id)) = (kinds.get(i), ids.get(i)) else { continue };
            if *k == Kind::Skip || last[i] == Some(v) {
                continue;
            }
            // A value of another kind (cannot happen within one trace) is skipped.
            if kind(v) != *k {
                continue;
            }
            push_change(&mut body, *k, v, id);
            last[i] = Some(v);
        }
        if body.is_empty() {
            continue;
        }
        if last_time.is_none() {
            let _ = writeln!(out, "#{t}\n$dumpvars");
            out.push_str(&body);
            out.push_str("$end\n");
        } else {
            let _ = writeln!(out, "#{t}");
            out.push_str(&body);
        }
        last_time = Some(t);
    }
    if let (Some(s), Some(lt)) = (trace.samples().last(), last_time) {
        let t = s.time_ns / unit;
        if t > lt {
            let _ = writeln!(out, "#{t}");
        }
    }
    out
}

#[cfg(test)]
pub(super) fn tests_ident(n: usize) -> String {
    ident(n)
}
