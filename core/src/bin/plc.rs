//! `plc`: the command line of the PLC trainer, for instructors, CI and benchmarks.
//! It uses exactly the same core as the browser.

#[path = "plc/class_report.rs"]
mod class_report;
#[path = "plc/grade.rs"]
mod grade;
#[path = "plc/petri.rs"]
mod petri;
#[path = "plc/why.rs"]
mod why;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use plc_core::diagnostics::{Code, LineIndex};
use plc_core::project::Project;
use plc_core::run::{run_project, run_source, DiagnosticReport, RunOptions, RunReport, RunStatus};

#[derive(Parser)]
#[command(
    name = "plc",
    version,
    about = "Check and run IEC 61131-3 Structured Text on a simulated PLC"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Check a program and print its diagnostics as FILE:LINE:COL: error[CODE]: message.
    Check {
        /// The ST source file.
        file: PathBuf,
        /// The language of the messages: en (the default), pl or cs.
        #[arg(long, default_value = "en")]
        lang: plc_core::i18n::Lang,
    },
    /// Run a program for a number of scans on a virtual clock and print its variables.
    Run {
        /// The ST source file.
        file: PathBuf,
        /// The PROGRAM to run (default: the first one in the file).
        #[arg(long)]
        program: Option<String>,
        /// How many scans to run.
        #[arg(long, default_value_t = 1)]
        cycles: u64,
        /// Virtual milliseconds per scan (1 to 60000).
        #[arg(long = "cycle-ms", default_value_t = 10,
              value_parser = clap::value_parser!(u64).range(1..=60_000))]
        cycle_ms: u64,
        /// VAR=VALUE (an IEC literal). Inputs are held at the value on every scan; other
        /// variables are set before the first scan.
        #[arg(long = "set", value_name = "VAR=VALUE")]
        set: Vec<String>,
        /// SCAN:VAR=VALUE: from scan SCAN (1-based) on, VAR is VALUE (an input is held at
        /// it, any other variable is set before that scan). Repeatable: `--set-at
        /// 5:Start=TRUE --set-at 7:Start=FALSE` presses Start for two scans.
        #[arg(long = "set-at", value_name = "SCAN:VAR=VALUE")]
        set_at: Vec<String>,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
        /// Record VAR after every scan (repeatable; a plant's variables as `Plant.Name`).
        /// With `--csv` the recording is printed.
        #[arg(long = "trace", value_name = "VAR")]
        trace: Vec<String>,
        /// Print the recorded variables as CSV, one row per scan (`time_ms,scan,VAR…`,
        /// as the web app's timeline exports them) instead of the report. Without
        /// `--trace`, a project's timeline variables are recorded.
        #[arg(long, conflicts_with = "json")]
        csv: bool,
    },
    /// Explain why a variable has its value at a scan (or why a Petri net place holds a
    /// token): what wrote it, and the values that decided it, each since when.
    Why {
        /// The ST source, project or PLCopen XML file.
        file: PathBuf,
        /// The variable (`Motor`, `T1.Q`, `Filling.X`) or Petri net place (`P3`).
        var: String,
        /// The scan (1-based; 0: the initial values).
        #[arg(long)]
        at: u64,
        /// The PROGRAM to run (default: the first one in the file).
        #[arg(long)]
        program: Option<String>,
        /// How many scans to run (default: up to the scan asked about); later scans give
        /// the next change.
        #[arg(long)]
        cycles: Option<u64>,
        /// Virtual milliseconds per scan (1 to 60000).
        #[arg(long = "cycle-ms", default_value_t = 10,
              value_parser = clap::value_parser!(u64).range(1..=60_000))]
        cycle_ms: u64,
        /// VAR=VALUE, as for `run`.
        #[arg(long = "set", value_name = "VAR=VALUE")]
        set: Vec<String>,
        /// SCAN:VAR=VALUE, as for `run`.
        #[arg(long = "set-at", value_name = "SCAN:VAR=VALUE")]
        set_at: Vec<String>,
        /// Print one JSON object (`var`, `value`, `scan`, `written_by`, `operands`, …).
        #[arg(long)]
        json: bool,
    },
    /// Explain a problem code such as E0150: what it means, how to fix it, and a wrong and a
    /// right example.
    Explain {
        /// The code.
        #[arg(required_unless_present_any = ["markdown", "html", "json"])]
        code: Option<String>,
        /// Print every code as the Markdown page docs/problems.md.
        #[arg(long, conflicts_with_all = ["code", "html", "json"])]
        markdown: bool,
        /// Print every code as the HTML page problems.html of the site (with `--lang`,
        /// problems.pl.html or problems.cs.html).
        #[arg(long, conflicts_with_all = ["code", "markdown", "json"])]
        html: bool,
        /// Print every code's title and explanation as the JSON a translation file has
        /// (core/i18n/problems.en.json is this in English).
        #[arg(long, conflicts_with_all = ["code", "markdown", "html"])]
        json: bool,
        /// The language: en (the default), pl or cs.
        #[arg(long, default_value = "en", conflicts_with = "markdown")]
        lang: plc_core::i18n::Lang,
    },
    /// Print the readable ST view of a ladder POU of a project, or the ST a network POU
    /// (an LD or FBD body kept as drawn in an imported file) runs as.
    StView {
        /// The project file.
        project: PathBuf,
        /// The ladder or network POU.
        #[arg(long)]
        pou: String,
    },
    /// Convert a PLCopen XML file into a project file (printed to standard output).
    Import {
        /// The PLCopen XML file.
        file: PathBuf,
    },
    /// Convert a project (or ST file) into another format (printed to standard output).
    Export {
        /// Write PLCopen XML (TC6 0201).
        #[arg(long, required = true)]
        plcopen: bool,
        /// The project file.
        project: PathBuf,
    },
    /// Grade submissions against an exercise: one row per submission (a project file, ST
    /// file or PLCopen XML, or a folder of them), graded in parallel.
    Grade {
        /// The exercise file (TOML).
        exercise: PathBuf,
        /// The submissions: files, or folders of them.
        #[arg(required = true)]
        submissions: Vec<PathBuf>,
        /// A file of hidden scenarios to add (the same form as an exercise file).
        #[arg(long, value_name = "HIDDEN.toml")]
        scenarios: Option<PathBuf>,
        /// text, json, csv, or html (a class report: one self-contained page).
        #[arg(long, value_enum, default_value_t = grade::Format::Text)]
        format: grade::Format,
        /// How many submissions are graded at once (default: the cores).
        #[arg(long)]
        jobs: Option<usize>,
        /// The language of the text report: en (the default), pl or cs.
        #[arg(long, default_value = "en")]
        lang: plc_core::i18n::Lang,
    },
    /// Exercises: validate one (reference, starter, mutants), write a skeleton, a link or a
    /// SCORM package.
    Exercise {
        #[command(subcommand)]
        command: grade::ExerciseCommand,
    },
    /// Petri nets: analyse, generate CASE OF code, convert PNML.
    Petri {
        #[command(subcommand)]
        command: petri::PetriCommand,
    },
    /// Run the benchmark suite (B1–B7) and print each figure with its ratio.
    Bench {
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
        /// A short smoke pass with tiny sizes (for CI).
        #[arg(long)]
        quick: bool,
        /// Run only these figures (`--only B2 --only B4`), e.g. under a profiler.
        #[arg(long, value_name = "FIGURE")]
        only: Vec<String>,
    },
}

/// What a file holds: plain ST text or a whole project (with ladder POUs).
enum Input {
    Source(String),
    Project(Box<Project>),
}

/// A file opened: what it holds, and what its import skipped or changed.
struct Loaded {
    input: Input,
    /// Import notes, each with its place in the file.
    notes: Vec<plc_core::plcopen::ImportNote>,
    /// POUs the import left out.
    skipped: Vec<plc_core::plcopen::SkippedPou>,
    /// Where the imported ladder cells and ST lines came from in the file.
    file_map: plc_core::build::FileMap,
}

/// Why a file could not be opened: the message and its place in the file (0, 0 when not
/// known).
struct LoadFailure {
    message: String,
    /// The message as data, when it is (shown in the language asked for).
    msg: Option<plc_core::diagnostics::Message>,
    line: u32,
    column: u32,
}

impl LoadFailure {
    /// As a diagnostic of the report.
    fn diagnostic(&self) -> DiagnosticReport {
        let mut d = DiagnosticReport::new(
            plc_core::diagnostics::Severity::Error,
            Code::FileNotOpened,
            self.message.clone(),
            self.line,
            self.column,
        );
        d.msg = self.msg.clone();
        d
    }
}

/// Reads FILE as ST text, a project file (JSON), a PLCopen XML file or a PNML net.
fn open_file(path: &Path) -> Result<Loaded, LoadFailure> {
    let text = read_source(path).map_err(|message| LoadFailure {
        message: message.replacen("plc: ", "", 1),
        msg: None,
        line: 0,
        column: 0,
    })?;
    if plc_core::open::file_kind(&text) == plc_core::open::FileKind::St {
        return Ok(Loaded {
            input: Input::Source(text),
            notes: Vec::new(),
            skipped: Vec::new(),
            file_map: Default::default(),
        });
    }
    let opened = plc_core::open::open_text("project", &text).map_err(|e| {
        let (line, column) = e.location_in(&text).unwrap_or((0, 0));
        let msg = Some(e.said().message);
        LoadFailure { message: e.to_string(), msg, line, column }
    })?;
    Ok(Loaded {
        input: Input::Project(Box::new(opened.project)),
        notes: opened.warnings,
        skipped: opened.skipped,
        file_map: opened.file_map,
    })
}

/// [`open_file`] for the commands that take the file whole (import notes go to stderr).
fn load_input(path: &Path) -> Result<Input, String> {
    let loaded = open_file(path).map_err(|f| format!("plc: {}: {}", path.display(), f.message))?;
    for w in &loaded.notes {
        eprintln!("plc: {}: warning: {w}", path.display());
    }
    Ok(loaded.input)
}

/// The import notes as warnings of a report.
fn note_diagnostics(notes: &[plc_core::plcopen::ImportNote]) -> Vec<DiagnosticReport> {
    notes
        .iter()
        .map(|n| {
            let mut d = DiagnosticReport::new(
                plc_core::diagnostics::Severity::Warning,
                Code::ImportChanged,
                n.message.clone(),
                n.line,
                n.column,
            );
            d.msg = Some(n.said.message.clone());
            d
        })
        .collect()
}

/// "No PROGRAM to run" names the PROGRAMs the import left out, and why.
fn name_skipped_programs(report: &mut RunReport, skipped: &[plc_core::plcopen::SkippedPou]) {
    let programs: Vec<String> = skipped
        .iter()
        .filter(|s| s.kind == "PROGRAM")
        .map(|s| format!("{} ({})", s.name, s.reason))
        .collect();
    if programs.is_empty() {
        return;
    }
    for d in &mut report.diagnostics {
        if d.code == Code::NoProgram.as_str() {
            d.message = format!(
                "the file holds no PROGRAM that could be imported: left out {}",
                programs.join(", ")
            );
            d.msg = None;
        }
    }
}

/// The error for `--program NAME` when the import left NAME out.
fn skipped_program(loaded: &Loaded, program: Option<&str>) -> Option<DiagnosticReport> {
    let name = program?;
    let Input::Project(project) = &loaded.input else { return None };
    let has = |n: &str| n.eq_ignore_ascii_case(name);
    if project.ladder.iter().any(|l| has(&l.name)) || project.petri.iter().any(|p| has(&p.name)) {
        return None;
    }
    let skipped = loaded.skipped.iter().find(|s| has(&s.name))?;
    Some(DiagnosticReport::new(
        plc_core::diagnostics::Severity::Error,
        Code::ProgramSkipped,
        format!(
            "the {} {} was left out when the file was imported: {}",
            skipped.kind, skipped.name, skipped.reason
        ),
        0,
        0,
    ))
}

/// Loads a project file (JSON) or a PLCopen XML file as a project.
fn load_project(path: &Path) -> Result<Project, String> {
    match load_input(path)? {
        Input::Project(p) => Ok(*p),
        Input::Source(text) => {
            let mut p = Project::new(
                path.file_stem().map_or("project".into(), |s| s.to_string_lossy().into_owned()),
            );
            p.source = text;
            p.ladder.clear();
            Ok(p)
        }
    }
}

fn read_source(path: &Path) -> Result<String, String> {
    let bytes =
        std::fs::read(path).map_err(|e| format!("plc: cannot read {}: {e}", path.display()))?;
    Ok(String::from_utf8(bytes).unwrap_or_else(|e| {
        // Latin-1 files (common for PLC sources) become text byte by byte.
        e.into_bytes().into_iter().map(char::from).collect()
    }))
}

fn check(path: &Path, lang: plc_core::i18n::Lang) -> ExitCode {
    let loaded = match open_file(path) {
        Ok(l) => l,
        Err(f) => {
            let d = f.diagnostic();
            let message = d.render(lang);
            print_diagnostic(path, d.severity, d.line, d.column, &d.code, &message);
            eprintln!("{}: 1 error(s), 0 warning(s)", path.display());
            return ExitCode::from(2);
        }
    };
    let source = match loaded.input {
        Input::Source(s) => s,
        Input::Project(ref project) => return check_project(path, project, &loaded, lang),
    };
    let analysis = plc_core::semantic::analyze(&source);
    let index = LineIndex::new(&source);
    let (mut errors, mut warnings) = (0, 0);
    for d in &analysis.diagnostics {
        let loc = index.location(d.span.start);
        if d.is_error() {
            errors += 1;
        } else {
            warnings += 1;
        }
        let message = d.render(lang);
        print_diagnostic(path, d.severity, loc.line, loc.column, d.code.as_str(), &message);
    }
    eprintln!("{}: {errors} error(s), {warnings} warning(s)", path.display());
    if errors > 0 {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

/// Checks a project (ST and ladder POUs): diagnostics as for ST; ladder problems name
/// their POU, rung, row and column in the message.
fn check_project(
    path: &Path,
    project: &Project,
    loaded: &Loaded,
    lang: plc_core::i18n::Lang,
) -> ExitCode {
    let options =
        RunOptions { cycles: 0, file_map: loaded.file_map.clone(), ..RunOptions::default() };
    let mut report = run_project(project, &options);
    name_skipped_programs(&mut report, &loaded.skipped);
    let (mut errors, mut warnings) = (0, 0);
    for d in note_diagnostics(&loaded.notes).iter().chain(&report.diagnostics) {
        match d.severity {
            plc_core::diagnostics::Severity::Error => errors += 1,
            plc_core::diagnostics::Severity::Warning => warnings += 1,
        }
        let message = d.render(lang);
        print_diagnostic(path, d.severity, d.line, d.column, &d.code, &message);
    }
    eprintln!("{}: {errors} error(s), {warnings} warning(s)", path.display());
    if errors > 0 {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

fn st_view(path: &Path, pou: &str) -> ExitCode {
    let project = match load_project(path) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    if let Some(lp) = project.ladder.iter().find(|p| p.name.eq_ignore_ascii_case(pou)) {
        print!("{}", plc_core::ladder::st_view_pou(lp));
        return ExitCode::SUCCESS;
    }
    // A network POU (LD or FBD kept as drawn in an imported file): the ST it runs as.
    if let Some(net) = project.networks.iter().find(|p| p.name.eq_ignore_ascii_case(pou)) {
        return match net.to_st() {
            Ok(text) => {
                print!("{}", text.st);
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("plc: network POU `{}` cannot run: {e}", net.name);
                ExitCode::FAILURE
            }
        };
    }
    let names: Vec<&str> = project
        .ladder
        .iter()
        .map(|p| p.name.as_str())
        .chain(project.networks.iter().map(|p| p.name.as_str()))
        .collect();
    eprintln!(
        "plc: no ladder or network POU `{pou}` in {} (they are: {})",
        path.display(),
        names.join(", ")
    );
    ExitCode::FAILURE
}

fn bench(json: bool, quick: bool, only: &[String]) -> ExitCode {
    let effort = if quick { plc_core::bench::Effort::Quick } else { plc_core::bench::Effort::Full };
    match plc_core::bench::run_selected(effort, only) {
        Ok(report) if json => {
            println!("{report}");
            ExitCode::SUCCESS
        }
        Ok(report) => {
            print!("{}", plc_core::bench::report_text(&report, effort));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("plc: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Prints one diagnostic as `FILE:LINE:COL: severity[CODE]: message` (what `plc check` and
/// `plc run` print alike).
fn print_diagnostic(
    path: &Path,
    severity: plc_core::diagnostics::Severity,
    line: u32,
    column: u32,
    code: &str,
    message: &str,
) {
    println!("{}", diagnostic_line(path, severity, line, column, code, message));
}

/// One diagnostic as `FILE:LINE:COL: severity[CODE]: message`.
fn diagnostic_line(
    path: &Path,
    severity: plc_core::diagnostics::Severity,
    line: u32,
    column: u32,
    code: &str,
    message: &str,
) -> String {
    format!("{}:{line}:{column}: {}[{code}]: {message}", path.display(), severity.as_str())
}

fn print_text(path: &Path, report: &RunReport) {
    for d in &report.diagnostics {
        print_diagnostic(path, d.severity, d.line, d.column, &d.code, &d.message);
    }
    match report.status {
        RunStatus::Ok => println!("status: ok after {} scan(s)", report.cycles),
        RunStatus::Fault => {
            if let Some(f) = &report.fault {
                println!(
                    "status: FAULT after {} scan(s) at {}:{}:{}: {}",
                    report.cycles,
                    path.display(),
                    f.line,
                    f.column,
                    f.message
                );
            }
        }
        RunStatus::Error => println!("status: error (the program did not run)"),
    }
    for (name, value) in &report.vars {
        println!("  {name} = {value}");
    }
}

/// How `plc run` prints its result.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Output {
    Text,
    Json,
    /// The trace as CSV; problems go to standard error.
    Csv,
}

fn run(path: &Path, mut options: RunOptions, output: Output) -> ExitCode {
    let print = |report: &RunReport| match (output, &report.trace_csv) {
        (Output::Json, _) => println!("{}", report.to_json()),
        (Output::Csv, csv) => {
            for d in &report.diagnostics {
                eprintln!(
                    "{}",
                    diagnostic_line(path, d.severity, d.line, d.column, &d.code, &d.message)
                );
            }
            if let Some(f) = &report.fault {
                eprintln!(
                    "{}:{}:{}: FAULT after {} scan(s): {}",
                    path.display(),
                    f.line,
                    f.column,
                    report.cycles,
                    f.message
                );
            }
            match csv {
                Some(csv) if report.status != RunStatus::Error => print!("{csv}"),
                _ => {
                    eprintln!("{}: nothing was recorded (the program did not run)", path.display())
                }
            }
        }
        (Output::Text, _) => print_text(path, report),
    };
    let loaded = match open_file(path) {
        Ok(l) => l,
        Err(f) => {
            // The file could not be opened: the normal report, with the reason.
            print(&RunReport::failed(f.diagnostic()));
            return ExitCode::from(2);
        }
    };
    let notes = note_diagnostics(&loaded.notes);
    let mut report = match skipped_program(&loaded, options.program.as_deref()) {
        Some(d) => RunReport::failed(d),
        None => match &loaded.input {
            Input::Source(source) => run_source(source, &options),
            Input::Project(project) => {
                if output == Output::Csv && options.trace.is_empty() {
                    options.trace = project.settings.traced.clone();
                }
                run_project(project, &RunOptions { file_map: loaded.file_map.clone(), ..options })
            }
        },
    };
    name_skipped_programs(&mut report, &loaded.skipped);
    report.diagnostics.splice(0..0, notes);
    print(&report);
    if report.status == RunStatus::Ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

fn explain(code: &str, lang: plc_core::i18n::Lang) -> ExitCode {
    match Code::all().iter().find(|c| c.as_str().eq_ignore_ascii_case(code)) {
        Some(c) => {
            print!("{}", plc_core::diagnostics::explain_text_in(*c, lang));
            ExitCode::SUCCESS
        }
        None => {
            eprintln!("plc: unknown problem code `{code}`");
            ExitCode::FAILURE
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Check { file, lang } => check(&file, lang),
        Command::Run { file, program, cycles, cycle_ms, set, set_at, json, trace, csv } => {
            let (pairs, set_at) = match settings(&set, &set_at) {
                Ok(s) => s,
                Err(code) => return code,
            };
            run(
                &file,
                RunOptions {
                    program,
                    cycles,
                    cycle_ms,
                    set: pairs,
                    file_map: Default::default(),
                    plant: None,
                    trace,
                    set_at,
                    record: false,
                },
                if csv {
                    Output::Csv
                } else if json {
                    Output::Json
                } else {
                    Output::Text
                },
            )
        }
        Command::Explain { markdown: true, .. } => {
            print!("{}", plc_core::diagnostics::problems_markdown());
            ExitCode::SUCCESS
        }
        Command::Explain { html: true, lang, .. } => {
            print!("{}", plc_core::diagnostics::problems_html_in(lang));
            ExitCode::SUCCESS
        }
        Command::Explain { json: true, lang, .. } => {
            print!("{}", plc_core::diagnostics::ProblemTexts::of(lang).to_json());
            ExitCode::SUCCESS
        }
        Command::Explain { code, lang, .. } => explain(code.as_deref().unwrap_or_default(), lang),
        Command::StView { project, pou } => st_view(&project, &pou),
        Command::Why { file, var, at, program, cycles, cycle_ms, set, set_at, json } => {
            let (pairs, set_at) = match settings(&set, &set_at) {
                Ok(s) => s,
                Err(code) => return code,
            };
            let project = match load_project(&file) {
                Ok(p) => p,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(2);
                }
            };
            let options = RunOptions {
                program,
                cycles: cycles.unwrap_or(at).max(at),
                cycle_ms,
                set: pairs,
                set_at,
                ..RunOptions::default()
            };
            why::run(&file, &project, &var, at, options, json)
        }
        Command::Bench { json, quick, only } => bench(json, quick, &only),
        Command::Petri { command } => petri::run(command),
        Command::Exercise { command } => grade::exercise(command),
        Command::Grade { exercise, submissions, scenarios, format, jobs, lang } => {
            grade::run(&exercise, &submissions, scenarios.as_deref(), format, jobs, lang)
        }
        Command::Import { file } => import(&file),
        Command::Export { plcopen: _, project } => export(&project),
    }
}

/// The `--set VAR=VALUE` and `--set-at SCAN:VAR=VALUE` options, parsed (exit code 2 and
/// a message when one is malformed).
#[allow(clippy::type_complexity)]
fn settings(
    set: &[String],
    set_at: &[String],
) -> Result<(Vec<(String, String)>, Vec<(u64, String, String)>), ExitCode> {
    let mut pairs = Vec::new();
    for s in set {
        match s.split_once('=') {
            Some((k, v)) => pairs.push((k.trim().to_string(), v.trim().to_string())),
            None => {
                eprintln!("plc: --set expects VAR=VALUE, got `{s}`");
                return Err(ExitCode::from(2));
            }
        }
    }
    let mut scheduled = Vec::new();
    for s in set_at {
        match plc_core::run::parse_set_at(s) {
            Ok(entry) => scheduled.push(entry),
            Err(message) => {
                eprintln!("plc: {message}");
                return Err(ExitCode::from(2));
            }
        }
    }
    Ok((pairs, scheduled))
}

/// `plc import FILE.xml`: prints the project file converted from PLCopen XML.
fn import(path: &Path) -> ExitCode {
    match load_project(path) {
        Ok(p) => {
            println!("{}", p.to_file());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}

/// `plc export --plcopen PROJECT`: prints the project as PLCopen XML (TC6 0201).
fn export(path: &Path) -> ExitCode {
    match load_project(path) {
        Ok(p) => {
            print!("{}", plc_core::plcopen::export(&p));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}
