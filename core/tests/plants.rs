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

fn boolean(s: &plc_core::sim::Simulator, path: &str) -> bool {
    match s.read(path).unwrap() {
        Value::Bool(b) => b,
        other => panic!("{path} is {other:?}"),
    }
}

/// Runs the tank example with `program` (its reference controller when `None`) for
/// `scans` scans with Auto on and `faults` held, and returns the simulator.
fn tank_run(program: Option<&str>, scans: u32, faults: &[&str]) -> plc_core::sim::Simulator {
    let project = example("tank-plant.plcproj.json");
    let mut s = project_simulator(&project, program).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(s.plant_name(), Some("TankPlant"));
    s.set_cycle_ns(10_000_000);
    s.hold("Auto", "TRUE").unwrap();
    for f in faults {
        s.hold(f, "TRUE").unwrap();
    }
    for _ in 0..scans {
        assert_eq!(s.scan(), ScanOutcome::Completed);
        assert!(!boolean(&s, "TankPlant.DryRun"), "the pump ran dry");
    }
    s
}

/// The tank with its reference controller: an hour of two-point control between the
/// level switches (a fill of 700 l at 30 l/s net, a draw-down at 20 l/s: 58 s a cycle),
/// never over the rim and never dry.
#[test]
fn the_tank_cycles_between_its_switches_for_a_plant_hour() {
    let s = tank_run(None, 360_000, &[]);
    assert_eq!(int(&s, "TankPlant.Faults"), 0);
    let fills = int(&s, "TankPlant.Fills");
    assert!((58..=64).contains(&fills), "{fills} fills in a plant hour");
    assert!(!boolean(&s, "AlarmLamp"));
}

/// The controller with a mistake (it never closes the inlet) runs the tank over.
#[test]
fn the_wrong_controller_runs_the_tank_over() {
    let s = tank_run(Some("TankWrong"), 6_000, &[]);
    assert!(boolean(&s, "TankPlant.Overflow"));
    assert_eq!(int(&s, "TankPlant.Faults"), 1);
}

/// A stuck high switch (the plant's fault input): the reference controller's watchdog
/// closes the inlet and lights the alarm before the tank runs over.
#[test]
fn a_stuck_high_switch_is_caught_before_the_tank_runs_over() {
    let s = tank_run(None, 60_000, &["TankPlant.FaultHighStuck"]);
    assert_eq!(int(&s, "TankPlant.Faults"), 0);
    assert!(boolean(&s, "AlarmLamp"));
    assert!(!boolean(&s, "InletValve"));
}

/// A shipped plant's plant hour: the example, the inputs held, and the plant counters
/// with the range each must end in (`Faults` must end at 0).
struct PlantHour {
    file: &'static str,
    hold: &'static [&'static str],
    counters: &'static [(&'static str, std::ops::RangeInclusive<i128>)],
}

/// Runs a plant hour (360 000 scans of 10 ms) with the example's reference controller and
/// returns the simulator.
fn plant_hour(h: &PlantHour) -> plc_core::sim::Simulator {
    let project = example(h.file);
    let mut s = project_simulator(&project, None).unwrap_or_else(|e| panic!("{e:?}"));
    let plant = s.plant_name().unwrap_or_else(|| panic!("{} has no plant", h.file)).to_string();
    s.set_cycle_ns(10_000_000);
    for input in h.hold {
        s.hold(input, "TRUE").unwrap();
    }
    assert_eq!(s.run_scans(360_000), ScanOutcome::Completed, "{}", h.file);
    assert_eq!(int(&s, &format!("{plant}.Faults")), 0, "{}: faults in a plant hour", h.file);
    for (path, range) in h.counters {
        let v = int(&s, path);
        assert!(range.contains(&v), "{}: {path} = {v}, not in {range:?}", h.file);
    }
    s
}

/// The conveyor: a box every 5 s, every fourth one bad, pushed off by the reject pusher
/// between the photo-eye and the belt's end; 719 boxes in the hour.
#[test]
fn the_conveyor_sorts_its_boxes_for_a_plant_hour() {
    plant_hour(&PlantHour {
        file: "conveyor-plant.plcproj.json",
        hold: &["Start"],
        counters: &[("ConveyorPlant.Good", 530..=545), ("ConveyorPlant.Rejected", 175..=180)],
    });
}

/// The conveyor with its photo-eye stuck (the plant's fault input): bad boxes pass.
#[test]
fn a_stuck_photo_eye_lets_bad_boxes_through() {
    let project = example("conveyor-plant.plcproj.json");
    let mut s = project_simulator(&project, None).unwrap();
    s.set_cycle_ns(10_000_000);
    s.hold("Start", "TRUE").unwrap();
    s.hold("ConveyorPlant.FaultEyeStuck", "TRUE").unwrap();
    assert_eq!(s.run_scans(60_000), ScanOutcome::Completed);
    assert!(int(&s, "ConveyorPlant.Faults") > 0);
    assert_eq!(int(&s, "ConveyorPlant.Rejected"), 0);
}

/// The pedestrian crossing: a pedestrian every 25 s and a car every 4 s; the lights
/// never let a car through while someone is on the road.
#[test]
fn the_crossing_lets_pedestrians_and_cars_through_for_a_plant_hour() {
    plant_hour(&PlantHour {
        file: "traffic-crossing.plcproj.json",
        hold: &[],
        counters: &[("CrossingPlant.Crossings", 138..=143), ("CrossingPlant.Cars", 885..=899)],
    });
}

/// The garage door: a car every 90 s (the driver's remote opens the door, it closes by
/// itself), a dog under the closing door (it reverses), a child's three presses.
#[test]
fn the_garage_door_cycles_for_a_plant_hour() {
    plant_hour(&PlantHour {
        file: "garage-door.plcproj.json",
        hold: &[],
        counters: &[("DoorPlant.Cycles", 39..=40), ("DoorPlant.Cars", 39..=40)],
    });
}

/// The star–delta starter: a start every minute, star for 5 s, the dead time, delta.
#[test]
fn the_star_delta_starter_starts_once_a_minute_for_a_plant_hour() {
    plant_hour(&PlantHour {
        file: "star-delta.plcproj.json",
        hold: &[],
        counters: &[("MotorPlant.Starts", 59..=60)],
    });
}

/// A welded star contactor (the plant's fault input): the controller sees the contact
/// closed without its coil and never closes the main contactor.
#[test]
fn a_welded_star_contactor_is_caught() {
    let project = example("star-delta.plcproj.json");
    let mut s = project_simulator(&project, None).unwrap();
    s.set_cycle_ns(10_000_000);
    s.hold("MotorPlant.FaultStarWelded", "TRUE").unwrap();
    assert_eq!(s.run_scans(30_000), ScanOutcome::Completed);
    assert_eq!(int(&s, "MotorPlant.Faults"), 0);
    assert_eq!(int(&s, "MotorPlant.Starts"), 0);
    assert!(boolean(&s, "FaultLamp"));
}

/// A breakpoint or an exercise's expectation may name the plant's variables.
#[test]
fn conditions_name_the_plants_variables() {
    let project = example("tank-plant.plcproj.json");
    let mut s = project_simulator(&project, Some("TankWrong")).unwrap();
    s.set_cycle_ns(10_000_000);
    s.hold("Auto", "TRUE").unwrap();
    let overflow = s.add_probe("TankPlant.Overflow AND TankPlant.Volume >= 1000.0").unwrap();
    assert!(!s.probe(overflow));
    assert_eq!(s.run_scans(6_000), ScanOutcome::Completed);
    assert!(s.probe(overflow));
    assert!(s.add_probe("TankPlant.Nope").is_err());
}

/// Every shipped plant's scene is bound to variables its programs have; a mistyped one is
/// W0033, naming the widget and the path.
#[test]
fn scenes_name_only_variables_the_programs_have() {
    use plc_core::build::build_project;
    for file in [
        "weighing-plant.plcproj.json",
        "tank-plant.plcproj.json",
        "conveyor-plant.plcproj.json",
        "traffic-crossing.plcproj.json",
        "garage-door.plcproj.json",
        "star-delta.plcproj.json",
    ] {
        let build = build_project(&example(file));
        assert!(build.diagnostics.is_empty(), "{file}: {:?}", build.diagnostics);
    }
    let mut project = example("tank-plant.plcproj.json");
    let scene = project.scene.as_mut().unwrap();
    scene.widgets[5].var = "TankPlant.Volme".into();
    scene.widgets[5].alarm = Some("Overflow".into());
    scene.widgets[0].var = "Auto".into();
    let build = build_project(&project);
    let messages: Vec<String> =
        build.diagnostics.iter().map(|d| format!("{} {}", d.code.as_str(), d.message)).collect();
    assert_eq!(
        messages,
        [
            "W0033 the scene's widget “Tank T1” is bound to `TankPlant.Volme`, which the program does not have",
            "W0033 the scene's widget “Tank T1” is bound to `Overflow`, which the program does not have",
        ]
    );
}

/// Exported as PLCopen XML and imported back, a plant project keeps the PROGRAM it runs,
/// its plant and its scene (in the file's `addData`, which other tools discard), and runs
/// the same.
#[test]
fn a_plant_project_round_trips_through_plcopen_xml() {
    let project = example("tank-plant.plcproj.json");
    let xml = plc_core::plcopen::export(&project);
    assert!(xml.contains("<pouInstance name=\"instance0\" typeName=\"TankControl\"/>"), "{xml}");
    let back = plc_core::open::open_text("tank", &xml).unwrap().project;
    assert_eq!(back.settings.program.as_deref(), Some("TankControl"));
    assert_eq!(back.settings.plant.as_deref(), Some("TankPlant"));
    assert_eq!(back.scene, project.scene);
    let volume = |p: &Project| {
        let mut s = project_simulator(p, None).unwrap();
        s.set_cycle_ns(10_000_000);
        s.hold("Auto", "TRUE").unwrap();
        assert_eq!(s.run_scans(3_000), ScanOutcome::Completed);
        s.read("TankPlant.Volume").unwrap()
    };
    assert_eq!(volume(&back), volume(&project));
}
