//! `examples/sfc-weighing.st` (docs/weighing.md, sequential version, as a textual SFC)
//! run scan by scan against a simple plant: before each scan the load cell reads 20 more
//! if the feed valve was open after the previous scan, 25 less (not below 0) if the
//! discharge valve was. Setpoint 100, cycle 100 ms; expected scans derived by hand.

mod sfc_common;
use sfc_common::Run;

const EXAMPLE: &str = include_str!("../../examples/sfc-weighing.st");
const STEPS: [&str; 5] = ["Ready", "Alarm", "Filling", "Settling", "Discharging"];

struct Plant {
    run: Run,
    weight: i64,
    scans: usize,
}

impl Plant {
    fn new() -> Plant {
        let mut run = Run::new(EXAMPLE, &["Start", "Fault", "Ack"]);
        run.sim.set_cycle_ns(100_000_000);
        run.sim.hold("Setpoint", "100").unwrap();
        Plant { run, weight: 0, scans: 0 }
    }

    /// One scan with the plant updated from the previous scan's outputs.
    fn scan(&mut self, on: &[&str]) {
        if self.scans > 0 {
            if self.run.bool("FeedValve") {
                self.weight += 20;
            }
            if self.run.bool("DischargeValve") {
                self.weight = (self.weight - 25).max(0);
            }
        }
        self.run.sim.hold("Weight", &self.weight.to_string()).unwrap();
        self.run.scan(on);
        self.scans += 1;
    }

    fn step(&self) -> String {
        let active = self.run.active(&STEPS);
        assert_eq!(active.len(), 1, "a sequential chart has one active step: {active:?}");
        active[0].clone()
    }

    fn outputs(&self) -> [bool; 5] {
        ["ReadyLamp", "AlarmLamp", "FeedValve", "DischargeValve", "Mixer"].map(|o| self.run.bool(o))
    }
}

#[test]
fn one_batch_scan_by_scan() {
    let mut p = Plant::new();
    p.scan(&[]);
    assert_eq!((p.step(), p.outputs()), ("Ready".into(), [true, false, false, false, false]));
    // Scan 2: Start → Filling; the feed valve opens.
    p.scan(&["Start"]);
    assert_eq!((p.step(), p.outputs()), ("Filling".into(), [false, false, true, false, false]));
    // Scans 3..6 read 20, 40, 60, 80: still filling.
    for expected in [20, 40, 60, 80] {
        p.scan(&[]);
        assert_eq!((p.step(), p.run.int("Weight")), ("Filling".into(), expected));
    }
    // Scan 7 reads 100 = Setpoint: settling, valve closed.
    p.scan(&[]);
    assert_eq!((p.step(), p.outputs()), ("Settling".into(), [false; 5]));
    // Settling.T = 0 in scan 7 and 1.9 s in scan 26; 2 s in scan 27.
    for _ in 8..=26 {
        p.scan(&[]);
    }
    assert_eq!((p.step(), p.run.ms("Settling.T")), ("Settling".into(), 1900));
    p.scan(&[]);
    assert_eq!((p.step(), p.outputs()), ("Discharging".into(), [false, false, false, true, true]));
    assert_eq!((p.run.ms("Settling.T"), p.run.int("Batches")), (2000, 1), "S.T kept; P1 ran");
    // Scans 28..30 read 75, 50, 25; scan 31 reads 0 <= 5: ready again.
    for expected in [75, 50, 25] {
        p.scan(&[]);
        assert_eq!((p.step(), p.run.int("Weight")), ("Discharging".into(), expected));
    }
    p.scan(&[]);
    assert_eq!((p.step(), p.outputs()), ("Ready".into(), [true, false, false, false, false]));
    assert_eq!((p.scans, p.run.int("Batches")), (31, 1));
}

#[test]
fn a_fault_goes_to_the_alarm_from_any_step_and_ack_returns_to_ready() {
    let mut p = Plant::new();
    p.scan(&[]);
    p.scan(&["Start", "Fault"]);
    assert_eq!(p.step(), "Alarm", "Fault (priority 0) wins over Start in Ready");
    p.scan(&["Fault", "Ack"]);
    assert_eq!(p.step(), "Alarm", "no acknowledgement while the fault lasts");
    p.scan(&["Ack"]);
    assert_eq!(p.step(), "Ready");
    p.scan(&["Start"]);
    p.scan(&[]);
    assert_eq!((p.step(), p.run.int("Weight")), ("Filling".into(), 20));
    p.scan(&["Fault"]);
    assert_eq!((p.step(), p.outputs()), ("Alarm".into(), [false, true, false, false, false]));
}

#[test]
fn a_cold_restart_returns_to_ready_and_clears_the_batch_count() {
    let mut p = Plant::new();
    p.scan(&[]);
    p.scan(&["Start"]);
    p.run.sim.cold_restart();
    p.scans = 0;
    p.weight = 0;
    p.scan(&[]);
    assert_eq!((p.step(), p.run.int("Batches")), ("Ready".into(), 0));
}

/// `plc run --json` shows the steps (`Filling.X`) but none of the lowering's bookkeeping.
#[test]
fn the_run_report_hides_the_generated_variables() {
    let options = plc_core::run::RunOptions {
        cycles: 3,
        set: vec![("Start".into(), "TRUE".into())],
        ..Default::default()
    };
    let report = plc_core::run::run_source(EXAMPLE, &options);
    assert_eq!(report.status, plc_core::run::RunStatus::Ok);
    assert_eq!(report.vars["Filling"]["X"], serde_json::json!(true));
    let hidden: Vec<&String> = report.vars.keys().filter(|k| k.starts_with("SFC__")).collect();
    assert!(hidden.is_empty(), "generated variables in the report: {hidden:?}");
    assert!(plc_core::build::is_hidden_variable("sfc__dt"));
    assert!(plc_core::build::is_hidden_variable("LdPow_0_0_1"));
    assert!(plc_core::build::is_hidden_variable("PnScan_pA"));
    assert!(!plc_core::build::is_hidden_variable("Filling"));
}
