//! `plc grade EXERCISE SUBMISSION...`: grades submissions (project files, ST files, PLCopen
//! XML, or folders of them) against an exercise, in parallel, one row per submission; a
//! submission that cannot be read gets its own row and never stops the batch.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use plc_core::exercise::{grade, scenarios_from_toml, time_text, Exercise, Report};

/// How the grades are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A line per submission, and the first wrong expectation of each failed scenario.
    Text,
    /// One JSON array.
    Json,
    /// A CSV table with a header row.
    Csv,
}

/// One submission's outcome: its report, or why it could not be read.
struct Row {
    name: String,
    result: Result<Report, String>,
}

/// The files to grade: each path, or the files of each folder (sorted by name).
fn expand(paths: &[PathBuf]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for p in paths {
        match std::fs::read_dir(p) {
            Ok(entries) => {
                let mut files: Vec<PathBuf> =
                    entries.flatten().map(|e| e.path()).filter(|f| f.is_file()).collect();
                plc_core::order::sort(&mut files);
                out.extend(files);
            }
            Err(_) => out.push(p.clone()),
        }
    }
    out
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("plc: {}: {e}", path.display()))
}

/// Runs `plc grade`.
pub fn run(
    exercise: &Path,
    submissions: &[PathBuf],
    hidden: Option<&Path>,
    format: Format,
    jobs: Option<usize>,
) -> ExitCode {
    let mut ex = match read(exercise).and_then(|t| {
        Exercise::from_toml(&t).map_err(|e| format!("plc: {}: {e}", exercise.display()))
    }) {
        Ok(ex) => ex,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    if let Some(h) = hidden {
        match read(h)
            .and_then(|t| scenarios_from_toml(&t).map_err(|e| format!("plc: {}: {e}", h.display())))
        {
            Ok(more) => ex.scenarios.extend(more),
            Err(e) => {
                eprintln!("{e}");
                return ExitCode::from(2);
            }
        }
    }
    let files = expand(submissions);
    let jobs = jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .clamp(1, 64);
    let mut rows: Vec<Option<Row>> = (0..files.len()).map(|_| None).collect();
    let chunk = files.len().div_ceil(jobs).max(1);
    std::thread::scope(|scope| {
        for (files, rows) in files.chunks(chunk).zip(rows.chunks_mut(chunk)) {
            let ex = &ex;
            scope.spawn(move || {
                for (file, row) in files.iter().zip(rows) {
                    let result = super::load_project(file).and_then(|project| {
                        grade(ex, &project).map_err(|e| format!("plc: the exercise: {e}"))
                    });
                    *row = Some(Row { name: file.display().to_string(), result });
                }
            });
        }
    });
    let rows: Vec<Row> = rows.into_iter().flatten().collect();
    match format {
        Format::Text => print_text(&rows),
        Format::Json => println!("{}", json(&rows)),
        Format::Csv => print!("{}", csv(&rows)),
    }
    ExitCode::SUCCESS
}

fn print_text(rows: &[Row]) {
    for row in rows {
        match &row.result {
            Err(e) => println!("{}: cannot be graded: {e}", row.name),
            Ok(r) => {
                println!("{}: {}/{}", row.name, r.score, r.total);
                if let Some(e) = &r.error {
                    println!("  {e}");
                }
                for s in r.scenarios.iter().filter(|s| !s.passed()) {
                    if let Some(f) = &s.failure {
                        println!("  FAIL {}: expected {}; {}", s.name, f.expected, f.actual);
                    }
                    if let Some(h) = &s.hint {
                        println!("    hint: {h}");
                    }
                }
            }
        }
    }
}

fn json(rows: &[Row]) -> serde_json::Value {
    let rows: Vec<serde_json::Value> = rows
        .iter()
        .map(|row| match &row.result {
            Err(e) => serde_json::json!({ "submission": row.name, "error": e }),
            Ok(r) => serde_json::json!({
                "submission": row.name,
                "score": r.score,
                "total": r.total,
                "error": r.error,
                "scenarios": r.scenarios.iter().map(|s| serde_json::json!({
                    "name": s.name,
                    "weight": s.weight,
                    "passed": s.passed(),
                    "expected": s.failure.as_ref().map(|f| &f.expected),
                    "actual": s.failure.as_ref().map(|f| &f.actual),
                    "time": s.failure.as_ref().map(|f| time_text(f.time_ns)),
                    "scan": s.failure.as_ref().map(|f| f.scan),
                    "hint": s.hint,
                })).collect::<Vec<_>>(),
            }),
        })
        .collect();
    serde_json::Value::Array(rows)
}

/// A CSV field, quoted when it must be.
fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

fn csv(rows: &[Row]) -> String {
    let mut out = String::from("submission,score,total,passed,failed,error,first_failure\n");
    for row in rows {
        let line = match &row.result {
            Err(e) => format!("{},,,,,{},", field(&row.name), field(e)),
            Ok(r) => {
                let passed = r.scenarios.iter().filter(|s| s.passed()).count();
                let failed = r.scenarios.len() - passed;
                let first = r
                    .scenarios
                    .iter()
                    .find_map(|s| s.failure.as_ref().map(|f| format!("{}: {}", s.name, f.actual)))
                    .unwrap_or_default();
                format!(
                    "{},{},{},{passed},{failed},{},{}",
                    field(&row.name),
                    r.score,
                    r.total,
                    field(r.error.as_deref().unwrap_or_default()),
                    field(&first)
                )
            }
        };
        out.push_str(&line);
        out.push('\n');
    }
    out
}
