//! Behavioural and structural analysis of the underlying place/transition net.
//!
//! Guards are ignored, so every result is about the uncontrolled net: an over-approximation
//! of what the program can do (a deadlock found here may be avoided by the guards; a net
//! found safe stays safe with any guards). The report says so.
//!
//! - Reachability graph with a state budget; when the net is unbounded, Karp–Miller
//!   coverability (ω markings). Bounds, boundedness and safeness come from it.
//! - Deadlocks, each with a shortest firing sequence from the initial marking.
//! - Dead transitions (never enabled: exact even for unbounded nets, as coverability
//!   decides it), liveness per transition (L4: from every reachable marking the transition
//!   can fire again; equivalently, it labels an edge inside every terminal strongly
//!   connected component of the reachability graph), reversibility (the graph is strongly
//!   connected). Liveness and reversibility are left undecided (`None`) for unbounded nets
//!   and when the budget cut the search, unless a deadlock or a dead transition decides them.
//! - Minimal P- and T-semiflows and the state-machine components.

use serde::ser::{Serialize, SerializeMap, Serializer};

use super::components::{state_machine_components, uncovered};
use super::net::{Marking, PtNet};
use super::reach::{explore_with, scc, OMEGA};
use super::semiflows::{is_semiflow, minimal_semiflows, Semiflow, Semiflows};

pub use crate::limits::PETRI_DEFAULT_BUDGET as DEFAULT_BUDGET;

/// A reachable marking where no transition is enabled.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Deadlock {
    /// The marking.
    pub marking: Marking,
    /// A shortest firing sequence (transition indices) from the initial marking.
    pub path: Vec<usize>,
}

/// Everything the analysis finds out about a net.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetAnalysis {
    /// Markings in the (reachability or coverability) graph.
    pub states: usize,
    /// Edges in it.
    pub edges: usize,
    /// False when the state budget stopped the exploration.
    pub complete: bool,
    /// Every place bounded; `None` when the budget stopped the search before deciding.
    pub bounded: Option<bool>,
    /// Every place holds at most one token; `None` when undecided.
    pub safe: Option<bool>,
    /// Per place: the largest token count found (`None`: unbounded, ω).
    pub bounds: Vec<Option<u32>>,
    /// The deadlocks found (all of them when the graph is complete and bounded).
    pub deadlocks: Vec<Deadlock>,
    /// The transitions that can never fire; `None` when undecided.
    pub dead_transitions: Option<Vec<usize>>,
    /// Per transition: L4-live; `None` when undecided.
    pub live_transitions: Option<Vec<bool>>,
    /// Every transition live; `None` when undecided.
    pub live: Option<bool>,
    /// The initial marking can be reached again from every reachable marking.
    pub reversible: Option<bool>,
    /// Minimal-support P-semiflows (place invariants).
    pub p_semiflows: Semiflows,
    /// Minimal-support T-semiflows (transition invariants).
    pub t_semiflows: Semiflows,
    /// The state-machine components (place lists).
    pub components: Vec<Vec<usize>>,
    /// Places no state-machine component covers.
    pub uncovered: Vec<usize>,
}

/// Analyses `net`, exploring at most `budget` markings.
pub fn analyze(net: &PtNet, budget: usize) -> NetAnalysis {
    analyze_with(net, budget, minimal_semiflows(&net.incidence()), true)
}

/// [`analyze`] with the net's P-semiflows already computed; without `t_semiflows` the
/// T-semiflows are left empty (and marked incomplete), for the checks run when compiling.
pub fn analyze_with(
    net: &PtNet,
    budget: usize,
    p_semiflows: Semiflows,
    t_semiflows: bool,
) -> NetAnalysis {
    let conservative = {
        let mut covered = vec![false; net.places()];
        for y in &p_semiflows.flows {
            for (p, &w) in y.iter().enumerate() {
                covered[p] |= w > 0;
            }
        }
        covered.iter().all(|&c| c)
    };
    let g = explore_with(net, budget, conservative);
    let n_t = net.transitions();
    let mut bounds: Vec<Option<u32>> = vec![Some(0); net.places()];
    for m in &g.markings {
        for (b, &k) in bounds.iter_mut().zip(m) {
            *b = match (*b, k) {
                (None, _) | (_, OMEGA) => None,
                (Some(x), k) => Some(x.max(k)),
            };
        }
    }
    let succ = g.successors();
    let deadlocks: Vec<Deadlock> = (0..g.markings.len())
        .filter(|&m| succ[m].is_empty() && !g.markings[m].contains(&OMEGA))
        .filter(|&m| (0..n_t).all(|t| !net.enabled(&g.markings[m], t)))
        .map(|m| Deadlock { marking: g.markings[m].clone(), path: g.path_to(m) })
        .collect();
    let mut fired = vec![false; n_t];
    for &(_, t, _) in &g.edges {
        fired[t] = true;
    }
    let omega = g.has_omega;
    let bounded = if omega { Some(false) } else { g.complete.then_some(true) };
    let too_many = bounds.iter().any(|b| b.is_none_or(|k| k > 1));
    let safe = if too_many { Some(false) } else { g.complete.then_some(true) };
    let dead_transitions = g.complete.then(|| (0..n_t).filter(|&t| !fired[t]).collect::<Vec<_>>());
    let (live_transitions, mut live, mut reversible) = if g.complete && !omega {
        let (comp, count) = scc(&succ);
        let mut terminal = vec![true; count];
        for &(from, _, to) in &g.edges {
            if comp[from] != comp[to] {
                terminal[comp[from]] = false;
            }
        }
        let per_t: Vec<bool> = (0..n_t)
            .map(|t| {
                (0..count).filter(|&c| terminal[c]).all(|c| {
                    g.edges.iter().any(|&(from, u, to)| u == t && comp[from] == c && comp[to] == c)
                })
            })
            .collect();
        let live = per_t.iter().all(|&l| l);
        (Some(per_t), Some(live), Some(count == 1))
    } else {
        (None, None, None)
    };
    // What a deadlock or a dead transition decides even in an incomplete or ω graph.
    if live.is_none()
        && n_t > 0
        && (!deadlocks.is_empty() || dead_transitions.as_ref().is_some_and(|d| !d.is_empty()))
    {
        live = Some(false);
    }
    if reversible.is_none() && deadlocks.iter().any(|d| d.marking != net.initial) {
        reversible = Some(false);
    }
    let t_semiflows = if t_semiflows {
        minimal_semiflows(&net.incidence().transpose())
    } else {
        Semiflows::default()
    };
    debug_assert!(p_semiflows.flows.iter().all(|y| is_semiflow(&net.incidence(), y)));
    let components = state_machine_components(net, &p_semiflows.flows);
    let uncovered = uncovered(net, &components);
    NetAnalysis {
        states: g.markings.len(),
        edges: g.edges.len(),
        complete: g.complete,
        bounded,
        safe,
        bounds,
        deadlocks,
        dead_transitions,
        live_transitions,
        live,
        reversible,
        p_semiflows,
        t_semiflows,
        components,
        uncovered,
    }
}

/// A map serialised with its keys in the order given (places and transitions in net order).
struct Ordered<V>(Vec<(String, V)>);

impl<V: Serialize> Serialize for Ordered<V> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

#[derive(serde::Serialize)]
struct DeadlockJson {
    marking: Ordered<u32>,
    path: Vec<String>,
}

/// The `plc petri analyze --json` object; field order as the issue gives it.
#[derive(serde::Serialize)]
struct AnalysisJson {
    states: usize,
    edges: usize,
    complete: bool,
    bounded: Option<bool>,
    safe: Option<bool>,
    bounds: Ordered<Option<u32>>,
    deadlocks: Vec<DeadlockJson>,
    dead_transitions: Option<Vec<String>>,
    live: Option<bool>,
    reversible: Option<bool>,
    p_invariants: Vec<Ordered<u64>>,
    t_invariants: Vec<Ordered<u64>>,
}

fn support_map(names: &[String], flow: &Semiflow) -> Ordered<u64> {
    Ordered(names.iter().zip(flow).filter(|(_, &w)| w > 0).map(|(n, &w)| (n.clone(), w)).collect())
}

fn marking_map(net: &PtNet, m: &[u32]) -> Ordered<u32> {
    Ordered(
        net.place_names
            .iter()
            .zip(m)
            .filter(|(_, &k)| k > 0)
            .map(|(n, &k)| (n.clone(), k))
            .collect(),
    )
}

impl NetAnalysis {
    /// The report as the JSON object of `plc petri analyze --json`: `{"states","edges",
    /// "complete","bounded","safe","bounds","deadlocks","dead_transitions","live",
    /// "reversible","p_invariants","t_invariants"}` with places and transitions by name.
    /// An unbounded place's bound is `null` (ω); a property the search could not decide
    /// is `null`.
    pub fn to_json(&self, net: &PtNet) -> String {
        let t_names = |ts: &[usize]| ts.iter().map(|&t| net.transition_names[t].clone()).collect();
        let json = AnalysisJson {
            states: self.states,
            edges: self.edges,
            complete: self.complete,
            bounded: self.bounded,
            safe: self.safe,
            bounds: Ordered(
                net.place_names.iter().cloned().zip(self.bounds.iter().copied()).collect(),
            ),
            deadlocks: self
                .deadlocks
                .iter()
                .map(|d| DeadlockJson {
                    marking: marking_map(net, &d.marking),
                    path: t_names(&d.path),
                })
                .collect(),
            dead_transitions: self.dead_transitions.as_deref().map(t_names),
            live: self.live,
            reversible: self.reversible,
            p_invariants: self
                .p_semiflows
                .flows
                .iter()
                .map(|y| support_map(&net.place_names, y))
                .collect(),
            t_invariants: self
                .t_semiflows
                .flows
                .iter()
                .map(|x| support_map(&net.transition_names, x))
                .collect(),
        };
        serde_json::to_string(&json).unwrap_or_default()
    }
}
