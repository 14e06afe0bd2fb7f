//! CSV (RFC 4180) files: a variables snapshot and a trace.

use crate::sim::Trace;

use super::{ms_text, value_number, value_text, SnapshotRow};

/// One CSV field, quoted when it holds a comma, a quote or a line break.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A snapshot as CSV: `name,address,type,value`, one row per scalar.
pub fn variables_csv(rows: &[SnapshotRow]) -> String {
    let mut out = String::from("name,address,type,value\r\n");
    for r in rows {
        let fields = [&r.path, &r.address, &r.ty, &r.value];
        let line: Vec<String> = fields.iter().map(|f| csv_field(f)).collect();
        out.push_str(&line.join(","));
        out.push_str("\r\n");
    }
    out
}

/// A trace as CSV: `time_ms,scan,<path>…`, one row per sample; BOOL as 0/1, numbers as
/// numbers, other values as IEC literals.
pub fn trace_csv(trace: &Trace) -> String {
    let mut out = String::from("time_ms,scan");
    for p in trace.paths() {
        out.push(',');
        out.push_str(&csv_field(p));
    }
    out.push_str("\r\n");
    for s in trace.samples() {
        out.push_str(&ms_text(s.time_ns));
        out.push(',');
        out.push_str(&s.scan.to_string());
        for v in &s.values {
            out.push(',');
            let text = match v {
                crate::vm::Value::Time(_) => value_text(v),
                _ => value_number(v).map_or_else(|| value_text(v), |n| n.to_string()),
            };
            out.push_str(&csv_field(&text));
        }
        out.push_str("\r\n");
    }
    out
}
