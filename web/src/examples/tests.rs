use super::*;

fn read(file: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples").join(file);
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{file}: {e}"))
}

#[test]
fn every_shipped_example_opens_and_builds() {
    let list = examples();
    assert!(list.len() >= 6, "{list:?}");
    for e in &list {
        let p = project_of(e.file, &read(e.file)).unwrap_or_else(|err| panic!("{}: {err}", e.file));
        let build = plc_core::build::build_project(&p);
        assert!(!build.has_errors(), "{}: {:?}", e.file, build.diagnostics);
        assert!(!build.program_names().is_empty(), "{} has a PROGRAM", e.file);
        if e.file.ends_with(".json") {
            assert_eq!(p.name, e.title, "the menu shows the project's name");
        }
    }
    assert!(project_of("x.xml", "<?xml version=\"1.0\"?><project/>").is_err());
}

#[test]
fn titles_come_from_the_project_or_the_file_name() {
    let list = examples();
    let titles: Vec<&str> = list.iter().map(|e| e.title).collect();
    assert!(titles.contains(&"Ladder latch"), "{titles:?}");
    assert!(titles.contains(&"Weighing (ST)"), "{titles:?}");
    // Ladder projects come first, Petri nets last.
    assert!(titles[0].starts_with("Ladder"), "{titles:?}");
    assert!(titles.last().is_some_and(|t| t.contains("Petri")), "{titles:?}");
    assert_eq!(naming::humanise("sfc-weighing"), "SFC weighing");
    assert_eq!(naming::humanise("traffic_light"), "Traffic light");
    assert_eq!(naming::describe("x.st", None).0, "X (ST)");
}
