//! The analysis on classic nets; every expected value is worked out by hand below.

use super::*;

fn analysed(n: &Net) -> (PtNet, NetAnalysis) {
    let pt = build(n).unwrap();
    let a = analyze(&pt, DEFAULT_BUDGET);
    (pt, a)
}

fn names(pt: &PtNet, ts: &[usize]) -> Vec<String> {
    ts.iter().map(|&t| pt.transition_names[t].clone()).collect()
}

fn marked(pt: &PtNet, m: &[u32]) -> Vec<(String, u32)> {
    m.iter()
        .enumerate()
        .filter(|(_, &k)| k > 0)
        .map(|(p, &k)| (pt.place_names[p].clone(), k))
        .collect()
}

fn mutex() -> Net {
    net(
        &[("idle1", 1), ("crit1", 0), ("idle2", 1), ("crit2", 0), ("mutex", 1)],
        &[
            ("enter1", &["idle1", "mutex"], &["crit1"]),
            ("exit1", &["crit1"], &["idle1", "mutex"]),
            ("enter2", &["idle2", "mutex"], &["crit2"]),
            ("exit2", &["crit2"], &["idle2", "mutex"]),
        ],
    )
}

#[test]
fn mutual_exclusion() {
    // Markings: {idle1, idle2, mutex} → enter1 → {crit1, idle2} → exit1 → back;
    // likewise through {idle1, crit2}: 3 markings, 4 edges, one terminal SCC holding
    // every edge, so every transition is live and the net is reversible.
    let (pt, a) = analysed(&mutex());
    assert_eq!((a.states, a.edges, a.complete), (3, 4, true));
    assert_eq!(
        (a.bounded, a.safe, a.live, a.reversible),
        (Some(true), Some(true), Some(true), Some(true))
    );
    assert_eq!(a.bounds, vec![Some(1); 5]);
    assert!(a.deadlocks.is_empty());
    assert_eq!(a.dead_transitions, Some(vec![]));
    // P-semiflows: idle1+crit1, idle2+crit2, mutex+crit1+crit2 (the mutual exclusion);
    // sorted by support (places in net order, earlier places first).
    assert_eq!(
        a.p_semiflows.flows,
        vec![vec![1, 1, 0, 0, 0], vec![0, 1, 0, 1, 1], vec![0, 0, 1, 1, 0]]
    );
    // T-semiflows: enter1+exit1, enter2+exit2.
    assert_eq!(a.t_semiflows.flows, vec![vec![1, 1, 0, 0], vec![0, 0, 1, 1]]);
    // All three are state-machine components; together they cover every place.
    assert_eq!(a.components.len(), 3);
    assert!(a.uncovered.is_empty());
    let json: serde_json::Value = serde_json::from_str(&a.to_json(&pt)).unwrap();
    assert_eq!(json["p_invariants"][1], serde_json::json!({"crit1": 1, "crit2": 1, "mutex": 1}));
    assert_eq!(json["bounds"]["mutex"], 1);
}

#[test]
fn mutual_exclusion_never_marks_both_critical_sections() {
    let pt = build(&mutex()).unwrap();
    let g = reach::explore(&pt, 100);
    assert!(g.markings.iter().all(|m| m[1] + m[3] <= 1));
}

#[test]
fn producer_consumer_with_a_buffer_of_two() {
    // Producer P0 -produce-> P1 -put(takes a free slot, adds an item)-> P0; consumer
    // C0 -get(takes an item, frees a slot)-> C1 -consume-> C0; free starts at 2.
    // Every (producer, consumer, items 0..2) combination is reachable: 2·2·3 = 12
    // markings. Edges: produce in the 6 markings with P0, consume in the 6 with C1, put
    // with P1 and items < 2 (2·2 = 4), get with C0 and items > 0 (4): 20.
    let n = producer_consumer();
    let (_, a) = analysed(&n);
    assert_eq!((a.states, a.edges), (12, 20));
    assert_eq!((a.bounded, a.safe), (Some(true), Some(false)));
    assert_eq!(a.bounds, vec![Some(1), Some(1), Some(1), Some(1), Some(2), Some(2)]);
    assert_eq!((a.live, a.reversible), (Some(true), Some(true)));
    assert!(a.deadlocks.is_empty());
    // Invariants: P0+P1 = 1, C0+C1 = 1, items+free = 2; one cycle of all four transitions.
    assert_eq!(
        a.p_semiflows.flows,
        vec![vec![1, 1, 0, 0, 0, 0], vec![0, 0, 1, 1, 0, 0], vec![0, 0, 0, 0, 1, 1]]
    );
    assert_eq!(a.t_semiflows.flows, vec![vec![1, 1, 1, 1]]);
    // items+free holds two tokens: a component, but not one a step variable can hold.
    assert_eq!(a.components.len(), 3);
}

fn philosophers() -> Net {
    // Philosopher i takes its left fork f_i, then its right fork f_(i+1 mod 3), eats and
    // puts both back.
    net(
        &[
            ("think0", 1),
            ("left0", 0),
            ("eat0", 0),
            ("think1", 1),
            ("left1", 0),
            ("eat1", 0),
            ("think2", 1),
            ("left2", 0),
            ("eat2", 0),
            ("f0", 1),
            ("f1", 1),
            ("f2", 1),
        ],
        &[
            ("takeL0", &["think0", "f0"], &["left0"]),
            ("takeR0", &["left0", "f1"], &["eat0"]),
            ("release0", &["eat0"], &["think0", "f0", "f1"]),
            ("takeL1", &["think1", "f1"], &["left1"]),
            ("takeR1", &["left1", "f2"], &["eat1"]),
            ("release1", &["eat1"], &["think1", "f1", "f2"]),
            ("takeL2", &["think2", "f2"], &["left2"]),
            ("takeR2", &["left2", "f0"], &["eat2"]),
            ("release2", &["eat2"], &["think2", "f2", "f0"]),
        ],
    )
}

#[test]
fn dining_philosophers_deadlock_with_its_firing_path() {
    // States: each philosopher thinks (T), holds its left fork (L) or eats (E); when
    // philosopher i-1 eats it holds f_i, so philosopher i must think. No E: 2³ = 8;
    // one E (3 choices): its right neighbour thinks, the third is T or L: 6; two E's are
    // impossible. 14 markings. Edges: with no E, each thinker can take its fork (12 over
    // the 8 states) and a left-holder can take its right fork iff its right neighbour
    // thinks (2 states for each of 3 philosophers: 6); with one E: its release, plus a
    // take-left by the third philosopher when it thinks: 3·(2+1) = 9. 27 edges.
    let (pt, a) = analysed(&philosophers());
    assert_eq!((a.states, a.edges), (14, 27));
    assert_eq!((a.bounded, a.safe), (Some(true), Some(true)));
    // The one deadlock: every philosopher holds its left fork. Breadth-first search
    // reaches it first by takeL0, takeL1, takeL2.
    assert_eq!(a.deadlocks.len(), 1);
    let d = &a.deadlocks[0];
    assert_eq!(
        marked(&pt, &d.marking),
        vec![("left0".to_string(), 1), ("left1".to_string(), 1), ("left2".to_string(), 1)]
    );
    assert_eq!(names(&pt, &d.path), vec!["takeL0", "takeL1", "takeL2"]);
    // Replaying the path from the initial marking gives the deadlock.
    let mut m = pt.initial.clone();
    for &t in &d.path {
        assert!(pt.enabled(&m, t));
        m = pt.fire(&m, t);
    }
    assert_eq!(m, d.marking);
    // The deadlock is a terminal SCC without edges: nothing is live, nothing dead.
    assert_eq!(a.live, Some(false));
    assert_eq!(a.live_transitions, Some(vec![false; 9]));
    assert_eq!(a.dead_transitions, Some(vec![]));
    assert_eq!(a.reversible, Some(false));
    let json: serde_json::Value = serde_json::from_str(&a.to_json(&pt)).unwrap();
    assert_eq!(
        json["deadlocks"],
        serde_json::json!([{"marking": {"left0": 1, "left1": 1, "left2": 1}, "path": ["takeL0", "takeL1", "takeL2"]}])
    );
}

#[test]
fn unbounded_net_gets_omega() {
    // t0 keeps its token in p0 and adds one to p1; t1 moves a token from p1 to p2.
    // Karp–Miller: (1,0,0) -t0-> (1,1,0) covers (1,0,0) → (1,ω,0); t0 loops there;
    // t1 gives (1,ω,1) covering (1,ω,0) → (1,ω,ω), where t0 and t1 loop.
    // 3 nodes, 5 edges.
    let n = net(
        &[("p0", 1), ("p1", 0), ("p2", 0)],
        &[("t0", &["p0"], &["p0", "p1"]), ("t1", &["p1"], &["p2"])],
    );
    let (pt, a) = analysed(&n);
    assert_eq!((a.states, a.edges, a.complete), (3, 5, true));
    assert_eq!((a.bounded, a.safe), (Some(false), Some(false)));
    assert_eq!(a.bounds, vec![Some(1), None, None]);
    assert!(a.deadlocks.is_empty());
    assert_eq!(a.dead_transitions, Some(vec![]));
    // Coverability cannot decide liveness or reversibility here.
    assert_eq!((a.live, a.reversible), (None, None));
    // yᵀC = 0: C = [[0,0],[1,-1],[0,1]] forces y1 = y2 = 0: only p0.
    assert_eq!(a.p_semiflows.flows, vec![vec![1, 0, 0]]);
    // Cx = 0: x0 − x1 = 0 and x1 = 0: no T-semiflow.
    assert!(a.t_semiflows.flows.is_empty());
    let json = a.to_json(&pt);
    assert!(json.contains(r#""bounds":{"p0":1,"p1":null,"p2":null}"#), "{json}");
    assert!(json.contains(r#""live":null,"reversible":null"#), "{json}");
}

#[test]
fn a_dead_transition_is_found_in_an_unbounded_net() {
    // t0 pumps tokens into p1; t1 needs a token in p2, which nothing ever marks.
    let n = net(
        &[("p0", 1), ("p1", 0), ("p2", 0)],
        &[("t0", &["p0"], &["p0", "p1"]), ("t1", &["p2"], &["p1"])],
    );
    let (_, a) = analysed(&n);
    assert_eq!(a.dead_transitions, Some(vec![1]));
    // A dead transition is never live, whatever coverability leaves open.
    assert_eq!(a.live, Some(false));
}

#[test]
fn the_budget_cuts_the_search_and_says_so() {
    let (pt, _) = analysed(&mutex());
    let a = analyze(&pt, 2);
    assert_eq!((a.states, a.complete), (2, false));
    assert_eq!((a.bounded, a.safe, a.live, a.reversible), (None, None, None, None));
    assert_eq!(a.dead_transitions, None);
    let json = a.to_json(&pt);
    assert!(json.starts_with(r#"{"states":2,"edges":"#), "{json}");
    assert!(json.contains(r#""complete":false"#), "{json}");
}

#[test]
fn json_has_exactly_the_issue_keys_in_order() {
    let (pt, a) = analysed(&mutex());
    let json = a.to_json(&pt);
    let keys = [
        "states",
        "edges",
        "complete",
        "bounded",
        "safe",
        "bounds",
        "deadlocks",
        "dead_transitions",
        "live",
        "reversible",
        "p_invariants",
        "t_invariants",
    ];
    let mut last = 0;
    for k in keys {
        let at = json.find(&format!("\"{k}\":")).unwrap_or_else(|| panic!("{k} missing: {json}"));
        assert!(at >= last, "{k} out of order");
        last = at;
    }
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v.as_object().unwrap().len(), keys.len());
}

#[test]
fn weights_count_in_enabling_and_firing() {
    // t needs 2 tokens from a and puts 3 into b: (2,0) → (0,3), then nothing: a deadlock.
    let n = net(&[("a", 2), ("b", 0)], &[("t", &["a*2"], &["b*3"])]);
    let (pt, a) = analysed(&n);
    assert_eq!(a.states, 2);
    assert_eq!(a.deadlocks.len(), 1);
    assert_eq!(marked(&pt, &a.deadlocks[0].marking), vec![("b".to_string(), 3)]);
    // 3a + 2b is invariant: 3·2 = 6 = 2·3.
    assert_eq!(a.p_semiflows.flows, vec![vec![3, 2]]);
}

#[test]
fn text_report_says_guards_are_ignored() {
    let n = philosophers();
    let (pt, a) = analysed(&n);
    let text = text_report(&n, &pt, &a);
    assert!(text.starts_with("Guards are ignored"), "{text}");
    assert!(
        text.contains("deadlock: {left0, left1, left2} after [takeL0, takeL1, takeL2]"),
        "{text}"
    );
}
