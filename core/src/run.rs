//! One-shot runs: compile a source text, run N scans, and report in the JSON shape that
//! `plc run --json` prints. The CLI, the conformance suite and the wasm tests all go
//! through here, so they cannot disagree.

use serde::Serialize;
use serde_json::Value as Json;

use crate::build::{build_project, FileMap, ProjectDiagnostic, Site};
use crate::diagnostics::{Code, Diagnostic, LineIndex, Said, Severity};
use crate::semantic;
use crate::sim::{ScanOutcome, SimError, Simulator};

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
    /// For a project imported from a file: where its ladder cells and ST lines came from,
    /// so their problems carry the line and column in that file.
    pub file_map: FileMap,
    /// The plant PROGRAM run after the controller on every scan (a project's settings name
    /// it); its variables are reported under its name.
    pub plant: Option<String>,
    /// Variables recorded after every scan (`plc run --trace`); the report then carries
    /// the trace as CSV (the web app's timeline export).
    pub trace: Vec<String>,
    /// `(scan, VAR, VALUE)` (`plc run --set-at SCAN:VAR=VALUE`): from scan `scan` (1-based)
    /// on, an input is held at the value; any other variable is set before that scan. A
    /// button pressed and released is two entries.
    pub set_at: Vec<(u64, String, String)>,
    /// Keep the run's history ([`Simulator::set_recording`]), to ask about its scans
    /// afterwards (`plc why`).
    pub record: bool,
}

impl Default for RunOptions {
    fn default() -> Self {
        RunOptions {
            program: None,
            cycles: 1,
            cycle_ms: 10,
            set: Vec::new(),
            file_map: FileMap::default(),
            plant: None,
            trace: Vec::new(),
            set_at: Vec::new(),
            record: false,
        }
    }
}

/// Parses `SCAN:VAR=VALUE` (`plc run --set-at`).
pub fn parse_set_at(text: &str) -> Result<(u64, String, String), String> {
    let bad = || format!("--set-at expects SCAN:VAR=VALUE (e.g. 5:Start=TRUE), got `{text}`");
    let (scan, rest) = text.split_once(':').ok_or_else(bad)?;
    let scan: u64 = scan.trim().parse().map_err(|_| bad())?;
    if scan == 0 {
        return Err(format!("--set-at {text}: scans are numbered from 1"));
    }
    let (var, value) = rest.split_once('=').ok_or_else(bad)?;
    let (var, value) = (var.trim(), value.trim());
    if var.is_empty() || value.is_empty() {
        return Err(bad());
    }
    Ok((scan, var.to_string(), value.to_string()))
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
    /// The declared name an unknown one probably misspells (the message ends with `did you
    /// mean NAME?`); absent when there is none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub suggestion: Option<String>,
    /// The message as data, with the place in front when it has one (`None` while it is
    /// English only): [`DiagnosticReport::render`] shows it in any language.
    #[serde(skip)]
    pub msg: Option<crate::diagnostics::Message>,
}

impl DiagnosticReport {
    /// A diagnostic at a line and column (0, 0: the file as a whole).
    pub fn new(severity: Severity, code: Code, message: String, line: u32, column: u32) -> Self {
        let code = code.as_str().to_string();
        DiagnosticReport { severity, code, message, line, column, suggestion: None, msg: None }
    }

    /// The message in `lang` (English when it is not data yet).
    pub fn render(&self, lang: crate::i18n::Lang) -> String {
        match &self.msg {
            Some(m) => crate::diagnostics::render_with_hint(m, self.suggestion.as_deref(), lang),
            None => self.message.clone(),
        }
    }
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
    /// The variables of [`RunOptions::trace`] after every scan, as CSV
    /// (`time_ms,scan,<path>…`, as the web app's timeline exports them).
    #[serde(skip)]
    pub trace_csv: Option<String>,
}

impl RunReport {
    /// The report of a run that could not start (the file could not be opened, the PROGRAM
    /// asked for was left out by an import): one error, nothing ran.
    pub fn failed(diagnostic: DiagnosticReport) -> RunReport {
        RunReport {
            status: RunStatus::Error,
            cycles: 0,
            vars: serde_json::Map::new(),
            fault: None,
            diagnostics: vec![diagnostic],
            trace_csv: None,
        }
    }

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
        suggestion: d.suggestion.clone(),
        msg: Some(d.msg.clone()),
    }
}

fn option_error(code: Code, message: impl Into<crate::diagnostics::Said>) -> DiagnosticReport {
    let said = message.into();
    let mut report = DiagnosticReport::new(Severity::Error, code, said.english, 0, 0);
    report.msg = Some(said.message);
    report
}

/// The program instance's variables as JSON, without the generated ones.
fn visible_vars(sim: &Simulator) -> serde_json::Map<String, Json> {
    let mut vars = sim.vars_json();
    vars.retain(|k, _| !crate::build::is_hidden_variable(k));
    vars
}

/// Compiles and runs `source` as `plc run` does.
pub fn run_source(source: &str, options: &RunOptions) -> RunReport {
    let index = LineIndex::new(source);
    let analysis = semantic::analyze(source);
    let diagnostics = analysis.diagnostics.iter().map(|d| diagnostic_report(&index, d)).collect();
    run_checked(analysis.program, options, diagnostics, |info| {
        let loc = index.location(info.span.start);
        FaultReport { message: info.fault.to_string(), line: loc.line, column: loc.column }
    })
    .0
}

/// Sets `name` to `value` as `--set` does: an input is held, any other variable written.
fn set_one(sim: &mut Simulator, name: &str, value: &str) -> Result<(), SimError> {
    let is_input = sim
        .executable()
        .main_vars()
        .iter()
        .any(|v| v.var.name.eq_ignore_ascii_case(name) && v.var.is_input());
    if is_input {
        sim.hold(name, value)
    } else {
        sim.write(name, value)
    }
}

fn set_error(flag: &str, name: &str, value: &str, e: &SimError) -> DiagnosticReport {
    let (code, detail) = match e {
        SimError::UnknownVariable(_) => (Code::UnknownSetVariable, e.said()),
        SimError::BadValue { path, message } => {
            (Code::BadSetValue, crate::msg!(ValueOfPath, path = path, detail = message))
        }
        _ => (Code::BadSetValue, e.said()),
    };
    option_error(
        code,
        crate::msg!(SetOption, flag = flag, name = name, value = value, detail = detail),
    )
}

/// Runs `options.cycles` scans, applying `options.set_at` before the scans they name;
/// stops at a fault.
fn run_scheduled(sim: &mut Simulator, options: &RunOptions) -> ScanOutcome {
    let mut schedule: Vec<&(u64, String, String)> = options.set_at.iter().collect();
    crate::order::sort_by_key(&mut schedule, |(scan, ..)| *scan);
    let mut outcome = ScanOutcome::Completed;
    for (scan, name, value) in schedule {
        if *scan > options.cycles {
            break;
        }
        let due = scan.saturating_sub(1).saturating_sub(sim.scan_count());
        if due > 0 {
            outcome = sim.run_scans(due);
            if matches!(outcome, ScanOutcome::Fault(_)) {
                return outcome;
            }
        }
        // Checked before the run: a failure here cannot happen.
        let _ = set_one(sim, name, value);
    }
    let rest = options.cycles.saturating_sub(sim.scan_count());
    if rest > 0 || options.cycles == 0 {
        outcome = sim.run_scans(rest);
    }
    outcome
}

/// Runs a checked program (`None`: it did not check, and `diagnostics` say why) as `plc run`
/// does; `fault_report` locates a runtime fault. The simulator is handed back after the
/// run when it could be made.
fn run_checked(
    program: Option<semantic::Program>,
    options: &RunOptions,
    diagnostics: Vec<DiagnosticReport>,
    fault_report: impl FnOnce(&crate::sim::FaultInfo) -> FaultReport,
) -> (RunReport, Option<Simulator>) {
    let mut report = RunReport {
        status: RunStatus::Error,
        cycles: 0,
        vars: serde_json::Map::new(),
        fault: None,
        diagnostics,
        trace_csv: None,
    };
    let Some(program) = program else { return (report, None) };
    let made =
        crate::build::simulator_for(program, options.program.as_deref(), options.plant.as_deref());
    let mut sim = match made {
        Ok(sim) => sim,
        Err((code, message)) => {
            report.diagnostics.push(option_error(code, message));
            return (report, None);
        }
    };
    match crate::limits::cycle_ns(options.cycle_ms) {
        Ok(ns) => sim.set_cycle_ns(ns),
        Err(_) => {
            let (min, max) = (crate::limits::MIN_CYCLE_MS, crate::limits::MAX_CYCLE_MS);
            let message = crate::msg!(ScanCycleRange, min = min, max = max, ms = options.cycle_ms);
            report.diagnostics.push(option_error(Code::BadCycleTime, message));
            return (report, Some(sim));
        }
    }
    if options.record {
        if let Err(e) = sim.set_recording(true) {
            let message = match e {
                crate::sim::RecordError::TooLarge { bytes } => {
                    crate::msg!(MemoryTooLargeToRecord, kb = bytes / 1024)
                }
                other => other.to_string().into(),
            };
            report.diagnostics.push(option_error(Code::ProgramTooLarge, message));
        }
    }
    for (name, value) in &options.set {
        if let Err(e) = set_one(&mut sim, name, value) {
            report.diagnostics.push(set_error("--set", name, value, &e));
        }
    }
    for (scan, name, value) in &options.set_at {
        if let Err(e) = sim.parse_value(name, value) {
            report.diagnostics.push(set_error(&format!("--set-at {scan}:"), name, value, &e));
        }
    }
    if !options.trace.is_empty() {
        let paths: Vec<&str> = options.trace.iter().map(String::as_str).collect();
        let capacity = usize::try_from(options.cycles).unwrap_or(usize::MAX).saturating_add(1);
        if let Err(e) = sim.set_trace(&paths, capacity) {
            let message = crate::msg!(OptionDetail, flag = "--trace", detail = e.said());
            report.diagnostics.push(option_error(Code::UnknownSetVariable, message));
        }
    }
    if report.diagnostics.iter().any(|d| d.severity == Severity::Error) {
        report.vars = visible_vars(&sim);
        return (report, Some(sim));
    }
    let outcome = run_scheduled(&mut sim, options);
    if !options.trace.is_empty() {
        report.trace_csv = Some(crate::export::trace_csv(sim.trace()));
    }
    report.cycles = sim.scan_count();
    report.vars = visible_vars(&sim);
    match outcome {
        ScanOutcome::Fault(info) => {
            report.status = RunStatus::Fault;
            report.fault = Some(fault_report(&info));
        }
        ScanOutcome::Completed | ScanOutcome::Breakpoint(_) => report.status = RunStatus::Ok,
    }
    (report, Some(sim))
}

/// A message about `site` as reports give it: ST problems keep their line and column,
/// ladder and Petri net problems get line 0 and their site in front of the message.
fn located(site: &Site, message: &str) -> (String, u32, u32) {
    match (site, site.describe()) {
        (Site::St { line, column, .. }, _) => (message.to_string(), *line, *column),
        (_, Some(place)) => (format!("{place}: {message}"), 0, 0),
        (_, None) => (message.to_string(), 0, 0),
    }
}

fn project_report(d: &ProjectDiagnostic) -> DiagnosticReport {
    project_report_in(d, &FileMap::default())
}

/// [`project_report`], at the element's place in the file the project was imported from
/// when `file_map` knows it.
fn project_report_in(d: &ProjectDiagnostic, file_map: &FileMap) -> DiagnosticReport {
    let (message, mut line, mut column) = located(&d.site, &d.message);
    if let Some(at) = file_map.locate(&d.site) {
        (line, column) = at;
    }
    DiagnosticReport {
        severity: d.severity,
        code: d.code.as_str().to_string(),
        message,
        line,
        column,
        suggestion: d.suggestion().map(str::to_string),
        msg: d.msg.as_deref().map(|m| match d.site.message() {
            Some(place) => {
                let said = Said { message: m.clone(), english: d.message.clone() };
                crate::msg!(PlaceLocated, place = place, message = said).message
            }
            None => m.clone(),
        }),
    }
}

/// Compiles and runs a project (its ST source, ladder and Petri net POUs) as `plc run` does.
/// Ladder problems are reported with line 0 and `POU Name, rung R, row r, column c:` in the
/// message, Petri net problems with `POU Name, transition T (guard line l, column c):`;
/// the hidden variables of the ladder lowering and the Petri net code are left out of
/// `vars`. Without `options.program`, the PROGRAM the project's settings chose runs (when
/// it still exists), else the first.
pub fn run_project(project: &crate::project::Project, options: &RunOptions) -> RunReport {
    run_project_kept(project, options).report
}

/// A run of a project kept for questions about it (`plc why`): the build, the report and
/// the simulator after the run (its history recorded when [`RunOptions::record`]).
#[derive(Debug)]
pub struct KeptRun {
    /// The project's build (its source and where each line came from).
    pub build: crate::build::ProjectBuild,
    /// The report `plc run --json` prints.
    pub report: RunReport,
    /// The simulator after the run (`None` when the project did not build).
    pub sim: Option<Simulator>,
}

/// [`run_project`], keeping the build and the simulator.
pub fn run_project_kept(project: &crate::project::Project, options: &RunOptions) -> KeptRun {
    let build = build_project(project);
    let diagnostics =
        build.diagnostics.iter().map(|d| project_report_in(d, &options.file_map)).collect();
    let program = if build.has_errors() { None } else { build.program.clone() };
    let mut options = options.clone();
    options.plant = project.settings.plant.clone();
    if options.program.is_none() {
        options.program = build.chosen_program(&project.settings).map(str::to_string);
    }
    let (report, sim) = run_checked(program, &options, diagnostics, |info| {
        let site = build.site_of(info.span);
        let (message, mut line, mut column) = located(&site, &info.fault.to_string());
        if let Some(at) = options.file_map.locate(&site) {
            (line, column) = at;
        }
        FaultReport { message, line, column }
    });
    KeptRun { build, report, sim }
}

/// Compiles a project and powers a simulator on for PROGRAM `program` (or the one the
/// project's settings choose, else the first one), with the plant the settings name, for
/// scan-by-scan use (tests, the web app). Errors come as [`run_project`] reports them.
pub fn project_simulator(
    project: &crate::project::Project,
    program: Option<&str>,
) -> Result<Simulator, Vec<DiagnosticReport>> {
    let build = build_project(project);
    if build.has_errors() {
        return Err(build.diagnostics.iter().map(project_report).collect());
    }
    let program = program.or(build.chosen_program(&project.settings));
    build.simulator_with_plant(program, project.settings.plant.as_deref()).map_err(|d| {
        let mut reports: Vec<DiagnosticReport> =
            build.diagnostics.iter().map(project_report).collect();
        let message =
            d.msg.map_or_else(|| crate::diagnostics::Message::text(d.message.clone()), |m| *m);
        reports
            .push(option_error(d.code, crate::diagnostics::Said { message, english: d.message }));
        reports
    })
}
