use super::*;

const CODE: &str = "CASE p OF
    1: (* P1: ready *)
        ReadyLamp := TRUE;
        IF Fault THEN
            p := 20;
        END_IF;
    31: (* P31: filling *)

        FeedValve := TRUE;
    32:
        x := 1;
END_CASE;
Settle(IN := p = 32);
";

#[test]
fn a_branch_runs_from_its_label_to_the_next_label() {
    // The first statement of branch 1 is on line 3; the branch is lines 2..=6.
    assert_eq!(branch_lines(CODE, 3), (2, 6));
    // A blank line inside a branch does not end it; the next label does.
    assert_eq!(branch_lines(CODE, 9), (7, 9));
    // The last branch ends before END_CASE.
    assert_eq!(branch_lines(CODE, 11), (10, 11));
}

#[test]
fn labels_on_the_statement_line_and_odd_input_are_handled() {
    let one_line = "CASE p OF\n    1: p := 2;\n    2: p := 1;\nEND_CASE;\n";
    assert_eq!(branch_lines(one_line, 2), (2, 2));
    assert_eq!(branch_lines(one_line, 3), (3, 3));
    // No label above: the statement's line alone.
    assert_eq!(branch_lines("x := 1;\n    y := 2;\n", 2), (2, 2));
    // Out of range and empty texts do not panic.
    assert_eq!(branch_lines(CODE, 999), (13, 13));
    assert_eq!(branch_lines("", 5), (1, 1));
    assert!(!is_label("    x := 1;"));
    assert!(is_label("    10..19, 25:"));
}
