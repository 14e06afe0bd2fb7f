//! `plc`: the command line of the PLC trainer, for instructors, CI and benchmarks.
//! It uses exactly the same core as the browser.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use plc_core::diagnostics::{Code, LineIndex};
use plc_core::run::{run_source, RunOptions, RunReport, RunStatus};

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
        /// Virtual milliseconds per scan.
        #[arg(long = "cycle-ms", default_value_t = 10)]
        cycle_ms: u64,
        /// VAR=VALUE (an IEC literal). Inputs are held at the value on every scan; other
        /// variables are set before the first scan.
        #[arg(long = "set", value_name = "VAR=VALUE")]
        set: Vec<String>,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Explain a problem code such as E0150.
    Explain {
        /// The code.
        code: String,
    },
}

fn read_source(path: &Path) -> Result<String, String> {
    let bytes =
        std::fs::read(path).map_err(|e| format!("plc: cannot read {}: {e}", path.display()))?;
    Ok(String::from_utf8(bytes).unwrap_or_else(|e| {
        // Latin-1 files (common for PLC sources) become text byte by byte.
        e.into_bytes().into_iter().map(char::from).collect()
    }))
}

fn check(path: &Path) -> ExitCode {
    let source = match read_source(path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    let analysis = plc_core::semantic::analyze(&source);
    let index = LineIndex::new(&source);
    let (mut errors, mut warnings) = (0, 0);
    for d in &analysis.diagnostics {
        let loc = index.location(d.span.start);
        let severity = if d.is_error() {
            errors += 1;
            "error"
        } else {
            warnings += 1;
            "warning"
        };
        println!(
            "{}:{}:{}: {severity}[{}]: {}",
            path.display(),
            loc.line,
            loc.column,
            d.code,
            d.message
        );
    }
    eprintln!("{}: {errors} error(s), {warnings} warning(s)", path.display());
    if errors > 0 {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

fn print_text(path: &Path, report: &RunReport) {
    for d in &report.diagnostics {
        println!(
            "{}:{}:{}: {:?}[{}]: {}",
            path.display(),
            d.line,
            d.column,
            d.severity,
            d.code,
            d.message
        );
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

fn run(path: &Path, options: RunOptions, json: bool) -> ExitCode {
    let source = match read_source(path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    let report = run_source(&source, &options);
    if json {
        println!("{}", report.to_json());
    } else {
        print_text(path, &report);
    }
    if report.status == RunStatus::Ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

fn explain(code: &str) -> ExitCode {
    match Code::all().iter().find(|c| c.as_str().eq_ignore_ascii_case(code)) {
        Some(c) => {
            println!("{}: {}", c.as_str(), c.title());
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
        Command::Check { file } => check(&file),
        Command::Run { file, program, cycles, cycle_ms, set, json } => {
            let mut pairs = Vec::new();
            for s in set {
                match s.split_once('=') {
                    Some((k, v)) => pairs.push((k.trim().to_string(), v.trim().to_string())),
                    None => {
                        eprintln!("plc: --set expects VAR=VALUE, got `{s}`");
                        return ExitCode::from(2);
                    }
                }
            }
            run(&file, RunOptions { program, cycles, cycle_ms, set: pairs }, json)
        }
        Command::Explain { code } => explain(&code),
    }
}
