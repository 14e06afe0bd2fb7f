#![allow(clippy::unwrap_used)]

use super::*;
use crate::project::Project;

#[test]
fn catalog_reads_pou_signatures_and_operand_types() {
    let mut project = Project::new("p");
    project.source = "TYPE Level : INT(0..100); Pos : STRUCT x : REAL; ok : BOOL; END_STRUCT; Alias : Level; END_TYPE
VAR_GLOBAL g : Alias; END_VAR
FUNCTION_BLOCK Fb VAR_INPUT a : Alias; END_VAR VAR_OUTPUT q : BOOL; p : Pos; END_VAR END_FUNCTION_BLOCK
FUNCTION F : WORD VAR_INPUT x : BYTE; END_VAR F := x; END_FUNCTION
"
    .into();
    let c = project.catalog();
    let fb = c.block("fb").unwrap();
    assert_eq!(
        fb.input("A").unwrap().ty,
        Some(catalog::TypeKey::Named("INT".into())),
        "aliases resolve"
    );
    let f = c.block("F").unwrap();
    assert_eq!(f.output("OUT").unwrap().ty, Some(catalog::TypeKey::Named("WORD".into())));
    assert!(c.block("TON").is_some(), "the standard FBs come from the prelude");
    let scope = c.scope("VAR i : Fb; arr : ARRAY[1..3] OF Pos; w : WORD; END_VAR");
    let ty = |t: &str| c.place_type(&scope, t).map(|k| k.to_string());
    assert_eq!(ty("g").as_deref(), Some("INT"));
    assert_eq!(ty("i.q").as_deref(), Some("BOOL"));
    assert_eq!(ty("i.p.x").as_deref(), Some("REAL"));
    assert_eq!(ty("arr[2].ok").as_deref(), Some("BOOL"));
    assert_eq!(ty("w.3").as_deref(), Some("BOOL"));
    assert_eq!(ty("%IW2").as_deref(), Some("WORD"));
    assert_eq!(ty("nope"), None);
    let int = catalog::TypeKey::Named("INT".into());
    let fits = |v: &str| c.value_fits(&scope, v, &int).map(|(ok, _)| ok);
    assert_eq!(fits("5"), Some(true));
    assert_eq!(fits("2.5"), Some(false));
    assert_eq!(fits("T#1s"), Some(false));
    assert_eq!(fits("SINT#3"), Some(true), "SINT widens to INT");
    assert_eq!(fits("DINT#3"), Some(false), "DINT does not narrow to INT");
    assert_eq!(fits("g"), Some(true));
    assert_eq!(fits("-5"), None, "expressions are left to the ST checker");
}
