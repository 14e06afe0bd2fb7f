//! Petri net POUs inside projects: the combined source, problems reported at the place or
//! transition (never at a line of generated text), hidden variables, the project file.
#![allow(clippy::unwrap_used)]

use plc_core::petri::{Arc, Net, PetriPou, Place, Transition};
use plc_core::project::Project;
use plc_core::run::{run_project, RunOptions, RunStatus};

fn example(name: &str) -> Project {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    Project::from_file(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

fn run(project: &Project, cycles: u64) -> plc_core::run::RunReport {
    run_project(project, &RunOptions { cycles, ..RunOptions::default() })
}

/// A two-place loop `A -go-> B -back-> A` in a PROGRAM `Loop`.
fn looping(action_a: &str, guard: &str) -> Project {
    let mut net = Net::default();
    net.places.push(Place { actions: action_a.into(), ..Place::new("A", 1, 1) });
    net.places.push(Place::new("B", 2, 0));
    net.transitions.push(Transition::new("go", guard));
    net.transitions.push(Transition::new("back", ""));
    for (a, b) in [("A", "go"), ("go", "B"), ("B", "back"), ("back", "A")] {
        net.arcs.push(Arc::new(a, b));
    }
    let mut project = Project::new("loop");
    project.source.clear();
    project.petri.push(PetriPou {
        name: "Loop".into(),
        declarations:
            "VAR_INPUT\n    x : BOOL;\nEND_VAR\nVAR\n    n : INT;\n    d : INT;\nEND_VAR\n".into(),
        prologue: String::new(),
        epilogue: String::new(),
        net,
        options: Default::default(),
    });
    project
}

#[test]
fn a_net_runs_through_the_project_pipeline() {
    // A marked on scans 1, 3, 5: n counts 3 after 5 scans (go and back fire every scan).
    let report = run(&looping("n := n + 1;", "TRUE"), 5);
    assert_eq!(report.status, RunStatus::Ok, "{:?}", report.diagnostics);
    assert_eq!(report.vars["n"], 3);
    assert_eq!(report.vars["p"], 2);
}

#[test]
fn a_type_error_in_a_guard_is_reported_at_the_transition() {
    let report = run(&looping("", "n + 1"), 1);
    assert_eq!(report.status, RunStatus::Error);
    let d = report
        .diagnostics
        .iter()
        .find(|d| d.code == "E0154")
        .unwrap_or_else(|| panic!("{:?}", report.diagnostics));
    assert!(
        d.message.starts_with("POU Loop, transition go (guard line 1, column 1): "),
        "{}",
        d.message
    );
    assert_eq!((d.line, d.column), (0, 0), "no line of generated text");
}

#[test]
fn an_undeclared_name_in_actions_is_reported_at_the_place() {
    let report = run(&looping("n := n + 1;\nm := 2;", "x"), 1);
    assert_eq!(report.status, RunStatus::Error);
    let d = report.diagnostics.iter().find(|d| d.code == "E0100").unwrap();
    assert!(
        d.message.starts_with("POU Loop, place A (actions line 2, column 1): "),
        "{}",
        d.message
    );
}

#[test]
fn a_runtime_fault_in_actions_names_the_place() {
    let report = run(&looping("n := 1 / d;", "x"), 1);
    assert_eq!(report.status, RunStatus::Fault);
    let f = report.fault.unwrap();
    assert!(
        f.message.starts_with("POU Loop, place A (actions line 1, column 1): "),
        "{}",
        f.message
    );
}

#[test]
fn net_errors_stop_the_run_before_any_code_exists() {
    let mut project = looping("", "x");
    project.petri[0].net.places[1].tokens = 1;
    let report = run(&project, 1);
    assert_eq!(report.status, RunStatus::Error);
    assert_eq!(report.diagnostics.len(), 1);
    assert_eq!(report.diagnostics[0].code, "E0505");
    assert!(
        report.diagnostics[0].message.starts_with("POU Loop, the net: "),
        "{}",
        report.diagnostics[0].message
    );
}

#[test]
fn net_warnings_come_with_the_run() {
    let mut project = looping("", "x");
    // A second transition from A with the same priority and an overlapping guard.
    project.petri[0].net.transitions.push(Transition::new("again", "TRUE"));
    project.petri[0].net.arcs.push(Arc::new("A", "again"));
    project.petri[0].net.arcs.push(Arc::new("again", "B"));
    let report = run(&project, 1);
    assert_eq!(report.status, RunStatus::Ok);
    assert_eq!(report.diagnostics[0].code, "W0010");
}

#[test]
fn st_pous_of_the_project_are_usable_in_actions() {
    let mut project = looping("n := Twice(21);", "x");
    project.source =
        "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\nTwice := v * 2;\nEND_FUNCTION\n".into();
    let report = run_project(
        &project,
        &RunOptions { program: Some("Loop".into()), ..RunOptions::default() },
    );
    assert_eq!(report.status, RunStatus::Ok, "{:?}", report.diagnostics);
    assert_eq!(report.vars["n"], 42);
}

#[test]
fn scan_copies_are_hidden_from_the_variables() {
    let report = run(&example("weighing-concurrent.plcproj.json"), 3);
    assert_eq!(report.status, RunStatus::Ok, "{:?}", report.diagnostics);
    assert!(report.vars.contains_key("pA"));
    assert!(!report.vars.keys().any(|k| k.starts_with("PnScan_")), "{:?}", report.vars.keys());
}

#[test]
fn projects_keep_their_nets_and_old_files_still_load() {
    let project = example("weighing-concurrent.plcproj.json");
    let again = Project::from_file(&project.to_file()).unwrap();
    assert_eq!(again, project);
    let old = r#"{"schema":1,"name":"old","source":"PROGRAM P END_PROGRAM"}"#;
    assert!(Project::from_file(old).unwrap().petri.is_empty());
    assert!(!Project::new("x").to_file().contains("petri"), "no petri key when empty");
}

#[test]
fn the_program_chosen_in_the_settings_runs_unless_the_options_name_another() {
    let mut project = looping("n := n + 1;", "x");
    project.source = "PROGRAM First\nVAR k : INT; END_VAR\nk := k + 1;\nEND_PROGRAM\n".into();
    // No choice: the first PROGRAM (the ST one).
    assert!(run(&project, 2).vars.contains_key("k"));
    project.settings.program = Some("Loop".into());
    let report = run(&project, 2);
    assert_eq!(report.vars.get("n").map(|v| v.to_string()).as_deref(), Some("2"), "{report:?}");
    // `--program` wins over the settings; a stale choice falls back to the first PROGRAM.
    let options = RunOptions { program: Some("First".into()), ..RunOptions::default() };
    assert!(run_project(&project, &options).vars.contains_key("k"));
    project.settings.program = Some("Renamed".into());
    let report = run(&project, 1);
    assert_eq!(report.status, RunStatus::Ok, "{report:?}");
    assert!(report.vars.contains_key("k"));
}

#[test]
fn a_misspelled_name_in_a_guard_gets_did_you_mean_at_the_transition() {
    let mut project = looping("", "NOT Stopp");
    project.petri[0].declarations.insert_str(0, "VAR_INPUT\n    Stop : BOOL;\nEND_VAR\n");
    let build = plc_core::build::build_project(&project);
    let d = build
        .diagnostics
        .iter()
        .find(|d| d.code.as_str() == "E0100")
        .unwrap_or_else(|| panic!("{:?}", build.diagnostics));
    assert_eq!(d.message, "`Stopp` is not declared; did you mean Stop?");
    assert_eq!(d.suggestion(), Some("Stop"));
    assert_eq!(d.implied_type(), Some("BOOL"), "NOT of a guard: a BOOL");
    assert!(
        d.located_message().starts_with("POU Loop, transition go (guard line 1, column 5): "),
        "{}",
        d.located_message()
    );
}

#[test]
fn a_net_problem_of_a_project_is_shown_in_polish_and_czech() {
    use plc_core::i18n::Lang;
    let mut project = looping("", "x");
    project.petri[0].net.places[1].tokens = 1;
    let build = plc_core::build::build_project(&project);
    let d = &build.diagnostics[0];
    assert_eq!(
        d.message,
        "no sequential process (state-machine component) covers place(s) A, B; the CASE OF \
         method needs every place inside a process holding one token"
    );
    assert_eq!(d.render(Lang::En), d.message);
    assert_eq!(
        d.render(Lang::Pl),
        "żaden proces sekwencyjny (komponent automatowy) nie obejmuje miejsc: A, B; metoda CASE \
         OF wymaga, by każde miejsce należało do procesu z jednym znacznikiem"
    );
    // A guard that does not parse carries the parser's message, translated too.
    let build = plc_core::build::build_project(&looping("", "x +"));
    let d = &build.diagnostics[0];
    assert_eq!(d.code.as_str(), "E0503");
    assert_eq!(d.render(Lang::En), d.message);
    assert_ne!(d.render(Lang::Cs), d.message, "{}", d.message);
}
