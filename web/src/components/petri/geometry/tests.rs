use super::*;

fn pt(x: f64, y: f64) -> Point {
    Point { x, y }
}

#[test]
fn bars_lie_across_the_flow() {
    let t = pt(100.0, 100.0);
    // Flow from above to below: a flat bar.
    assert_eq!(bar_of(t, &[pt(100.0, 40.0)], &[pt(100.0, 160.0)]), Bar::Horizontal);
    // Flow from left to right: a standing bar.
    assert_eq!(bar_of(t, &[pt(20.0, 110.0)], &[pt(190.0, 90.0)]), Bar::Vertical);
    // No arcs: flat.
    assert_eq!(bar_of(t, &[], &[]), Bar::Horizontal);
    assert_eq!(Bar::Vertical.half(), (BAR_THICK / 2.0, BAR_LONG / 2.0));
}

#[test]
fn arcs_run_from_border_to_border() {
    let (p, t) = (pt(0.0, 0.0), pt(0.0, 100.0));
    let (a, b) = arc_line(p, t, Bar::Horizontal, true, false);
    assert_eq!(a, pt(0.0, PLACE_R), "leaves the place's circle");
    assert_eq!(b, pt(0.0, 100.0 - BAR_THICK / 2.0), "ends on the bar's edge");
    // Transition to place: the same line, reversed.
    let (c, d) = arc_line(p, t, Bar::Horizontal, false, false);
    assert_eq!((c, d), (b, a));
    // Diagonal into a standing bar: ends on its side.
    let e = box_exit(pt(0.0, 0.0), pt(-50.0, -10.0), Bar::Vertical.half());
    assert_eq!(e.x, -BAR_THICK / 2.0);
    assert!((e.y - -BAR_THICK / 10.0).abs() < 1e-9, "{e:?}");
}

#[test]
fn twin_arcs_are_drawn_apart() {
    let (p, t) = (pt(0.0, 0.0), pt(100.0, 0.0));
    let (a, _) = arc_line(p, t, Bar::Vertical, true, true);
    let (_, d) = arc_line(p, t, Bar::Vertical, false, true);
    assert!(a.y > 0.0 && d.y < 0.0, "{a:?} {d:?}");
    assert!((a.y - d.y).abs() > 8.0);
}

#[test]
fn macro_places_and_view_boxes_enclose_their_parts() {
    assert_eq!(macro_box(&[]), None);
    let (x, y, w, h) = macro_box(&[pt(60.0, 220.0), pt(60.0, 420.0)]).unwrap();
    assert!(x < 60.0 - PLACE_R && x + w > 60.0 + PLACE_R);
    assert!(y < 220.0 - PLACE_R && y + h > 420.0 + PLACE_R);
    let (vx, vy, vw, vh) = view_box(&[pt(0.0, 0.0), pt(300.0, 500.0)], &[(x, y, w, h)]);
    assert!(vx < -PLACE_R && vy < -PLACE_R);
    assert!(vx + vw > 300.0 + PLACE_R && vy + vh > 500.0 + PLACE_R);
    assert_eq!(view_box(&[], &[]), (0.0, 0.0, 200.0, 100.0));
}

#[test]
fn transition_labels_move_left_of_a_place_they_would_cover() {
    let (hw, _) = Bar::Horizontal.half();
    // The weighing net's T(P33,P1) at x 0, P31 at (60, 220): its label would cover P31.
    let t = pt(0.0, 240.0);
    assert!(label_on_left(t, hw, &[pt(60.0, 220.0)]));
    // Nothing on the right: labels stay right.
    assert!(!label_on_left(t, hw, &[pt(-60.0, 240.0)]));
    // Places on both sides: right, as everywhere else.
    assert!(!label_on_left(t, hw, &[pt(60.0, 220.0), pt(-60.0, 240.0)]));
    let (x, _, w, _) = label_box(t, hw, true);
    assert!(x + w < t.x - hw, "a left label ends before the bar");
}
