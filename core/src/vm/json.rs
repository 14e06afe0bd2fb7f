//! JSON rendering of values for the CLI (`plc run --json`), traces and the web UI:
//! BOOL → true/false, integers → numbers, REAL → its shortest f32 decimal, non-finite
//! reals → null, strings → JSON strings, TIME/DATE/TOD/DT → canonical literals,
//! enumerations → the enumerator's name, arrays → nested arrays, structs and FB instances
//! → objects.

use serde_json::{Map, Number, Value as Json};

use super::text::{format_date, format_dt, format_real, format_time, format_tod};
use super::value::Value;
use crate::semantic::types::Elem;

/// Renders `v` as JSON (see the module comment).
pub fn to_json(v: &Value) -> Json {
    match v {
        Value::Bool(b) => Json::Bool(*b),
        Value::Int(value, _) => {
            if let Ok(i) = i64::try_from(*value) {
                Json::Number(i.into())
            } else if let Ok(u) = u64::try_from(*value) {
                Json::Number(u.into())
            } else {
                Json::String(value.to_string())
            }
        }
        Value::Real(value, elem) => real(*value, *elem),
        Value::Str(b) => Json::String(decode_bytes(b)),
        Value::WStr(u) => Json::String(String::from_utf16_lossy(u)),
        Value::Time(t) => Json::String(format_time(*t)),
        Value::Date(t) => Json::String(format_date(*t)),
        Value::Tod(t) => Json::String(format_tod(*t)),
        Value::Dt(t) => Json::String(format_dt(*t)),
        Value::Enum { value, name } => match name {
            Some(n) => Json::String(n.clone()),
            None => Json::Number((*value).into()),
        },
        Value::Ref(None) => Json::String("NULL".into()),
        Value::Ref(Some(path)) => Json::String(format!("REF({path})")),
        Value::Array(items) => Json::Array(items.iter().map(to_json).collect()),
        Value::Struct(fields) => {
            let mut m = Map::new();
            for (name, x) in fields {
                m.insert(name.clone(), to_json(x));
            }
            Json::Object(m)
        }
    }
}

/// A real as a JSON number: REAL by its shortest f32 text (0.1, not 0.10000000149).
fn real(f: f64, elem: Elem) -> Json {
    if !f.is_finite() {
        return Json::Null;
    }
    let shown =
        if elem == Elem::Real { format_real(Elem::Real, f).parse::<f64>().unwrap_or(f) } else { f };
    Number::from_f64(shown).map_or(Json::Null, Json::Number)
}

/// STRING bytes as text: UTF-8 where valid, other bytes as Latin-1.
pub fn decode_bytes(b: &[u8]) -> String {
    match std::str::from_utf8(b) {
        Ok(s) => s.to_string(),
        Err(_) => {
            let mut out = String::with_capacity(b.len());
            let mut rest = b;
            while !rest.is_empty() {
                match std::str::from_utf8(rest) {
                    Ok(s) => {
                        out.push_str(s);
                        break;
                    }
                    Err(e) => {
                        let (good, bad) = rest.split_at(e.valid_up_to());
                        out.push_str(std::str::from_utf8(good).unwrap_or_default());
                        let n = e.error_len().unwrap_or(bad.len()).max(1);
                        out.extend(bad[..n].iter().map(|&c| char::from(c)));
                        rest = &bad[n..];
                    }
                }
            }
            out
        }
    }
}
