//! The indexed place/transition net the analysis and the code generator work on, built from
//! the model with its structural checks (ids, arcs, weights, macro-places).
//!
//! Places and transitions keep the model's order; arcs become per-transition input and
//! output lists. Nothing here looks at guards or actions.

use std::collections::HashMap;

use super::diagnostic::{NetElement, PetriDiagnostic};
use super::model::Net;
use super::semiflows::SparseMatrix;
use crate::diagnostics::Code;

/// A marking: tokens per place, in place order.
pub type Marking = Vec<u32>;

/// A place/transition net by index.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PtNet {
    /// Place names as reports show them (unique: the id replaces an empty or shared name).
    pub place_names: Vec<String>,
    /// Transition names as reports show them (unique, as for places).
    pub transition_names: Vec<String>,
    /// Per transition: `(place, weight)` of its input arcs, in place order.
    pub pre: Vec<Vec<(usize, u32)>>,
    /// Per transition: `(place, weight)` of its output arcs, in place order.
    pub post: Vec<Vec<(usize, u32)>>,
    /// The initial marking.
    pub initial: Marking,
    /// Per place: at most this many tokens (`None`: unlimited).
    pub capacity: Vec<Option<u32>>,
}

impl PtNet {
    /// Number of places.
    pub fn places(&self) -> usize {
        self.place_names.len()
    }

    /// Number of transitions.
    pub fn transitions(&self) -> usize {
        self.transition_names.len()
    }

    /// Whether transition `t` is enabled in marking `m`: every input place holds the arc's
    /// weight, and no output place would go over its capacity.
    pub fn enabled(&self, m: &[u32], t: usize) -> bool {
        self.pre[t].iter().all(|&(p, w)| m[p] >= w)
            && self.post[t].iter().all(|&(p, w)| {
                let Some(cap) = self.capacity.get(p).copied().flatten() else { return true };
                let taken = self.pre[t].iter().find(|&&(q, _)| q == p).map_or(0, |&(_, v)| v);
                u64::from(m[p]) - u64::from(taken) + u64::from(w) <= u64::from(cap)
            })
    }

    /// The marking after firing transition `t` (which must be enabled) in `m`. Token counts
    /// saturate, so the ω of the coverability graph (`u32::MAX`) stays ω.
    pub fn fire(&self, m: &[u32], t: usize) -> Marking {
        let mut next = m.to_vec();
        for &(p, w) in &self.pre[t] {
            if next[p] != u32::MAX {
                next[p] -= w;
            }
        }
        for &(p, w) in &self.post[t] {
            if next[p] != u32::MAX {
                next[p] = next[p].saturating_add(w).min(u32::MAX - 1);
            }
        }
        next
    }

    /// The incidence matrix C (places × transitions, kept sparse): `C[p][t] = post − pre`.
    pub fn incidence(&self) -> SparseMatrix {
        let mut rows: Vec<Vec<(usize, i64)>> = vec![Vec::new(); self.places()];
        for (t, (pre, post)) in self.pre.iter().zip(&self.post).enumerate() {
            for &(p, w) in pre {
                rows[p].push((t, -i64::from(w)));
            }
            for &(p, w) in post {
                match rows[p].last_mut() {
                    Some((last, v)) if *last == t => *v += i64::from(w),
                    _ => rows[p].push((t, i64::from(w))),
                }
            }
        }
        for row in &mut rows {
            row.retain(|&(_, v)| v != 0);
        }
        SparseMatrix { columns: self.transitions(), rows }
    }

    /// The weight of the arc from place `p` to transition `t` (0 when there is none).
    pub fn pre_weight(&self, p: usize, t: usize) -> u32 {
        self.pre[t].iter().find(|&&(q, _)| q == p).map_or(0, |&(_, w)| w)
    }

    /// The weight of the arc from transition `t` to place `p` (0 when there is none).
    pub fn post_weight(&self, p: usize, t: usize) -> u32 {
        self.post[t].iter().find(|&&(q, _)| q == p).map_or(0, |&(_, w)| w)
    }

    /// The transitions that take tokens from place `p`.
    pub fn outputs_of_place(&self, p: usize) -> Vec<usize> {
        (0..self.transitions()).filter(|&t| self.pre_weight(p, t) > 0).collect()
    }
}

/// Unique display names: the element's name, or its id when the name is empty or shared.
fn unique_names<'a>(items: impl Iterator<Item = (&'a str, &'a str)> + Clone) -> Vec<String> {
    let mut count: HashMap<&str, usize> = HashMap::new();
    for (_, name) in items.clone() {
        *count.entry(name).or_default() += 1;
    }
    items
        .map(|(id, name)| {
            if name.is_empty() || count.get(name).copied().unwrap_or(0) > 1 {
                id.to_string()
            } else {
                name.to_string()
            }
        })
        .collect()
}

/// Builds the indexed net, or every structural problem of the model.
pub fn build(net: &Net) -> Result<PtNet, Vec<PetriDiagnostic>> {
    let mut diags = Vec::new();
    if net.places.is_empty() {
        diags.push(PetriDiagnostic::error(
            Code::PetriEmptyNet,
            NetElement::Pou,
            crate::msg!(PetriEmptyNet),
        ));
    }
    // Ids are unique across places, transitions and macro-places.
    let mut ids: HashMap<&str, NetElement> = HashMap::new();
    let elements = net
        .places
        .iter()
        .map(|p| (p.id.as_str(), NetElement::Place(p.id.clone())))
        .chain(
            net.transitions.iter().map(|t| (t.id.as_str(), NetElement::Transition(t.id.clone()))),
        )
        .chain(
            net.macro_places.iter().map(|m| (m.id.as_str(), NetElement::MacroPlace(m.id.clone()))),
        );
    for (id, element) in elements {
        if id.trim().is_empty() {
            diags.push(PetriDiagnostic::error(
                Code::PetriDuplicateId,
                element,
                crate::msg!(PetriElementNeedsId),
            ));
        } else if let Some(first) = ids.get(id) {
            // The element first holding the id has it too: `place P1`.
            let said = match first {
                NetElement::Place(_) => crate::msg!(PetriIdUsedByPlace, id = id),
                NetElement::Transition(_) => crate::msg!(PetriIdUsedByTransition, id = id),
                _ => crate::msg!(PetriIdUsedByMacroPlace, id = id),
            };
            diags.push(PetriDiagnostic::error(Code::PetriDuplicateId, element, said));
        } else {
            ids.insert(id, element);
        }
    }
    let place_index: HashMap<&str, usize> =
        net.places.iter().enumerate().map(|(i, p)| (p.id.as_str(), i)).collect();
    let trans_index: HashMap<&str, usize> =
        net.transitions.iter().enumerate().map(|(i, t)| (t.id.as_str(), i)).collect();
    let mut pre = vec![Vec::new(); net.transitions.len()];
    let mut post = vec![Vec::new(); net.transitions.len()];
    for (i, arc) in net.arcs.iter().enumerate() {
        let here = NetElement::Arc(i);
        if arc.weight == 0 {
            diags.push(PetriDiagnostic::error(
                Code::PetriBadArc,
                here.clone(),
                crate::msg!(PetriArcWeightZero, from = arc.from, to = arc.to),
            ));
            continue;
        }
        let (list, p, t) = match (
            place_index.get(arc.from.as_str()),
            trans_index.get(arc.to.as_str()),
            trans_index.get(arc.from.as_str()),
            place_index.get(arc.to.as_str()),
        ) {
            (Some(&p), Some(&t), _, _) => (&mut pre, p, t),
            (_, _, Some(&t), Some(&p)) => (&mut post, p, t),
            _ => {
                diags.push(PetriDiagnostic::error(Code::PetriBadArc, here, arc_problem(net, arc)));
                continue;
            }
        };
        if list[t].iter().any(|&(q, _)| q == p) {
            diags.push(PetriDiagnostic::error(
                Code::PetriDuplicateArc,
                here,
                crate::msg!(PetriSecondArc, from = arc.from, to = arc.to),
            ));
            continue;
        }
        list[t].push((p, arc.weight));
    }
    for list in pre.iter_mut().chain(post.iter_mut()) {
        crate::order::sort(list);
    }
    check_macro_places(net, &place_index, &mut diags);
    if !diags.is_empty() {
        return Err(diags);
    }
    Ok(PtNet {
        place_names: unique_names(net.places.iter().map(|p| (p.id.as_str(), p.name.trim()))),
        transition_names: unique_names(
            net.transitions.iter().map(|t| (t.id.as_str(), t.name.trim())),
        ),
        pre,
        post,
        initial: net.places.iter().map(|p| p.tokens).collect(),
        capacity: net.places.iter().map(|p| p.capacity).collect(),
    })
}

fn arc_problem(net: &Net, arc: &super::model::Arc) -> crate::diagnostics::Said {
    let kind = |id: &str| {
        if net.place(id).is_some() {
            crate::phrase!(PetriArcEndPlace)
        } else if net.transition(id).is_some() {
            crate::phrase!(PetriArcEndTransition)
        } else if net.macro_places.iter().any(|m| m.id == id) {
            crate::phrase!(PetriArcEndMacroPlace)
        } else {
            crate::phrase!(PetriArcEndNothing)
        }
    };
    crate::msg!(
        PetriArcMustJoin,
        from = arc.from,
        from_kind = kind(&arc.from),
        to = arc.to,
        to_kind = kind(&arc.to)
    )
}

fn check_macro_places(
    net: &Net,
    place_index: &HashMap<&str, usize>,
    diags: &mut Vec<PetriDiagnostic>,
) {
    let mut owner: HashMap<&str, &str> = HashMap::new();
    for m in &net.macro_places {
        let here = NetElement::MacroPlace(m.id.clone());
        for id in &m.places {
            if !place_index.contains_key(id.as_str()) {
                diags.push(PetriDiagnostic::error(
                    Code::PetriBadMacroPlace,
                    here.clone(),
                    crate::msg!(PetriNotAPlace, id = id),
                ));
            } else if let Some(other) = owner.insert(id, &m.id) {
                diags.push(PetriDiagnostic::error(
                    Code::PetriBadMacroPlace,
                    here.clone(),
                    crate::msg!(PetriPlaceInTwoMacroPlaces, id = id, other = other),
                ));
            }
        }
    }
}
