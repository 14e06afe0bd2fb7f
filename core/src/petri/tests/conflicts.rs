//! What the guard check proves mutually exclusive, and what it must not.

use super::super::conflicts::mutually_exclusive;

#[test]
fn complementary_guards_are_exclusive() {
    assert!(mutually_exclusive("g", "NOT g"));
    assert!(mutually_exclusive("Fault", "Start AND NOT Fault"));
    assert!(mutually_exclusive("x >= 10", "x < 10"));
    assert!(mutually_exclusive("x > 10", "x <= 10"));
    assert!(mutually_exclusive("x = 3", "x <> 3"));
    assert!(mutually_exclusive("10 <= x", "x < 10"));
    assert!(mutually_exclusive("x < 0", "x > 0"));
    assert!(mutually_exclusive("Weight >= Setpoint", "Weight < Setpoint"));
    assert!(mutually_exclusive("a > b", "b >= a"));
    assert!(mutually_exclusive("(a AND b) OR c", "NOT c AND NOT (a AND b)"));
    assert!(mutually_exclusive("FALSE", "TRUE"));
    assert!(mutually_exclusive("x >= 5 AND x <= 7", "x < 5 OR x > 7"));
    assert!(mutually_exclusive("T1.Q AND_THEN ok", "NOT T1.Q"));
}

#[test]
fn overlapping_guards_are_not() {
    assert!(!mutually_exclusive("Fault", "Weight >= Setpoint"));
    assert!(!mutually_exclusive("x >= 5", "x <= 5"));
    assert!(!mutually_exclusive("x > 1", "x < 2"), "1.5 satisfies both when x is REAL");
    assert!(!mutually_exclusive("", "g"));
    assert!(!mutually_exclusive("a OR b", "b"));
    assert!(!mutually_exclusive("a XOR b", "a AND NOT b"));
}

#[test]
fn unrelated_comparisons_are_not_claimed_exclusive() {
    // x > y and y > x are exclusive, but we do not relate them: no false proof.
    assert!(!mutually_exclusive("x > y", "y > x"));
    assert!(!mutually_exclusive("f(x) > 0", "f(x) > 0"));
}

#[test]
fn a_guard_that_does_not_parse_is_not_exclusive() {
    assert!(!mutually_exclusive("a AND", "NOT a"));
}
