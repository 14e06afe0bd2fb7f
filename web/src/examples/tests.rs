use super::*;

#[test]
fn every_shipped_example_opens_and_builds() {
    let list = examples();
    assert!(list.len() >= 6, "{list:?}");
    for e in &list {
        let p = open(e.file).unwrap_or_else(|err| panic!("{}: {err}", e.file));
        let build = plc_core::build::build_project(&p);
        assert!(!build.has_errors(), "{}: {:?}", e.file, build.diagnostics);
        assert!(!build.program_names().is_empty(), "{} has a PROGRAM", e.file);
    }
    assert!(open("nope.st").is_err());
}

#[test]
fn titles_come_from_the_project_or_the_file_name() {
    let list = examples();
    let titles: Vec<&str> = list.iter().map(|e| e.title.as_str()).collect();
    assert!(titles.contains(&"Ladder latch"), "{titles:?}");
    assert!(titles.contains(&"Weighing (ST)"), "{titles:?}");
    // Ladder projects come first, Petri nets last.
    assert!(titles[0].starts_with("Ladder"), "{titles:?}");
    assert!(titles.last().is_some_and(|t| t.contains("Petri")), "{titles:?}");
    assert_eq!(humanise("sfc-weighing"), "SFC weighing");
    assert_eq!(humanise("traffic_light"), "Traffic light");
    assert_eq!(describe("x.st", "PROGRAM P END_PROGRAM").title, "X (ST)");
}
