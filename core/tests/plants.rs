#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Shipped plants (issue 17): each runs with its reference controller without a fault,
//! and does what the process it models does.

use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::sim::ScanOutcome;
use plc_core::vm::Value;

fn example(name: &str) -> Project {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    Project::from_file(&std::fs::read_to_string(&path).expect("example")).expect("project")
}

fn int(s: &plc_core::sim::Simulator, path: &str) -> i128 {
    match s.read(path).unwrap() {
        Value::Int(v, _) => v,
        other => panic!("{path} is {other:?}"),
    }
}

/// The weighing process with its plant: started, it fills to the setpoint, settles,
/// discharges and starts again, batch after batch, for an hour of plant time; the
/// scale never reads past the setpoint by more than one scan's inflow.
#[test]
fn the_weighing_plant_runs_batch_after_batch() {
    let project = example("weighing-plant.plcproj.json");
    let mut s = project_simulator(&project, None).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(s.plant_name(), Some("WeighingPlant"));
    s.set_cycle_ns(10_000_000);
    s.hold("Start", "TRUE").unwrap();
    let mut highest = 0;
    let mut filling_seen = false;
    for _ in 0..360_000 {
        assert_eq!(s.scan(), ScanOutcome::Completed);
        let w = int(&s, "Weight");
        highest = highest.max(w);
        filling_seen |= s.read("FeedValve").unwrap() == Value::Bool(true) && w > 0;
    }
    assert!(filling_seen);
    assert!(highest <= 505, "the scale read {highest}");
    let batches = int(&s, "WeighingPlant.Batches");
    // A batch: 1.25 s filling, 2 s settling, 0.63 s discharging.
    assert!((900..=940).contains(&batches), "{batches} batches in a plant hour");
}
