//! Unit tests of the directive parser, the path lookup and the value comparison.

use super::*;
use crate::path::{parse_path, Step};
use serde_json::json;

#[test]
fn parses_every_directive() {
    let src = "//! program: Main\n//! cycles: 3\n//! cycle_ms: 100\n//! set: Start = TRUE\n\
               //! set: t=T#1s\n//! expect: x = 42\n//! expect: tmr.ET = \"T#200ms\"\n\
               //! cycles_done: 2\nPROGRAM Main END_PROGRAM\n";
    let d = parse_directives(src).expect("parses");
    assert_eq!(d.program.as_deref(), Some("Main"));
    assert_eq!(d.cycles, Some(3));
    assert_eq!(d.cycle_ms, Some(100));
    assert_eq!(d.set, vec![("Start".into(), "TRUE".into()), ("t".into(), "T#1s".into())]);
    assert_eq!(d.expects.len(), 2);
    assert_eq!(d.expects[0].path, "x");
    assert_eq!(d.expects[0].value, json!(42));
    assert_eq!(d.expects[0].line, 6);
    assert_eq!(d.expects[1].value, json!("T#200ms"));
    assert_eq!(d.cycles_done, Some(2));
    assert_eq!(d.status, ExpectedStatus::Ok);
}

#[test]
fn expect_value_may_contain_equals_and_dollar() {
    let d = parse_directives("//! expect: s = \"a=b$c\"\n").expect("parses");
    assert_eq!(d.expects[0].path, "s");
    assert_eq!(d.expects[0].value, json!("a=b$c"));
}

#[test]
fn fault_and_error_directives_imply_status() {
    let d = parse_directives("//! fault_line: 7\n").expect("parses");
    assert_eq!(d.status, ExpectedStatus::Fault);
    assert_eq!(d.fault_line, Some(7));
    let d = parse_directives("//! error_code: E0100\n//! error_line: 5\n//! error_count: 1\n")
        .expect("parses");
    assert_eq!(d.status, ExpectedStatus::Error);
    assert_eq!(d.error_codes, vec!["E0100".to_string()]);
    assert_eq!((d.error_line, d.error_count), (Some(5), Some(1)));
    let d = parse_directives("//! status: error\n//! error_message: MyVar\n").expect("parses");
    assert_eq!(d.error_messages, vec!["MyVar".to_string()]);
}

#[test]
fn rejects_malformed_directives() {
    for bad in [
        "//! cycle: 3",
        "//! cycles: three",
        "//! expect: x 42",
        "//! expect: x = {not json",
        "//! expect: [0] = 1",
        "//! status: crashed",
        "//! error_code: 100",
        "//! set: x",
        "//! nonsense",
        "//! status: ok\n//! fault_line: 3",
        "//! fault_line: 3\n//! error_line: 3",
    ] {
        assert!(parse_directives(bad).is_err(), "accepted {bad:?}");
    }
}

#[test]
fn ordinary_comments_are_not_directives() {
    let d = parse_directives("// expect: x = 1\n(* //! cycles: x *)\nPROGRAM P END_PROGRAM")
        .expect("ok");
    assert!(d.expects.is_empty());
    assert_eq!(d.cycles, None);
}

#[test]
fn parses_paths() {
    assert_eq!(parse_path("x").expect("ok"), ("x".to_string(), vec![]));
    assert_eq!(
        parse_path("grid[1][0].x").expect("ok"),
        ("grid".to_string(), vec![Step::Index(1), Step::Index(0), Step::Field("x".into())])
    );
    assert_eq!(
        parse_path("tmr.ET").expect("ok"),
        ("tmr".to_string(), vec![Step::Field("ET".into())])
    );
    for bad in ["", ".x", "a.", "a[", "a[-1]", "a[x]", "a b", "a..b"] {
        assert!(parse_path(bad).is_err(), "accepted {bad:?}");
    }
}

#[test]
fn looks_paths_up() {
    let vars = json!({"x": 1, "arr": [10, 20, {"f": [true]}], "tmr": {"Q": false, "ET": "T#0s"}});
    assert_eq!(lookup(&vars, "x").expect("x"), &json!(1));
    assert_eq!(lookup(&vars, "arr[1]").expect("arr"), &json!(20));
    assert_eq!(lookup(&vars, "arr[2].f[0]").expect("nested"), &json!(true));
    assert_eq!(lookup(&vars, "tmr.ET").expect("field"), &json!("T#0s"));
    assert!(lookup(&vars, "X").unwrap_err().contains("no variable `X`"));
    assert!(lookup(&vars, "arr[3]").unwrap_err().contains("3 elements"));
    assert!(lookup(&vars, "tmr.PT").unwrap_err().contains("no field `PT`"));
    assert!(lookup(&vars, "x[0]").unwrap_err().contains("not an array"));
}

#[test]
fn compares_values() {
    assert!(values_match(&json!(42), &json!(42)));
    assert!(!values_match(&json!(42), &json!(43)));
    assert!(values_match(&json!(-5), &json!(-5)));
    assert!(values_match(&json!(18446744073709551615u64), &json!(18446744073709551615u64)));
    assert!(values_match(&json!(3), &json!(3.0)));
    assert!(!values_match(&json!(3), &json!(3.5)));
    // Reals: relative 1e-6.
    assert!(values_match(&json!(1.2345678), &json!(1.2345679)));
    assert!(!values_match(&json!(2.71), &json!(2.72)));
    assert!(values_match(&json!(1.234e-6), &json!(1.2340001e-6)));
    assert!(!values_match(&json!(1.234e-6), &json!(0.0)));
    assert!(values_match(&json!(0.0), &json!(0)));
    assert!(!values_match(&json!(0.0), &json!(1e-9)));
    assert!(values_match(&json!("T#1s"), &json!("T#1s")));
    assert!(!values_match(&json!("1"), &json!(1)));
    assert!(!values_match(&json!(true), &json!(1)));
    assert!(values_match(&json!([1, 2.5]), &json!([1, 2.5000001])));
    assert!(!values_match(&json!([1, 2]), &json!([1, 2, 3])));
    assert!(values_match(&json!({"a": 1, "b": [true]}), &json!({"b": [true], "a": 1})));
    assert!(!values_match(&json!({"a": 1}), &json!({"a": 1, "b": 2})));
}

fn report(status: &str) -> serde_json::Value {
    json!({
        "status": status, "cycles": 2,
        "vars": {"x": 42, "t": {"ET": "T#20ms"}},
        "fault": if status == "fault" { json!({"message": "division by zero", "line": 7, "column": 5}) } else { json!(null) },
        "diagnostics": if status == "error" {
            json!([{"severity": "error", "code": "E0100", "message": "`Foo` is not declared", "line": 5, "column": 3}])
        } else { json!([]) }
    })
}

fn case(src: &'static str) -> Case {
    Case::new("unit/case", src)
}

#[test]
fn checks_a_passing_report() {
    let c = case(
        "//! cycles: 2\n//! expect: x = 42\n//! expect: t.ET = \"T#20ms\"\n//! cycles_done: 2\n",
    );
    assert_eq!(check_case(&c, &report("ok")), Ok(()));
    let c = case("//! fault_line: 7\n//! expect: x = 42\n");
    assert_eq!(check_case(&c, &report("fault")), Ok(()));
    let c = case(
        "//! error_code: E0100\n//! error_line: 5\n//! error_count: 1\n//! error_message: Foo\n",
    );
    assert_eq!(check_case(&c, &report("error")), Ok(()));
}

#[test]
fn names_case_path_expected_and_actual() {
    let c = case("//! expect: x = 41\n//! expect: y = 1\n");
    let err = check_case(&c, &report("ok")).unwrap_err();
    assert!(err.contains("[unit/case] x (line 1): expected 41, got 42"), "{err}");
    assert!(err.contains("no variable `y`"), "{err}");
    let err = check_case(&case("//! fault_line: 8\n"), &report("fault")).unwrap_err();
    assert!(err.contains("fault line: expected 8, got 7"), "{err}");
    let err = check_case(&case("//! error_code: E0150\n"), &report("error")).unwrap_err();
    assert!(err.contains("no diagnostic with code E0150"), "{err}");
    let err = check_case(&case(""), &report("error")).unwrap_err();
    assert!(err.contains("status: expected ok, got error"), "{err}");
    let err = check_case(&case("//! cycles: x"), &report("ok")).unwrap_err();
    assert!(err.contains("bad directives"), "{err}");
}

#[test]
fn options_follow_directives() {
    let c = case("//! program: P2\n//! cycles: 5\n//! set: a=1\n");
    let o = c.options();
    assert_eq!(o.program.as_deref(), Some("P2"));
    assert_eq!((o.cycles, o.cycle_ms), (5, 10));
    assert_eq!(o.set, vec![("a".to_string(), "1".to_string())]);
}

#[test]
fn embedded_cases_are_sorted_and_parse() {
    let all = cases();
    assert!(all.len() >= 170, "only {} cases", all.len());
    assert!(all.windows(2).all(|w| w[0].name < w[1].name));
    for c in &all {
        assert!(c.directive_error.is_none(), "{}: {:?}", c.name, c.directive_error);
        assert!(c.name.contains('/'), "{} is not in a group", c.name);
    }
}

#[test]
fn finds_first_difference() {
    use crate::path::first_difference;
    let a = json!({"status": "ok", "vars": {"x": [1, 2.5]}});
    assert_eq!(first_difference(&a, &a), "");
    let b = json!({"status": "ok", "vars": {"x": [1, 2.4]}});
    assert_eq!(first_difference(&a, &b), ".vars.x[1]: 2.5 vs 2.4");
    let c = json!({"status": "ok", "vars": {"x": [1, 2.5], "y": 0}});
    assert_eq!(first_difference(&a, &c), ".vars.y: missing vs 0");
}
