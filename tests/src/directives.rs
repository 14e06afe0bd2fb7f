//! The `//!` header of a case file: how to run it and what must come out.
//!
//! ```text
//! //! program: Main                  PROGRAM to run (default: the only/first one)
//! //! cycles: 3                      scans to run (default 1)
//! //! cycle_ms: 100                  virtual ms per scan (default 10)
//! //! set: Start=TRUE                an IEC literal for a variable (repeatable)
//! //! expect: tmr.ET = "T#200ms"     PATH = JSON value (repeatable)
//! //! status: fault                  ok | fault | error (default: ok, or fault/error
//! //!                                when a fault_/error_ directive is present)
//! //! fault_line: 7                  line of the faulting statement
//! //! cycles_done: 2                 the report's `cycles` (scans completed)
//! //! error_code: E0100              some diagnostic has this code (repeatable)
//! //! error_line: 5                  some error diagnostic is on this line
//! //! error_count: 1                 exactly this many error diagnostics
//! //! error_message: MyVar           some diagnostic message contains this text (repeatable)
//! //! set_at: 3:Start=TRUE           SCAN:VAR=VALUE from that scan on (repeatable)
//! //! why: Motor @ 3                 explain VAR (or a Petri net place) at SCAN
//! //! why_value: true                the explained value (JSON)
//! //! why_written_by: kind=rung rung=1   fields of `written_by` (dotted: then.kind=…)
//! //! why_operand: Start = true since 3  an operand's value and since_scan (repeatable)
//! ```

use serde_json::Value;

/// The outcome a case expects from the run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ExpectedStatus {
    /// Every scan ran.
    #[default]
    Ok,
    /// A runtime fault stopped the PLC.
    Fault,
    /// The source did not compile.
    Error,
}

impl ExpectedStatus {
    /// The spelling used in directives and in the report's `status` field.
    pub fn as_str(self) -> &'static str {
        match self {
            ExpectedStatus::Ok => "ok",
            ExpectedStatus::Fault => "fault",
            ExpectedStatus::Error => "error",
        }
    }
}

/// One `expect: PATH = JSON` line.
#[derive(Debug, Clone, PartialEq)]
pub struct Expectation {
    /// The path into `vars`, e.g. `tmr.ET` or `arr[2]`.
    pub path: String,
    /// The expected JSON value.
    pub value: Value,
    /// The 1-based line of the directive in the case file.
    pub line: usize,
}

/// One `why_operand: NAME = JSON since N` line.
#[derive(Debug, Clone, PartialEq)]
pub struct WhyOperand {
    /// The operand's name.
    pub name: String,
    /// Its expected value.
    pub value: Value,
    /// Its expected `since_scan`.
    pub since: u64,
}

/// What a case asks `plc why` (the `why*` lines).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Why {
    /// The variable or place.
    pub var: String,
    /// The scan.
    pub scan: u64,
    /// `why_value:`.
    pub value: Option<Value>,
    /// `why_written_by:` pairs (dotted keys reach into `then`).
    pub written_by: Vec<(String, String)>,
    /// `why_operand:` lines.
    pub operands: Vec<WhyOperand>,
}

/// Everything the `//!` lines of a case say.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Directives {
    /// `program:` — the PROGRAM to run.
    pub program: Option<String>,
    /// `cycles:` — scans to run.
    pub cycles: Option<u64>,
    /// `cycle_ms:` — virtual milliseconds per scan.
    pub cycle_ms: Option<u64>,
    /// `set:` lines as `(variable, IEC literal)`.
    pub set: Vec<(String, String)>,
    /// `expect:` lines.
    pub expects: Vec<Expectation>,
    /// `status:` (or implied by fault_/error_ directives).
    pub status: ExpectedStatus,
    /// `fault_line:`.
    pub fault_line: Option<u64>,
    /// `cycles_done:`.
    pub cycles_done: Option<u64>,
    /// `error_code:` lines.
    pub error_codes: Vec<String>,
    /// `error_line:`.
    pub error_line: Option<u64>,
    /// `error_count:`.
    pub error_count: Option<u64>,
    /// `error_message:` lines (substrings).
    pub error_messages: Vec<String>,
    /// `set_at:` lines as `(scan, variable, IEC literal)`.
    pub set_at: Vec<(u64, String, String)>,
    /// `why:` and the lines that check its answer.
    pub why: Option<Why>,
}

/// Parses the `//!` lines of a case source. Lines may appear anywhere but by convention
/// form the header. Unknown keys and malformed values are errors, so a typo cannot
/// silently turn a check off.
pub fn parse_directives(source: &str) -> Result<Directives, String> {
    let mut d = Directives::default();
    let mut explicit_status = None;
    for (idx, raw) in source.lines().enumerate() {
        let line_no = idx + 1;
        let Some(rest) = raw.trim_start().strip_prefix("//!") else {
            continue;
        };
        let rest = rest.trim();
        if rest.is_empty() {
            continue;
        }
        let (key, value) = rest
            .split_once(':')
            .ok_or_else(|| format!("line {line_no}: directive without `key:` — {raw:?}"))?;
        let key = key.trim();
        let value = value.trim();
        let err = |what: &str| format!("line {line_no}: {what} in `{key}:` directive — {raw:?}");
        match key {
            "program" => d.program = Some(non_empty(value).ok_or_else(|| err("empty name"))?),
            "cycles" => d.cycles = Some(value.parse().map_err(|_| err("not a count"))?),
            "cycle_ms" => d.cycle_ms = Some(value.parse().map_err(|_| err("not a count"))?),
            "set" => {
                let (var, lit) = value.split_once('=').ok_or_else(|| err("expected VAR=VALUE"))?;
                let (var, lit) = (var.trim(), lit.trim());
                if var.is_empty() || lit.is_empty() {
                    return Err(err("expected VAR=VALUE"));
                }
                d.set.push((var.to_string(), lit.to_string()));
            }
            "expect" => {
                let (path, json) =
                    value.split_once('=').ok_or_else(|| err("expected PATH = JSON"))?;
                let path = path.trim();
                crate::path::parse_path(path).map_err(|e| err(&e))?;
                let value: Value = serde_json::from_str(json.trim())
                    .map_err(|e| err(&format!("bad JSON value ({e})")))?;
                d.expects.push(Expectation { path: path.to_string(), value, line: line_no });
            }
            "status" => {
                explicit_status = Some(match value {
                    "ok" => ExpectedStatus::Ok,
                    "fault" => ExpectedStatus::Fault,
                    "error" => ExpectedStatus::Error,
                    _ => return Err(err("expected ok, fault or error")),
                })
            }
            "fault_line" => d.fault_line = Some(value.parse().map_err(|_| err("not a line"))?),
            "cycles_done" => d.cycles_done = Some(value.parse().map_err(|_| err("not a count"))?),
            "error_code" => {
                let ok = value.len() == 5
                    && (value.starts_with('E') || value.starts_with('W'))
                    && value[1..].bytes().all(|b| b.is_ascii_digit());
                if !ok {
                    return Err(err("expected a code like E0100"));
                }
                d.error_codes.push(value.to_string());
            }
            "error_line" => d.error_line = Some(value.parse().map_err(|_| err("not a line"))?),
            "error_count" => d.error_count = Some(value.parse().map_err(|_| err("not a count"))?),
            "error_message" => {
                d.error_messages.push(non_empty(value).ok_or_else(|| err("empty text"))?)
            }
            "set_at" => d.set_at.push(plc_core::run::parse_set_at(value).map_err(|e| err(&e))?),
            "why" => {
                let (var, scan) =
                    value.split_once('@').ok_or_else(|| err("expected VAR @ SCAN"))?;
                let scan = scan.trim().parse().map_err(|_| err("not a scan"))?;
                let var = non_empty(var.trim()).ok_or_else(|| err("empty name"))?;
                let why = d.why.get_or_insert_with(Why::default);
                (why.var, why.scan) = (var, scan);
            }
            "why_value" => {
                let v = serde_json::from_str(value).map_err(|e| err(&format!("bad JSON ({e})")))?;
                d.why.get_or_insert_with(Why::default).value = Some(v);
            }
            "why_written_by" => {
                let why = d.why.get_or_insert_with(Why::default);
                for pair in value.split_whitespace() {
                    let (k, v) = pair.split_once('=').ok_or_else(|| err("expected key=value"))?;
                    why.written_by.push((k.to_string(), v.to_string()));
                }
            }
            "why_operand" => {
                let (name, rest) =
                    value.split_once('=').ok_or_else(|| err("expected NAME = JSON since N"))?;
                let (json, since) = rest
                    .rsplit_once(" since ")
                    .ok_or_else(|| err("expected NAME = JSON since N"))?;
                let value = serde_json::from_str(json.trim())
                    .map_err(|e| err(&format!("bad JSON value ({e})")))?;
                let since = since.trim().parse().map_err(|_| err("not a scan"))?;
                d.why.get_or_insert_with(Why::default).operands.push(WhyOperand {
                    name: name.trim().to_string(),
                    value,
                    since,
                });
            }
            _ => return Err(format!("line {line_no}: unknown directive `{key}` — {raw:?}")),
        }
    }

    if d.why.as_ref().is_some_and(|w| w.var.is_empty()) {
        return Err("why_ lines without a `why: VAR @ SCAN` line".to_string());
    }
    let wants_error = !d.error_codes.is_empty()
        || d.error_line.is_some()
        || d.error_count.is_some()
        || !d.error_messages.is_empty();
    let wants_fault = d.fault_line.is_some();
    if wants_error && wants_fault {
        return Err("both fault_ and error_ directives in one case".to_string());
    }
    let implied = if wants_error {
        Some(ExpectedStatus::Error)
    } else if wants_fault {
        Some(ExpectedStatus::Fault)
    } else {
        None
    };
    d.status = match (explicit_status, implied) {
        (Some(s), Some(i)) if s != i => {
            return Err(format!(
                "`status: {}` contradicts directives that imply `{}`",
                s.as_str(),
                i.as_str()
            ))
        }
        (Some(s), _) => s,
        (None, Some(i)) => i,
        (None, None) => ExpectedStatus::Ok,
    };
    Ok(d)
}

fn non_empty(s: &str) -> Option<String> {
    (!s.is_empty()).then(|| s.to_string())
}
