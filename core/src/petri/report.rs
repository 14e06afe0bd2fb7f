//! The readable form of the analysis (`plc petri analyze` without `--json`) and the list of
//! structural conflicts with what decides them.

use std::fmt::Write as _;

use super::analysis::NetAnalysis;
use super::conflicts::mutually_exclusive;
use super::model::{Net, PetriPou};
use super::net::PtNet;

/// Two transitions taking tokens from one place.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Conflict {
    /// The shared input place.
    pub place: usize,
    /// The transition tested first (lower priority number, then net order).
    pub first: usize,
    /// The other transition.
    pub second: usize,
    /// Whether the guards are provably mutually exclusive (see `conflicts`).
    pub exclusive: bool,
}

/// Every structural conflict of the POU's net.
pub fn conflicts(pou: &PetriPou, net: &PtNet) -> Vec<Conflict> {
    net_conflicts(&pou.net, net)
}

fn net_conflicts(model: &Net, net: &PtNet) -> Vec<Conflict> {
    let mut out = Vec::new();
    for p in 0..net.places() {
        let mut ts = net.outputs_of_place(p);
        crate::order::sort_by_key(&mut ts, |&t| (model.transitions[t].priority, t));
        for (i, &a) in ts.iter().enumerate() {
            for &b in &ts[i + 1..] {
                let exclusive =
                    mutually_exclusive(&model.transitions[a].guard, &model.transitions[b].guard);
                out.push(Conflict { place: p, first: a, second: b, exclusive });
            }
        }
    }
    out
}

fn yes_no(v: Option<bool>) -> &'static str {
    match v {
        Some(true) => "yes",
        Some(false) => "no",
        None => "unknown",
    }
}

fn flow_text(names: &[String], flow: &[u64]) -> String {
    let terms: Vec<String> = names
        .iter()
        .zip(flow)
        .filter(|(_, &w)| w > 0)
        .map(|(n, &w)| if w == 1 { n.clone() } else { format!("{w}·{n}") })
        .collect();
    terms.join(" + ")
}

/// The analysis as text for a student.
pub fn text_report(model: &Net, net: &PtNet, a: &NetAnalysis) -> String {
    let mut s = String::new();
    let p = |i: usize| net.place_names[i].as_str();
    let t = |i: usize| net.transition_names[i].as_str();
    let _ = writeln!(s, "Guards are ignored: this is the analysis of the uncontrolled net, an over-approximation of the program.");
    let kind = if a.bounded == Some(false) {
        "coverability graph (Karp-Miller)"
    } else {
        "reachability graph"
    };
    let _ = writeln!(
        s,
        "{kind}: {} markings, {} edges{}",
        a.states,
        a.edges,
        if a.complete { "" } else { " (INCOMPLETE: the state budget stopped the search)" }
    );
    let _ = writeln!(
        s,
        "bounded: {}   safe: {}   live: {}   reversible: {}   deadlock-free: {}",
        yes_no(a.bounded),
        yes_no(a.safe),
        yes_no(a.live),
        yes_no(a.reversible),
        if a.deadlocks.is_empty() {
            if a.complete && a.bounded == Some(true) {
                "yes"
            } else {
                "unknown"
            }
        } else {
            "no"
        }
    );
    let bounds: Vec<String> = a
        .bounds
        .iter()
        .enumerate()
        .map(|(i, b)| match b {
            Some(k) => format!("{}={k}", p(i)),
            None => format!("{}=ω", p(i)),
        })
        .collect();
    let _ = writeln!(s, "bounds: {}", bounds.join(", "));
    for d in &a.deadlocks {
        let marking: Vec<String> = d
            .marking
            .iter()
            .enumerate()
            .filter(|(_, &k)| k > 0)
            .map(|(i, &k)| if k == 1 { p(i).to_string() } else { format!("{k}·{}", p(i)) })
            .collect();
        let path: Vec<&str> = d.path.iter().map(|&i| t(i)).collect();
        let _ = writeln!(s, "deadlock: {{{}}} after [{}]", marking.join(", "), path.join(", "));
    }
    match &a.dead_transitions {
        Some(d) if !d.is_empty() => {
            let _ = writeln!(
                s,
                "dead transitions: {}",
                d.iter().map(|&i| t(i)).collect::<Vec<_>>().join(", ")
            );
        }
        Some(_) => {
            let _ = writeln!(s, "dead transitions: none");
        }
        None => {
            let _ = writeln!(s, "dead transitions: unknown (incomplete search)");
        }
    }
    if let Some(live) = &a.live_transitions {
        let not_live: Vec<&str> =
            live.iter().enumerate().filter(|(_, &l)| !l).map(|(i, _)| t(i)).collect();
        if !not_live.is_empty() {
            let _ = writeln!(s, "not live: {}", not_live.join(", "));
        }
    }
    let _ = writeln!(
        s,
        "P-semiflows ({}{}):",
        a.p_semiflows.flows.len(),
        if a.p_semiflows.complete { "" } else { ", incomplete" }
    );
    for y in &a.p_semiflows.flows {
        let _ = writeln!(s, "  {}", flow_text(&net.place_names, y));
    }
    let _ = writeln!(
        s,
        "T-semiflows ({}{}):",
        a.t_semiflows.flows.len(),
        if a.t_semiflows.complete { "" } else { ", incomplete" }
    );
    for x in &a.t_semiflows.flows {
        let _ = writeln!(s, "  {}", flow_text(&net.transition_names, x));
    }
    let _ = writeln!(s, "state-machine components ({}):", a.components.len());
    for c in &a.components {
        let _ = writeln!(s, "  {{{}}}", c.iter().map(|&i| p(i)).collect::<Vec<_>>().join(", "));
    }
    if !a.uncovered.is_empty() {
        let _ = writeln!(
            s,
            "NOT COVERED by any state-machine component (CASE OF code cannot be generated): {}",
            a.uncovered.iter().map(|&i| p(i)).collect::<Vec<_>>().join(", ")
        );
    }
    for m in &model.macro_places {
        let _ = writeln!(
            s,
            "macro-place {}: {}",
            if m.name.trim().is_empty() { &m.id } else { m.name.trim() },
            m.places.join(", ")
        );
    }
    for c in net_conflicts(model, net) {
        let verdict = if c.exclusive {
            "guards mutually exclusive"
        } else {
            "guards may both hold: the IF order decides"
        };
        let _ = writeln!(
            s,
            "conflict at {}: {} before {} ({verdict})",
            p(c.place),
            t(c.first),
            t(c.second)
        );
    }
    s
}
