use super::*;
use plc_core::petri::{Arc, Place, Position, Transition};

/// P1 -t1-> P2 -t2-> P1, with P1 marked, no positions.
fn cycle() -> Net {
    let mut net = Net::default();
    net.places.push(Place::new("P1", 1, 1));
    net.places.push(Place::new("P2", 2, 0));
    net.transitions.push(Transition::new("t1", ""));
    net.transitions.push(Transition::new("t2", ""));
    for (a, b) in [("P1", "t1"), ("t1", "P2"), ("P2", "t2"), ("t2", "P1")] {
        net.arcs.push(Arc::new(a, b));
    }
    net
}

#[test]
fn stored_positions_are_used_when_every_element_has_one() {
    let mut net = cycle();
    for (i, p) in net.places.iter_mut().enumerate() {
        p.position = Some(Position { x: 10.0 * i as f64, y: 5.0 });
    }
    for t in &mut net.transitions {
        t.position = Some(Position { x: 1.0, y: 2.0 });
    }
    let l = layout(&net);
    assert!(!l.automatic);
    assert_eq!(l.places[1], Point { x: 10.0, y: 5.0 });
    assert_eq!(l.transitions[0], Point { x: 1.0, y: 2.0 });
    // One missing position: the whole net is laid out.
    net.transitions[1].position = None;
    assert!(layout(&net).automatic);
}

#[test]
fn a_cycle_is_laid_out_in_layers_from_the_marked_place() {
    let l = layout(&cycle());
    assert!(l.automatic);
    // P1 layer 0, t1 layer 1, P2 layer 2, t2 layer 3: one column.
    let y = |p: Point| ((p.y - 60.0) / LAYER_DY).round() as i32;
    assert_eq!(
        [y(l.places[0]), y(l.transitions[0]), y(l.places[1]), y(l.transitions[1])],
        [0, 1, 2, 3]
    );
    assert!(l.places.iter().chain(&l.transitions).all(|p| p.x == 60.0));
}

#[test]
fn a_fork_spreads_its_branches_and_the_join_is_centred_below() {
    // P0 -fork-> A, B -join-> P0 (A and B on one layer, side by side).
    let mut net = Net::default();
    net.places.push(Place::new("P0", 0, 1));
    net.places.push(Place::new("A", 1, 0));
    net.places.push(Place::new("B", 2, 0));
    net.transitions.push(Transition::new("fork", ""));
    net.transitions.push(Transition::new("join", ""));
    for (a, b) in
        [("P0", "fork"), ("fork", "A"), ("fork", "B"), ("A", "join"), ("B", "join"), ("join", "P0")]
    {
        net.arcs.push(Arc::new(a, b));
    }
    let l = layout(&net);
    let (a, b) = (l.places[1], l.places[2]);
    assert_eq!(a.y, b.y);
    assert_eq!((b.x - a.x).abs(), LAYER_DX);
    assert!(a.x < b.x, "model order is kept on ties");
    assert_eq!(l.transitions[1].x, (a.x + b.x) / 2.0, "the single join is centred");
    assert_eq!(layout(&net), l, "deterministic");
}

#[test]
fn unreachable_and_dangling_elements_still_get_a_place() {
    let mut net = cycle();
    net.places.push(Place::new("Lonely", 9, 0));
    net.arcs.push(Arc::new("Nowhere", "t1"));
    let l = layout(&net);
    assert_eq!(l.places.len(), 3);
    let lonely = l.places[2];
    let others: Vec<Point> = l.places[..2].iter().chain(&l.transitions).copied().collect();
    assert!(others.iter().all(|p| *p != lonely), "no two elements on one spot");
    assert!(layout(&Net::default()).places.is_empty());
}
