//! Paths into a report's `vars` (`tmr.ET`, `arr[2]`, `grid[1][0].x`) and the comparison of
//! an expected JSON value with an actual one.

use serde_json::Value;

/// One step of a path after the variable name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// `.field` — a struct or FB member.
    Field(String),
    /// `[n]` — a 0-based index into the JSON array (not the declared IEC index).
    Index(usize),
}

/// Splits `name(.field|[index])*` into the variable name and the steps after it.
pub fn parse_path(path: &str) -> Result<(String, Vec<Step>), String> {
    let bad = |why: &str| format!("bad path `{path}`: {why}");
    let ident_end = |s: &str| {
        s.char_indices()
            .find(|&(_, c)| !(c.is_alphanumeric() || c == '_' || c == '%'))
            .map_or(s.len(), |(i, _)| i)
    };
    let end = ident_end(path);
    if end == 0 {
        return Err(bad("missing variable name"));
    }
    let name = path[..end].to_string();
    let mut rest = &path[end..];
    let mut steps = Vec::new();
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('.') {
            let end = ident_end(r);
            if end == 0 {
                return Err(bad("missing field name after `.`"));
            }
            steps.push(Step::Field(r[..end].to_string()));
            rest = &r[end..];
        } else if let Some(r) = rest.strip_prefix('[') {
            let close = r.find(']').ok_or_else(|| bad("unclosed `[`"))?;
            let index = r[..close]
                .trim()
                .parse()
                .map_err(|_| bad("an index must be a non-negative JSON array index"))?;
            steps.push(Step::Index(index));
            rest = &r[close + 1..];
        } else {
            return Err(bad("expected `.field` or `[index]`"));
        }
    }
    Ok((name, steps))
}

/// Looks `path` up in the `vars` object of a report. Names match exactly (the report uses
/// the spelling of the declaration).
pub fn lookup<'a>(vars: &'a Value, path: &str) -> Result<&'a Value, String> {
    let (name, steps) = parse_path(path)?;
    let mut cur = vars
        .get(&name)
        .ok_or_else(|| format!("no variable `{name}` in vars (has: {})", keys(vars)))?;
    let mut walked = name;
    for step in steps {
        match step {
            Step::Field(f) => {
                cur = cur
                    .get(&f)
                    .ok_or_else(|| format!("`{walked}` has no field `{f}` (has: {})", keys(cur)))?;
                walked.push('.');
                walked.push_str(&f);
            }
            Step::Index(i) => {
                let arr = cur
                    .as_array()
                    .ok_or_else(|| format!("`{walked}` is not an array: {}", short(cur)))?;
                cur = arr
                    .get(i)
                    .ok_or_else(|| format!("`{walked}` has {} elements, no [{i}]", arr.len()))?;
                walked.push_str(&format!("[{i}]"));
            }
        }
    }
    Ok(cur)
}

/// Whether `actual` matches `expected`: integers exactly, numbers written with a fraction
/// or exponent (reals) within a relative 1e-6 (exactly when zero is expected), arrays
/// element by element, objects with the same keys, everything else by equality.
pub fn values_match(expected: &Value, actual: &Value) -> bool {
    match (expected, actual) {
        (Value::Number(e), Value::Number(a)) => {
            if e.is_f64() {
                let (e, a) = (e.as_f64().unwrap_or(f64::NAN), a.as_f64().unwrap_or(f64::NAN));
                if e == 0.0 {
                    a.abs() <= 1e-12
                } else {
                    (a - e).abs() <= 1e-6 * e.abs()
                }
            } else if let (Some(e), Some(a)) = (e.as_i64(), a.as_i64()) {
                e == a
            } else if let (Some(e), Some(a)) = (e.as_u64(), a.as_u64()) {
                e == a
            } else {
                // An integer expected, a real rendered: equal only if exactly the same value.
                e.as_f64() == a.as_f64() && a.as_f64().is_some_and(|a| a.fract() == 0.0)
            }
        }
        (Value::Array(e), Value::Array(a)) => {
            e.len() == a.len() && e.iter().zip(a).all(|(e, a)| values_match(e, a))
        }
        (Value::Object(e), Value::Object(a)) => {
            e.len() == a.len()
                && e.iter().all(|(k, ev)| a.get(k).is_some_and(|av| values_match(ev, av)))
        }
        _ => expected == actual,
    }
}

/// A value shortened for messages.
pub fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 300 {
        let cut: String = s.chars().take(300).collect();
        format!("{cut}…")
    } else {
        s
    }
}

fn keys(v: &Value) -> String {
    match v.as_object() {
        Some(o) if o.is_empty() => "nothing".to_string(),
        Some(o) => o.keys().cloned().collect::<Vec<_>>().join(", "),
        None => format!("not an object: {}", short(v)),
    }
}

/// Where two JSON values first differ, as `path: a vs b` (empty when they are equal).
pub fn first_difference(a: &Value, b: &Value) -> String {
    fn walk(a: &Value, b: &Value, at: &str) -> Option<String> {
        match (a, b) {
            (Value::Object(x), Value::Object(y)) => {
                for (k, va) in x {
                    match y.get(k) {
                        Some(vb) => {
                            if let Some(d) = walk(va, vb, &format!("{at}.{k}")) {
                                return Some(d);
                            }
                        }
                        None => return Some(format!("{at}.{k}: {} vs missing", short(va))),
                    }
                }
                y.keys()
                    .find(|k| !x.contains_key(*k))
                    .map(|k| format!("{at}.{k}: missing vs {}", short(&y[k])))
            }
            (Value::Array(x), Value::Array(y)) if x.len() == y.len() => x
                .iter()
                .zip(y)
                .enumerate()
                .find_map(|(i, (va, vb))| walk(va, vb, &format!("{at}[{i}]"))),
            _ if a == b => None,
            _ => Some(format!("{at}: {} vs {}", short(a), short(b))),
        }
    }
    walk(a, b, "").unwrap_or_default()
}
