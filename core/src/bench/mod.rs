//! The benchmark suite behind `plc bench`: each figure runs the real pipeline (check,
//! compile, simulate) and, where the issue asks for it, the same work hand-written in Rust
//! in the same run, so the ratio VM/native is measured on the same machine at the same
//! moment. Timing uses the wall clock, so this module exists only in native builds; the
//! tests assert nothing about timings (they only run a quick pass).

pub mod programs;

use std::hint::black_box;
use std::time::Instant;

use serde::Serialize;
use serde_json::{json, Value as Json};

use crate::semantic::{self, Elem};
use crate::sim::{ScanOutcome, Simulator};
use crate::vm::Value;

/// How much work each benchmark does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Effort {
    /// The sizes the issue names (B5 runs a full virtual hour).
    Full,
    /// A smoke pass for CI: tiny sizes, a few repetitions.
    Quick,
}

/// A VM figure with its native baseline.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Paired {
    /// Best wall time of the VM, ms.
    pub vm_ms: f64,
    /// Best wall time of the hand-written Rust, ms.
    pub native_ms: f64,
    /// vm_ms / native_ms.
    pub ratio: f64,
}

/// Why a benchmark could not run (a bug in a benchmark program, reported, never a panic).
#[derive(Debug, Clone, PartialEq)]
pub struct BenchError(pub String);

impl std::fmt::Display for BenchError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "benchmark failed: {}", self.0)
    }
}

fn ms(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1000.0
}

/// The best of `reps` timings of `f`, in ms.
fn best_of(reps: usize, mut f: impl FnMut()) -> f64 {
    (0..reps.max(1))
        .map(|_| {
            let t = Instant::now();
            f();
            ms(t)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Checks and compiles `source` into a simulator for its first PROGRAM.
pub fn load(source: &str) -> Result<Simulator, BenchError> {
    let analysis = semantic::analyze(source);
    let program = analysis.program.ok_or_else(|| {
        let first = analysis.diagnostics.first().map_or(String::new(), |d| d.message.clone());
        BenchError(format!("program does not check: {first}"))
    })?;
    let main = program
        .programs()
        .find(|&p| !program.pou(p).library)
        .ok_or_else(|| BenchError("no PROGRAM".into()))?;
    let mut sim = Simulator::new(program, main).map_err(|e| BenchError(e.to_string()))?;
    sim.set_watchdog(u64::MAX / 2);
    Ok(sim)
}

fn scan(sim: &mut Simulator) -> Result<(), BenchError> {
    match sim.scan() {
        ScanOutcome::Fault(f) => Err(BenchError(f.fault.to_string())),
        _ => Ok(()),
    }
}

fn paired(vm_ms: f64, native_ms: f64) -> Paired {
    Paired { vm_ms, native_ms, ratio: vm_ms / native_ms.max(1e-9) }
}

/// B1: `d := REAL_TO_DINT(a * b)` with changing a and b, `n` iterations in one scan.
pub fn b1(effort: Effort) -> Result<Paired, BenchError> {
    let n = if effort == Effort::Full { 100_000 } else { 1_000 };
    let reps = if effort == Effort::Full { 20 } else { 2 };
    let mut sim = load(&programs::b1(n))?;
    let vm = best_of(reps, || {
        let _ = scan(&mut sim);
    });
    scan(&mut sim)?;
    let native = best_of(reps, || {
        black_box(programs::b1_native(black_box(n)));
    });
    Ok(paired(vm, native))
}

/// B2: worst-case bubble sort of a `n`-element INT array in one scan.
pub fn b2(effort: Effort) -> Result<Paired, BenchError> {
    let n = if effort == Effort::Full { 1_000 } else { 50 };
    let reps = if effort == Effort::Full { 5 } else { 2 };
    let mut sim = load(&programs::b2(n))?;
    scan(&mut sim)?;
    let vm = best_of(reps, || {
        let _ = scan(&mut sim);
    });
    let native = best_of(reps, || {
        black_box(programs::b2_native(black_box(n)));
    });
    Ok(paired(vm, native))
}

/// B3: scan time of CASE OF code for sequences of 10 … 10,000 places (ns per scan), and
/// the ratio largest/smallest.
pub fn b3(effort: Effort) -> Result<Json, BenchError> {
    let sizes: &[usize] =
        if effort == Effort::Full { &[10, 100, 1_000, 10_000] } else { &[10, 100] };
    let scans = if effort == Effort::Full { 200_000 } else { 1_000 };
    let mut per_size = serde_json::Map::new();
    let mut first = None;
    let mut last = 0.0;
    for &places in sizes {
        let mut sim = load(&programs::b3(places))?;
        sim.hold("Go", "TRUE").map_err(|e| BenchError(e.to_string()))?;
        let t = best_of(3, || {
            for _ in 0..scans {
                let _ = scan(&mut sim);
            }
        });
        let ns = t * 1e6 / scans as f64;
        first.get_or_insert(ns);
        last = ns;
        per_size.insert(places.to_string(), json!(ns));
    }
    let ratio = last / first.unwrap_or(1.0).max(1e-9);
    Ok(json!({ "scan_ns": per_size, "ratio": ratio }))
}

/// B5: the weighing example fast-forwarded through one hour of virtual time at 10 ms.
pub fn b5(effort: Effort) -> Result<f64, BenchError> {
    let scans = if effort == Effort::Full { 360_000 } else { 3_600 };
    let mut sim = load(programs::WEIGHING)?;
    sim.hold("Start", "TRUE").map_err(|e| BenchError(e.to_string()))?;
    sim.hold("Setpoint", "500").map_err(|e| BenchError(e.to_string()))?;
    let t = Instant::now();
    for k in 0..scans {
        // A plant that fills while the feed valve is open and empties while discharging.
        let w = (k % 600) as i128 * 2;
        sim.hold_value("Weight", Value::Int(w, Elem::Int))
            .map_err(|e| BenchError(e.to_string()))?;
        scan(&mut sim)?;
    }
    Ok(ms(t))
}

/// B6: check + compile of a generated 5,000-line ST program.
pub fn b6(effort: Effort) -> Result<f64, BenchError> {
    let lines = if effort == Effort::Full { 5_000 } else { 200 };
    let source = programs::b6(lines);
    load(&source)?;
    Ok(best_of(5, || {
        let _ = black_box(load(black_box(&source)));
    }))
}

/// The figures `plc bench` measures, in the order it prints them.
pub const FIGURES: [&str; 5] = ["B1", "B2", "B3", "B5", "B6"];

/// Runs every benchmark and returns the `plc bench --json` object.
pub fn run_all(effort: Effort) -> Result<Json, BenchError> {
    run_selected(effort, &[])
}

/// Runs the figures named in `only` (case-insensitive; every figure when empty) and
/// returns their part of the `plc bench --json` object.
pub fn run_selected(effort: Effort, only: &[String]) -> Result<Json, BenchError> {
    if let Some(bad) = only.iter().find(|o| !FIGURES.iter().any(|f| f.eq_ignore_ascii_case(o))) {
        return Err(BenchError(format!(
            "unknown figure `{bad}` (figures: {})",
            FIGURES.join(", ")
        )));
    }
    let wanted = |f: &str| only.is_empty() || only.iter().any(|o| o.eq_ignore_ascii_case(f));
    let mut out = serde_json::Map::new();
    for f in FIGURES.into_iter().filter(|f| wanted(f)) {
        let v = match f {
            "B1" => json!(b1(effort)?),
            "B2" => json!(b2(effort)?),
            "B3" => b3(effort)?,
            "B5" => json!({ "native_ms": b5(effort)? }),
            _ => json!({ "native_ms": b6(effort)? }),
        };
        out.insert(f.to_string(), v);
    }
    Ok(Json::Object(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_benchmark_program_runs_in_a_quick_pass() {
        let report = run_all(Effort::Quick);
        assert!(report.is_ok(), "{report:?}");
    }

    #[test]
    fn the_vm_and_the_native_baselines_compute_the_same_results() {
        let mut sim = load(&programs::b1(1000)).expect("B1 loads");
        scan(&mut sim).expect("B1 runs");
        let acc = sim.read("acc").expect("acc");
        assert_eq!(
            format!("{:?}", acc),
            format!(
                "{:?}",
                crate::vm::Value::Int(
                    programs::b1_native(1000) as i128,
                    crate::semantic::Elem::DInt
                )
            )
        );
        let mut sim = load(&programs::b2(50)).expect("B2 loads");
        scan(&mut sim).expect("B2 runs");
        assert_eq!(
            format!("{:?}", sim.read("checksum").expect("checksum")),
            format!(
                "{:?}",
                crate::vm::Value::Int(programs::b2_native(50) as i128, crate::semantic::Elem::DInt)
            )
        );
    }
}
