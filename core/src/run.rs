//! One-shot runs: compile a source text, run N scans, and report in the JSON shape that
//! `plc run --json` prints. The CLI, the conformance suite and the wasm tests all go
//! through here, so they cannot disagree.

use serde::Serialize;
use serde_json::Value as Json;

use crate::diagnostics::{Code, Diagnostic, LineIndex, Severity};
use crate::semantic;
use crate::sim::{ScanOutcome, SimError, Simulator};
use crate::syntax::PouKind;

/// What to run and how.
#[derive(Debug, Clone)]
pub struct RunOptions {
    /// The PROGRAM to run; `None` runs the only (or first) one.
    pub program: Option<String>,
    /// How many scans to run.
    pub cycles: u64,
    /// Virtual milliseconds added to the clock after each scan.
    pub cycle_ms: u64,
    /// `VAR=VALUE` settings, values written as IEC literals. An input (VAR_INPUT or `%I`)
    /// is held at the value on every scan; any other variable is set before the first scan.
    pub set: Vec<(String, String)>,
}

impl Default for RunOptions {
    fn default() -> Self {
        RunOptions { program: None, cycles: 1, cycle_ms: 10, set: Vec::new() }
    }
}

/// The overall outcome of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum RunStatus {
    /// Every scan ran.
    Ok,
    /// A runtime fault stopped the PLC.
    Fault,
    /// The program did not compile, or the options were wrong.
    Error,
}

/// Where and why the PLC stopped.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FaultReport {
    /// What went wrong, for a student.
    pub message: String,
    /// 1-based source line of the faulting statement.
    pub line: u32,
    /// 1-based column.
    pub column: u32,
}

/// One diagnostic as reported in JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DiagnosticReport {
    /// `"error"` or `"warning"`.
    pub severity: crate::diagnostics::Severity,
    /// The stable code (`E0042`).
    pub code: String,
    /// The message.
    pub message: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column.
    pub column: u32,
}

/// The result of [`run_source`], serialising to exactly the `plc run --json` object:
/// `{"status","cycles","vars","fault","diagnostics"}`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunReport {
    /// ok, fault or error.
    pub status: RunStatus,
    /// Scans completed (a faulting scan is not counted).
    pub cycles: u64,
    /// Every variable of the program instance by declared name.
    pub vars: serde_json::Map<String, Json>,
    /// The fault, when status is fault.
    pub fault: Option<FaultReport>,
    /// Diagnostics from compiling (warnings included), and option errors.
    pub diagnostics: Vec<DiagnosticReport>,
}

impl RunReport {
    /// The report as a JSON value.
    pub fn to_json(&self) -> Json {
        serde_json::to_value(self).unwrap_or(Json::Null)
    }
}

fn diagnostic_report(index: &LineIndex<'_>, d: &Diagnostic) -> DiagnosticReport {
    let loc = index.location(d.span.start);
    DiagnosticReport {
        severity: d.severity,
        code: d.code.as_str().to_string(),
        message: d.message.clone(),
        line: loc.line,
        column: loc.column,
    }
}

fn option_error(code: Code, message: String) -> DiagnosticReport {
    DiagnosticReport {
        severity: Severity::Error,
        code: code.as_str().to_string(),
        message,
        line: 0,
        column: 0,
    }
}

/// Whether `name` is a hidden variable that a front-end generated (ladder power flow and
/// edge memories, Petri-net scan copies, SFC bookkeeping): kept out of reports and of the
/// variable table, but readable by name for the views that need them.
pub fn is_generated_variable(name: &str) -> bool {
    crate::ladder::is_hidden_name(name)
        || crate::petri::is_hidden_name(name)
        || crate::sfc::is_hidden_name(name)
}

/// The program instance's variables as JSON, without the generated ones.
fn visible_vars(sim: &Simulator) -> serde_json::Map<String, Json> {
    let mut vars = sim.vars_json();
    vars.retain(|k, _| !is_generated_variable(k));
    vars
}

/// Compiles and runs `source` as `plc run` does.
pub fn run_source(source: &str, options: &RunOptions) -> RunReport {
    let index = LineIndex::new(source);
    let analysis = semantic::analyze(source);
    let mut report = RunReport {
        status: RunStatus::Error,
        cycles: 0,
        vars: serde_json::Map::new(),
        fault: None,
        diagnostics: analysis.diagnostics.iter().map(|d| diagnostic_report(&index, d)).collect(),
    };
    let Some(program) = analysis.program else { return report };
    let main = match &options.program {
        Some(name) => {
            match program.find_pou(name).filter(|&p| program.pou(p).kind == PouKind::Program) {
                Some(p) => p,
                None => {
                    let msg = format!("there is no PROGRAM `{name}` in the source");
                    report.diagnostics.push(option_error(Code::UnknownProgram, msg));
                    return report;
                }
            }
        }
        None => match program.programs().find(|&p| !program.pou(p).library) {
            Some(p) => p,
            None => {
                let msg = "the source holds no PROGRAM to run".to_string();
                report.diagnostics.push(option_error(Code::NoProgram, msg));
                return report;
            }
        },
    };
    let mut sim = match Simulator::new(program, main) {
        Ok(sim) => sim,
        Err(e) => {
            report.diagnostics.push(option_error(Code::ProgramTooLarge, e.to_string()));
            return report;
        }
    };
    sim.set_cycle_ns((options.cycle_ms as i64).saturating_mul(1_000_000));
    for (name, value) in &options.set {
        let is_input = sim
            .executable()
            .main_vars()
            .iter()
            .any(|v| v.var.name.eq_ignore_ascii_case(name) && v.var.is_input());
        let result = if is_input { sim.hold(name, value) } else { sim.write(name, value) };
        if let Err(e) = result {
            let code = match e {
                SimError::UnknownVariable(_) => Code::UnknownSetVariable,
                _ => Code::BadSetValue,
            };
            report.diagnostics.push(option_error(code, format!("--set {name}={value}: {e}")));
        }
    }
    if report.diagnostics.iter().any(|d| d.severity == Severity::Error) {
        report.vars = visible_vars(&sim);
        return report;
    }
    let outcome = sim.run_scans(options.cycles);
    report.cycles = sim.scan_count();
    report.vars = visible_vars(&sim);
    match outcome {
        ScanOutcome::Fault(info) => {
            let loc = index.location(info.span.start);
            report.status = RunStatus::Fault;
            report.fault = Some(FaultReport {
                message: info.fault.to_string(),
                line: loc.line,
                column: loc.column,
            });
        }
        ScanOutcome::Completed | ScanOutcome::Breakpoint(_) => report.status = RunStatus::Ok,
    }
    report
}

fn petri_report(pou: &str, d: &crate::petri::PetriDiagnostic) -> DiagnosticReport {
    let place = crate::petri::describe(pou, &d.element, d.at.as_ref());
    DiagnosticReport {
        severity: d.severity,
        code: d.code.as_str().to_string(),
        message: format!("{place}: {}", d.message),
        line: 0,
        column: 0,
    }
}

fn ladder_report(pou: &str, d: &crate::ladder::LadderDiagnostic) -> DiagnosticReport {
    DiagnosticReport {
        severity: d.severity,
        code: d.code.as_str().to_string(),
        message: format!("POU {pou}, {d}"),
        line: 0,
        column: 0,
    }
}

/// Compiles and runs a project (its ST source, ladder and Petri net POUs) as `plc run` does.
/// Ladder problems are reported with line 0 and `POU Name, rung R, row r, column c:` in the
/// message, Petri net problems with `POU Name, transition T (guard line l, column c):`;
/// the hidden variables of the ladder lowering and the Petri net code are left out of
/// `vars`.
pub fn run_project(project: &crate::project::Project, options: &RunOptions) -> RunReport {
    let petri = crate::petri::project_diagnostics(project);
    if petri.iter().any(|(_, d)| d.is_error()) {
        return RunReport {
            status: RunStatus::Error,
            cycles: 0,
            vars: serde_json::Map::new(),
            fault: None,
            diagnostics: petri.iter().map(|(p, d)| petri_report(p, d)).collect(),
        };
    }
    let src = match crate::ladder::project_source(project) {
        Ok(src) => src,
        Err(diags) => {
            return RunReport {
                status: RunStatus::Error,
                cycles: 0,
                vars: serde_json::Map::new(),
                fault: None,
                diagnostics: diags.iter().map(|(p, d)| ladder_report(p, d)).collect(),
            }
        }
    };
    let mut report = run_source(&src.text, options);
    for d in &mut report.diagnostics {
        if d.line > 0 {
            let (line, message) = src.map.locate_message_at(d.line, d.column, &d.message);
            d.message = message;
            if line.is_none() {
                d.line = 0;
                d.column = 0;
            }
        }
    }
    if let Some(f) = &mut report.fault {
        let (line, message) = src.map.locate_message_at(f.line, f.column, &f.message);
        f.message = message;
        if line.is_none() {
            f.line = 0;
            f.column = 0;
        }
    }
    let mut warnings: Vec<DiagnosticReport> =
        src.warnings.iter().map(|(p, d)| ladder_report(p, d)).collect();
    warnings.extend(petri.iter().map(|(p, d)| petri_report(p, d)));
    report.diagnostics.splice(0..0, warnings);
    report.vars.retain(|k, _| !is_generated_variable(k));
    report
}

/// Compiles a project and powers a simulator on for PROGRAM `program` (or the first one),
/// for scan-by-scan use (tests, the web app). Errors come as [`run_project`] reports them.
pub fn project_simulator(
    project: &crate::project::Project,
    program: Option<&str>,
) -> Result<Simulator, Vec<DiagnosticReport>> {
    let options =
        RunOptions { program: program.map(str::to_string), cycles: 0, ..RunOptions::default() };
    let report = run_project(project, &options);
    if report.status == RunStatus::Error {
        return Err(report.diagnostics);
    }
    let src = crate::ladder::project_source(project)
        .map_err(|d| d.iter().map(|(p, d)| ladder_report(p, d)).collect::<Vec<_>>())?;
    let analysis = semantic::analyze(&src.text);
    let Some(prog) = analysis.program else { return Err(report.diagnostics) };
    let main = match program {
        Some(name) => prog.find_pou(name),
        None => prog.programs().find(|&p| !prog.pou(p).library),
    };
    let Some(main) = main else { return Err(report.diagnostics) };
    Simulator::new(prog, main).map_err(|e| vec![option_error(Code::ProgramTooLarge, e.to_string())])
}
