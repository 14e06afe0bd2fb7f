//! State-machine components and the processes the CASE OF code is generated for.
//!
//! A state-machine component is a minimal P-semiflow with 0/1 weights whose support S
//! induces a state machine: every transition touching S has exactly one input place and
//! one output place in S, by arcs of weight 1. Its places then always hold together the
//! tokens they start with; with exactly one, the marked place is the value of one INT step
//! variable — a sequential process of Franczok's CASE OF method (PAR 2014).
//!
//! The processes come from the net's declared [`Process`](super::Process) list when there
//! is one (each is checked to be such a component), else from a greedy cover: repeatedly
//! the component adding the most uncovered places (ties: the one overlapping least, then
//! the one found first). Places no component covers are an error naming them.

use super::diagnostic::{NetElement, PetriDiagnostic};
use super::model::Net;
use super::net::PtNet;
use super::semiflows::Semiflow;
use crate::diagnostics::Code;

/// A process of the generated code: a state-machine component with its step variable.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProcessPlan {
    /// The process's name (used in comments and flag names).
    pub name: String,
    /// Its INT step variable.
    pub step_variable: String,
    /// Its places, in net order.
    pub places: Vec<usize>,
}

/// Whether the places `support` induce a state machine with weight-1 arcs: every transition
/// touching them has exactly one input and one output among them.
pub fn is_state_machine(net: &PtNet, support: &[bool]) -> bool {
    (0..net.transitions()).all(|t| {
        let ins: Vec<u32> =
            net.pre[t].iter().filter(|&&(p, _)| support[p]).map(|&(_, w)| w).collect();
        let outs: Vec<u32> =
            net.post[t].iter().filter(|&&(p, _)| support[p]).map(|&(_, w)| w).collect();
        (ins.is_empty() && outs.is_empty()) || (ins == [1] && outs == [1])
    })
}

/// The state-machine components among the P-semiflows: their supports, as place lists.
pub fn state_machine_components(net: &PtNet, p_semiflows: &[Semiflow]) -> Vec<Vec<usize>> {
    p_semiflows
        .iter()
        .filter(|y| y.iter().all(|&w| w <= 1))
        .filter_map(|y| {
            let support: Vec<bool> = y.iter().map(|&w| w == 1).collect();
            is_state_machine(net, &support)
                .then(|| (0..net.places()).filter(|&p| support[p]).collect())
        })
        .collect()
}

/// The places no component covers.
pub fn uncovered(net: &PtNet, components: &[Vec<usize>]) -> Vec<usize> {
    (0..net.places()).filter(|p| !components.iter().any(|c| c.contains(p))).collect()
}

fn tokens(net: &PtNet, places: &[usize]) -> u64 {
    places.iter().map(|&p| u64::from(net.initial[p])).sum()
}

/// Chooses the processes for code generation: the declared ones (checked) or a greedy cover
/// by state-machine components holding one token each.
pub fn plan_processes(
    model: &Net,
    net: &PtNet,
    components: &[Vec<usize>],
) -> Result<Vec<ProcessPlan>, Vec<PetriDiagnostic>> {
    let plans = if model.processes.is_empty() {
        automatic(net, components)?
    } else {
        declared(model, net)?
    };
    let mut diags = Vec::new();
    let missing = uncovered(net, &plans.iter().map(|p| p.places.clone()).collect::<Vec<_>>());
    if !missing.is_empty() {
        let names: Vec<&str> = missing.iter().map(|&p| model.places[p].id.as_str()).collect();
        diags.push(PetriDiagnostic::error(
            Code::PetriNotCovered,
            NetElement::Pou,
            crate::msg!(PetriNotCovered, names = names.join(", ")),
        ));
    }
    for plan in &plans {
        let mut seen: Vec<(i64, usize)> = Vec::new();
        for &p in &plan.places {
            let label = model.places[p].label;
            if let Some(&(_, q)) = seen.iter().find(|&&(l, _)| l == label) {
                diags.push(PetriDiagnostic::error(
                    Code::PetriDuplicateLabel,
                    NetElement::Place(model.places[p].id.clone()),
                    crate::msg!(
                        PetriDuplicateLabel,
                        label = label,
                        other = model.places[q].id,
                        process = plan.name
                    ),
                ));
            }
            seen.push((label, p));
        }
    }
    if diags.is_empty() {
        Ok(plans)
    } else {
        Err(diags)
    }
}

fn automatic(
    net: &PtNet,
    components: &[Vec<usize>],
) -> Result<Vec<ProcessPlan>, Vec<PetriDiagnostic>> {
    let candidates: Vec<&Vec<usize>> = components.iter().filter(|c| tokens(net, c) == 1).collect();
    let mut covered = vec![false; net.places()];
    let mut chosen: Vec<&Vec<usize>> = Vec::new();
    loop {
        let best = candidates
            .iter()
            .filter(|c| !chosen.contains(c))
            .map(|c| {
                let new = c.iter().filter(|&&p| !covered[p]).count();
                let overlap = c.len() - new;
                (c, new, overlap)
            })
            .filter(|&(_, new, _)| new > 0)
            .min_by_key(|&(_, new, overlap)| (std::cmp::Reverse(new), overlap));
        let Some((c, ..)) = best else { break };
        for &p in c.iter() {
            covered[p] = true;
        }
        chosen.push(c);
    }
    let single = chosen.len() == 1;
    Ok(chosen
        .into_iter()
        .enumerate()
        .map(|(i, c)| ProcessPlan {
            name: if single { "Main".to_string() } else { format!("P{}", i + 1) },
            step_variable: if single { "p".to_string() } else { format!("p{}", i + 1) },
            places: c.clone(),
        })
        .collect())
}

fn declared(model: &Net, net: &PtNet) -> Result<Vec<ProcessPlan>, Vec<PetriDiagnostic>> {
    let mut diags = Vec::new();
    let mut plans = Vec::new();
    for proc in &model.processes {
        let here = NetElement::Process(proc.name.clone());
        let mut support = vec![false; net.places()];
        for id in &proc.places {
            match model.places.iter().position(|p| &p.id == id) {
                Some(i) => support[i] = true,
                None => diags.push(PetriDiagnostic::error(
                    Code::PetriBadProcess,
                    here.clone(),
                    crate::msg!(PetriNotAPlace, id = id),
                )),
            }
        }
        let places: Vec<usize> = (0..net.places()).filter(|&p| support[p]).collect();
        let y: Vec<u64> = support.iter().map(|&s| u64::from(s)).collect();
        let c = net.incidence();
        if places.is_empty() {
            diags.push(PetriDiagnostic::error(
                Code::PetriBadProcess,
                here.clone(),
                crate::msg!(PetriProcessNoPlaces),
            ));
        } else if !super::semiflows::is_semiflow(&c, &y) {
            let leaks: Vec<&str> = (0..net.transitions())
                .filter(|&t| places.iter().map(|&p| c.get(p, t)).sum::<i64>() != 0)
                .map(|t| model.transitions[t].id.as_str())
                .collect();
            diags.push(PetriDiagnostic::error(
                Code::PetriBadProcess,
                here.clone(),
                crate::msg!(PetriNotStateMachine, leaks = leaks.join(", ")),
            ));
        } else if !is_state_machine(net, &support) {
            diags.push(PetriDiagnostic::error(
                Code::PetriArcWeight,
                here.clone(),
                crate::msg!(PetriProcessArcWeight),
            ));
        } else if tokens(net, &places) != 1 {
            diags.push(PetriDiagnostic::error(
                Code::PetriProcessTokens,
                here.clone(),
                crate::msg!(PetriProcessTokens, n = tokens(net, &places)),
            ));
        }
        plans.push(ProcessPlan {
            name: proc.name.trim().to_string(),
            step_variable: proc.step_variable.trim().to_string(),
            places,
        });
    }
    if diags.is_empty() {
        Ok(plans)
    } else {
        Err(diags)
    }
}
