//! Issue 35: a start/stop latch drawn in OpenPLC Editor — its I/O declared as the
//! program's local variables at `%IX0.0`, `%IX0.1` and `%QX0.0`, as OpenPLC writes them —
//! scores full marks against the shipped `latch` exercise (it got 0 of 3: "declares Start
//! in another section than the exercise asks").

#![allow(clippy::unwrap_used)]

use plc_core::exercise::{grade, Exercise};
use plc_core::open::open_text;

#[test]
fn an_openplc_latch_with_located_io_passes_the_latch_exercise() {
    let exercise = Exercise::from_toml(include_str!("../../exercises/latch/latch.toml")).unwrap();
    let xml = include_str!("data/openplc-latch.xml");
    let opened = open_text("openplc-latch", xml).unwrap();
    let report = grade(&exercise, &opened.project).unwrap();
    assert_eq!(report.error, None, "{report:#?}");
    assert_eq!((report.score, report.total), (3, 3), "{report:#?}");
}
