//! PLCopen XML import/export: the project's sample files, hand-written LD snippets, errors,
//! round trips. The samples are `tests/samples/*.xml` of this repository, written for the
//! project in the dialects of OpenPLC Editor and Beremiz; each says in its first comment
//! which points of its dialect it exercises (`tests/samples/README.md` lists them).

use plc_core::ladder::{st_view, validate, Block, CoilKind, ContactKind, Element, Rung};
use plc_core::plcopen::{export, import, load};
use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::vm::Value;

/// The path of the sample `NAME` in the repository's `tests/samples/`.
fn sample_path(name: &str) -> String {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/samples")
        .join(name)
        .display()
        .to_string()
}

fn sample(name: &str) -> plc_core::plcopen::Import {
    load(&sample_path(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn st_errors(p: &Project) -> Vec<String> {
    plc_core::semantic::analyze(&p.source)
        .diagnostics
        .iter()
        .filter(|d| format!("{:?}", d.severity).contains("Error"))
        .map(|d| d.message.clone())
        .collect()
}

fn norm(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn elements(r: &Rung) -> Vec<&Element> {
    r.cells
        .iter()
        .flatten()
        .map(|c| &c.element)
        .filter(|e| !matches!(e, Element::Empty | Element::Wire | Element::Covered))
        .collect()
}

fn assert_round_trip(p: &Project) {
    let xml = export(p);
    let back = import(&xml).unwrap_or_else(|e| panic!("re-import failed: {e}\n{xml}")).project;
    assert_eq!(norm(&back.source), norm(&p.source), "ST differs after round trip");
    assert_eq!(back.ladder, p.ladder, "ladder differs after round trip");
    assert_eq!(back.name, p.name);
    assert_eq!(back.settings.cycle_ms, p.settings.cycle_ms);
}

#[test]
fn latch_with_a_negated_seal_in_is_kept_as_drawn() {
    let i = sample("ld_latch_negated_seal_in.xml");
    let p = &i.project;
    assert!(i.warnings.is_empty(), "{:?}", i.warnings);
    assert_eq!(p.settings.cycle_ms, 100, "the task interval T#100ms");
    assert_eq!(p.ladder.len(), 1);
    let lp = &p.ladder[0];
    assert_eq!(lp.name, "Conveyor");
    assert_eq!(lp.rungs.len(), 1);
    assert!(lp.declarations.contains("Run_PB AT %I0.0 : BOOL := FALSE; (* Run push button *)"));
    assert!(lp
        .declarations
        .contains("Belt_Motor AT %Q0.0 : BOOL := FALSE; (* Belt motor contactor *)"));
    let r = &lp.rungs[0];
    assert_eq!(r.rows(), 2);
    assert!(r.comment.starts_with("Belt conveyor: Run starts the belt"), "{}", r.comment);
    // Run_PB on row 0, the seal-in contact below it, joined by vertical links, then Halt_PB.
    assert!(
        matches!(&r.cells[0][0].element, Element::Contact { kind: ContactKind::NormallyOpen, operand } if operand == "Run_PB")
    );
    assert!(
        matches!(&r.cells[1][0].element, Element::Contact { kind: ContactKind::NormallyClosed, operand } if operand == "Belt_Motor")
    );
    assert!(
        matches!(&r.cells[0][1].element, Element::Contact { kind: ContactKind::NormallyClosed, operand } if operand == "Halt_PB")
    );
    assert!(r.cells[0][0].link_down && r.cells[0][1].link_down);
    assert!(
        matches!(&r.cells[0][r.columns() - 1].element, Element::Coil { kind: CoilKind::Normal, operand } if operand == "Belt_Motor")
    );
    assert_round_trip(p);
    // The seal-in drawn NC: Belt_Motor := (Run_PB OR NOT Belt_Motor) AND NOT Halt_PB, so
    // with no button pressed the belt turns on and off on alternate scans, as on the PLC.
    let mut s = project_simulator(p, None).unwrap_or_else(|e| panic!("{e:?}"));
    let belt: Vec<bool> = (0..4)
        .map(|_| {
            s.scan();
            s.read("Belt_Motor").unwrap() == Value::Bool(true)
        })
        .collect();
    assert_eq!(belt, [true, false, true, false]);
    // Halt held: off whatever the seal-in says.
    s.write("Halt_PB", "TRUE").unwrap();
    s.scan();
    s.scan();
    assert_eq!(s.read("Belt_Motor").unwrap(), Value::Bool(false));
}

#[test]
fn five_rungs_on_one_shared_rail_split_and_run() {
    let i = sample("ld_five_rungs_shared_rail.xml");
    assert!(i.warnings.is_empty(), "{:?}", i.warnings);
    let lp = &i.project.ladder[0];
    assert_eq!(lp.rungs.len(), 5);
    // The rungs come in drawing order (top to bottom), not in the file's element order.
    let coils: Vec<String> = lp
        .rungs
        .iter()
        .flat_map(|r| {
            elements(r).into_iter().filter_map(|e| match e {
                Element::Coil { operand, .. } => Some(operand.clone()),
                _ => None,
            })
        })
        .collect();
    assert_eq!(coils, ["L1", "L2", "L3", "L4", "L5"]);
    // L2 and L5 OR two series branches: two rows each; the others one.
    let rows: Vec<usize> = lp.rungs.iter().map(Rung::rows).collect();
    assert_eq!(rows, [1, 2, 1, 1, 2]);
    let contacts: Vec<usize> = lp.rungs.iter().map(|r| elements(r).len() - 1).collect();
    assert_eq!(contacts, [3, 4, 2, 2, 4]);
    assert_round_trip(&i.project);
    // Every lamp follows its rung's logic for all eight input combinations.
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    for bits in 0..8u32 {
        let [s1, s2, s3] = [0, 1, 2].map(|k| bits & (1 << k) != 0);
        for (name, on) in [("S1", s1), ("S2", s2), ("S3", s3)] {
            s.write(name, if on { "TRUE" } else { "FALSE" }).unwrap();
        }
        s.scan();
        let expected = [
            s1 && s2 && !s3,
            (s1 && !s2) || (!s1 && s3),
            !s1 && !s2,
            s3 && !s2,
            (s2 && s3) || (!s3 && s1),
        ];
        let lamps = ["L1", "L2", "L3", "L4", "L5"].map(|l| s.read(l).unwrap() == Value::Bool(true));
        assert_eq!(lamps, expected, "S1 S2 S3 = {s1} {s2} {s3}");
    }
}

#[test]
fn timers_counters_and_set_reset_coils_on_two_rail_pairs() {
    let i = sample("ld_timers_counters_set_reset.xml");
    let lp = &i.project.ladder[0];
    // Four rungs on the first rail pair, two on the second (drawn beside it, higher up):
    // in drawing order, the start rung, the second pair's two, then timer, counter, unload.
    assert_eq!(lp.rungs.len(), 6);
    let first_coil: Vec<String> = lp
        .rungs
        .iter()
        .map(|r| {
            elements(r)
                .into_iter()
                .find_map(|e| match e {
                    Element::Coil { operand, .. } => Some(operand.clone()),
                    _ => None,
                })
                .unwrap_or_default()
        })
        .collect();
    assert_eq!(first_coil, ["CONVEYOR", "RUN_LAMP", "CONVEYOR", "CAPPER", "START", "CAPPER"]);
    let kinds: Vec<CoilKind> = lp
        .rungs
        .iter()
        .flat_map(|r| elements(r))
        .filter_map(|e| match e {
            Element::Coil { kind, .. } => Some(*kind),
            _ => None,
        })
        .collect();
    let count = |k: CoilKind| kinds.iter().filter(|&&x| x == k).count();
    assert_eq!((count(CoilKind::Set), count(CoilKind::Reset), count(CoilKind::Normal)), (5, 8, 2));
    let blocks: Vec<_> = lp
        .rungs
        .iter()
        .flat_map(|r| elements(r))
        .filter_map(|e| match e {
            Element::Block(b) => Some(b.clone()),
            _ => None,
        })
        .collect();
    let ton = blocks.iter().find(|b| b.type_name == "TON").expect("TON");
    assert!(ton.inputs.iter().any(|p| p.name == "PT" && p.operand == "CAP_TIME"));
    let ctu = blocks.iter().find(|b| b.type_name == "CTU").expect("CTU");
    assert!(ctu.inputs.iter().any(|p| p.name == "PV" && p.operand == "BATCH"));
    assert!(ctu.inputs.iter().any(|p| p.name == "R" && p.wired_row.is_some()));
    assert!(
        i.warnings.iter().any(|w| w.message.contains("localId 41")),
        "dangling contact 41 reported: {:?}",
        i.warnings
    );
    assert_eq!(i.warnings.len(), 1, "{:?}", i.warnings);
    assert!(st_errors(&i.project).is_empty());
    assert_round_trip(&i.project);
}

#[test]
fn pump_station_from_the_newer_editor_with_st_function_blocks() {
    let i = sample("ld_new_editor_pump_station.xml");
    let p = &i.project;
    assert_eq!(p.ladder.len(), 1);
    assert_eq!(p.ladder[0].name, "station");
    // One rung per left/right rail pair, whatever their 7-digit localIds.
    assert_eq!(p.ladder[0].rungs.len(), 8);
    assert!(p.source.contains("FUNCTION_BLOCK Mode_Select"));
    assert!(p.source.contains("FUNCTION_BLOCK Pump_Cmd"));
    assert!(p.source.contains("PUMP_MODE"));
    assert_round_trip(p);
    // `Mode := MODE_LOCAL;` inside Mode_Select, whose input is `Mode_Local`: the enumeration
    // value, as the expected type says (warning W0030), so the file builds and runs.
    let build = plc_core::build::build_project(p);
    assert!(!build.has_errors(), "{:?}", build.diagnostics);
    let shadowed = build.diagnostics.iter().filter(|d| d.code.as_str() == "W0030").count();
    assert_eq!(shadowed, 2, "{:?}", build.diagnostics);
    let mut sim = project_simulator(p, None).expect("builds");
    let mode = |sim: &plc_core::sim::Simulator| {
        plc_core::export::value_text(&sim.read("PUMP_CMD0.Selector0.Mode").expect("Mode"))
    };
    sim.write("Local_Switch", "TRUE").expect("Local_Switch");
    assert!(matches!(sim.scan(), plc_core::sim::ScanOutcome::Completed));
    assert_eq!(mode(&sim), "MODE_LOCAL");
    // The FB's output reached its outVariable on the same rung.
    assert_eq!(sim.read("Local_Enabled").unwrap(), Value::Bool(true));
    sim.write("Remote_Switch", "TRUE").unwrap();
    sim.scan();
    assert_eq!(mode(&sim), "MODE_OFF", "both switches: neither mode");
    sim.write("Local_Switch", "FALSE").unwrap();
    sim.scan();
    assert_eq!(mode(&sim), "MODE_REMOTE");
    assert_eq!(sim.read("Remote_Enabled").unwrap(), Value::Bool(true));
    assert_eq!(sim.read("Local_Enabled").unwrap(), Value::Bool(false));
}

#[test]
fn beremiz_programs_in_one_task_with_configuration_globals() {
    let i = sample("st_beremiz_programs_in_one_task.xml");
    let p = &i.project;
    assert!(p.ladder.is_empty());
    assert_eq!(p.settings.cycle_ms, 100);
    let (file, _) = plc_core::syntax::parse(&p.source);
    let pous =
        file.items.iter().filter(|it| matches!(it, plc_core::syntax::ast::Item::Pou(_))).count();
    assert_eq!(pous, 5, "five PROGRAMs");
    assert!(p.source.contains("Phase_t : (idle, heating, venting, alarm) := idle;"));
    assert!(p.source.contains("VAR_GLOBAL"));
    assert!(p.source.contains("VAR CONSTANT"));
    // The only problem: panel's VAR_EXTERNAL whose global lives outside the file.
    let errs = st_errors(p);
    assert!(!errs.is_empty());
    assert!(
        errs.iter().all(|e| e.contains("VAR_EXTERNAL") && e.contains("panel_brightness")),
        "{errs:?}"
    );
    assert_round_trip(p);
    // Given that global, the five programs run in the task's order on one scan: sensors
    // scales the raw reading, climate picks the phase, actuators switch, blinker flashes.
    let mut p = p.clone();
    p.source = p.source.replacen("VAR_GLOBAL\n", "VAR_GLOBAL\n    panel_brightness : DINT;\n", 1);
    assert!(st_errors(&p).is_empty(), "{:?}", st_errors(&p));
    let mut s = project_simulator(&p, None).unwrap_or_else(|e| panic!("{e:?}"));
    // One scan per run of the task (T#100ms).
    s.set_cycle_ns(100_000_000);
    let text = |s: &plc_core::sim::Simulator, v: &str| {
        plc_core::export::value_text(&s.read(v).unwrap_or_else(|e| panic!("{v}: {e:?}")))
    };
    for (raw, phase, heater, vent) in [
        ("150", "heating", "TRUE", "FALSE"), // 15.0 °C < 18.0
        ("180", "idle", "FALSE", "FALSE"),   // 18.0 is not below 18.0
        ("261", "venting", "FALSE", "TRUE"), // 26.1 > 26.0
        ("351", "alarm", "FALSE", "TRUE"),   // 35.1 > 35.0
    ] {
        s.write("raw_temp", raw).unwrap();
        s.scan();
        assert_eq!(
            [text(&s, "phase"), text(&s, "heater_on"), text(&s, "vent_open")],
            [phase, heater, vent],
            "raw_temp {raw}"
        );
    }
    // The alarm lamp: on while scan_count MOD 10 < 5. Scan 4 was the first in alarm.
    let lamp: Vec<String> = (5..=14)
        .map(|_| {
            s.scan();
            text(&s, "instance3.lamp")
        })
        .collect();
    let expected: Vec<&str> = (5..=14).map(|n| if n % 10 < 5 { "TRUE" } else { "FALSE" }).collect();
    assert_eq!(lamp, expected);
    assert_eq!(text(&s, "scan_count"), "14");
}

/// Exports `p` and imports it again: the network POUs come back element for element
/// (positions, pins, wire paths, execution order), the ladder and ST as they were.
fn assert_networks_round_trip(p: &Project) {
    let strip = |p: &Project| {
        let mut nets = p.networks.clone();
        for e in nets.iter_mut().flat_map(|n| n.elements.iter_mut()) {
            e.at = (0, 0);
        }
        for b in nets.iter_mut().flat_map(|n| n.actions.iter_mut().chain(n.transitions.iter_mut()))
        {
            b.at = (0, 0);
        }
        nets
    };
    let xml = export(p);
    let back = import(&xml).unwrap_or_else(|e| panic!("{e}\n{xml}"));
    assert!(!p.networks.is_empty());
    assert_eq!(strip(&back.project), strip(p), "{xml}");
    assert_eq!(back.project.ladder, p.ladder);
}

/// The ST a network POU of `p` runs as.
fn network_st(p: &Project, name: &str) -> String {
    let net = p.networks.iter().find(|n| n.name == name).unwrap_or_else(|| panic!("no {name}"));
    net.to_st().unwrap_or_else(|e| panic!("{name}: {e}")).st
}

#[test]
fn fbd_bodies_are_kept_as_networks_and_the_fbd_sample_builds() {
    let i = sample("fbd_function_and_blocks.xml");
    // Every FBD POU is kept as a network (drawn as in the file), none skipped, no note.
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    let names: Vec<&str> = i.project.networks.iter().map(|n| n.name.as_str()).collect();
    assert_eq!(names, ["Cell", "Guard_Monitor", "GUARD_OK", "Valve_5_2"]);
    assert!(i.warnings.iter().all(|w| !w.message.contains("FBD")), "{:?}", i.warnings);
    // The function answers through the outVariable named like it.
    let function = network_st(&i.project, "GUARD_OK");
    assert!(function.starts_with("FUNCTION GUARD_OK : BOOL"), "{function}");
    assert!(function.contains("GUARD_OK := AND(rec.Closed, rec.Locked);"), "{function}");
    let valve = network_st(&i.project, "Valve_5_2");
    assert!(valve.contains("SR0(S1 := Open_Cmd, R := Close_Cmd);"), "{valve}");
    assert!(valve.contains("Coil_A := SR0.Q1;"), "{valve}");
    let monitor = network_st(&i.project, "Guard_Monitor");
    assert!(monitor.contains("Status.Fault := TRUE;"), "{monitor}");
    assert!(i.project.networks.iter().any(|n| n.to_st().unwrap().st.contains("T_GUARD")));
    assert!(i.project.source.contains("plant_status : T_GUARD;"), "the resource's global");
    assert_networks_round_trip(&i.project);
    // GUARD_OK writes its own input `rec` (W0032, twice), as OpenPLC allows: the file builds.
    let build = plc_core::build::build_project(&i.project);
    let errors: Vec<_> = build.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert!(errors.is_empty(), "{errors:?}");
    assert_eq!(build.diagnostics.iter().filter(|d| d.code.as_str() == "W0032").count(), 2);
    // And runs: ready when the door is closed and locked; the caller's Guard is not
    // changed by the function's writes to its copy; the global member is written and read
    // back; the clamp valve holds its position between the panel's commands.
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    let get = |s: &plc_core::sim::Simulator, v: &str| s.read(v).unwrap() == Value::Bool(true);
    for (closed, locked) in [(false, false), (true, false), (false, true), (true, true)] {
        s.write("Door_Closed", if closed { "TRUE" } else { "FALSE" }).unwrap();
        s.write("Door_Locked", if locked { "TRUE" } else { "FALSE" }).unwrap();
        s.scan();
        assert_eq!(get(&s, "Cell_Ready"), closed && locked, "closed {closed}, locked {locked}");
        assert_eq!(get(&s, "Mirror"), closed);
        assert!(!get(&s, "Guard.Closed") && !get(&s, "Guard.Locked"));
    }
    s.write("Clamp_Open_HMI", "TRUE").unwrap();
    s.scan();
    s.write("Clamp_Open_HMI", "FALSE").unwrap();
    s.scan();
    assert!(get(&s, "Clamp_Coil"), "set, and held");
    s.write("Clamp_Close_HMI", "TRUE").unwrap();
    s.scan();
    assert!(!get(&s, "Clamp_Coil"));
}

/// The lamps of the pedestrian crossing sample (CAR_GREEN, CAR_AMBER, CAR_RED, WALK_GREEN,
/// WALK_FLASH), scan by scan, as the scans at which they change: `(first scan, lamps)`.
/// `press_at`: the request button is held on that scan and the next.
fn crossing_phases(
    s: &mut plc_core::sim::Simulator,
    scans: u32,
    press_at: Option<u32>,
) -> Vec<(u32, [bool; 5])> {
    let lamp = |s: &plc_core::sim::Simulator, v: &str| s.read(v).unwrap() == Value::Bool(true);
    let mut phases: Vec<(u32, [bool; 5])> = Vec::new();
    for k in 1..=scans {
        if let Some(p) = press_at {
            let pressed = if k == p || k == p + 1 { "TRUE" } else { "FALSE" };
            s.write("Request_PB", pressed).unwrap();
        }
        s.scan();
        let lamps =
            ["CAR_GREEN", "CAR_AMBER", "CAR_RED", "WALK_GREEN", "WALK_FLASH"].map(|v| lamp(s, v));
        if phases.last().is_none_or(|(_, l)| *l != lamps) {
            phases.push((k, lamps));
        }
    }
    phases
}

#[test]
fn sfc_crossing_runs_its_cycle_with_fbd_conditions() {
    let i = sample("sfc_pedestrian_crossing.xml");
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    assert!(i.warnings.is_empty(), "{:?}", i.warnings);
    let p = i.project;
    assert_eq!(p.settings.cycle_ms, 50);
    // The chart is kept as drawn (steps, transitions, action blocks at the file's
    // positions) and written back as SFC.
    assert_eq!(p.networks.len(), 1);
    assert_eq!(p.networks[0].language, plc_core::network::NetworkLanguage::Sfc);
    let initial = p.networks[0].elements.iter().find(|e| e.id == "1").unwrap();
    assert_eq!((initial.x, initial.y), (440.0, 190.0));
    assert_networks_round_trip(&p);
    let run = |p: &Project, scans: u32, press_at: Option<u32>| {
        let mut s = project_simulator(p, None).unwrap_or_else(|e| panic!("{e:?}"));
        s.set_cycle_ns(50_000_000);
        crossing_phases(&mut s, scans, press_at)
    };
    const GREEN: [bool; 5] = [true, false, false, false, false];
    const AMBER: [bool; 5] = [false, true, false, false, false];
    const WALK: [bool; 5] = [false, false, true, true, false];
    const FLASH: [bool; 5] = [false, false, true, false, true];
    // A step's timer (IN = the step's boolean action, 50 ms scans) starts with the step and
    // reaches its preset P after P / 50 ms more scans; the transition sees it at the start
    // of the scan after, so a step of preset P lasts P / 50 ms + 1 scans: cars green 121
    // (6 s), amber 41 (2 s), walk 101 (5 s), flashing 41 (2 s), then the jump back to
    // CarsGo, whose timer starts afresh (its input fell when the step was left).
    assert_eq!(
        run(&p, 470, None),
        vec![
            (1, GREEN),
            (122, AMBER),
            (163, WALK),
            (264, FLASH),
            (305, GREEN),
            (426, AMBER),
            (467, WALK)
        ]
    );
    // The request button (R_TRIG_REQ on its rising edge, ORed with the green timer) cuts
    // the green phase short: pressed in scan 60, the edge is seen by the transition at the
    // start of scan 61.
    assert_eq!(
        run(&p, 400, Some(60)),
        vec![(1, GREEN), (61, AMBER), (102, WALK), (203, FLASH), (244, GREEN), (365, AMBER)]
    );
    // Pressed while the pedestrians walk, the edge passes unseen: the transition out of
    // the cars' green is not enabled then.
    assert_eq!(
        run(&p, 430, Some(200)),
        vec![(1, GREEN), (122, AMBER), (163, WALK), (264, FLASH), (305, GREEN), (426, AMBER)]
    );
    // Exported (the chart as textual SFC in an ST body) and imported again, it runs the
    // same cycle.
    let back = import(&export(&p)).unwrap_or_else(|e| panic!("{e}")).project;
    assert_eq!(
        run(&back, 310, None),
        vec![(1, GREEN), (122, AMBER), (163, WALK), (264, FLASH), (305, GREEN)]
    );
}

/// The element of rung `r` at `(row, col)`.
fn at(p: &Project, r: usize, row: usize, col: usize) -> &Element {
    &p.ladder[0].rungs[r].cells[row][col].element
}

fn block_at(p: &Project, r: usize, row: usize, col: usize) -> &Block {
    match at(p, r, row, col) {
        Element::Block(b) => b,
        other => panic!("rung {r} ({row}, {col}) holds {other:?}"),
    }
}

#[test]
fn mixing_plant_lays_out_reset_networks_as_wired_inputs() {
    let i = sample("ld_mixing_plant_shared_address.xml");
    let p = &i.project;
    let lp = &p.ladder[0];
    assert_eq!(lp.rungs.len(), 3, "fill, mix, drain");
    assert!(lp.rungs[0].comment.starts_with("Fill:"), "{}", lp.rungs[0].comment);
    // Rung 1: the set path takes columns 0..3 (START and LOW_SW with the seal-in below,
    // then HIGH_SW and STOP), so FillLatch stands in column 4; its R is wired to HIGH_SW
    // OR STOP, two contacts laid out below the set path's two rows, before the block.
    let fill = block_at(p, 0, 0, 4);
    assert_eq!(fill.instance.as_deref(), Some("FillLatch"));
    let r = &fill.inputs[0];
    assert_eq!((r.name.as_str(), r.operand.as_str()), ("R", ""));
    let row = r.wired_row.expect("R is wired") as usize;
    assert_eq!(row, 2);
    assert!(
        matches!(at(p, 0, row, 3), Element::Contact { kind: ContactKind::NormallyOpen, operand } if operand == "HIGH_SW")
    );
    assert!(
        matches!(at(p, 0, row + 1, 3), Element::Contact { kind: ContactKind::NormallyOpen, operand } if operand == "STOP")
    );
    // The two feed valves hang in parallel from FillLatch's output.
    let last = lp.rungs[0].columns() - 1;
    assert!(matches!(at(p, 0, 0, last), Element::Coil { operand, .. } if operand == "FEED_A"));
    assert!(matches!(at(p, 0, 1, last), Element::Coil { operand, .. } if operand == "FEED_B"));
    // Rung 2: MixLatch's R takes MixEnd, which taps MixTimer's output, besides DRAIN and
    // STOP.
    let mix = block_at(p, 1, 0, 5);
    assert_eq!(mix.instance.as_deref(), Some("MixLatch"));
    assert_eq!(mix.inputs[0].wired_row, Some(1));
    let f_trig = block_at(p, 1, 1, 4);
    assert_eq!(f_trig.instance.as_deref(), Some("MixEnd"));
    assert!(lp.rungs[1].cells[0][4].link_down, "MixEnd hangs from MixTimer's output");
    let timer = block_at(p, 1, 0, 3);
    assert_eq!(timer.instance.as_deref(), Some("MixTimer"));
    assert!(timer.inputs.iter().any(|p| p.name == "PT" && p.operand == "T#3000ms"));
    let (view, _) = st_view(lp);
    assert!(view.contains("FillLatch(S1 := (START AND LOW_SW OR FEED_A) AND NOT HIGH_SW AND NOT STOP, R := HIGH_SW OR STOP);"), "{view}");
    assert!(view.contains("FEED_A := FillLatch.Q1;\nFEED_B := FillLatch.Q1;"), "{view}");
    assert!(
        view.contains(
            "MixTimer(IN := (START AND HIGH_SW OR AGITATOR) AND NOT DRAIN, PT := T#3000ms);"
        ),
        "{view}"
    );
    assert!(view.contains("MixEnd(CLK := MixTimer.Q);"), "{view}");
    assert!(
        view.contains("MixLatch(S1 := MixTimer.Q AND NOT STOP, R := MixEnd.Q OR DRAIN OR STOP);"),
        "{view}"
    );
    assert!(view.contains("DrainLatch(S := (START AND HIGH_SW AND NOT AGITATOR OR DRAIN) AND NOT STOP, R1 := STOP OR NOT LOW_SW);"), "{view}");
    assert!(i.warnings.is_empty(), "{:?}", i.warnings);
    assert!(validate(lp).iter().all(|d| !d.is_error()), "{:?}", validate(lp));
    assert_round_trip(p);
}

/// The plant as its comments describe it: fill with both feed valves, mix for the TP's
/// 3 s, drain, STOP overrides. `LOW_SW` and `HIGH_SW` are TRUE while liquid covers them
/// (the drain rung closes the drain through an NC contact when the low switch uncovers).
#[test]
fn mixing_plant_runs_fill_mix_drain_scan_by_scan() {
    let mut p = sample("ld_mixing_plant_shared_address.xml").project;
    assert_eq!(p.settings.cycle_ms, 25, "the task interval T#25ms");
    // The file puts AGITATOR and DRAIN both at %Q0.2: in one process image, as on the PLC,
    // they are one output, so running the agitator opens the drain.
    let mut same = project_simulator(&p, None).unwrap_or_else(|e| panic!("{e:?}"));
    same.write("AGITATOR", "TRUE").unwrap();
    assert_eq!(same.read("DRAIN").unwrap(), Value::Bool(true));
    same.write("AGITATOR", "FALSE").unwrap();
    assert_eq!(same.read("DRAIN").unwrap(), Value::Bool(false));
    // The plant the comments describe has its own drain output: give it %Q0.3.
    let lp = &mut p.ladder[0];
    assert_eq!(lp.declarations.matches("DRAIN AT %Q0.2").count(), 1);
    lp.declarations = lp.declarations.replace("DRAIN AT %Q0.2", "DRAIN AT %Q0.3");
    let mut s = project_simulator(&p, None).unwrap_or_else(|e| panic!("{e:?}"));
    s.set_cycle_ns(25_000_000);
    let set = |s: &mut plc_core::sim::Simulator, v: &str, on: bool| {
        s.write(v, if on { "TRUE" } else { "FALSE" }).unwrap();
    };
    let get = |s: &plc_core::sim::Simulator, v: &str| s.read(v).unwrap() == Value::Bool(true);
    let outputs =
        |s: &plc_core::sim::Simulator| ["FEED_A", "FEED_B", "AGITATOR", "DRAIN"].map(|v| get(s, v));
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    // Fill: START with liquid over the low switch opens both feed valves, which hold.
    set(&mut s, "LOW_SW", true);
    set(&mut s, "START", true);
    s.scan();
    assert_eq!(outputs(&s), [true, true, false, false]);
    set(&mut s, "START", false);
    s.scan();
    assert_eq!(outputs(&s), [true, true, false, false]);
    // Full: HIGH_SW closes the feed valves.
    set(&mut s, "HIGH_SW", true);
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    // Mix: START on a full tank runs the agitator for MixTimer's 3 s (120 scans of 25 ms).
    set(&mut s, "START", true);
    s.scan();
    assert_eq!(outputs(&s), [false, false, true, false]);
    for k in 1..120 {
        s.scan();
        assert_eq!(outputs(&s), [false, false, true, false], "mixing, scan {k} of the pulse");
    }
    // The pulse ends: MixEnd resets the agitator and, START still held on a full tank, the
    // drain rung opens the drain in the same scan.
    s.scan();
    assert_eq!(outputs(&s), [false, false, false, true]);
    // Drain: the drain holds itself while the level falls, and closes at the low switch.
    set(&mut s, "START", false);
    set(&mut s, "HIGH_SW", false);
    s.scan();
    assert_eq!(outputs(&s), [false, false, false, true]);
    set(&mut s, "LOW_SW", false);
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    // STOP wins: valves opened again close at once, and START cannot open them while held.
    set(&mut s, "LOW_SW", true);
    set(&mut s, "START", true);
    s.scan();
    assert_eq!(outputs(&s), [true, true, false, false]);
    set(&mut s, "STOP", true);
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
}

fn doc(body: &str, vars: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="Snippet"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface><localVars>{vars}</localVars></interface>
      <body><LD>{body}</LD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>"#
    )
}

fn var(name: &str, ty: &str) -> String {
    format!(r#"<variable name="{name}"><type><{ty}/></type></variable>"#)
}

/// OpenPLC style: start with a parallel seal-in, NC stop, coil, wired by refLocalId.
#[test]
fn openplc_style_latch() {
    let vars = ["Start", "Stop", "Motor"].map(|v| var(v, "BOOL")).concat();
    let body = r#"
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="50" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>Start</variable></contact>
<contact localId="3" negated="false"><position x="50" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>Motor</variable></contact>
<contact localId="4" negated="true"><position x="150" y="10"/><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/></connectionPointIn><connectionPointOut/><variable>Stop</variable></contact>
<coil localId="5"><position x="250" y="10"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>Motor</variable></coil>
<rightPowerRail localId="6"><position x="300" y="0"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
<comment localId="7" height="10" width="100"><position x="0" y="-20"/><content><xhtml:p>Latch</xhtml:p></content></comment>"#;
    let i = import(&doc(body, &vars)).unwrap();
    let r = &i.project.ladder[0].rungs[0];
    assert_eq!(r.comment, "Latch");
    assert_eq!(r.rows(), 2);
    assert_eq!(elements(r).len(), 4);
    assert!(matches!(
        &r.cells[0][1].element,
        Element::Contact { kind: ContactKind::NormallyClosed, .. }
    ));
    assert!(r.cells[0][0].link_down && r.cells[0][1].link_down && !r.cells[1][1].link_down);
    assert_round_trip(&i.project);
}

/// Beremiz style: TON with PT from an inVariable and ET to an outVariable.
#[test]
fn beremiz_style_ton_with_in_variable() {
    let vars = [
        var("Go", "BOOL"),
        var("Lamp", "BOOL"),
        var("Elapsed", "TIME"),
        r#"<variable name="T1"><type><derived name="TON"/></type></variable>"#.to_string(),
    ]
    .concat();
    let body = r#"
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2"><position x="50" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>Go</variable></contact>
<inVariable localId="3"><position x="50" y="40"/><connectionPointOut/><expression>T#2s</expression></inVariable>
<block localId="4" typeName="TON" instanceName="T1"><position x="100" y="10"/>
  <inputVariables>
    <variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
    <variable formalParameter="PT"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable>
  </inputVariables><inOutVariables/>
  <outputVariables>
    <variable formalParameter="Q"><connectionPointOut/></variable>
    <variable formalParameter="ET"><connectionPointOut/></variable>
  </outputVariables></block>
<outVariable localId="5"><position x="200" y="40"/><connectionPointIn><connection refLocalId="4" formalParameter="ET"/></connectionPointIn><expression>Elapsed</expression></outVariable>
<coil localId="6"><position x="250" y="10"/><connectionPointIn><connection refLocalId="4" formalParameter="Q"/></connectionPointIn><connectionPointOut/><variable>Lamp</variable></coil>
<rightPowerRail localId="7"><position x="300" y="0"/><connectionPointIn><connection refLocalId="6"/></connectionPointIn></rightPowerRail>"#;
    let i = import(&doc(body, &vars)).unwrap();
    let r = &i.project.ladder[0].rungs[0];
    let Element::Block(b) = &r.cells[0][1].element else { panic!("{:?}", r.cells[0]) };
    assert_eq!(b.type_name, "TON");
    assert_eq!(b.instance.as_deref(), Some("T1"));
    assert_eq!(b.inputs[0].name, "PT");
    assert_eq!(b.inputs[0].operand, "T#2s");
    assert_eq!(b.outputs[0].name, "ET");
    assert_eq!(b.outputs[0].operand, "Elapsed");
    assert_eq!(r.cells[1][1].element, Element::Covered);
    assert_round_trip(&i.project);
}

#[test]
fn non_series_parallel_network_runs_by_power_flow() {
    let vars = ["A", "B", "C", "D", "E", "Y"].map(|v| var(v, "BOOL")).concat();
    let c = |id: u32, v: &str, from: &[u32], y: u32| {
        let conns: String =
            from.iter().map(|f| format!(r#"<connection refLocalId="{f}"/>"#)).collect();
        format!(
            r#"<contact localId="{id}"><position x="0" y="{y}"/><connectionPointIn>{conns}</connectionPointIn><connectionPointOut/><variable>{v}</variable></contact>"#
        )
    };
    // A Wheatstone bridge: C links the middle of two parallel paths.
    let body = [
        r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>"#.to_string(),
        c(2, "A", &[1], 0),
        c(3, "B", &[1], 50),
        c(4, "C", &[2], 25),
        c(5, "D", &[2], 0),
        c(6, "E", &[3, 4], 50),
        r#"<coil localId="7"><position x="0" y="0"/><connectionPointIn><connection refLocalId="5"/><connection refLocalId="6"/></connectionPointIn><connectionPointOut/><variable>Y</variable></coil>"#.to_string(),
    ]
    .concat();
    // It does not fit the rung grid, so it runs by power flow (left to right, as OpenPLC
    // runs it): Y = A·D + (B + A·C)·E.
    let i = import(&doc(&body, &vars)).unwrap();
    assert!(i.project.ladder.is_empty());
    assert_networks_round_trip(&i.project);
    assert!(
        i.warnings.iter().any(|w| w.message.contains("series-parallel")
            && w.message.contains("kept as drawn in the file and runs by power flow")),
        "{:?}",
        i.warnings
    );
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    for bits in 0..32u32 {
        let [a, b, c, d, e] = [0, 1, 2, 3, 4].map(|k| bits & (1 << k) != 0);
        for (name, on) in [("A", a), ("B", b), ("C", c), ("D", d), ("E", e)] {
            s.write(name, if on { "TRUE" } else { "FALSE" }).unwrap();
        }
        s.scan();
        let y = (a && d) || ((b || (a && c)) && e);
        assert_eq!(s.read("Y").unwrap(), Value::Bool(y), "A B C D E = {a} {b} {c} {d} {e}");
    }
}

#[test]
fn unknown_ref_and_garbage_are_errors() {
    let body = r#"<coil localId="5"><position x="0" y="0"/><connectionPointIn><connection refLocalId="99"/></connectionPointIn><variable>Y</variable></coil>"#;
    let e = import(&doc(body, &var("Y", "BOOL"))).unwrap_err();
    assert!(e.to_string().contains("99"), "{e}");
    for bad in ["", "garbage", "<project>", "<a></b>", "<?xml version='1.0'?><root/>", "<project><types><pous><pou/></pous></types></project>", "<project><types><pous><pou name='x' pouType='program'><body><LD><contact/></LD></body></pou></pous></types></project>", "\u{0}\u{1}<<<&&&"] {
        assert!(import(bad).is_err(), "{bad:?} should fail");
    }
}

#[test]
fn st_project_round_trip() {
    let mut p = Project::new("Demo");
    p.source = "TYPE\n    Color : (Red, Green := 5, Blue);\n    Pt : STRUCT\n        x : INT := 1;\n        y : INT;\n    END_STRUCT;\n    Arr : ARRAY[1..3] OF INT := [1, 2, 3];\n    Small : INT(0..10);\nEND_TYPE\n\nVAR_GLOBAL\n    g AT %MW10 : INT := 5; (* a global *)\nEND_VAR\n\nFUNCTION Twice : INT\nVAR_INPUT\n    x : INT;\nEND_VAR\nTwice := x * 2;\nEND_FUNCTION\n\nFUNCTION_BLOCK Fb\nVAR_OUTPUT\n    s : STRING[20] := 'hi';\nEND_VAR\nEND_FUNCTION_BLOCK\n\nPROGRAM Main\nVAR_INPUT\n    Start : BOOL; (* start button *)\nEND_VAR\nVAR RETAIN\n    n : INT;\n    c : Color := Green;\nEND_VAR\nIF Start THEN\n    n := Twice(n) + g; (* comment kept *)\nEND_IF;\nEND_PROGRAM\n".into();
    assert!(st_errors(&p).is_empty(), "{:?}", st_errors(&p));
    let xml = export(&p);
    assert!(xml.contains("xmlns=\"http://www.plcopen.org/xml/tc6_0201\""));
    assert!(xml.contains("<coordinateInfo>"));
    assert!(xml.contains("typeName=\"Main\""));
    assert_round_trip(&p);
    let back = import(&xml).unwrap().project;
    assert!(st_errors(&back).is_empty());
}

#[test]
fn starter_project_round_trip() {
    assert_round_trip(&Project::new("Starter"));
}

/// `plc run FILE --json` and `plc check FILE` (issue 16, the command line's contract):
/// the normal report for every failure, import failures included, located in the file;
/// every import note a located warning in the JSON and the count; a PROGRAM the import
/// left out named as such.
mod command_line {
    use super::sample_path;
    use std::process::{Command, Output};

    fn plc(args: &[&str]) -> Output {
        Command::new(env!("CARGO_BIN_EXE_plc")).args(args).output().unwrap()
    }

    fn json(out: &Output) -> serde_json::Value {
        serde_json::from_slice(&out.stdout)
            .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&out.stdout)))
    }

    #[test]
    fn a_file_that_does_not_import_still_gets_its_report_with_the_place() {
        let dir = std::env::temp_dir().join(format!("plc-contract-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("broken.xml");
        std::fs::write(&file, "<?xml version=\"1.0\"?>\n<project>\n  <types><pous>\n</project>\n")
            .unwrap();
        let file = file.to_string_lossy().into_owned();
        let out = plc(&["run", &file, "--json"]);
        assert_eq!(out.status.code(), Some(2));
        let report = json(&out);
        assert_eq!(report["status"], "error");
        assert_eq!(report["cycles"], 0);
        let d = &report["diagnostics"][0];
        assert_eq!(
            (d["code"].as_str(), d["line"].as_u64(), d["column"].as_u64()),
            (Some("E0304"), Some(4), Some(1))
        );
        assert!(
            d["message"].as_str().unwrap().starts_with("not well-formed XML at line 4, column 1: "),
            "{d}"
        );
        let check = plc(&["check", &file]);
        assert_eq!(check.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&check.stdout).contains("broken.xml:4:1: error[E0304]: "));
        // In Polish, the place and the reason (quick-xml's own words stay English).
        let polish = plc(&["check", "--lang", "pl", &file]);
        assert!(
            String::from_utf8_lossy(&polish.stdout).contains(
                "broken.xml:4:1: error[E0304]: XML nie jest poprawnie sformułowany, wiersz 4, kolumna 1: "
            ),
            "{}",
            String::from_utf8_lossy(&polish.stdout)
        );
        let missing = plc(&["run", "no-such-file.xml", "--json"]);
        assert_eq!(json(&missing)["diagnostics"][0]["code"], "E0304");
    }

    /// The line (from 1) of the first line of `text` holding `needle`.
    fn line_of(text: &str, needle: &str) -> u64 {
        text.lines().position(|l| l.contains(needle)).unwrap_or_else(|| panic!("no {needle}"))
            as u64
            + 1
    }

    #[test]
    fn import_notes_are_located_warnings_in_the_json_and_the_count() {
        let file = sample_path("ld_timers_counters_set_reset.xml");
        // The contact left behind, on a line of its own in a file with CRLF line ends.
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(text.contains("\r\n"));
        let line = line_of(&text, "<contact localId=\"41\"");
        assert_eq!(line, 731);
        let report = json(&plc(&["run", &file, "--json"]));
        assert_eq!(report["status"], "ok");
        let note = report["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .find(|d| d["code"] == "W0031")
            .expect("the skipped element is a warning");
        assert_eq!((note["line"].as_u64(), note["column"].as_u64()), (Some(line), Some(13)));
        assert!(note["message"].as_str().unwrap().contains("localId 41"));
        let check = plc(&["check", &file]);
        let err = String::from_utf8_lossy(&check.stderr);
        assert!(err.contains("0 error(s), 1 warning(s)"), "{err}");
        assert!(String::from_utf8_lossy(&check.stdout).contains(":731:13: warning[W0031]: "));
        // `--lang pl` translates the note and keeps its program text.
        let english = note["message"].as_str().unwrap();
        let polish = plc(&["check", "--lang", "pl", &file]);
        let polish = String::from_utf8_lossy(&polish.stdout);
        let line = polish.lines().find(|l| l.contains(":731:13: warning[W0031]: ")).unwrap();
        assert!(line.contains("localId 41") && !line.contains(english), "{line}");
    }

    #[test]
    fn a_problem_after_multi_byte_headers_is_at_its_place() {
        // The Beremiz sample's headers are Cyrillic (two bytes a character); the VAR_EXTERNAL
        // without a global is located at its <variable> all the same.
        let file = sample_path("st_beremiz_programs_in_one_task.xml");
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(text.len() > text.chars().count(), "multi-byte text before the problem");
        let line = line_of(&text, "<variable name=\"panel_brightness\">");
        assert_eq!(line, 220);
        let check = plc(&["check", &file]);
        assert!(!check.status.success(), "an error: a non-zero exit");
        let out = String::from_utf8_lossy(&check.stdout);
        assert!(out.contains(":220:13: error[E0109]: VAR_EXTERNAL `panel_brightness`"), "{out}");
    }

    #[test]
    fn a_problem_in_an_imported_rung_is_at_its_element_in_the_file() {
        let text = std::fs::read_to_string(sample_path("ld_latch_negated_seal_in.xml")).unwrap();
        assert_eq!(line_of(&text, "<contact localId=\"3\""), 86);
        // The NC contact (localId 3, line 86) reads an undeclared variable.
        let text =
            text.replacen("<variable>Halt_PB</variable>", "<variable>Halt_PBX</variable>", 1);
        let dir = std::env::temp_dir().join(format!("plc-contract-ld-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("latch.xml");
        std::fs::write(&file, text).unwrap();
        let file = file.to_string_lossy().into_owned();
        let report = json(&plc(&["run", &file, "--json"]));
        let d = &report["diagnostics"][0];
        assert_eq!(
            (d["code"].as_str(), d["line"].as_u64(), d["column"].as_u64()),
            (Some("E0418"), Some(86), Some(13)),
            "{d}"
        );
        let check = plc(&["check", &file]);
        assert!(String::from_utf8_lossy(&check.stdout)
            .contains("latch.xml:86:13: error[E0418]: POU Conveyor, rung 1, row 1, column 2:"));
    }

    #[test]
    fn an_element_that_does_not_import_is_located() {
        let text = std::fs::read_to_string(sample_path("ld_latch_negated_seal_in.xml")).unwrap();
        // The NC contact (localId 3, line 86) is wired from an element that does not exist.
        let text = text.replacen(r#"refLocalId="2""#, r#"refLocalId="99""#, 1);
        let dir = std::env::temp_dir().join(format!("plc-contract-el-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("dangling.xml");
        std::fs::write(&file, text).unwrap();
        let out = plc(&["run", &file.to_string_lossy(), "--json"]);
        assert_eq!(out.status.code(), Some(2));
        let d = &json(&out)["diagnostics"][0];
        assert_eq!(
            (d["code"].as_str(), d["line"].as_u64(), d["column"].as_u64()),
            (Some("E0304"), Some(86), Some(13)),
            "{d}"
        );
        assert!(d["message"]
            .as_str()
            .unwrap()
            .contains("localId 3: connection refers to localId 99"));
    }

    /// A PLCopen file whose program `Main` has the ST body `body`, declared in `vars`.
    fn st_file(name: &str, vars: &str, body: &str) -> String {
        let text = super::doc("", vars).replace(
            "<LD></LD>",
            &format!("<ST>\n        <xhtml:p><![CDATA[{body}]]></xhtml:p>\n      </ST>"),
        );
        let dir = std::env::temp_dir().join(format!("plc-contract-st-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join(name);
        std::fs::write(&file, text).unwrap();
        file.to_string_lossy().into_owned()
    }

    /// (code, line, column) of every diagnostic of a `--json` report.
    fn located(report: &serde_json::Value) -> Vec<(String, u64, u64)> {
        report["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .map(|d| {
                let s = |k: &str| d[k].as_str().unwrap().to_string();
                (s("code"), d["line"].as_u64().unwrap(), d["column"].as_u64().unwrap())
            })
            .collect()
    }

    #[test]
    fn problems_in_st_bodies_and_declarations_are_at_their_place_in_the_file() {
        // doc() puts the variables on line 7 and the body's CDATA on line 9, column 28.
        let vars = format!("{}\n{}", super::var("x", "INT"), super::var("b", "BOOL"));
        let file = st_file("st-errors.xml", &vars, "x := 1;\n  b := x;\n  undeclared := 2;");
        let report = json(&plc(&["run", &file, "--json"]));
        assert_eq!(report["status"], "error");
        let text = std::fs::read_to_string(&file).unwrap();
        let line_of = |needle: &str| {
            text.lines().position(|l| l.contains(needle)).map(|k| k as u64 + 1).unwrap()
        };
        let body = line_of("<![CDATA[");
        assert_eq!(
            located(&report),
            vec![
                ("E0150".into(), body + 1, 8), // b := x: INT into BOOL
                ("E0100".into(), body + 2, 3), // undeclared
            ],
            "{report}"
        );
        // The first line of the body starts after `<![CDATA[`.
        let file = st_file("st-first.xml", &vars, "b := 1.5;");
        let column = text.lines().nth(body as usize - 1).unwrap().find("<![CDATA[").unwrap() + 10;
        assert_eq!(
            located(&json(&plc(&["run", &file, "--json"]))),
            vec![("E0150".into(), body, column as u64 + 5)]
        );
        // A runtime fault is at its statement in the file, too.
        let file = st_file("st-fault.xml", &vars, "x := 0;\n  x := 10 / x;");
        let report = json(&plc(&["run", &file, "--json"]));
        assert_eq!(report["status"], "fault", "{report}");
        assert_eq!(
            (report["fault"]["line"].as_u64(), report["fault"]["column"].as_u64()),
            (Some(body + 1), Some(3)),
            "{report}"
        );
        // A declaration problem is at its <variable>.
        let vars = format!(
            "{}\n{}",
            super::var("x", "INT"),
            super::var("y", "derived name=\"NoSuchType\"")
        );
        let file = st_file("st-decl.xml", &vars, "x := 1;");
        let report = json(&plc(&["run", &file, "--json"]));
        let text = std::fs::read_to_string(&file).unwrap();
        let y = text.lines().position(|l| l.contains("name=\"y\"")).unwrap() as u64 + 1;
        assert_eq!(
            located(&report).first().map(|d| (d.0.as_str(), d.1)),
            Some(("E0102", y)),
            "{report}"
        );
    }

    #[test]
    fn a_program_the_import_left_out_is_named() {
        // The crossing's chart, as if it were written in CODESYS's CFC (not a PLCopen
        // language; IL bodies import since issue 18).
        let text = std::fs::read_to_string(sample_path("sfc_pedestrian_crossing.xml"))
            .unwrap()
            .replace("<SFC>", "<CFC>")
            .replace("</SFC>", "</CFC>");
        let dir = std::env::temp_dir().join(format!("plc-contract-il-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("il.xml");
        std::fs::write(&file, text).unwrap();
        let file = file.to_string_lossy().into_owned();
        let report = json(&plc(&["run", &file, "--json"]));
        let messages: Vec<&str> = report["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|d| d["message"].as_str())
            .collect();
        assert!(
            messages.iter().any(|m| m.contains("Crossing") && m.contains("CFC")),
            "{messages:?}"
        );
        assert!(
            messages.contains(&"the file holds no PROGRAM that could be imported: left out Crossing (CFC bodies are not supported yet)"),
            "{messages:?}"
        );
        let asked = json(&plc(&["run", &file, "--program", "Crossing", "--json"]));
        let last = asked["diagnostics"].as_array().unwrap().last().unwrap().clone();
        assert_eq!(last["code"], "E0305");
        assert_eq!(
            last["message"],
            "the PROGRAM Crossing was left out when the file was imported: CFC bodies are not supported yet"
        );
    }
}

/// An FBD body: `<LD>` replaced by `<FBD>` in [`doc`].
fn fbd_doc(body: &str, vars: &str) -> String {
    doc(body, vars).replace("<LD>", "<FBD>").replace("</LD>", "</FBD>")
}

fn inv(id: u32, x: u32, y: u32, expr: &str) -> String {
    format!(
        r#"<inVariable localId="{id}"><position x="{x}" y="{y}"/><connectionPointOut/><expression>{expr}</expression></inVariable>"#
    )
}

fn outv(id: u32, x: u32, y: u32, order: u32, from: u32, param: &str, expr: &str) -> String {
    let param =
        if param.is_empty() { String::new() } else { format!(r#" formalParameter="{param}""#) };
    format!(
        r#"<outVariable localId="{id}" executionOrderId="{order}"><position x="{x}" y="{y}"/><connectionPointIn><connection refLocalId="{from}"{param}/></connectionPointIn><expression>{expr}</expression></outVariable>"#
    )
}

fn blk(
    id: u32,
    x: u32,
    y: u32,
    ty: &str,
    inst: &str,
    inputs: &[(&str, u32)],
    outputs: &[&str],
) -> String {
    let inst = if inst.is_empty() { String::new() } else { format!(r#" instanceName="{inst}""#) };
    let ins: String = inputs
        .iter()
        .map(|(p, from)| format!(r#"<variable formalParameter="{p}"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn></variable>"#))
        .collect();
    let outs: String = outputs
        .iter()
        .map(|p| format!(r#"<variable formalParameter="{p}"><connectionPointOut/></variable>"#))
        .collect();
    format!(
        r#"<block localId="{id}" typeName="{ty}"{inst}><position x="{x}" y="{y}"/><inputVariables>{ins}</inputVariables><inOutVariables/><outputVariables>{outs}</outputVariables></block>"#
    )
}

/// FBD bodies run (issue 16): functions written inline, function blocks as calls, output
/// variables as assignments; feedback reads the previous scan's value.
#[test]
fn an_fbd_body_runs_with_inline_functions_a_timer_and_feedback() {
    let vars = [var("A", "BOOL"), var("B", "BOOL"), var("Q", "BOOL"), var("Cnt", "INT")].concat();
    let body = [
        inv(1, 0, 0, "A"),
        inv(2, 0, 40, "B"),
        blk(3, 100, 0, "AND", "", &[("IN1", 1), ("IN2", 2)], &["OUT"]),
        inv(5, 100, 80, "T#20ms"),
        blk(4, 200, 0, "TON", "T1", &[("IN", 3), ("PT", 5)], &["Q", "ET"]),
        outv(6, 300, 0, 0, 4, "Q", "Q"),
        // Cnt := ADD(Cnt, 1): a feedback loop through a variable.
        inv(8, 0, 200, "Cnt"),
        inv(10, 0, 240, "1"),
        blk(9, 100, 200, "ADD", "", &[("IN1", 8), ("IN2", 10)], &["OUT"]),
        outv(11, 200, 200, 0, 9, "", "Cnt"),
    ]
    .concat();
    let imported = import(&fbd_doc(&body, &vars)).unwrap();
    assert!(imported.skipped.is_empty());
    assert_networks_round_trip(&imported.project);
    let st = network_st(&imported.project, "Main");
    assert!(st.contains("T1(IN := AND(A, B), PT := T#20ms);"), "{st}");
    assert!(st.contains("T1 : TON;"), "the instance is declared");
    let mut sim = project_simulator(&imported.project, None).unwrap();
    sim.hold("A", "TRUE").unwrap();
    sim.hold("B", "TRUE").unwrap();
    let mut q = Vec::new();
    for _ in 0..4 {
        sim.scan();
        q.push(sim.read("Q").unwrap() == Value::Bool(true));
    }
    assert_eq!(q, [false, false, true, true], "TON of 20 ms at a 10 ms cycle");
    assert!(matches!(sim.read("Cnt").unwrap(), Value::Int(4, _)), "Cnt counts one per scan");
}

/// Statements run in `executionOrderId` order when every one has its own, else top to
/// bottom: `X := Y` above `Y := TRUE` reads last scan's Y.
#[test]
fn fbd_statements_follow_the_execution_order_or_the_drawing() {
    let vars = [var("X", "BOOL"), var("Y", "BOOL")].concat();
    let run = |order_x: u32, order_y: u32| {
        let body = [
            inv(1, 0, 0, "Y"),
            outv(2, 100, 0, order_x, 1, "", "X"),
            inv(3, 0, 100, "TRUE"),
            outv(4, 100, 100, order_y, 3, "", "Y"),
        ]
        .concat();
        let imported = import(&fbd_doc(&body, &vars)).unwrap();
        assert_networks_round_trip(&imported.project);
        let mut sim = project_simulator(&imported.project, None).unwrap();
        sim.scan();
        sim.read("X").unwrap() == Value::Bool(true)
    };
    assert!(!run(0, 0), "by the drawing: X := Y runs first, Y is still FALSE");
    assert!(run(2, 1), "by executionOrderId: Y := TRUE runs first");
}

/// A hostile FBD network (each function's output feeding both inputs of the next, forty
/// deep: 2^40 terms written out) is refused with a note, and nothing else is lost.
#[test]
fn an_fbd_network_that_would_explode_as_st_is_skipped_with_a_note() {
    let vars = [var("X", "INT"), var("Y", "INT")].concat();
    let mut body = inv(1, 0, 0, "X");
    for k in 0..40u32 {
        body.push_str(&blk(
            k + 2,
            10 * k,
            0,
            "ADD",
            "",
            &[("IN1", k + 1), ("IN2", k + 1)],
            &["OUT"],
        ));
    }
    body.push_str(&outv(100, 500, 0, 0, 41, "", "Y"));
    let imported = import(&fbd_doc(&body, &vars)).unwrap();
    assert_eq!(imported.skipped.len(), 1);
    assert!(imported.skipped[0].reason.contains("too large"), "{:?}", imported.skipped);
}

/// LD elements for the networks that do not fit the rung grid.
mod off_grid {
    /// `<leftPowerRail>`.
    pub fn rail(id: u32, y: u32) -> String {
        format!(
            r#"<leftPowerRail localId="{id}"><position x="0" y="{y}"/><connectionPointOut formalParameter=""/></leftPowerRail>"#
        )
    }

    /// Wires into a `connectionPointIn`: `(from, output pin)`.
    fn wires(from: &[(u32, &str)]) -> String {
        from.iter()
            .map(|(f, p)| {
                let p =
                    if p.is_empty() { String::new() } else { format!(r#" formalParameter="{p}""#) };
                format!(r#"<connection refLocalId="{f}"{p}/>"#)
            })
            .collect()
    }

    /// A contact (`edge`: "", "rising" or "falling").
    pub fn contact(id: u32, x: u32, y: u32, v: &str, edge: &str, from: &[(u32, &str)]) -> String {
        let edge = if edge.is_empty() { String::new() } else { format!(r#" edge="{edge}""#) };
        format!(
            r#"<contact localId="{id}" negated="false"{edge}><position x="{x}" y="{y}"/><connectionPointIn>{}</connectionPointIn><connectionPointOut/><variable>{v}</variable></contact>"#,
            wires(from)
        )
    }

    /// A coil (`storage`: "", "set" or "reset").
    pub fn coil(id: u32, x: u32, y: u32, v: &str, storage: &str, from: &[(u32, &str)]) -> String {
        let storage =
            if storage.is_empty() { String::new() } else { format!(r#" storage="{storage}""#) };
        format!(
            r#"<coil localId="{id}" negated="false"{storage}><position x="{x}" y="{y}"/><connectionPointIn>{}</connectionPointIn><connectionPointOut/><variable>{v}</variable></coil>"#,
            wires(from)
        )
    }

    /// A block whose inputs are wired from `(pin, from, output pin of from)`.
    pub fn block(
        id: u32,
        (x, y): (u32, u32),
        ty: &str,
        inst: &str,
        inputs: &[(&str, u32, &str)],
        outputs: &[&str],
    ) -> String {
        let inst =
            if inst.is_empty() { String::new() } else { format!(r#" instanceName="{inst}""#) };
        let ins: String = inputs
            .iter()
            .map(|(p, f, o)| {
                format!(
                    r#"<variable formalParameter="{p}"><connectionPointIn>{}</connectionPointIn></variable>"#,
                    wires(&[(*f, o)])
                )
            })
            .collect();
        let outs: String = outputs
            .iter()
            .map(|p| format!(r#"<variable formalParameter="{p}"><connectionPointOut/></variable>"#))
            .collect();
        format!(
            r#"<block localId="{id}" typeName="{ty}"{inst}><position x="{x}" y="{y}"/><inputVariables>{ins}</inputVariables><inOutVariables/><outputVariables>{outs}</outputVariables></block>"#
        )
    }
}

/// Scans `s` once with the BOOL inputs `set` and returns the BOOL variables `read`.
fn scan_bools(s: &mut plc_core::sim::Simulator, set: &[(&str, bool)], read: &[&str]) -> Vec<bool> {
    for (name, on) in set {
        s.write(name, if *on { "TRUE" } else { "FALSE" }).unwrap();
    }
    s.scan();
    read.iter().map(|v| s.read(v).unwrap() == Value::Bool(true)).collect()
}

/// Networks OpenPLC and Beremiz run that the rung grid cannot hold run by power flow
/// (SEMANTICS "imported LD/FBD networks"): blocks with no left rail, a function fed by
/// contacts, a counter whose two outputs drive two coils, a variable box driving a coil,
/// an edge contact.
#[test]
fn ld_networks_off_the_grid_run_as_their_tools_run_them() {
    use off_grid::*;
    let bools = ["A", "B", "C", "Y4", "Y5", "Y6", "Y7", "Y8", "Y9"];
    let vars = format!(
        "{}{}",
        bools.map(|v| var(v, "BOOL")).concat(),
        var("C1", r#"derived name="CTUD""#)
    );
    let body = [
        // No left rail: Y4 := AND(B, C), FBD style.
        inv(1, 0, 0, "B"),
        inv(2, 0, 40, "C"),
        block(3, (100, 0), "AND", "", &[("IN1", 1, ""), ("IN2", 2, "")], &["OUT"]),
        coil(4, 200, 0, "Y4", "", &[(3, "OUT")]),
        // OR fed by two contacts: its type comes from the power flow.
        rail(10, 100),
        contact(11, 50, 100, "A", "", &[(10, "")]),
        contact(12, 50, 140, "B", "", &[(10, "")]),
        block(13, (100, 100), "OR", "", &[("IN1", 11, ""), ("IN2", 12, "")], &["OUT"]),
        coil(14, 200, 100, "Y5", "", &[(13, "OUT")]),
        // A counter's QU and QD both drive coils.
        contact(20, 50, 200, "A", "", &[(10, "")]),
        contact(21, 50, 240, "B", "", &[(10, "")]),
        inv(22, 0, 280, "C"),
        inv(23, 0, 320, "FALSE"),
        inv(24, 0, 360, "2"),
        block(
            25,
            (100, 200),
            "CTUD",
            "C1",
            &[("CU", 20, ""), ("CD", 21, ""), ("R", 22, ""), ("LD", 23, ""), ("PV", 24, "")],
            &["QU", "QD", "CV"],
        ),
        coil(26, 200, 200, "Y6", "", &[(25, "QU")]),
        coil(27, 200, 240, "Y7", "", &[(25, "QD")]),
        // A BOOL variable box drives a coil.
        inv(30, 0, 400, "C"),
        coil(31, 200, 400, "Y8", "", &[(30, "")]),
        // A rising-edge contact.
        contact(40, 50, 500, "A", "rising", &[(10, "")]),
        coil(41, 200, 500, "Y9", "", &[(40, "")]),
    ]
    .concat();
    let i = import(&doc(&body, &vars)).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.project.ladder.is_empty(), "the network is not a grid");
    assert_networks_round_trip(&i.project);
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    let read = ["Y4", "Y5", "Y6", "Y7", "Y8", "Y9"];
    let (t, f) = (true, false);
    // Y4 = B·C, Y5 = A + B, Y6 = C1.QU (CV >= 2), Y7 = C1.QD (CV <= 0), Y8 = C,
    // Y9 = rising edge of A.
    let steps: [([bool; 3], [bool; 6]); 7] = [
        ([f, f, f], [f, f, f, t, f, f]),
        ([t, f, f], [f, t, f, f, f, t]), // CV 1
        ([t, f, f], [f, t, f, f, f, f]),
        ([f, f, f], [f, f, f, f, f, f]),
        ([t, f, f], [f, t, t, f, f, t]), // CV 2
        ([t, t, f], [f, t, f, f, f, f]), // CD: CV 1
        ([t, t, t], [t, t, f, t, t, f]), // R: CV 0
    ];
    for (k, (inputs, expected)) in steps.iter().enumerate() {
        let set = [("A", inputs[0]), ("B", inputs[1]), ("C", inputs[2])];
        assert_eq!(scan_bools(&mut s, &set, &read), expected.to_vec(), "scan {}", k + 1);
    }
}

/// A coil passes its power on and a coil on the rail is always on (E0408 and E0401 in the
/// trainer's own rungs): a network that lays out on the grid but breaks those rules runs by
/// power flow, with a note naming the rule.
#[test]
fn coils_pass_power_and_a_coil_on_the_rail_is_always_on() {
    use off_grid::*;
    let vars = ["A", "B", "Y1", "Y2", "Y3"].map(|v| var(v, "BOOL")).concat();
    let body = [
        rail(1, 0),
        coil(2, 100, 0, "Y1", "", &[(1, "")]),
        contact(3, 20, 100, "A", "", &[(1, "")]),
        coil(4, 60, 100, "Y2", "", &[(3, "")]),
        contact(5, 100, 100, "B", "", &[(4, "")]),
        coil(6, 140, 100, "Y3", "", &[(5, "")]),
    ]
    .concat();
    let i = import(&doc(&body, &vars)).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.project.ladder.is_empty());
    assert_networks_round_trip(&i.project);
    assert!(
        i.warnings.iter().any(|w| w.message.contains("E0401") || w.message.contains("E0408")),
        "{:?}",
        i.warnings
    );
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    let read = ["Y1", "Y2", "Y3"];
    assert_eq!(scan_bools(&mut s, &[("A", false), ("B", true)], &read), [true, false, false]);
    assert_eq!(scan_bools(&mut s, &[("A", true), ("B", false)], &read), [true, true, false]);
    assert_eq!(scan_bools(&mut s, &[("A", true), ("B", true)], &read), [true, true, true]);
}

/// A document of two POUs: the LD FUNCTION `Majority` and a program calling it in ST.
fn ld_function_doc() -> String {
    use off_grid::*;
    let body = [
        rail(1, 0),
        contact(2, 20, 0, "X", "", &[(1, "")]),
        contact(3, 60, 0, "Y", "", &[(2, "")]),
        contact(4, 20, 40, "X", "", &[(1, "")]),
        contact(5, 60, 40, "Z", "", &[(4, "")]),
        contact(6, 20, 80, "Y", "", &[(1, "")]),
        contact(7, 60, 80, "Z", "", &[(6, "")]),
        coil(8, 120, 0, "Majority", "", &[(3, ""), (5, ""), (7, "")]),
    ]
    .concat();
    let inputs = ["X", "Y", "Z"].map(|v| var(v, "BOOL")).concat();
    let program = doc("", &["A", "B", "C", "M"].map(|v| var(v, "BOOL")).concat()).replace(
        "<body><LD></LD></body>",
        "<body><ST><xhtml:p><![CDATA[M := Majority(A, B, C);]]></xhtml:p></ST></body>",
    );
    program.replace(
        "<pou name=\"Main\"",
        &format!(
            r#"<pou name="Majority" pouType="function"><interface><returnType><BOOL/></returnType><inputVars>{inputs}</inputVars></interface><body><LD>{body}</LD></body></pou>
    <pou name="Main""#
        ),
    )
}

#[test]
fn an_ld_function_runs_by_power_flow() {
    let i = import(&ld_function_doc()).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    assert_networks_round_trip(&i.project);
    let mut s = project_simulator(&i.project, Some("Main")).unwrap_or_else(|e| panic!("{e:?}"));
    for bits in 0..8u32 {
        let [a, b, c] = [0, 1, 2].map(|k| bits & (1 << k) != 0);
        let m = scan_bools(&mut s, &[("A", a), ("B", b), ("C", c)], &["M"]);
        let majority = [a, b, c].iter().filter(|x| **x).count() >= 2;
        assert_eq!(m, [majority], "{a} {b} {c}");
    }
}

/// An SFC whose transitions have an LD condition (a contact on the rail) and an inline ST
/// one, with an action block, a jump and a selection divergence.
#[test]
fn an_sfc_with_ld_and_st_conditions_runs() {
    use off_grid::*;
    let step = |id: u32, name: &str, initial: bool, from: &[u32]| {
        let ins: String =
            from.iter().map(|f| format!(r#"<connection refLocalId="{f}"/>"#)).collect();
        let input = if from.is_empty() {
            String::new()
        } else {
            format!("<connectionPointIn>{ins}</connectionPointIn>")
        };
        format!(
            r#"<step localId="{id}" name="{name}" initialStep="{initial}"><position x="0" y="{id}"/>{input}<connectionPointOut/><connectionPointOutAction/></step>"#
        )
    };
    let transition = |id: u32, from: u32, condition: &str| {
        format!(
            r#"<transition localId="{id}"><position x="0" y="{id}"/><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn><connectionPointOut/><condition>{condition}</condition></transition>"#
        )
    };
    let body = [
        step(1, "Idle", true, &[]),
        r#"<selectionDivergence localId="2"><position x="0" y="2"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut formalParameter=""/><connectionPointOut formalParameter=""/></selectionDivergence>"#.to_string(),
        // Idle → Run when Start (a contact on the rail wired into the condition).
        rail(3, 0),
        contact(4, 20, 0, "Start", "", &[(3, "")]),
        transition(5, 2, r#"<connectionPointIn><connection refLocalId="4"/></connectionPointIn>"#),
        // Idle → Fault when Alarm (inline ST), priority by order.
        transition(6, 2, r#"<inline name=""><ST><xhtml:p><![CDATA[Alarm]]></xhtml:p></ST></inline>"#),
        step(7, "Run", false, &[5]),
        r#"<actionBlock localId="8"><position x="0" y="8"/><connectionPointIn><connection refLocalId="7"/></connectionPointIn><action localId="0" qualifier="N"><reference name="Motor"/></action></actionBlock>"#.to_string(),
        step(9, "Fault", false, &[6]),
        r#"<actionBlock localId="10"><position x="0" y="10"/><connectionPointIn><connection refLocalId="9"/></connectionPointIn><action localId="0" qualifier="S"><reference name="Lamp"/></action></actionBlock>"#.to_string(),
        // Run → Idle when NOT Start; Fault → Idle when NOT Alarm (both jumps).
        transition(11, 7, r#"<inline name=""><ST><xhtml:p><![CDATA[NOT Start]]></xhtml:p></ST></inline>"#),
        r#"<jumpStep localId="12" targetName="Idle"><position x="0" y="12"/><connectionPointIn><connection refLocalId="11"/></connectionPointIn></jumpStep>"#.to_string(),
        transition(13, 9, r#"<inline name=""><ST><xhtml:p><![CDATA[NOT Alarm]]></xhtml:p></ST></inline>"#),
        r#"<jumpStep localId="14" targetName="Idle"><position x="0" y="14"/><connectionPointIn><connection refLocalId="13"/></connectionPointIn></jumpStep>"#.to_string(),
        // A transition left unconnected in the editor: skipped with a note.
        r#"<transition localId="15"><position x="200" y="0"/><connectionPointIn/><connectionPointOut/><condition><inline name=""><ST><xhtml:p><![CDATA[Alarm]]></xhtml:p></ST></inline></condition></transition>"#.to_string(),
    ]
    .concat();
    let vars = ["Start", "Alarm", "Motor", "Lamp"].map(|v| var(v, "BOOL")).concat();
    let text = doc(&body, &vars).replace("<LD>", "<SFC>").replace("</LD>", "</SFC>");
    let i = import(&text).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    assert_eq!(i.warnings.len(), 1, "{:?}", i.warnings);
    assert!(i.warnings[0].message.contains("transition localId 15 is not connected"));
    assert_networks_round_trip(&i.project);
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    let read = ["Idle.X", "Run.X", "Fault.X", "Motor", "Lamp"];
    let (t, f) = (true, false);
    // Scan 1 only activates; transitions are tested from scan 2 on.
    assert_eq!(scan_bools(&mut s, &[("Start", true)], &read), [t, f, f, f, f]);
    assert_eq!(scan_bools(&mut s, &[], &read), [f, t, f, t, f]);
    assert_eq!(scan_bools(&mut s, &[("Start", false)], &read), [t, f, f, f, f]);
    assert_eq!(scan_bools(&mut s, &[("Alarm", true)], &read), [f, f, t, f, t]);
    // Lamp was set (S) and stays on back in Idle.
    assert_eq!(scan_bools(&mut s, &[("Alarm", false)], &read), [t, f, f, f, t]);
}

/// Negated and edge-triggered block inputs (Beremiz draws them as a circle or an arrow on
/// the pin): a negated function input reads NOT the value, an edge-triggered function
/// block input reads the edge of the value.
#[test]
fn negated_and_edge_triggered_pins_run() {
    use off_grid::*;
    let vars = format!(
        "{}{}",
        ["A", "B", "Y"].map(|v| var(v, "BOOL")).concat(),
        [var("C1", r#"derived name="CTU""#), var("N", "INT")].concat()
    );
    let body = [
        inv(1, 0, 0, "A"),
        inv(2, 0, 40, "B"),
        block(3, (100, 0), "AND", "", &[("IN1", 1, ""), ("IN2", 2, "")], &["OUT"]),
        outv(4, 200, 0, 0, 3, "OUT", "Y"),
        inv(5, 0, 100, "10"),
        block(
            6,
            (100, 100),
            "CTU",
            "C1",
            &[("CU", 1, ""), ("R", 2, ""), ("PV", 5, "")],
            &["Q", "CV"],
        ),
        outv(7, 200, 100, 0, 6, "CV", "N"),
    ]
    .concat()
    .replacen(
        r#"<variable formalParameter="IN1">"#,
        r#"<variable formalParameter="IN1" negated="true">"#,
        1,
    )
    .replacen(
        r#"<variable formalParameter="R">"#,
        r#"<variable formalParameter="R" edge="rising">"#,
        1,
    );
    let i = import(&fbd_doc(&body, &vars)).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    assert_networks_round_trip(&i.project);
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    let mut step = |a: bool, b: bool| {
        let y = scan_bools(&mut s, &[("A", a), ("B", b)], &["Y"])[0];
        let Value::Int(n, _) = s.read("N").unwrap() else { panic!() };
        (y, n)
    };
    // Y = NOT A AND B; C1 counts A's rising edges and resets on B's rising edge only.
    assert_eq!(step(false, true), (true, 0));
    assert_eq!(step(true, true), (false, 1));
    assert_eq!(step(false, true), (true, 1));
    assert_eq!(step(true, true), (false, 2), "B held: no new reset");
    assert_eq!(step(false, false), (false, 2));
    assert_eq!(step(false, true), (true, 0), "B's rising edge resets");
}

/// An element of a kind the trainer does not know (a vendor's own) is left out with a note
/// naming it; the rest of the network runs.
#[test]
fn a_vendor_element_is_left_out_with_a_note() {
    let vars = [var("A", "BOOL"), var("Y", "BOOL")].concat();
    let body = [
        inv(1, 0, 0, "A"),
        outv(2, 100, 0, 0, 1, "", "Y"),
        r#"<vendorElement localId="3"><position x="0" y="50"/><alternativeText><xhtml:p>gauge</xhtml:p></alternativeText></vendorElement>"#.to_string(),
    ]
    .concat();
    let i = import(&fbd_doc(&body, &vars)).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    assert_eq!(i.warnings.len(), 1, "{:?}", i.warnings);
    assert!(i.warnings[0].message.contains("<vendorElement> localId 3"), "{:?}", i.warnings);
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(scan_bools(&mut s, &[("A", true)], &["Y"]), [true]);
    // The same element in an LD body that fits the rung grid.
    let ld = doc(
        &[
            off_grid::rail(1, 0),
            off_grid::contact(2, 20, 0, "A", "", &[(1, "")]),
            off_grid::coil(3, 60, 0, "Y", "", &[(2, "")]),
            r#"<vendorElement localId="4"><position x="0" y="50"/></vendorElement>"#.to_string(),
        ]
        .concat(),
        &vars,
    );
    let i = import(&ld).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(i.project.ladder.len(), 1, "still a grid");
    assert!(i.warnings.iter().any(|w| w.message.contains("<vendorElement> localId 4")));
}

/// A block whose ENO powers a contact that powers its own EN is a loop with no value: the
/// network is refused with the element named, never lowered forever (a damaged grid
/// exported and read back made one).
#[test]
fn an_eno_wired_back_to_its_own_en_is_refused() {
    use off_grid::*;
    let vars = [var("A", "BOOL"), var("Y", "BOOL")].concat();
    let body = [
        inv(1, 0, 0, "A"),
        block(
            2,
            (100, 0),
            "AND",
            "",
            &[("EN", 3, ""), ("IN1", 1, ""), ("IN2", 1, "")],
            &["ENO", "OUT"],
        ),
        contact(3, 50, 60, "A", "", &[(2, "ENO")]),
        coil(4, 200, 0, "Y", "", &[(2, "ENO")]),
    ]
    .concat();
    let e = import(&doc(&body, &vars)).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("ENO wired back to its own EN") || e.contains("loop"), "{e}");
}

/// A TIME initial value written as a whole number (`<simpleValue value="5000"/>`, as some
/// OpenPLC projects hold it) is read as milliseconds, with a located note saying so.
#[test]
fn a_time_initial_value_written_as_a_number_is_milliseconds() {
    let vars = [
        var("Go", "BOOL"),
        var("Lamp", "BOOL"),
        r#"<variable name="Delay"><type><TIME/></type><initialValue><simpleValue value="5000"/></initialValue></variable>"#.to_string(),
    ]
    .concat();
    let body = r#"
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2"><position x="50" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>Go</variable></contact>
<coil localId="3"><position x="150" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>Lamp</variable></coil>
<rightPowerRail localId="4"><position x="300" y="0"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn></rightPowerRail>"#;
    let i = import(&doc(body, &vars)).unwrap();
    let note = i.warnings.iter().find(|w| w.message.contains("Delay")).expect("a note");
    assert!(note.message.contains("read as T#5000ms"), "{}", note.message);
    assert!(note.line > 0);
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    s.scan();
    let delay = s.read("Delay").unwrap();
    assert_eq!(plc_core::export::value_text(&delay), "T#5s");
}

/// A conversion's output type is in its name: `BOOL_TO_INT` of a BOOL gives an INT
/// on the data wire to the next block, which then gets a variable of that type and the
/// network stays a grid of rungs.
#[test]
fn a_conversion_on_a_data_wire_gives_its_type() {
    let vars = [var("A", "BOOL"), var("N", "INT"), var("Lamp", "BOOL")].concat();
    let body = r#"
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<inVariable localId="2"><position x="50" y="40"/><connectionPointOut/><expression>A</expression></inVariable>
<block localId="3" typeName="BOOL_TO_INT"><position x="100" y="10"/>
  <inputVariables><variable formalParameter="EN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
  <variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable></inputVariables>
  <inOutVariables/><outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<inVariable localId="4"><position x="100" y="80"/><connectionPointOut/><expression>40</expression></inVariable>
<block localId="5" typeName="ADD"><position x="200" y="10"/>
  <inputVariables><variable formalParameter="EN"><connectionPointIn><connection refLocalId="3" formalParameter="ENO"/></connectionPointIn></variable>
  <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn></variable>
  <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable></inputVariables>
  <inOutVariables/><outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<outVariable localId="6"><position x="300" y="40"/><connectionPointIn><connection refLocalId="5" formalParameter="OUT"/></connectionPointIn><expression>N</expression></outVariable>
<coil localId="7"><position x="300" y="10"/><connectionPointIn><connection refLocalId="5" formalParameter="ENO"/></connectionPointIn><connectionPointOut/><variable>Lamp</variable></coil>
<rightPowerRail localId="8"><position x="400" y="0"/><connectionPointIn><connection refLocalId="7"/></connectionPointIn></rightPowerRail>"#;
    let i = import(&doc(body, &vars)).unwrap_or_else(|e| panic!("{e}"));
    assert!(i.project.networks.is_empty(), "{:?}", i.warnings);
    assert_eq!(i.project.ladder.len(), 1);
    assert!(
        i.project.ladder[0].declarations.contains(": INT;"),
        "{}",
        i.project.ladder[0].declarations
    );
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    s.write("A", "TRUE").unwrap();
    s.scan();
    assert_eq!(plc_core::export::value_text(&s.read("N").unwrap()), "41");
    assert_eq!(s.read("Lamp").unwrap(), Value::Bool(true));
    assert_round_trip(&i.project);
}

/// OpenPLC's way to add up what is switched on: each MOVE's EN is a contact, the MOVEs feed
/// an ADD and a MAX in an LD FUNCTION returning INT. A function whose EN is off gives 0 to
/// the block it feeds (matiec's execution control), and the untyped literals take INT from
/// the result (corpus file 086 computed 60 whatever its inputs before).
#[test]
fn functions_with_their_en_off_feed_zero_to_the_next_block() {
    use off_grid::*;
    let in_var = |id: u32, y: u32, e: &str| {
        format!(
            r#"<inVariable localId="{id}"><position x="40" y="{y}"/><connectionPointOut/><expression>{e}</expression></inVariable>"#
        )
    };
    let body = [
        rail(1, 0),
        contact(2, 20, 0, "V0", "", &[(1, "")]),
        contact(3, 20, 80, "V1", "", &[(1, "")]),
        in_var(4, 40, "30"),
        in_var(5, 120, "-30"),
        block(6, (80, 0), "MOVE", "", &[("EN", 2, ""), ("IN", 4, "")], &["ENO", "OUT"]),
        block(7, (80, 80), "MOVE", "", &[("EN", 3, ""), ("IN", 5, "")], &["ENO", "OUT"]),
        in_var(8, 160, "45"),
        block(9, (160, 0), "ADD", "", &[("IN1", 6, "OUT"), ("IN2", 7, "OUT"), ("IN3", 8, "")], &["OUT"]),
        in_var(10, 200, "0"),
        block(11, (240, 0), "MAX", "", &[("IN1", 9, "OUT"), ("IN2", 10, "")], &["OUT"]),
        r#"<outVariable localId="12"><position x="320" y="0"/><connectionPointIn><connection refLocalId="11" formalParameter="OUT"/></connectionPointIn><expression>Speed</expression></outVariable>"#.to_string(),
    ]
    .concat();
    let inputs = ["V0", "V1"].map(|v| var(v, "BOOL")).concat();
    let program = doc("", &[var("A", "BOOL"), var("B", "BOOL"), var("S", "INT")].concat())
        .replace(
            "<body><LD></LD></body>",
            "<body><ST><xhtml:p><![CDATA[S := Speed(A, B);]]></xhtml:p></ST></body>",
        )
        .replace(
            "<pou name=\"Main\"",
            &format!(
                r#"<pou name="Speed" pouType="function"><interface><returnType><INT/></returnType><inputVars>{inputs}</inputVars></interface><body><LD>{body}</LD></body></pou>
    <pou name="Main""#
            ),
        );
    let i = import(&program).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(i.project.networks.len(), 1, "{:?}", i.warnings);
    assert_networks_round_trip(&i.project);
    let mut s = project_simulator(&i.project, Some("Main")).unwrap_or_else(|e| panic!("{e:?}"));
    for (a, b, speed) in
        [(false, false, 45), (true, false, 75), (true, true, 45), (false, true, 15)]
    {
        scan_bools(&mut s, &[("A", a), ("B", b)], &[]);
        let got = plc_core::export::value_text(&s.read("S").unwrap());
        assert_eq!(got, speed.to_string(), "A={a} B={b}");
    }
}

/// LD programs that do not fit the grid stay in the file's order, so the first PROGRAM of
/// the file is still the first after a round trip (corpus file 086 ran another program
/// once exported and imported again).
#[test]
fn off_grid_programs_keep_the_file_order() {
    use off_grid::*;
    let body = |v: &str| {
        format!(
            r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>{v}</expression></inVariable>{}"#,
            coil(2, 60, 0, "Y", "", &[(1, "")])
        )
    };
    let vars = [var("A", "BOOL"), var("B", "BOOL"), var("C", "BOOL"), var("Y", "BOOL")].concat();
    let pou = |name: &str, v: &str| {
        format!(
            r#"<pou name="{name}" pouType="program"><interface><localVars>{vars}</localVars></interface><body><LD>{}</LD></body></pou>
    "#,
            body(v)
        )
    };
    let text = doc(&body("A"), &vars).replace(
        "<pou name=\"Main\"",
        &format!("{}{}<pou name=\"Main\"", pou("First", "B"), pou("Second", "C")),
    );
    let i = import(&text).unwrap_or_else(|e| panic!("{e}"));
    let names: Vec<&str> = i.project.networks.iter().map(|n| n.name.as_str()).collect();
    assert_eq!(names, ["First", "Second", "Main"]);
    let back = import(&export(&i.project)).unwrap();
    let again: Vec<&str> = back.project.networks.iter().map(|n| n.name.as_str()).collect();
    assert_eq!(again, names);
}

/// A function's output has no variable; the network view shows it through a simulator
/// watch of its expression (ADD's output beside its pin), never re-running a FUNCTION of
/// the project.
#[test]
fn function_outputs_are_shown_through_watches() {
    use off_grid::*;
    let in_var = |id: u32, y: u32, e: &str| {
        format!(
            r#"<inVariable localId="{id}"><position x="0" y="{y}"/><connectionPointOut/><expression>{e}</expression></inVariable>"#
        )
    };
    let body = [
        in_var(1, 0, "N"),
        in_var(2, 40, "5"),
        block(3, (60, 0), "ADD", "", &[("IN1", 1, ""), ("IN2", 2, "")], &["OUT"]),
        r#"<outVariable localId="4"><position x="160" y="0"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>M</expression></outVariable>"#.to_string(),
    ]
    .concat();
    let text = doc(&body, &[var("N", "INT"), var("M", "INT")].concat())
        .replace("<LD>", "<FBD>")
        .replace("</LD>", "</FBD>");
    let i = import(&text).unwrap_or_else(|e| panic!("{e}"));
    let net = &i.project.networks[0];
    let watches = plc_core::network::live::function_watches(net);
    assert_eq!(watches, vec![(("3".to_string(), "OUT".to_string()), "ADD(N, 5)".to_string())]);
    let mut s = project_simulator(&i.project, None).unwrap_or_else(|e| panic!("{e:?}"));
    for (_, text) in &watches {
        s.add_watch(text).unwrap();
    }
    s.write("N", "3").unwrap();
    s.scan();
    let values = plc_core::network::live::output_values(net, &|p: &str| {
        s.read(p).ok().or_else(|| s.watch(p).cloned())
    });
    let out = values.get(&("3".to_string(), "OUT".to_string())).expect("ADD's output");
    assert_eq!(plc_core::export::value_text(out), "8");
}

/// Network POUs are renamed and deleted like the other diagram POUs; their names are taken
/// for new POUs, and a FUNCTION's coil on its result follows its new name.
#[test]
fn network_pous_are_renamed_and_deleted() {
    use plc_core::project::PouError;
    let mut p = import(&ld_function_doc()).unwrap_or_else(|e| panic!("{e}")).project;
    assert_eq!(
        p.add_ladder_pou("majority", plc_core::ladder::LadderPouKind::Program),
        Err(PouError::Taken("majority".into()))
    );
    p.rename_network_pou("Majority", "Vote").unwrap();
    assert_eq!(p.networks[0].name, "Vote");
    let st = network_st(&p, "Vote");
    assert!(st.starts_with("FUNCTION Vote : BOOL"), "{st}");
    assert!(st.contains("Vote := "), "{st}");
    assert!(!st.contains("Majority"), "{st}");
    assert_eq!(p.rename_network_pou("Vote", "Main"), Err(PouError::Taken("Main".into())));
    assert_eq!(p.rename_network_pou("Nope", "X"), Err(PouError::NoSuchNetwork("Nope".into())));
    p.delete_network_pou("vote").unwrap();
    assert!(p.networks.is_empty());
}

/// A file as OpenPLC and Beremiz write one with two tasks: each PROGRAM's instance under its
/// own task (no CONFIGURATION text in any POU).
const TWO_TASKS_XML: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="TwoTasks"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types>
    <dataTypes/>
    <pous>
      <pou name="FastCount" pouType="program">
        <interface><localVars><variable name="n"><type><INT/></type></variable></localVars></interface>
        <body><ST><xhtml:p><![CDATA[n := n + 1;]]></xhtml:p></ST></body>
      </pou>
      <pou name="SlowCount" pouType="program">
        <interface><localVars><variable name="n"><type><INT/></type></variable></localVars>
        <externalVars><variable name="Ticks"><type><INT/></type></variable></externalVars></interface>
        <body><ST><xhtml:p><![CDATA[n := n + 1; Ticks := Ticks + 10;]]></xhtml:p></ST></body>
      </pou>
    </pous>
  </types>
  <instances>
    <configurations>
      <configuration name="Config0">
        <resource name="Res0">
          <task name="task0" priority="1" interval="T#20ms">
            <pouInstance name="instance0" typeName="FastCount"/>
          </task>
          <task name="task1" priority="0" interval="T#100ms">
            <pouInstance name="instance1" typeName="SlowCount"/>
          </task>
        </resource>
        <globalVars><variable name="Ticks"><type><INT/></type></variable></globalVars>
      </configuration>
    </configurations>
  </instances>
</project>
"#;

#[test]
fn every_program_instance_of_a_file_with_several_tasks_runs_under_its_task() {
    let i = import(TWO_TASKS_XML).expect("imports");
    let p = &i.project;
    assert!(p.source.contains("CONFIGURATION Config0"), "{}", p.source);
    assert!(p.source.contains("TASK task1 (INTERVAL := T#100ms, PRIORITY := 0);"), "{}", p.source);
    assert!(p.source.contains("PROGRAM instance0 WITH task0 : FastCount;"), "{}", p.source);
    // The clock ticks at the tasks' greatest common interval.
    assert_eq!(p.settings.cycle_ms, 20);
    let mut sim = project_simulator(p, None).expect("builds");
    sim.set_cycle_ns(p.settings.cycle_ms as i64 * 1_000_000);
    assert!(matches!(sim.run_scans(10), plc_core::sim::ScanOutcome::Completed));
    // 10 ticks of 20 ms: task0 runs on each, task1 (100 ms) on ticks 0 and 5.
    assert_eq!(sim.read("instance0.n"), Ok(Value::Int(10, plc_core::semantic::Elem::Int)));
    assert_eq!(sim.read("instance1.n"), Ok(Value::Int(2, plc_core::semantic::Elem::Int)));
    assert_eq!(sim.read("Ticks"), Ok(Value::Int(20, plc_core::semantic::Elem::Int)));
    let vars = sim.vars_json();
    assert!(vars["instance0"].is_object() && vars["instance1"].is_object(), "{vars:?}");
    // Export writes the tasks back, and the file imports to the same project.
    let xml = export(p);
    assert!(xml.contains("<task name=\"task1\" interval=\"T#100ms\" priority=\"0\">"), "{xml}");
    assert!(xml.contains("<pouInstance name=\"instance1\" typeName=\"SlowCount\"/>"), "{xml}");
    assert!(xml.contains("<configuration name=\"Config0\">"), "{xml}");
    assert_round_trip(p);
}

#[test]
fn an_instance_of_a_program_left_out_of_the_import_is_noted_not_run() {
    let xml = TWO_TASKS_XML.replace("typeName=\"SlowCount\"", "typeName=\"Missing\"");
    let i = import(&xml).expect("imports");
    // One instance left: the file's program runs on its own, as before.
    assert!(!i.project.source.contains("CONFIGURATION"), "{}", i.project.source);
    assert!(i.warnings.iter().any(|w| w.message.contains("instance1")), "{:?}", i.warnings);
}

#[test]
fn references_round_trip_as_tc6_pointers() {
    let mut p = Project::new("Refs");
    p.source = "TYPE PInt : REF_TO INT; END_TYPE\nPROGRAM Main\nVAR a : INT; r : REF_TO INT; q : PInt; END_VAR\nr := REF(a);\nq := r;\nq^ := 3;\nEND_PROGRAM\n".into();
    let xml = plc_core::plcopen::export(&p);
    assert!(xml.contains("<pointer><baseType><INT/></baseType></pointer>"), "{xml}");
    let back = plc_core::plcopen::import(&xml).unwrap().project;
    let report = plc_core::run::run_project(&back, &plc_core::run::RunOptions::default());
    assert_eq!(report.status, plc_core::run::RunStatus::Ok, "{:?}", report.diagnostics);
    assert_eq!(report.vars["a"], 3);
    assert_eq!(report.vars["q"], "REF(a)");
}

#[test]
fn date_literals_at_the_ends_of_the_range_round_trip() {
    let mut p = Project::new("Dates");
    p.source = "PROGRAM Main\nVAR d : DATE := D#0001-01-01; t : DT := DT#9999-12-31-23:59:59.999; END_VAR\nd := d;\nEND_PROGRAM\n".into();
    let xml = plc_core::plcopen::export(&p);
    assert!(xml.contains("D#0001-01-01") && xml.contains("DT#9999-12-31-23:59:59.999"), "{xml}");
    let back = plc_core::plcopen::import(&xml).unwrap().project;
    let report = plc_core::run::run_project(&back, &plc_core::run::RunOptions::default());
    assert_eq!(report.status, plc_core::run::RunStatus::Ok, "{:?}", report.diagnostics);
    assert_eq!(report.vars["d"], "D#0001-01-01");
    assert_eq!(report.vars["t"], "DT#9999-12-31-23:59:59.999");
}

/// A configuration with VAR_CONFIG entries: initial values without and with an address,
/// a structured and an array value (IEC 61131-3 2.7.1).
const CONFIGURED: &str = "TYPE TankData : STRUCT Level : INT; Volume : INT; END_STRUCT; END_TYPE
FUNCTION_BLOCK Valve
VAR_INPUT Setpoint : INT := 10; END_VAR
VAR_OUTPUT Open AT %Q* : BOOL; Out : INT; END_VAR
Out := Setpoint;
END_FUNCTION_BLOCK
PROGRAM Cell
VAR V1 : Valve; Tank : TankData := (Level := 1, Volume := 7); Table : ARRAY[1..3] OF INT; END_VAR
V1();
END_PROGRAM
PROGRAM Other
VAR r : REF_TO INT := REF(n); n : INT; END_VAR
r^ := r^ + 1;
END_PROGRAM
CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK Main (INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM Line WITH Main : Cell;
        PROGRAM Aux WITH Main : Other;
    END_RESOURCE
    VAR_CONFIG
        Line.V1.Setpoint : INT := 50;
        Line.V1.Open AT %QX1.0 : BOOL := TRUE;
        Line.Tank : TankData := (Level := 3);
        Line.Table : ARRAY[1..3] OF INT := [4, 5, 6];
    END_VAR
END_CONFIGURATION
";

#[test]
fn var_config_entries_and_reference_initial_values_round_trip() {
    let mut p = Project::new("Configured");
    p.source = CONFIGURED.into();
    let options = plc_core::run::RunOptions { cycles: 2, ..Default::default() };
    let before = plc_core::run::run_project(&p, &options);
    assert_eq!(before.status, plc_core::run::RunStatus::Ok, "{:?}", before.diagnostics);
    assert_eq!(before.vars["Line"]["V1"]["Out"], 50);
    let xml = export(&p);
    assert!(
        xml.contains(r#"<configVariable instancePathAndName="Line.V1.Open" address="%QX1.0">"#),
        "{xml}"
    );
    assert!(xml.contains(r#"<simpleValue value="REF(n)"/>"#), "{xml}");
    let back = import(&xml).expect("imports");
    assert!(back.warnings.is_empty(), "{:?}", back.warnings);
    assert!(
        back.project.source.contains("Line.V1.Setpoint : INT := 50;"),
        "{}",
        back.project.source
    );
    let after = plc_core::run::run_project(&back.project, &options);
    assert_eq!(after.status, plc_core::run::RunStatus::Ok, "{:?}", after.diagnostics);
    assert_eq!(after.vars, before.vars);
    assert_round_trip(&back.project);
}

#[test]
fn var_config_entries_of_a_configuration_not_kept_are_noted() {
    // One program instance: the import runs the program alone, without its VAR_CONFIG.
    let mut p = Project::new("One");
    p.source = CONFIGURED.replace("        PROGRAM Aux WITH Main : Other;\n", "");
    let i = import(&export(&p)).expect("imports");
    assert!(!i.project.source.contains("VAR_CONFIG"), "{}", i.project.source);
    assert!(i.warnings.iter().any(|w| w.message.contains("VAR_CONFIG")), "{:?}", i.warnings);
    // An entry that cannot be read is left out with a note at it; the others stay.
    let xml = export(&Project { source: CONFIGURED.into(), ..Project::new("Bad") })
        .replace(r#"address="%QX1.0""#, r#"address="%Q*""#);
    let i = import(&xml).expect("imports");
    assert!(i.project.source.contains("Line.V1.Setpoint : INT := 50;"), "{}", i.project.source);
    assert!(!i.project.source.contains("Line.V1.Open"), "{}", i.project.source);
    let note = i.warnings.iter().find(|w| w.message.contains("Line.V1.Open"));
    assert!(note.is_some_and(|n| n.line > 0), "{:?}", i.warnings);
}

/// The importer's notes and errors are data (issue 33): each renders in Polish and Czech
/// with its program text (POU names, element names, `localId`s, variables) kept as it is,
/// and its English text is the one the importer has always written.
#[test]
fn import_notes_and_errors_render_in_polish_and_czech() {
    use plc_core::i18n::Lang;
    let said_in = |said: &plc_core::diagnostics::Said, lang| said.message.render(lang);

    // A note: an element of a kind the trainer does not run.
    let vars = [var("A", "BOOL"), var("Y", "BOOL")].concat();
    let body = [
        inv(1, 0, 0, "A"),
        outv(2, 100, 0, 0, 1, "", "Y"),
        r#"<vendorElement localId="3"><position x="0" y="50"/></vendorElement>"#.to_string(),
    ]
    .concat();
    let i = import(&fbd_doc(&body, &vars)).unwrap_or_else(|e| panic!("{e}"));
    let note = &i.warnings[0];
    let english =
        "POU Main: <vendorElement> localId 3 is not an element the trainer runs; left out";
    assert_eq!(note.message, english);
    assert_eq!(note.said.english, english);
    assert_eq!(said_in(&note.said, Lang::En), english);
    assert_eq!(
        said_in(&note.said, Lang::Pl),
        "POU Main: <vendorElement> o localId 3 nie jest elementem, który trenażer wykonuje; pominięty"
    );
    assert_eq!(
        said_in(&note.said, Lang::Cs),
        "POU Main: <vendorElement> s localId 3 není prvek, který trenažér spouští; vynechán"
    );
    // The note as JSON (the CLI's report, the page) is what it was: no `said`.
    let json = serde_json::to_value(note).expect("a note serializes");
    let keys: Vec<&String> = json.as_object().expect("an object").keys().collect();
    assert_eq!(keys, ["column", "line", "message"]);

    // An error: the POU, then what is wrong.
    let no_body =
        "<project><types><pous><pou name='Main' pouType='program'/></pous></types></project>";
    let e = import(no_body).unwrap_err();
    assert_eq!(e.to_string(), "POU Main: no <body>");
    assert_eq!(e.said().english, e.to_string());
    assert_eq!(said_in(&e.said(), Lang::Pl), "POU Main: brak <body>");
    assert_eq!(said_in(&e.said(), Lang::Cs), "POU Main: chybí <body>");

    // An element's error nested in another: the grid's reason and power flow's, both
    // translated.
    let bad_contact = "<project><types><pous><pou name='Main' pouType='program'><body><LD><contact/></LD></body></pou></pous></types></project>";
    let e = import(bad_contact).unwrap_err();
    assert_eq!(
        e.to_string(),
        "POU Main, element localId ?: a contact without a variable; run by power flow instead: POU Main, element localId ?: a contact without a variable"
    );
    assert_eq!(e.said().english, e.to_string());
    assert_eq!(
        said_in(&e.said(), Lang::Pl),
        "POU Main, element o localId ?: styk bez zmiennej; przy działaniu według przepływu mocy: POU Main, element o localId ?: styk bez zmiennej"
    );

    // Not well-formed XML: the place and the reason.
    let e = import("<project><types></project>").unwrap_err();
    assert_eq!(e.said().english, e.to_string());
    assert!(e.to_string().starts_with("not well-formed XML at line 1, column "), "{e}");
    let polish = said_in(&e.said(), Lang::Pl);
    assert!(
        polish.starts_with("XML nie jest poprawnie sformułowany, wiersz 1, kolumna "),
        "{polish}"
    );
    let e = import("<?xml version='1.0'?><root/>").unwrap_err();
    assert_eq!(
        e.to_string(),
        "not a PLCopen XML project: the root element is <root>, not <project>"
    );
    assert_eq!(
        said_in(&e.said(), Lang::Cs),
        "nejde o projekt PLCopen XML: kořenovým elementem je <root>, ne <project>"
    );

    // A POU left out says why, in any language; opening the file gives the same error.
    let cfc = doc("", "").replace("<LD></LD>", "<CFC/>");
    let i = import(&cfc).unwrap_or_else(|e| panic!("{e}"));
    let skipped = &i.skipped[0];
    assert_eq!(skipped.reason, "CFC bodies are not supported yet");
    assert_eq!(skipped.reason_said.english, skipped.reason);
    assert_eq!(
        said_in(&skipped.reason_said, Lang::Pl),
        "treść POU w CFC nie jest jeszcze obsługiwana"
    );
    let opened = plc_core::open::open_text("x", no_body).unwrap_err();
    let said = opened.said();
    assert_eq!(said.english, opened.to_string());
    assert_eq!(said_in(&said, Lang::Pl), "POU Main: brak <body>");
}
