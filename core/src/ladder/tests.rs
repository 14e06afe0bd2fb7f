#![allow(clippy::unwrap_used)]

use super::*;

#[test]
fn empty_project_source_is_st_source() {
    let project = Project::new("p");
    let src = project_source(&project).unwrap();
    assert_eq!(src.text, project.source);
    assert_eq!(src.map.origin(1), Origin::St(1));
}
