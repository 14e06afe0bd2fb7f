//! The conformance suite of the ST engine.
//!
//! Every case is a complete ST program under `tests/conformance/cases/<group>/<name>.st`
//! whose `//!` header says how to run it and what must come out (see [`directives`] for the
//! format). `build.rs` embeds all of them, so the same list runs natively
//! (`tests/conformance.rs`) and in wasm32 under Node (`tests/wasm_conformance.rs`), and
//! the wasm run must produce the very same report JSON as the native one.
//!
//! Everything goes through [`plc_core::run::run_source`], the function behind
//! `plc run --json`, so the suite checks exactly what the CLI prints. A case may also be a
//! project file (`<name>.plcproj.json`, for ladder and Petri net POUs) whose ST source
//! holds the `//!` lines; it runs through [`plc_core::run::run_project`]. A case with a
//! `why:` line runs recorded and its report gets the explanation (`plc why --json`) under
//! `why`.

#![deny(missing_docs)]

pub mod directives;
pub mod fuzz;
pub mod hostile;
pub mod path;

#[cfg(test)]
mod tests;

pub use directives::{parse_directives, Directives, Expectation, ExpectedStatus, Why, WhyOperand};
pub use path::{lookup, values_match};

use plc_core::project::Project;
use plc_core::run::{run_project_kept, run_source, RunOptions};
use serde_json::{Map, Value};

include!(concat!(env!("OUT_DIR"), "/cases.rs"));

/// One conformance case: its name, its source and what its header asks for.
#[derive(Debug, Clone)]
pub struct Case {
    /// `group/name`, the path below `conformance/cases` without `.st`.
    pub name: String,
    /// The whole source file, header included (a project file's JSON).
    pub source: &'static str,
    /// The project, for a project file.
    pub project: Option<Project>,
    /// The parsed `//!` directives (defaults when they did not parse).
    pub directives: Directives,
    /// Why the directives did not parse, if they did not; such a case always fails.
    pub directive_error: Option<String>,
}

impl Case {
    /// Builds a case from its name and source, parsing the directives.
    pub fn new(name: &str, source: &'static str) -> Case {
        Case::of(name, source, None)
    }

    /// A case from a project file: its directives are in the project's ST source.
    pub fn project(name: &str, json: &'static str) -> Case {
        match Project::from_file(json) {
            Ok(p) => Case::of(name, json, Some(p)),
            Err(e) => {
                let mut case = Case::of(name, "", None);
                case.directive_error = Some(format!("not a project file: {e}"));
                case
            }
        }
    }

    fn of(name: &str, source: &'static str, project: Option<Project>) -> Case {
        let header = project.as_ref().map_or(source, |p| p.source.as_str());
        let (directives, directive_error) = match parse_directives(header) {
            Ok(d) => (d, None),
            Err(e) => (Directives::default(), Some(e)),
        };
        Case { name: name.to_string(), source, project, directives, directive_error }
    }

    /// The options the case runs with: its directives over `RunOptions::default()`.
    pub fn options(&self) -> RunOptions {
        let d = &self.directives;
        let defaults = RunOptions::default();
        RunOptions {
            program: d.program.clone(),
            cycle_ms: d.cycle_ms.unwrap_or(defaults.cycle_ms),
            set: d.set.clone(),
            set_at: d.set_at.clone(),
            // A `why` about scan N needs N scans.
            cycles: d.cycles.unwrap_or(defaults.cycles).max(d.why.as_ref().map_or(0, |w| w.scan)),
            ..defaults
        }
    }
}

/// Every embedded case, sorted by name.
pub fn cases() -> Vec<Case> {
    CASE_FILES
        .iter()
        .map(|(name, source)| match name.strip_suffix(".plcproj") {
            Some(stem) => Case::project(stem, source),
            None => Case::new(name, source),
        })
        .collect()
}

/// Runs one case through [`run_source`] (or, for a project file or a `why:` line,
/// [`plc_core::run::run_project`]) and returns the report JSON.
pub fn run_case(case: &Case) -> Value {
    let options = case.options();
    let Some(why) = &case.directives.why else {
        return match &case.project {
            Some(p) => plc_core::run::run_project(p, &options).to_json(),
            None => run_source(case.source, &options).to_json(),
        };
    };
    let project = case.project.clone().unwrap_or_else(|| {
        let mut p = Project::new("case");
        p.source = case.source.to_string();
        p.ladder.clear();
        p
    });
    let kept = run_project_kept(&project, &RunOptions { record: true, ..options });
    let mut report = kept.report.to_json();
    let answer = match &kept.sim {
        Some(sim) => {
            let ctx = plc_core::why::Context::new(&project, &kept.build);
            match plc_core::why::explain(&ctx, sim, &why.var, why.scan) {
                Err(plc_core::why::WhyError::Unknown(_)) => {
                    plc_core::why::explain_place(&ctx, sim, &why.var, why.scan)
                }
                other => other,
            }
            .map(|e| e.to_json())
            .unwrap_or_else(|e| serde_json::json!({ "error": e.to_string() }))
        }
        None => serde_json::json!({ "error": "the program did not run" }),
    };
    if let Value::Object(map) = &mut report {
        map.insert("why".to_string(), answer);
    }
    report
}

/// Checks a report against the case's directives. `Err` lists every mismatch, one per
/// line, each naming the case.
pub fn check_case(case: &Case, report: &Value) -> Result<(), String> {
    let mut problems = Vec::new();
    if let Some(e) = &case.directive_error {
        problems.push(format!("bad directives: {e}"));
    }
    let d = &case.directives;

    let status = report.get("status").and_then(Value::as_str).unwrap_or("<missing>");
    if status != d.status.as_str() {
        problems.push(format!(
            "status: expected {}, got {status}{}",
            d.status.as_str(),
            explain(report)
        ));
    }

    if let Some(line) = d.fault_line {
        let actual = report.pointer("/fault/line").and_then(Value::as_u64);
        if actual != Some(line) {
            problems.push(format!(
                "fault line: expected {line}, got {}",
                actual.map_or("none".to_string(), |l| l.to_string())
            ));
        }
    }
    if let Some(n) = d.cycles_done {
        let actual = report.get("cycles").and_then(Value::as_u64);
        if actual != Some(n) {
            problems.push(format!("cycles done: expected {n}, got {actual:?}"));
        }
    }

    let diags: &[Value] =
        report.get("diagnostics").and_then(Value::as_array).map_or(&[], Vec::as_slice);
    let errors: Vec<&Value> = diags
        .iter()
        .filter(|x| x.get("severity").and_then(Value::as_str) == Some("error"))
        .collect();
    for code in &d.error_codes {
        if !diags.iter().any(|x| x.get("code").and_then(Value::as_str) == Some(code)) {
            problems.push(format!("no diagnostic with code {code}; got {}", list_diags(diags)));
        }
    }
    if let Some(line) = d.error_line {
        if !errors.iter().any(|x| x.get("line").and_then(Value::as_u64) == Some(line)) {
            problems.push(format!("no error on line {line}; got {}", list_diags(diags)));
        }
    }
    if let Some(n) = d.error_count {
        if errors.len() as u64 != n {
            problems.push(format!(
                "expected {n} error diagnostic(s), got {}: {}",
                errors.len(),
                list_diags(diags)
            ));
        }
    }
    for text in &d.error_messages {
        let found = diags.iter().any(|x| {
            x.get("message").and_then(Value::as_str).is_some_and(|m| m.contains(text.as_str()))
        });
        if !found {
            problems.push(format!(
                "no diagnostic message contains {text:?}; got {}",
                list_diags(diags)
            ));
        }
    }

    if let Some(why) = &d.why {
        check_why(why, report.get("why").unwrap_or(&Value::Null), &mut problems);
    }

    let vars = report.get("vars").cloned().unwrap_or(Value::Null);
    for exp in &d.expects {
        match lookup(&vars, &exp.path) {
            Ok(actual) if values_match(&exp.value, actual) => {}
            Ok(actual) => problems.push(format!(
                "{} (line {}): expected {}, got {}",
                exp.path,
                exp.line,
                path::short(&exp.value),
                path::short(actual)
            )),
            Err(why) => problems.push(format!(
                "{} (line {}): expected {}, but {why}",
                exp.path,
                exp.line,
                path::short(&exp.value)
            )),
        }
    }

    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.iter().map(|p| format!("[{}] {p}", case.name)).collect::<Vec<_>>().join("\n"))
    }
}

/// Checks the explanation of a `why:` case against its `why_` lines.
fn check_why(why: &Why, answer: &Value, problems: &mut Vec<String>) {
    let at = format!("why {} @ {}", why.var, why.scan);
    if let Some(e) = answer.get("error") {
        problems.push(format!("{at}: {}", path::short(e)));
        return;
    }
    if let Some(v) = &why.value {
        if answer.get("value") != Some(v) {
            problems.push(format!(
                "{at}: value {}, expected {}",
                path::short(&answer["value"]),
                path::short(v)
            ));
        }
    }
    for (key, want) in &why.written_by {
        let mut got = &answer["written_by"];
        for part in key.split('.') {
            got = &got[part];
        }
        let text = match got {
            Value::String(s) => s.clone(),
            Value::Null => "<none>".to_string(),
            other => other.to_string(),
        };
        if text != *want {
            problems.push(format!(
                "{at}: written_by.{key} is {text}, expected {want} (written_by: {})",
                path::short(&answer["written_by"])
            ));
        }
    }
    let ops: &[Value] = answer.get("operands").and_then(Value::as_array).map_or(&[], Vec::as_slice);
    for o in &why.operands {
        match ops.iter().find(|x| x["name"] == o.name.as_str()) {
            None => problems.push(format!(
                "{at}: no operand {}; operands: {}",
                o.name,
                path::short(&answer["operands"])
            )),
            Some(x) => {
                if !values_match(&o.value, &x["value"]) || x["since_scan"].as_u64() != Some(o.since)
                {
                    problems.push(format!(
                        "{at}: operand {} is {} since {}, expected {} since {}",
                        o.name,
                        path::short(&x["value"]),
                        x["since_scan"],
                        path::short(&o.value),
                        o.since
                    ));
                }
            }
        }
    }
}

/// Runs every case and checks it: returns every report by case name and one failure
/// message per failing case. Natively each case runs on its own thread, so an engine panic
/// or a hang fails that case only.
pub fn run_all() -> (Map<String, Value>, Vec<String>) {
    run_matching("")
}

/// Like [`run_all`], limited to cases whose name contains `filter` (`""` runs all).
pub fn run_matching(filter: &str) -> (Map<String, Value>, Vec<String>) {
    let mut results = Map::new();
    let mut failures = Vec::new();
    for case in cases().into_iter().filter(|c| c.name.contains(filter)) {
        let report = match guarded_run(&case) {
            Ok(report) => report,
            Err(why) => {
                failures.push(format!("[{}] {why}", case.name));
                results.insert(
                    case.name.clone(),
                    serde_json::json!({ "status": "crash", "why": why }),
                );
                continue;
            }
        };
        if let Err(msg) = check_case(&case, &report) {
            failures.push(msg);
        }
        results.insert(case.name.clone(), report);
    }
    (results, failures)
}

/// Seconds a native case may take before it counts as hung.
#[cfg(not(target_arch = "wasm32"))]
pub const CASE_TIMEOUT_SECS: u64 = 60;

#[cfg(not(target_arch = "wasm32"))]
fn guarded_run(case: &Case) -> Result<Value, String> {
    use std::sync::mpsc;
    use std::time::Duration;
    let (tx, rx) = mpsc::channel();
    let owned = case.clone();
    let spawned = std::thread::Builder::new()
        .name(case.name.clone())
        .stack_size(32 * 1024 * 1024)
        .spawn(move || {
            let _ = tx.send(run_case(&owned));
        });
    if let Err(e) = spawned {
        return Err(format!("could not start a thread: {e}"));
    }
    match rx.recv_timeout(Duration::from_secs(CASE_TIMEOUT_SECS)) {
        Ok(report) => Ok(report),
        Err(mpsc::RecvTimeoutError::Timeout) => {
            Err(format!("engine did not return within {CASE_TIMEOUT_SECS} s (hang?)"))
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => Err("engine panicked".to_string()),
    }
}

#[cfg(target_arch = "wasm32")]
fn guarded_run(case: &Case) -> Result<Value, String> {
    Ok(run_case(case))
}

fn explain(report: &Value) -> String {
    let mut s = String::new();
    if let Some(f) = report.get("fault").filter(|f| !f.is_null()) {
        s.push_str(&format!(" (fault: {})", path::short(f)));
    }
    let diags = report.get("diagnostics").and_then(Value::as_array);
    if let Some(d) = diags.filter(|d| !d.is_empty()) {
        s.push_str(&format!(" (diagnostics: {})", list_diags(d)));
    }
    s
}

fn list_diags(diags: &[Value]) -> String {
    if diags.is_empty() {
        return "no diagnostics".to_string();
    }
    diags
        .iter()
        .map(|x| {
            let get = |k: &str| {
                x.get(k).map_or(String::new(), |v| match v {
                    Value::String(s) => s.clone(),
                    other => other.to_string(),
                })
            };
            format!(
                "{} {} at {}:{} {:?}",
                get("severity"),
                get("code"),
                get("line"),
                get("column"),
                get("message")
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// Where the native suite writes its reports and the wasm suite reads them:
/// `$PLC_NATIVE_RESULTS` when set (at run time natively, at compile time in wasm),
/// else `<workspace>/target/conformance/native.json`.
pub fn native_results_path() -> String {
    #[cfg(not(target_arch = "wasm32"))]
    if let Ok(p) = std::env::var("PLC_NATIVE_RESULTS") {
        if !p.is_empty() {
            return p;
        }
    }
    match option_env!("PLC_NATIVE_RESULTS") {
        Some(p) if !p.is_empty() => p.to_string(),
        _ => format!("{}/../target/conformance/native.json", env!("CARGO_MANIFEST_DIR")),
    }
}
