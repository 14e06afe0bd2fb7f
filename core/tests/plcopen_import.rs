//! PLCopen XML import/export: real samples, hand-written LD snippets, errors, round trips.
//! The samples are read from `shared/samples/plcopen/` beside the repository (as in CI; for a
//! worktree nested deeper, the nearest such folder above the crate).

use plc_core::ladder::{st_view, validate, Block, CoilKind, ContactKind, Element, Rung};
use plc_core::plcopen::{export, import, load, ImportError};
use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::vm::Value;

/// The path of a sample: `shared/samples/plcopen/NAME` in the nearest folder above the crate
/// that has one.
fn sample_path(name: &str) -> String {
    let crate_dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    crate_dir
        .ancestors()
        .map(|a| a.join("shared/samples/plcopen"))
        .find(|d| d.is_dir())
        .map(|d| d.join(name).display().to_string())
        .unwrap_or_else(|| panic!("no shared/samples/plcopen above {}", crate_dir.display()))
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
fn start_stop_latch_sample() {
    let i = sample("ld_start_stop_latch.xml");
    let p = &i.project;
    assert_eq!(p.ladder.len(), 1);
    let lp = &p.ladder[0];
    assert_eq!(lp.name, "Hello_World");
    assert_eq!(lp.rungs.len(), 1);
    assert!(lp.declarations.contains("Start_PB AT %I0.0 : BOOL := FALSE; (* Start Push Button *)"));
    let r = &lp.rungs[0];
    assert_eq!(r.rows(), 2);
    assert!(!r.comment.is_empty());
    // Start_PB on row 0, the seal-in contact below it, joined by vertical links.
    assert!(
        matches!(&r.cells[0][0].element, Element::Contact { kind: ContactKind::NormallyOpen, operand } if operand == "Start_PB")
    );
    assert!(
        matches!(&r.cells[1][0].element, Element::Contact { kind: ContactKind::NormallyClosed, operand } if operand == "Motor_Starter")
    );
    assert!(r.cells[0][0].link_down && r.cells[0][1].link_down);
    assert!(
        matches!(&r.cells[0][r.columns() - 1].element, Element::Coil { kind: CoilKind::Normal, operand } if operand == "Motor_Starter")
    );
    assert_round_trip(p);
}

#[test]
fn multi_rung_sample_splits_shared_rail() {
    let i = sample("ld_multi_rung_parallel_branches.xml");
    let lp = &i.project.ladder[0];
    assert_eq!(lp.rungs.len(), 5);
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
    assert_eq!(coils, ["H1", "H2", "H3", "H4", "H5"]);
    assert!(lp.rungs.iter().filter(|r| r.rows() > 1).count() >= 2);
    assert_round_trip(&i.project);
}

#[test]
fn timers_counters_sample() {
    let i = sample("ld_timers_counters_setreset.xml");
    let lp = &i.project.ladder[0];
    assert_eq!(lp.rungs.len(), 6);
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
    assert!(ton.inputs.iter().any(|p| p.name == "PT" && p.operand == "TON_TIME1"));
    let ctu = blocks.iter().find(|b| b.type_name == "CTU").expect("CTU");
    assert!(ctu.inputs.iter().any(|p| p.name == "PV"));
    assert!(ctu.inputs.iter().any(|p| p.name == "R"));
    assert!(
        i.warnings.iter().any(|w| w.message.contains("45")),
        "dangling contact 45 reported: {:?}",
        i.warnings
    );
    assert!(st_errors(&i.project).is_empty());
    assert_round_trip(&i.project);
}

#[test]
fn wastewater_sample_ld_and_st_fbs() {
    let i = sample("ld_st_user_fbs_wastewater_pump.xml");
    let p = &i.project;
    assert_eq!(p.ladder.len(), 1);
    assert_eq!(p.ladder[0].rungs.len(), 11);
    assert!(p.source.contains("FUNCTION_BLOCK Run_Mode"));
    assert!(p.source.contains("FUNCTION_BLOCK Start_CMD"));
    assert!(p.source.contains("HOA_MODE"));
    assert_round_trip(p);
    // `Mode := HOA_HAND;` inside Run_Mode, whose input is `HOA_Hand`: the enumeration value,
    // as the expected type says (warning W0030), so the sample builds and runs.
    let build = plc_core::build::build_project(p);
    assert!(!build.has_errors(), "{:?}", build.diagnostics);
    let shadowed = build.diagnostics.iter().filter(|d| d.code.as_str() == "W0030").count();
    assert_eq!(shadowed, 2, "{:?}", build.diagnostics);
    let mut sim = project_simulator(p, None).expect("builds");
    sim.write("Hand_Relay", "TRUE").expect("Hand_Relay");
    assert!(matches!(sim.scan(), plc_core::sim::ScanOutcome::Completed));
    let mode = sim.read("START_CMD0.Run_Mode0.Mode").expect("Mode");
    assert_eq!(plc_core::export::value_text(&mode), "HOA_HAND");
}

#[test]
fn oven_control_st_sample() {
    let i = sample("st_multi_program_oven_control.xml");
    let p = &i.project;
    assert!(p.ladder.is_empty());
    let (file, _) = plc_core::syntax::parse(&p.source);
    let pous =
        file.items.iter().filter(|it| matches!(it, plc_core::syntax::ast::Item::Pou(_))).count();
    assert!(pous >= 5, "{pous} POUs");
    assert!(p.source.contains("Mode_t"));
    assert!(p.source.contains("VAR_GLOBAL"));
    assert!(p.source.contains("VAR CONSTANT"));
    // Only the Beremiz-specific python_poll FBs are unknown to our checker.
    let errs = st_errors(p);
    assert!(
        errs.iter().all(|e| e.contains("python_poll")
            || e.contains("VAR_EXTERNAL")
            || e.contains("PID")
            || e.contains("_pid`")),
        "{errs:?}"
    );
    assert_round_trip(p);
}

#[test]
fn fbd_bodies_become_st_and_sfc_is_skipped_with_warnings() {
    let i = sample("fbd_user_function_and_fbs.xml");
    // Every FBD POU is imported (as ST statements, with a note saying the drawing is not
    // kept); none is skipped.
    assert!(i.skipped.is_empty(), "{:?}", i.skipped);
    for pou in ["program0_POU", "FA", "FA_SERV", "AKT_5_2_MV"] {
        assert!(
            i.warnings
                .iter()
                .any(|w| w.message.starts_with(&format!("POU {pou}: the FBD body runs as ST"))),
            "{pou}"
        );
    }
    assert!(i.project.source.contains("FUNCTION FA_SERV : BOOL"));
    assert!(i.project.source.contains("SR0(S1 := Hand_P2, R := Hand_P1);"), "{}", i.project.source);
    assert!(i.project.source.contains("S_FA_STATUS"));
    let i = sample("sfc_traffic_light.xml");
    assert!(i
        .warnings
        .iter()
        .any(|w| w.message.contains("Traffic_Control") && w.message.contains("SFC")));
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
fn mixing_tank_lays_out_reset_networks_as_wired_inputs() {
    let i = sample("ld_mixing_tank_plant.xml");
    let p = &i.project;
    let lp = &p.ladder[0];
    assert_eq!(lp.rungs.len(), 3, "pumps, mixer, valve");
    // Rung 1: SR0's R is wired to H_LEVEL OR STOP, laid out below the seal-in branches.
    let sr0 = block_at(p, 0, 0, 4);
    assert_eq!(sr0.instance.as_deref(), Some("SR0"));
    let r = &sr0.inputs[0];
    assert_eq!((r.name.as_str(), r.operand.as_str()), ("R", ""));
    let row = r.wired_row.expect("R is wired") as usize;
    assert!(
        matches!(at(p, 0, row, 3), Element::Contact { kind: ContactKind::NormallyOpen, operand } if operand == "H_LEVEL")
    );
    assert!(
        matches!(at(p, 0, row + 1, 3), Element::Contact { kind: ContactKind::NormallyOpen, operand } if operand == "STOP")
    );
    // Rung 2: SR1's R takes F_TRIG0, which taps TP0's output, besides VALVE and STOP.
    let sr1 = block_at(p, 1, 0, 5);
    assert_eq!(sr1.inputs[0].wired_row, Some(1));
    let f_trig = block_at(p, 1, 1, 4);
    assert_eq!(f_trig.instance.as_deref(), Some("F_TRIG0"));
    assert!(lp.rungs[1].cells[0][4].link_down, "F_TRIG0 hangs from TP0's output");
    let (view, _) = st_view(lp);
    assert!(view.contains("SR0(S1 := (START AND L_LEVEL OR PUMP_1 OR PUMP_1) AND NOT H_LEVEL AND NOT STOP, R := H_LEVEL OR STOP);"), "{view}");
    assert!(view.contains("F_TRIG0(CLK := TP0.Q);"), "{view}");
    assert!(
        view.contains("SR1(S1 := TP0.Q AND NOT STOP, R := F_TRIG0.Q OR VALVE OR STOP);"),
        "{view}"
    );
    assert!(view.contains("RS0(S := (START AND H_LEVEL AND NOT MIXER_MOTOR OR VALVE) AND NOT STOP, R1 := NOT L_LEVEL OR STOP);"), "{view}");
    assert!(i.warnings.is_empty(), "{:?}", i.warnings);
    assert!(validate(lp).iter().all(|d| !d.is_error()), "{:?}", validate(lp));
    assert_round_trip(p);
}

/// The plant as its rung comments describe it: fill with both pumps, mix for the TP's 8 s,
/// drain through the valve, STOP overrides. `L_LEVEL` is TRUE while liquid covers the low
/// sensor (the valve rung closes the valve through an NC contact when it uncovers).
#[test]
fn mixing_tank_runs_fill_mix_drain_scan_by_scan() {
    let p = sample("ld_mixing_tank_plant.xml").project;
    assert_eq!(p.settings.cycle_ms, 20, "the task interval T#20ms");
    let mut s = project_simulator(&p, None).unwrap_or_else(|e| panic!("{e:?}"));
    s.set_cycle_ns(20_000_000);
    let set = |s: &mut plc_core::sim::Simulator, v: &str, on: bool| {
        s.write(v, if on { "TRUE" } else { "FALSE" }).unwrap();
    };
    let get = |s: &plc_core::sim::Simulator, v: &str| s.read(v).unwrap() == Value::Bool(true);
    let outputs = |s: &plc_core::sim::Simulator| {
        ["PUMP_1", "PUMP_2", "MIXER_MOTOR", "VALVE"].map(|v| get(s, v))
    };
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    // Fill: START with liquid at the low sensor starts both pumps, which hold themselves.
    set(&mut s, "L_LEVEL", true);
    set(&mut s, "START", true);
    s.scan();
    assert_eq!(outputs(&s), [true, true, false, false]);
    set(&mut s, "START", false);
    s.scan();
    assert_eq!(outputs(&s), [true, true, false, false]);
    // Full: H_LEVEL stops the pumps.
    set(&mut s, "H_LEVEL", true);
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    // Mix: START on a full tank runs the mixer for TP0's 8 s (400 scans of 20 ms).
    set(&mut s, "START", true);
    s.scan();
    assert_eq!(outputs(&s), [false, false, true, false]);
    for k in 1..400 {
        s.scan();
        assert_eq!(outputs(&s), [false, false, true, false], "mixing, scan {k} of the pulse");
    }
    // The pulse ends: F_TRIG0 resets the mixer and, START still held on a full tank, the
    // valve rung opens the valve in the same scan.
    s.scan();
    assert_eq!(outputs(&s), [false, false, false, true]);
    // Drain: the valve holds itself while the level falls, and closes at the low sensor.
    set(&mut s, "START", false);
    set(&mut s, "H_LEVEL", false);
    s.scan();
    assert_eq!(outputs(&s), [false, false, false, true]);
    set(&mut s, "L_LEVEL", false);
    s.scan();
    assert_eq!(outputs(&s), [false; 4]);
    // STOP wins: pumps started again stop at once, and START cannot set them while held.
    set(&mut s, "L_LEVEL", true);
    set(&mut s, "START", true);
    s.scan();
    assert_eq!(outputs(&s), [true, true, false, false]);
    set(&mut s, "STOP", true);
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
fn non_series_parallel_network_names_the_element() {
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
    let e = import(&doc(&body, &vars)).unwrap_err();
    match &e {
        ImportError::Element { pou, local_id, message } => {
            assert_eq!(pou, "Main");
            assert!(["2", "3", "4", "5", "6"].contains(&local_id.as_str()), "{e}");
            assert!(message.contains("series-parallel"));
        }
        other => panic!("{other:?}"),
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
        let missing = plc(&["run", "no-such-file.xml", "--json"]);
        assert_eq!(json(&missing)["diagnostics"][0]["code"], "E0304");
    }

    #[test]
    fn import_notes_are_located_warnings_in_the_json_and_the_count() {
        let file = sample_path("ld_timers_counters_setreset.xml");
        let report = json(&plc(&["run", &file, "--json"]));
        assert_eq!(report["status"], "ok");
        let note = report["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .find(|d| d["code"] == "W0031")
            .expect("the skipped element is a warning");
        assert_eq!((note["line"].as_u64(), note["column"].as_u64()), (Some(947), Some(13)));
        assert!(note["message"].as_str().unwrap().contains("localId 45"));
        let check = plc(&["check", &file]);
        let err = String::from_utf8_lossy(&check.stderr);
        assert!(err.contains("0 error(s), 1 warning(s)"), "{err}");
        assert!(String::from_utf8_lossy(&check.stdout).contains(":947:13: warning[W0031]: "));
    }

    #[test]
    fn a_problem_in_an_imported_rung_is_at_its_element_in_the_file() {
        let text = std::fs::read_to_string(sample_path("ld_start_stop_latch.xml")).unwrap();
        // The NC contact (localId 3, line 80) reads an undeclared variable.
        let text =
            text.replacen("<variable>Stop_PB</variable>", "<variable>Stop_PBX</variable>", 1);
        let dir = std::env::temp_dir().join(format!("plc-contract-ld-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("latch.xml");
        std::fs::write(&file, text).unwrap();
        let file = file.to_string_lossy().into_owned();
        let report = json(&plc(&["run", &file, "--json"]));
        let d = &report["diagnostics"][0];
        assert_eq!(
            (d["code"].as_str(), d["line"].as_u64(), d["column"].as_u64()),
            (Some("E0418"), Some(80), Some(13)),
            "{d}"
        );
        let check = plc(&["check", &file]);
        assert!(String::from_utf8_lossy(&check.stdout)
            .contains("latch.xml:80:13: error[E0418]: POU Hello_World, rung 1, row 1, column 2:"));
    }

    #[test]
    fn an_element_that_does_not_import_is_located() {
        let text = std::fs::read_to_string(sample_path("ld_start_stop_latch.xml")).unwrap();
        // The NC contact (localId 3, line 80) is wired from an element that does not exist.
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
            (Some("E0304"), Some(80), Some(13)),
            "{d}"
        );
        assert!(d["message"]
            .as_str()
            .unwrap()
            .contains("localId 3: connection refers to localId 99"));
    }

    #[test]
    fn a_program_the_import_left_out_is_named() {
        let file = sample_path("sfc_traffic_light.xml");
        let report = json(&plc(&["run", &file, "--json"]));
        let messages: Vec<&str> = report["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|d| d["message"].as_str())
            .collect();
        assert!(
            messages.iter().any(|m| m.contains("Traffic_Control") && m.contains("SFC")),
            "{messages:?}"
        );
        assert!(
            messages.contains(&"the file holds no PROGRAM that could be imported: left out Traffic_Control (SFC bodies are not supported yet)"),
            "{messages:?}"
        );
        let asked = json(&plc(&["run", &file, "--program", "Traffic_Control", "--json"]));
        let last = asked["diagnostics"].as_array().unwrap().last().unwrap().clone();
        assert_eq!(last["code"], "E0305");
        assert_eq!(
            last["message"],
            "the PROGRAM Traffic_Control was left out when the file was imported: SFC bodies are not supported yet"
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
    assert!(
        imported.project.source.contains("T1(IN := AND(A, B), PT := T#20ms);"),
        "{}",
        imported.project.source
    );
    assert!(imported.project.source.contains("T1 : TON;"), "the instance is declared");
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
