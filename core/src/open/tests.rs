#![allow(clippy::unwrap_used)]

use super::*;
use crate::project::{Project, ProjectError};

#[test]
fn any_file_opens_as_the_kind_it_is() {
    let ladder = include_str!("../../../examples/ladder-five-rungs.plcproj.json");
    let opened = open_text("x", ladder).unwrap();
    assert_eq!(opened.kind, FileKind::Project);
    assert_eq!(opened.project.ladder.len(), 5);

    let xml = include_str!("../../../examples/ladder-five-rungs.xml");
    let opened = open_text("x", xml).unwrap();
    assert_eq!(opened.kind, FileKind::Plcopen);
    let names: Vec<&str> = opened.project.ladder.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["Latch", "DelayedLamp", "PartCounter", "LevelCopy", "ThreeWay"]);

    let net =
        Project::from_file(include_str!("../../../examples/weighing-sequential.plcproj.json"))
            .unwrap()
            .petri
            .remove(0);
    let pnml = crate::pnml::export(&net);
    let opened = open_text("x", &pnml).unwrap();
    assert_eq!(opened.kind, FileKind::Pnml);
    assert_eq!((opened.project.name.as_str(), opened.project.source.as_str()), ("Weighing", ""));
    assert_eq!(opened.project.petri, vec![net]);

    let opened = open_text("Mine", "\u{feff}PROGRAM P END_PROGRAM").unwrap();
    assert_eq!((opened.kind, opened.project.name.as_str()), (FileKind::St, "Mine"));
    assert!(opened.project.ladder.is_empty() && opened.project.petri.is_empty());
}

#[test]
fn a_damaged_file_says_what_it_was_read_as() {
    let e = open_text("x", "{ not json").unwrap_err();
    assert!(matches!(e, OpenError::Project(ProjectError::NotJson(_))), "{e:?}");
    let e = open_text("x", "<pnml><net></pnml>").unwrap_err();
    assert!(matches!(e, OpenError::Pnml(_)), "{e:?}");
    assert!(e.to_string().contains("E0516"), "{e}");
    let e = open_text("x", "<?xml version=\"1.0\"?><other/>").unwrap_err();
    assert!(matches!(e, OpenError::Plcopen(_)), "{e:?}");
}
