//! The timed side of the benchmarks (native builds only: it reads the wall clock): each
//! figure with its repetitions, the `plc bench --json` object and its text rendering.

use std::hint::black_box;
use std::time::Instant;

use serde::Serialize;
use serde_json::{json, Value as Json};

use super::workload::{check_and_compile, err, load, run_weighing, scan, weighing, BenchError};
use super::{ladder, programs};

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

fn paired(vm_ms: f64, native_ms: f64) -> Paired {
    Paired { vm_ms, native_ms, ratio: vm_ms / native_ms.max(1e-9) }
}

/// The best of `reps` timings of `vm` and of `native`, taken alternately, so that both
/// sides see the same moments of a busy machine.
fn best_pair(reps: usize, mut vm: impl FnMut(), mut native: impl FnMut()) -> Paired {
    let (mut best_vm, mut best_native) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..reps.max(1) {
        best_vm = best_vm.min(best_of(1, &mut vm));
        best_native = best_native.min(best_of(1, &mut native));
    }
    paired(best_vm, best_native)
}

/// B1: `d := REAL_TO_DINT(a * b)` with changing a and b, `n` iterations in one scan.
pub fn b1(effort: Effort) -> Result<Paired, BenchError> {
    let n = if effort == Effort::Full { 100_000 } else { 1_000 };
    let reps = if effort == Effort::Full { 30 } else { 2 };
    let mut sim = load(&programs::b1(n))?;
    scan(&mut sim)?;
    Ok(best_pair(
        reps,
        || {
            let _ = scan(&mut sim);
        },
        || {
            black_box(programs::b1_native(black_box(n)));
        },
    ))
}

/// B2: worst-case bubble sort of a `n`-element INT array in one scan.
pub fn b2(effort: Effort) -> Result<Paired, BenchError> {
    let n = if effort == Effort::Full { 1_000 } else { 50 };
    let reps = if effort == Effort::Full { 15 } else { 2 };
    let mut sim = load(&programs::b2(n))?;
    scan(&mut sim)?;
    Ok(best_pair(
        reps,
        || {
            let _ = scan(&mut sim);
        },
        || {
            black_box(programs::b2_native(black_box(n)));
        },
    ))
}

/// B3: scan time of the CASE OF code generated from Petri net cycles of 10 … 10,000 places
/// (ns per scan, best of 15 runs of 20,000 scans, the sizes taken in turn so that all see
/// the same moments of a busy machine), and the ratio largest/smallest.
pub fn b3(effort: Effort) -> Result<Json, BenchError> {
    let sizes: &[usize] =
        if effort == Effort::Full { &[10, 100, 1_000, 10_000] } else { &[10, 100] };
    let (scans, reps) = if effort == Effort::Full { (20_000, 15) } else { (1_000, 2) };
    let mut sims = Vec::with_capacity(sizes.len());
    for &places in sizes {
        let source = programs::b3(places)
            .map_err(|e| BenchError(format!("the {places}-place B3 net does not generate: {e}")))?;
        let mut sim = load(&source)?;
        sim.hold("Go", "TRUE").map_err(|e| BenchError(e.to_string()))?;
        sims.push(sim);
    }
    let mut best = vec![f64::INFINITY; sizes.len()];
    for _ in 0..reps {
        for (sim, best) in sims.iter_mut().zip(&mut best) {
            let t = best_of(1, || {
                for _ in 0..scans {
                    let _ = scan(sim);
                }
            });
            *best = best.min(t);
        }
    }
    let ns: Vec<f64> = best.iter().map(|t| t * 1e6 / scans as f64).collect();
    let per_size: serde_json::Map<String, Json> =
        sizes.iter().zip(&ns).map(|(p, v)| (p.to_string(), json!(v))).collect();
    let ratio = ns.last().copied().unwrap_or(0.0) / ns.first().copied().unwrap_or(1.0).max(1e-9);
    Ok(json!({ "scan_ns": per_size, "ratio": ratio }))
}

/// B4: a ladder POU of 1,000 rungs × 10 elements, lowered and compiled as the product does;
/// ns per element per scan (best of 20 runs of 100 scans), with the scan time.
pub fn b4(effort: Effort) -> Result<Json, BenchError> {
    let (rungs, scans, reps) = if effort == Effort::Full { (1_000, 100, 20) } else { (20, 20, 2) };
    let project = ladder::project(rungs);
    let mut sim = crate::run::project_simulator(&project, None).map_err(|d| {
        BenchError(
            d.first().map_or("the ladder POU does not compile".into(), |d| d.message.clone()),
        )
    })?;
    sim.set_watchdog(u64::MAX / 2);
    for i in (1..ladder::INPUTS).step_by(3) {
        sim.hold(&format!("I{i}"), "TRUE").map_err(|e| BenchError(e.to_string()))?;
    }
    scan(&mut sim)?;
    let t = best_of(reps, || {
        for _ in 0..scans {
            let _ = scan(&mut sim);
        }
    });
    let scan_ns = t * 1e6 / scans as f64;
    let elements = rungs * ladder::ELEMENTS_PER_RUNG;
    Ok(json!({
        "ns_per_element": scan_ns / elements as f64,
        "scan_us": scan_ns / 1000.0,
        "elements": elements,
    }))
}

/// B5: the weighing example against its plant, fast-forwarded through one hour of virtual
/// time at 10 ms (360,000 scans); wall time in ms.
pub fn b5(effort: Effort) -> Result<Json, BenchError> {
    let scans = if effort == Effort::Full { 360_000 } else { 3_600 };
    let mut sim = weighing()?;
    let t = Instant::now();
    let batches = run_weighing(&mut sim, scans)?;
    let native_ms = ms(t);
    Ok(json!({ "native_ms": native_ms, "scans": scans, "batches": batches }))
}

/// B6: check + compile of a generated 5,000-line ST program (best of 5), in ms.
pub fn b6(effort: Effort) -> Result<Json, BenchError> {
    let lines = if effort == Effort::Full { 5_000 } else { 200 };
    let source = programs::b6(lines);
    let instructions = check_and_compile(&source)?;
    let native_ms = best_of(5, || {
        let _ = black_box(check_and_compile(black_box(&source)));
    });
    Ok(
        json!({ "native_ms": native_ms, "lines": source.lines().count(), "instructions": instructions }),
    )
}

/// B7: ns per scan of the weighing controller alone, and with its plant PROGRAM run after
/// it on every scan (`examples/weighing-plant.plcproj.json`), Start held, best of 3 runs.
/// Alone, nothing moves the scale, so the controller stays filling; with its plant it
/// goes through every step.
pub fn b7(effort: Effort) -> Result<Json, BenchError> {
    let scans: u64 = if effort == Effort::Full { 360_000 } else { 3_600 };
    let with_plant = crate::project::Project::from_file(programs::WEIGHING_PLANT).map_err(err)?;
    let mut alone = with_plant.clone();
    alone.settings.plant = None;
    let per_scan = |project: &crate::project::Project| -> Result<f64, BenchError> {
        let mut sim = crate::run::project_simulator(project, None).map_err(|d| {
            BenchError(d.first().map_or("B7 does not build".into(), |d| d.message.clone()))
        })?;
        sim.set_watchdog(u64::MAX / 2);
        sim.hold("Start", "TRUE").map_err(err)?;
        let mut failed = None;
        let t = best_of(3, || {
            for _ in 0..scans {
                if let Err(e) = scan(&mut sim) {
                    failed = Some(e);
                    return;
                }
            }
        });
        match failed {
            Some(e) => Err(e),
            None => Ok(t * 1e6 / scans as f64),
        }
    };
    let controller_ns = per_scan(&alone)?;
    let with_plant_ns = per_scan(&with_plant)?;
    Ok(json!({
        "controller_ns": controller_ns,
        "with_plant_ns": with_plant_ns,
        "ratio": with_plant_ns / controller_ns.max(1e-9),
        "scans": scans,
    }))
}

/// B8, recording (issue 36): the cost of keeping the history — B1 and B5 with recording on
/// against off (best of several runs each, taken alternately) — the memory one simulated
/// hour of the weighing plant (B7's project, Start held) takes, and the time to show any
/// scan of that hour again (`Simulator::view_at`, 200 scans spread over it: mean and
/// worst) and to explain one (`why::explain`).
pub fn b8(effort: Effort) -> Result<Json, BenchError> {
    let full = effort == Effort::Full;
    let (n, reps) = if full { (100_000, 30) } else { (1_000, 2) };
    let mut off = load(&programs::b1(n))?;
    let mut on = load(&programs::b1(n))?;
    on.set_recording(true).map_err(err)?;
    scan(&mut off)?;
    scan(&mut on)?;
    let b1 = best_pair(
        reps,
        || {
            let _ = scan(&mut on);
        },
        || {
            let _ = scan(&mut off);
        },
    );
    let scans = if full { 360_000 } else { 3_600 };
    let (mut b5_on, mut b5_off) = (f64::INFINITY, f64::INFINITY);
    let mut hour_b5 = 0usize;
    for _ in 0..if full { 3 } else { 1 } {
        let mut sim = weighing()?;
        let t = Instant::now();
        run_weighing(&mut sim, scans)?;
        b5_off = b5_off.min(ms(t));
        let mut sim = weighing()?;
        sim.set_recording(true).map_err(err)?;
        let t = Instant::now();
        run_weighing(&mut sim, scans)?;
        b5_on = b5_on.min(ms(t));
        hour_b5 = sim.recording().map_or(0, |r| r.bytes);
    }
    let project = crate::project::Project::from_file(programs::WEIGHING_PLANT).map_err(err)?;
    let build = crate::build::build_project(&project);
    let mut sim = build
        .simulator_with_plant(
            build.chosen_program(&project.settings),
            project.settings.plant.as_deref(),
        )
        .map_err(|d| BenchError(d.message))?;
    sim.set_watchdog(u64::MAX / 2);
    sim.set_recording(true).map_err(err)?;
    sim.hold("Start", "TRUE").map_err(err)?;
    for _ in 0..scans {
        scan(&mut sim)?;
    }
    let kept = sim.recording().ok_or_else(|| BenchError("recording is off".into()))?;
    let (mut worst, mut total) = (0f64, 0f64);
    let probes = 200u64;
    for k in 0..probes {
        // Spread over the hour, and each one interval minus one past a snapshot: the
        // longest replay.
        let at = (kept.first + k * (kept.last - kept.first) / probes)
            .saturating_add(kept.interval - 1)
            .min(kept.last);
        let t = Instant::now();
        black_box(sim.view_at(at).map_err(err)?);
        let took = ms(t);
        worst = worst.max(took);
        total += took;
    }
    let ctx = crate::why::Context::new(&project, &build);
    let t = Instant::now();
    let why = crate::why::explain(&ctx, &sim, "DischargeValve", kept.last - 1).map_err(err)?;
    let why_ms = ms(t);
    black_box(why);
    Ok(json!({
        "b1_off_ms": b1.native_ms,
        "b1_on_ms": b1.vm_ms,
        "b1_ratio": b1.ratio,
        "b5_off_ms": b5_off,
        "b5_on_ms": b5_on,
        "b5_ratio": b5_on / b5_off.max(1e-9),
        "b5_recording_mb": hour_b5 as f64 / 1e6,
        "hour_mb": kept.bytes as f64 / 1e6,
        "hour_first": kept.first,
        "hour_scans": kept.last,
        "interval": kept.interval,
        "view_mean_ms": total / probes as f64,
        "view_max_ms": worst,
        "why_ms": why_ms,
    }))
}

/// The figures `plc bench` measures, in the order it prints them.
pub const FIGURES: [&str; 8] = ["B1", "B2", "B3", "B4", "B5", "B6", "B7", "B8"];

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
            "B4" => b4(effort)?,
            "B5" => b5(effort)?,
            "B6" => b6(effort)?,
            "B7" => b7(effort)?,
            _ => b8(effort)?,
        };
        out.insert(f.to_string(), v);
    }
    Ok(Json::Object(out))
}

/// The `plc bench` object as a table a person reads (figures absent from it are skipped).
/// After a quick pass the goals are not judged: the sizes are too small to mean anything.
pub fn report_text(report: &Json, effort: Effort) -> String {
    let line = |name: &str, result: String, goal: &str, met: bool| {
        let status = match (effort, met) {
            (Effort::Quick, _) => "(quick pass: not judged)",
            (Effort::Full, true) => "met",
            (Effort::Full, false) => "NOT MET",
        };
        format!("{name:<4} {result:<52} goal {goal:<22} {status}\n")
    };
    let num = |f: &str, k: &str| report[f][k].as_f64().unwrap_or(f64::NAN);
    let mut out = String::new();
    for f in ["B1", "B2"] {
        if report.get(f).is_some() {
            let r = num(f, "ratio");
            let text = format!(
                "VM {:.2} ms / native {:.2} ms = {r:.1}x",
                num(f, "vm_ms"),
                num(f, "native_ms")
            );
            out += &line(f, text, "ratio <= 8", r <= 8.0);
        }
    }
    if let Some(b3) = report.get("B3") {
        let sizes: Vec<String> = b3["scan_ns"]
            .as_object()
            .map(|m| {
                m.iter().map(|(k, v)| format!("{k}: {:.0}", v.as_f64().unwrap_or(0.0))).collect()
            })
            .unwrap_or_default();
        let r = num("B3", "ratio");
        let text = format!("ns/scan {}; ratio {r:.2}", sizes.join(", "));
        out += &line("B3", text, "ratio <= 1.1", r <= 1.1);
    }
    if report.get("B4").is_some() {
        let n = num("B4", "ns_per_element");
        let text = format!("{n:.2} ns per element ({:.1} us per scan)", num("B4", "scan_us"));
        out += &line("B4", text, "<= 5 ns per element", n <= 5.0);
    }
    if report.get("B5").is_some() {
        let t = num("B5", "native_ms");
        let text = format!("{t:.0} ms for {} scans (native)", report["B5"]["scans"]);
        out += &line("B5", text, "<= 1000 ms (Chromium)", t <= 1000.0);
    }
    if report.get("B7").is_some() {
        let r = num("B7", "ratio");
        let text = format!(
            "{:.0} ns/scan with the plant / {:.0} alone = {r:.2}x",
            num("B7", "with_plant_ns"),
            num("B7", "controller_ns")
        );
        out += &line("B7", text, "ratio <= 2", r <= 2.0);
    }
    if report.get("B6").is_some() {
        let t = num("B6", "native_ms");
        let text = format!("{t:.1} ms for {} lines (native)", report["B6"]["lines"]);
        out += &line("B6", text, "<= 50 ms native", t <= 50.0);
    }
    if report.get("B8").is_some() {
        let (r1, r5) = (num("B8", "b1_ratio"), num("B8", "b5_ratio"));
        let (mb, view) = (num("B8", "hour_mb"), num("B8", "view_max_ms"));
        let text = format!(
            "recording on: B1 {r1:.2}x, B5 {r5:.2}x; hour {mb:.1} MB; view <= {view:.2} ms"
        );
        let met = r1 <= 1.1 && r5 <= 1.1 && mb <= 64.0 && report["B8"]["hour_first"] == 0;
        out += &line("B8", text, "<= 1.1x, <= 64 MB", met);
    }
    out
}
