use super::*;

/// Each transition's arcs as (place, weight).
type Arcs = Vec<Vec<(usize, u32)>>;

/// The sequential weighing net's start: P1 (0) -T1-> P20 (1), P1 -T2-> P31 (2),
/// P31 -T5-> P32 (3); and a fork F: P1 + A0 (4) -> P30 (5) + A31 (6).
fn net() -> (Arcs, Arcs) {
    let pre = vec![vec![(0, 1)], vec![(0, 1)], vec![(2, 1)], vec![(0, 1), (4, 1)]];
    let post = vec![vec![(1, 1)], vec![(2, 1)], vec![(3, 1)], vec![(5, 1), (6, 1)]];
    (pre, post)
}

#[test]
fn transitions_are_enabled_by_their_input_places() {
    let (pre, _) = net();
    assert_eq!(enabled(&pre, &[1, 0, 0, 0, 0, 0, 0]), [true, true, false, false]);
    assert_eq!(enabled(&pre, &[1, 0, 0, 0, 1, 0, 0]), [true, true, false, true]);
    assert_eq!(enabled(&pre, &[0, 0, 1, 0, 0, 0, 0]), [false, false, true, false]);
    assert_eq!(enabled(&[vec![]], &[1]), [false], "a transition without inputs");
    assert_eq!(enabled(&[vec![(0, 2)]], &[1]), [false], "weights count");
}

#[test]
fn the_step_from_one_marking_to_the_next_names_the_transition_that_fired() {
    let (pre, post) = net();
    // The token moved from P1 to P31: T2, not T1 (P20 stayed empty).
    assert_eq!(
        fired(&pre, &post, &[1, 0, 0, 0, 0, 0, 0], &[0, 0, 1, 0, 0, 0, 0]),
        [false, true, false, false]
    );
    // Nothing changed: nothing fired.
    assert_eq!(fired(&pre, &post, &[1, 0, 0, 0, 0, 0, 0], &[1, 0, 0, 0, 0, 0, 0]), [false; 4]);
    // The fork takes both tokens and marks both outputs.
    assert_eq!(
        fired(&pre, &post, &[1, 0, 0, 0, 1, 0, 0], &[0, 0, 0, 0, 0, 1, 1]),
        [false, false, false, true]
    );
    // A forced jump (the emergency) that no transition explains.
    assert_eq!(fired(&pre, &post, &[0, 0, 0, 1, 0, 0, 0], &[0, 1, 0, 0, 0, 0, 0]), [false; 4]);
}
