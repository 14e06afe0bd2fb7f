//! The worked examples of `examples/` (docs/weighing.md and a two-way traffic light), generated,
//! compiled and run scan by scan with a plant model. The scan numbers are derived by hand
//! in the comments: the virtual clock reads (k − 1) × 100 ms during scan k; the plant adds
//! 25 to the weight after every scan with the feed valve open and removes 50 (down to 0)
//! after every scan with the discharge valve open.
#![allow(clippy::unwrap_used)]

use plc_core::petri::{self, SyncStyle};
use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::sim::{ScanOutcome, Simulator};
use plc_core::vm::Value;

fn example(name: &str) -> Project {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    Project::from_file(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

fn int(sim: &Simulator, var: &str) -> i64 {
    match sim.read(var).unwrap() {
        Value::Int(i, _) => i as i64,
        v => panic!("{var} = {v:?}"),
    }
}

fn bool_(sim: &Simulator, var: &str) -> bool {
    sim.read(var).unwrap() == Value::Bool(true)
}

/// A simulator with a 100 ms cycle and the weighing plant.
struct Plant {
    sim: Simulator,
    weight: i64,
}

impl Plant {
    fn new(project: &Project) -> Plant {
        let mut sim = project_simulator(project, None).unwrap();
        sim.set_cycle_ns(100_000_000);
        let mut plant = Plant { sim, weight: 0 };
        for input in ["Start", "Fault", "Ack"] {
            plant.set(input, false);
        }
        plant
    }

    fn set(&mut self, input: &str, value: bool) {
        self.sim.hold_value(input, Value::Bool(value)).unwrap();
    }

    fn scan(&mut self) {
        self.sim.hold("Weight", &self.weight.to_string()).unwrap();
        assert_eq!(self.sim.scan(), ScanOutcome::Completed);
        if bool_(&self.sim, "FeedValve") {
            self.weight += 25;
        }
        if bool_(&self.sim, "DischargeValve") {
            self.weight = (self.weight - 50).max(0);
        }
    }

    /// Scans until the step variable `var` changes; returns the scan count then.
    fn until_change(&mut self, var: &str) -> u64 {
        let before = int(&self.sim, var);
        for _ in 0..1000 {
            self.scan();
            if int(&self.sim, var) != before {
                return self.sim.scan_count();
            }
        }
        panic!("{var} stayed {before}");
    }
}

#[test]
fn sequential_weighing_runs_a_whole_cycle() {
    let mut plant = Plant::new(&example("weighing-sequential.plcproj.json"));
    plant.scan();
    assert_eq!(int(&plant.sim, "p"), 1);
    assert!(bool_(&plant.sim, "ReadyLamp"));
    // Scan 2: Start fires T(P1,P30) into P31.
    plant.set("Start", true);
    assert_eq!(plant.until_change("p"), 2);
    assert_eq!(int(&plant.sim, "p"), 31);
    plant.set("Start", false);
    // Filling from scan 3: the weight before scan k is 25·(k − 3), which reaches 500 at
    // scan 23, when T(P31,P32) fires.
    plant.scan();
    assert!(bool_(&plant.sim, "FeedValve") && !bool_(&plant.sim, "ReadyLamp"));
    assert_eq!(plant.until_change("p"), 23);
    assert_eq!(int(&plant.sim, "p"), 32);
    // The settle TON starts in scan 23's epilogue (t = 2.2 s), is done at t = 4.2 s
    // (scan 43), and scan 44 fires T(P32,P33).
    assert_eq!(plant.until_change("p"), 44);
    assert_eq!(int(&plant.sim, "p"), 33);
    // Discharging from scan 45 with 525 in the hopper: 525 − 50·n ≤ 5 first before scan 56.
    plant.scan();
    assert!(bool_(&plant.sim, "DischargeValve") && bool_(&plant.sim, "Mixer"));
    assert_eq!(plant.until_change("p"), 56);
    assert_eq!(int(&plant.sim, "p"), 1);
    plant.scan();
    assert!(bool_(&plant.sim, "ReadyLamp") && !bool_(&plant.sim, "DischargeValve"));
}

#[test]
fn warm_restart_resumes_filling_and_cold_restart_returns_to_p1() {
    let mut plant = Plant::new(&example("weighing-sequential.plcproj.json"));
    plant.set("Start", true);
    plant.scan();
    plant.scan();
    plant.set("Start", false);
    for _ in 0..5 {
        plant.scan();
    }
    assert_eq!(int(&plant.sim, "p"), 31);
    plant.sim.warm_restart();
    assert_eq!(int(&plant.sim, "p"), 31, "p is RETAIN");
    plant.scan();
    assert!(bool_(&plant.sim, "FeedValve"), "filling resumes on the first scan");
    plant.sim.cold_restart();
    assert_eq!(int(&plant.sim, "p"), 1);
    plant.scan();
    assert!(bool_(&plant.sim, "ReadyLamp") && !bool_(&plant.sim, "FeedValve"));
}

/// Runs the sequential net into `place`, then raises Fault for one scan.
fn fault_from(project: &Project, var: &str, steps: &[(u64, i64)]) {
    for &(scans_before_fault, expect) in steps {
        let mut plant = Plant::new(project);
        plant.set("Start", true);
        for _ in 0..scans_before_fault {
            plant.scan();
            plant.set("Start", false);
        }
        assert_eq!(int(&plant.sim, var), expect, "after {scans_before_fault} scans");
        plant.set("Fault", true);
        plant.scan();
        assert_eq!(int(&plant.sim, "p"), 20, "Fault in {var} = {expect} reaches P20 on that scan");
        plant.scan();
        assert!(bool_(&plant.sim, "AlarmLamp"));
        assert!(!bool_(&plant.sim, "FeedValve") && !bool_(&plant.sim, "DischargeValve"));
        // Ack while Fault holds does nothing; once Fault is gone, Ack returns to P1.
        plant.set("Ack", true);
        plant.scan();
        assert_eq!(int(&plant.sim, "p"), 20);
        plant.set("Fault", false);
        plant.scan();
        assert_eq!(int(&plant.sim, "p"), 1);
    }
}

#[test]
fn fault_from_any_place_reaches_the_alarm() {
    // From the timeline above: P1 before any scan with Start (0 scans: Start not yet
    // seen), P31 after 5 scans, P32 after 30, P33 after 50; P20 from P20 itself.
    let project = example("weighing-sequential.plcproj.json");
    fault_from(&project, "p", &[(0, 1), (5, 31), (30, 32), (50, 33)]);
}

#[test]
fn concurrent_weighing_forks_and_joins() {
    let project = example("weighing-concurrent.plcproj.json");
    let mut plant = Plant::new(&project);
    plant.scan();
    plant.set("Start", true);
    plant.scan();
    plant.set("Start", false);
    // Scan 2 forks: the main sequence waits in P30, dosing fills, the mixer runs.
    assert_eq!((int(&plant.sim, "p"), int(&plant.sim, "pA"), int(&plant.sim, "pB")), (30, 31, 41));
    assert!(!bool_(&plant.sim, "Mixer"), "the processes start on the next scan");
    plant.scan();
    assert!(bool_(&plant.sim, "Mixer") && bool_(&plant.sim, "FeedValve"));
    // Dosing as in the sequential net: settling after scan 23, discharging after 44,
    // ended after 56. The mixer timer started in scan 2's epilogue (t = 0.1 s), is done
    // at t = 5.1 s (scan 52), and scan 53 ends the mixer.
    let mut changes = Vec::new();
    while int(&plant.sim, "p") == 30 {
        let (a, b) = (int(&plant.sim, "pA"), int(&plant.sim, "pB"));
        plant.scan();
        let n = plant.sim.scan_count();
        if int(&plant.sim, "pA") != a {
            changes.push(("pA", n, int(&plant.sim, "pA")));
        }
        if int(&plant.sim, "pB") != b {
            changes.push(("pB", n, int(&plant.sim, "pB")));
        }
        assert!(n < 200);
    }
    assert_eq!(
        changes,
        vec![
            ("pA", 23, 32),
            ("pA", 44, 33),
            ("pB", 53, 42),
            ("pA", 56, 34),
            // Scan 57: the join moves all three at once.
            ("pA", 57, 0),
            ("pB", 57, 0),
        ]
    );
    assert_eq!(plant.sim.scan_count(), 57);
    assert_eq!(int(&plant.sim, "p"), 1);
}

#[test]
fn concurrent_weighing_is_the_same_with_start_and_end_flags() {
    let steps = example("weighing-concurrent.plcproj.json");
    let mut flags = steps.clone();
    flags.petri[0].options.sync = SyncStyle::Flags;
    let st = petri::compile(&flags.petri[0]).unwrap().generated.st;
    // Each process waits at two places (idle for the fork, ended for the join), so the
    // flags carry the place's label.
    assert!(
        st.contains("PA_Start_0 := TRUE;") && st.contains("IF PA_End_34 AND PB_End_42 THEN"),
        "{st}"
    );
    let (mut a, mut b) = (Plant::new(&steps), Plant::new(&flags));
    for k in 1..=130 {
        for plant in [&mut a, &mut b] {
            plant.set("Start", k == 2 || k == 70);
            plant.set("Fault", k == 100);
            plant.set("Ack", k == 105);
            plant.scan();
        }
        for var in ["p", "pA", "pB"] {
            assert_eq!(int(&a.sim, var), int(&b.sim, var), "{var} at scan {k}");
        }
    }
}

#[test]
fn the_emergency_forces_every_process_from_anywhere() {
    // Fault after 10 scans (filling, mixing), 30 (settling), 55 (mixer ended, dosing
    // discharging): on that very scan the main sequence is in P20, both processes idle.
    let project = example("weighing-concurrent.plcproj.json");
    for before in [0, 10, 30, 55] {
        let mut plant = Plant::new(&project);
        plant.set("Start", true);
        for _ in 0..before {
            plant.scan();
            plant.set("Start", false);
        }
        plant.set("Fault", true);
        plant.scan();
        assert_eq!(
            (int(&plant.sim, "p"), int(&plant.sim, "pA"), int(&plant.sim, "pB")),
            (20, 0, 0)
        );
        assert!(bool_(&plant.sim, "AlarmLamp"), "P20's actions run in the emergency scan");
        assert!(!bool_(&plant.sim, "FeedValve") && !bool_(&plant.sim, "Mixer"));
    }
}

#[test]
fn both_weighing_nets_are_safe_live_reversible_and_covered() {
    for (file, components) in
        [("weighing-sequential.plcproj.json", 1), ("weighing-concurrent.plcproj.json", 3)]
    {
        let project = example(file);
        let pou = &project.petri[0];
        let net = petri::build(&pou.net).unwrap();
        let a = petri::analyze(&net, petri::DEFAULT_BUDGET);
        assert_eq!(
            (a.bounded, a.safe, a.live, a.reversible),
            (Some(true), Some(true), Some(true), Some(true)),
            "{file}"
        );
        assert!(a.deadlocks.is_empty() && a.uncovered.is_empty(), "{file}");
        let compiled = petri::compile(pou).unwrap();
        assert_eq!(compiled.processes.len(), components, "{file}");
        // Every place is in exactly one process: one for the sequential net; the main
        // sequence and one per sub-process in the concurrent one.
        let mut seen = vec![0; net.places()];
        for p in &compiled.processes {
            for &i in &p.places {
                seen[i] += 1;
            }
        }
        assert!(seen.iter().all(|&n| n == 1), "{file}: {seen:?}");
    }
    // Sequential: 5 markings (one per place). Concurrent: P1, P20, and P30 with dosing in
    // one of 4 places × mixer in one of 2: 2 + 8 = 10.
    let states =
        |f: &str| petri::analyze(&petri::build(&example(f).petri[0].net).unwrap(), 1000).states;
    assert_eq!(states("weighing-sequential.plcproj.json"), 5);
    assert_eq!(states("weighing-concurrent.plcproj.json"), 10);
}

#[test]
fn traffic_light_alternates_and_never_shows_green_both_ways() {
    let project = example("traffic-light.plcproj.json");
    let mut sim = project_simulator(&project, None).unwrap();
    sim.set_cycle_ns(100_000_000);
    let mut changes = Vec::new();
    for _ in 0..160 {
        let before = (int(&sim, "pNS"), int(&sim, "pEW"));
        assert_eq!(sim.scan(), ScanOutcome::Completed);
        let ns_go = bool_(&sim, "NsGreen") || bool_(&sim, "NsYellow");
        let ew_go = bool_(&sim, "EwGreen") || bool_(&sim, "EwYellow");
        assert!(!(ns_go && ew_go), "both directions open at scan {}", sim.scan_count());
        assert_eq!(ns_go, !bool_(&sim, "NsRed"));
        assert_eq!(ew_go, !bool_(&sim, "EwRed"));
        let after = (int(&sim, "pNS"), int(&sim, "pEW"));
        if after != before {
            changes.push((sim.scan_count(), after));
        }
    }
    // EwWait (1 s) is done at scan 11 and NsWait (3 s) only at scan 31, so scan 12 gives
    // the crossing to east-west; green 5 s from t = 1.1 s: done at scan 62, yellow from
    // scan 63 (2 s from t = 6.2 s: done at scan 83), red and free at scan 84. North-south
    // has waited long enough: green at scan 85 (t = 8.4 s), yellow at 136, red at 157;
    // east-west's wait restarted at scan 84 and is over, so scan 158 gives it the crossing.
    assert_eq!(
        changes,
        vec![
            (12, (10, 21)),
            (63, (10, 22)),
            (84, (10, 20)),
            (85, (11, 20)),
            (136, (12, 20)),
            (157, (10, 20)),
            (158, (10, 21)),
        ]
    );
}

#[test]
fn priorities_that_process_order_overrides_are_flagged() {
    let mut project = example("traffic-light.plcproj.json");
    let pou = &mut project.petri[0];
    assert!(petri::compile(pou).unwrap().warnings.is_empty());
    // With the crossing's process last, "NS go" and "EW go" are decided by their own
    // directions: the priorities 0 and 1 no longer choose between them.
    pou.net.processes.rotate_left(1);
    let w = petri::compile(pou).unwrap().warnings;
    assert_eq!(w.len(), 1);
    assert_eq!(w[0].code.as_str(), "W0014");
    assert!(
        w[0].message.contains("T1 and T4 both take the token of place Free"),
        "{}",
        w[0].message
    );
}
