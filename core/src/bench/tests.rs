//! The benchmark programs run and compute what their hand-written twins compute.

use super::programs;
use super::workload::{check_and_compile, load, run_weighing, scan, weighing};
use crate::semantic::Elem;
use crate::vm::Value;

#[cfg(not(target_arch = "wasm32"))]
#[test]
fn every_benchmark_program_runs_in_a_quick_pass() {
    let report = super::run_all(super::Effort::Quick).expect("quick pass");
    for f in super::FIGURES {
        assert!(report.get(f).is_some(), "{f} missing from {report}");
    }
    let text = super::report_text(&report, super::Effort::Quick);
    assert_eq!(text.lines().count(), super::FIGURES.len(), "{text}");
    assert!(!text.contains("NOT MET") && !text.contains(" met"), "{text}");
}

#[cfg(not(target_arch = "wasm32"))]
#[test]
fn an_unknown_figure_is_an_error() {
    let r = super::run_selected(super::Effort::Quick, &["B9".to_string()]);
    assert!(r.is_err_and(|e| e.0.contains("unknown figure `B9`")));
}

#[test]
fn the_vm_and_the_native_baselines_compute_the_same_results() {
    let mut sim = load(&programs::b1(1000)).expect("B1 loads");
    scan(&mut sim).expect("B1 runs");
    assert_eq!(
        sim.read("acc").expect("acc"),
        Value::Int(i128::from(programs::b1_native(1000)), Elem::DInt)
    );
    let mut sim = load(&programs::b2(50)).expect("B2 loads");
    scan(&mut sim).expect("B2 runs");
    assert_eq!(
        sim.read("checksum").expect("checksum"),
        Value::Int(i128::from(programs::b2_native(50)), Elem::DInt)
    );
}

#[test]
fn the_weighing_plant_runs_whole_batches() {
    // One batch: fill 0 → 500 at 4 per scan (125 scans), settle 2 s (200 scans), drain
    // 500 → 0 at 8 per scan (63 scans), back to P1 and start again: about 390 scans.
    let mut sim = weighing().expect("loads");
    let batches = run_weighing(&mut sim, 3_600).expect("runs");
    assert!((8..=10).contains(&batches), "{batches} batches in 36 s");
}

#[test]
fn the_ladder_benchmark_compiles_and_latches() {
    let project = super::ladder::project(3);
    let mut sim = crate::run::project_simulator(&project, None).expect("compiles");
    // Rung 0 reads I{(7k + 13 salt) mod 64}: Start I0, Perm1 I13, NC Stop I26, the
    // previous coil (I0 on the first rung), NC I39, I52, NC I1; the seal-in branch Q0 and
    // Perm2 I14 bypasses Start and Perm1.
    for on in ["I0", "I13", "I52"] {
        sim.hold(on, "TRUE").expect("input");
    }
    scan(&mut sim).expect("scan");
    assert_eq!(sim.read("Q0").expect("Q0"), Value::Bool(true));
    // Releasing Perm1 keeps the coil through the seal-in branch (Q0 and Perm2)…
    sim.hold("I14", "TRUE").expect("input");
    sim.hold("I13", "FALSE").expect("input");
    scan(&mut sim).expect("scan");
    assert_eq!(sim.read("Q0").expect("Q0"), Value::Bool(true));
    // …and the normally closed Stop drops it.
    sim.hold("I26", "TRUE").expect("input");
    scan(&mut sim).expect("scan");
    assert_eq!(sim.read("Q0").expect("Q0"), Value::Bool(false));
    // Without Perm2 the coil stays off once Stop is released again.
    sim.hold("I26", "FALSE").expect("input");
    sim.hold("I14", "FALSE").expect("input");
    scan(&mut sim).expect("scan");
    assert_eq!(sim.read("Q0").expect("Q0"), Value::Bool(false));
}

#[test]
fn b6_source_has_the_asked_size_and_compiles() {
    let src = programs::b6(5_000);
    assert!(src.lines().count() >= 5_000);
    assert!(check_and_compile(&src).expect("compiles") > 5_000);
}

#[test]
fn b3_runs_the_code_the_petri_net_generator_writes_for_a_cycle() {
    let places = 1_000;
    let source = programs::b3(places).expect("the cycle generates");
    assert_eq!(
        source,
        crate::petri::compile(&programs::b3_net(places)).expect("compiles").generated.st
    );
    let branches =
        source.lines().filter(|l| l.trim_end().ends_with(" *)") && l.contains(": (*")).count();
    assert_eq!(branches, places, "one CASE branch per place:\n{}", &source[..400]);
    let mut sim = load(&source).expect("B3 loads");
    sim.hold("Go", "TRUE").expect("Go");
    for _ in 0..places + 3 {
        scan(&mut sim).expect("scan");
    }
    // One place's action and one firing per scan: round the cycle once and three more.
    assert_eq!(sim.read("n").expect("n"), Value::Int(1_003, Elem::DInt));
    assert_eq!(sim.read("p").expect("p"), Value::Int(4, Elem::Int));
}
