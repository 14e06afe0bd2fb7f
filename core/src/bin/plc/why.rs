//! `plc why FILE VAR --at SCAN`: runs the program as `plc run` does, with its history
//! recorded, and explains the value of a variable (or why a Petri net place holds a token)
//! at that scan: what wrote it and the values that decided it (`docs/why.md`).

use std::path::Path;
use std::process::ExitCode;

use plc_core::project::Project;
use plc_core::run::{run_project_kept, RunOptions, RunStatus};
use plc_core::why::{explain, explain_place, Context, WhyError};

/// Prints the explanation of `var` at scan `at` after running `project` with `options`
/// (whose `cycles` is at least `at`).
pub fn run(
    path: &Path,
    project: &Project,
    var: &str,
    at: u64,
    options: RunOptions,
    json: bool,
) -> ExitCode {
    let kept = run_project_kept(project, &RunOptions { record: true, ..options });
    let fail = |message: String, diagnostics: serde_json::Value| {
        if json {
            println!("{}", serde_json::json!({ "error": message, "diagnostics": diagnostics }));
        } else {
            eprintln!("plc: {}: {message}", path.display());
        }
        ExitCode::FAILURE
    };
    let diagnostics = serde_json::to_value(&kept.report.diagnostics).unwrap_or_default();
    if !json {
        for d in &kept.report.diagnostics {
            println!(
                "{}",
                super::diagnostic_line(path, d.severity, d.line, d.column, &d.code, &d.message)
            );
        }
    }
    let Some(sim) = kept.sim.as_ref().filter(|_| kept.report.status != RunStatus::Error) else {
        return fail("the program did not run".to_string(), diagnostics);
    };
    if kept.report.status == RunStatus::Fault && sim.scan_count() < at {
        let fault = kept.report.fault.as_ref().map(|f| f.message.clone()).unwrap_or_default();
        return fail(
            format!("the PLC faulted after scan {} (before scan {at}): {fault}", sim.scan_count()),
            diagnostics,
        );
    }
    let ctx = Context::new(project, &kept.build);
    let answer = match explain(&ctx, sim, var, at) {
        Err(WhyError::Unknown(_)) => explain_place(&ctx, sim, var, at),
        other => other,
    };
    match answer {
        Ok(e) if json => {
            println!("{}", e.to_json());
            ExitCode::SUCCESS
        }
        Ok(e) => {
            println!("{}", e.to_text());
            ExitCode::SUCCESS
        }
        Err(e) => fail(e.to_string(), diagnostics),
    }
}
