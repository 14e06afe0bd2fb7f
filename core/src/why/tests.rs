#![allow(clippy::unwrap_used)]

use super::*;
use crate::build::build_project;

const LATCH: &str = "PROGRAM Main
VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; Lamp : BOOL; END_VAR
VAR T1 : TON; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
T1(IN := Motor, PT := T#50ms);
Lamp := T1.Q;
END_PROGRAM
";

fn st_project(source: &str) -> Project {
    let mut p = Project::new("test");
    p.source = source.to_string();
    p.ladder.clear();
    p
}

fn file_project(name: &str) -> Project {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).unwrap();
    crate::open::open_text(name, &text).unwrap().project
}

fn simulator(project: &Project, build: &ProjectBuild) -> Simulator {
    let program = build.chosen_program(&project.settings);
    let mut sim = build.simulator_with_plant(program, project.settings.plant.as_deref()).unwrap();
    sim.set_recording(true).unwrap();
    sim
}

#[test]
fn print_latch() {
    let p = st_project(LATCH);
    let b = build_project(&p);
    let mut sim = simulator(&p, &b);
    sim.run_scans(2);
    sim.hold("Start", "TRUE").unwrap();
    sim.run_scans(1);
    sim.hold("Start", "FALSE").unwrap();
    sim.run_scans(10);
    let ctx = Context::new(&p, &b);
    for (v, k) in [
        ("Motor", 3),
        ("Motor", 8),
        ("Lamp", 9),
        ("Lamp", 12),
        ("T1.Q", 9),
        ("Start", 5),
        ("Motor", 1),
    ] {
        let e = explain(&ctx, &sim, v, k).unwrap();
        println!("{}\n{}\n", e.to_text(), e.to_json());
    }
}

#[test]
fn print_examples() {
    for (file, vars, script) in [
        (
            "latch-ladder.plcproj.json",
            vec![("Motor", 3u64), ("Motor", 9), ("Lamp", 300)],
            vec![(2u64, "Start", "TRUE"), (3, "Start", "FALSE")],
        ),
        (
            "weighing-sequential.plcproj.json",
            vec![("p", 3), ("FeedValve", 10), ("P31", 10), ("p", 60)],
            vec![(2, "Start", "TRUE"), (50, "Weight", "600")],
        ),
        (
            "weighing-plant.plcproj.json",
            vec![("DischargeValve", 400), ("FeedValve", 10), ("Weight", 100)],
            vec![(2, "Start", "TRUE")],
        ),
        (
            "lecture-ld-il-st.plcproj.json",
            vec![("Motor", 5), ("C", 5)],
            vec![(2, "Start", "TRUE"), (3, "A", "TRUE")],
        ),
    ] {
        let p = file_project(file);
        let b = build_project(&p);
        let mut sim = simulator(&p, &b);
        let mut at = 0;
        for (k, var, val) in &script {
            sim.run_scans(k - at);
            at = *k;
            sim.hold(var, val).unwrap();
        }
        sim.run_scans(500 - at);
        let ctx = Context::new(&p, &b);
        for (v, k) in vars {
            let e = if v.starts_with('P') {
                explain_place(&ctx, &sim, v, k)
            } else {
                explain(&ctx, &sim, v, k)
            };
            match e {
                Ok(e) => println!("{file}: {}\n{}\n", e.to_text(), e.to_json()),
                Err(e) => println!("{file}: {v}@{k}: error {e}"),
            }
        }
    }
}

#[test]
fn print_sfc() {
    let path = format!("{}/../examples/sfc-weighing.st", env!("CARGO_MANIFEST_DIR"));
    let p = st_project(&std::fs::read_to_string(path).unwrap());
    let b = build_project(&p);
    let mut sim = simulator(&p, &b);
    sim.run_scans(2);
    sim.hold("Start", "TRUE").unwrap();
    sim.run_scans(10);
    let ctx = Context::new(&p, &b);
    for (v, k) in [("Filling.X", 3), ("Ready.X", 3), ("FeedValve", 5), ("Filling.X", 8)] {
        match explain(&ctx, &sim, v, k) {
            Ok(e) => println!("{}\n{}\n", e.to_text(), e.to_json()),
            Err(e) => println!("{v}@{k}: error {e}"),
        }
    }
}
