//! Interpreted Petri nets: the model (part of the project file), the analysis of the
//! underlying place/transition net, CASE OF code generation (after Franczok, PAR 2014) and
//! PNML.
//!
//! A Petri net POU becomes an ST PROGRAM that goes the ST way (checker, compiler, VM), so a
//! net runs on the one VM and its token game is read back from the step variables through
//! the [`PlaceMap`]. Guards and actions are ST; their errors are reported at the place or
//! transition they belong to. The firing rule and the generation scheme are documented in
//! `codegen` and in `docs/petri.md`. Nothing here runs a net by itself.

pub(crate) mod analysis;
pub(crate) mod check;
pub(crate) mod codegen;
pub(crate) mod components;
pub(crate) mod conflicts;
mod diagnostic;
pub mod edit;
pub(crate) mod model;
pub(crate) mod net;
pub(crate) mod reach;
mod report;
pub(crate) mod semiflows;

pub use analysis::{analyze, Deadlock, NetAnalysis, DEFAULT_BUDGET};
pub use codegen::{
    Generated, LineSource, MacroEntry, PlaceEntry, PlaceMap, ProcessEntry, SCAN_PREFIX,
};
pub use components::ProcessPlan;
pub use diagnostic::{has_errors, NetElement, PetriDiagnostic, TextPart, TextPosition};
pub use edit::{ElementKind, NetEdit, NetEditError};
pub use model::*;
pub use net::{build, Marking, PtNet};
pub use report::{conflicts, text_report, Conflict};

use crate::diagnostics::Code;

pub use crate::limits::{
    PETRI_COMPILE_BUDGET as COMPILE_BUDGET, PETRI_MARKING_CELLS as COMPILE_CELLS,
};

/// The state budget of the analysis run when a net of `places` places is compiled.
pub fn compile_budget(places: usize) -> usize {
    COMPILE_BUDGET.min(COMPILE_CELLS / places.max(1)).max(1)
}

/// The state budget of the web app's analysis panel for a net of `places` places: larger
/// than when compiling, and scaled down by the net's size the same way.
pub fn panel_budget(places: usize) -> usize {
    crate::limits::PETRI_PANEL_BUDGET.min(COMPILE_CELLS / places.max(1)).max(1)
}

/// A Petri net POU ready to run: its net, processes and generated PROGRAM.
#[derive(Debug, Clone, PartialEq)]
pub struct Compiled {
    /// The indexed net.
    pub net: PtNet,
    /// The processes the code was generated for.
    pub processes: Vec<ProcessPlan>,
    /// The generated PROGRAM.
    pub generated: Generated,
    /// Warnings (guard conflicts, deadlocks, dead transitions).
    pub warnings: Vec<PetriDiagnostic>,
}

/// Checks a Petri net POU and generates its PROGRAM, or returns every error found (with
/// the warnings).
pub fn compile(pou: &PetriPou) -> Result<Compiled, Vec<PetriDiagnostic>> {
    let net = build(&pou.net)?;
    let diags = check::check_pou(pou, &net);
    if has_errors(&diags) {
        return Err(diags);
    }
    let flows = semiflows::minimal_semiflows(&net.incidence());
    let components = components::state_machine_components(&net, &flows.flows);
    let processes = components::plan_processes(&pou.net, &net, &components)?;
    let generated = codegen::generate(pou, &net, &processes)?;
    let mut warnings = diags;
    warnings.extend(warnings_of(pou, &net, &processes, flows));
    Ok(Compiled { net, processes, generated, warnings })
}

/// Where the generated code tests transition `t`: the deciding process (the first one
/// containing an input place of `t`) and that input place.
fn decided_at(net: &PtNet, processes: &[ProcessPlan], t: usize) -> Option<(usize, usize)> {
    processes.iter().enumerate().find_map(|(c, plan)| {
        net.pre[t].iter().map(|&(p, _)| p).find(|p| plan.places.contains(p)).map(|p| (c, p))
    })
}

/// The warnings of a net that compiles: conflicts decided only by declaration order or
/// by process order (where priorities cannot act), and what the analysis finds within
/// [`COMPILE_BUDGET`] (deadlocks, dead transitions).
fn warnings_of(
    pou: &PetriPou,
    net: &PtNet,
    processes: &[ProcessPlan],
    p_semiflows: semiflows::Semiflows,
) -> Vec<PetriDiagnostic> {
    let mut out = Vec::new();
    for c in conflicts(pou, net) {
        let (a, b) = (&pou.net.transitions[c.first], &pou.net.transitions[c.second]);
        let (da, db) = (decided_at(net, processes, c.first), decided_at(net, processes, c.second));
        if da != db && !c.exclusive && a.priority != b.priority {
            let first = match (da, db) {
                (Some((x, _)), Some((y, _))) if y < x => b,
                _ => a,
            };
            out.push(PetriDiagnostic::warning(
                Code::PetriPriorityIgnored,
                NetElement::Transition(b.id.clone()),
                crate::msg!(
                    PetriPriorityIgnored,
                    a = a.id,
                    b = b.id,
                    place = pou.net.places[c.place].id,
                    first = first.id
                ),
            ));
        } else if a.priority == b.priority && !c.exclusive {
            out.push(PetriDiagnostic::warning(
                Code::PetriGuardConflict,
                NetElement::Transition(b.id.clone()),
                crate::msg!(
                    PetriGuardConflict,
                    a = a.id,
                    b = b.id,
                    place = pou.net.places[c.place].id,
                    priority = a.priority
                ),
            ));
        }
    }
    let budget = compile_budget(net.places());
    let a = analysis::analyze_with(net, budget, p_semiflows, false);
    for d in &a.deadlocks {
        let path: Vec<&str> = d.path.iter().map(|&t| pou.net.transitions[t].id.as_str()).collect();
        out.push(PetriDiagnostic::warning(
            Code::PetriDeadlock,
            NetElement::Pou,
            crate::msg!(PetriDeadlock, path = path.join(", ")),
        ));
    }
    for &t in a.dead_transitions.iter().flatten() {
        out.push(PetriDiagnostic::warning(
            Code::PetriDeadTransition,
            NetElement::Transition(pou.net.transitions[t].id.clone()),
            crate::msg!(PetriDeadTransition),
        ));
    }
    if !a.complete {
        out.push(PetriDiagnostic::warning(
            Code::PetriAnalysisIncomplete,
            NetElement::Pou,
            crate::msg!(PetriAnalysisIncomplete, budget = budget, places = net.places()),
        ));
    }
    out
}

/// Whether `name` is a hidden variable of the generated code (a scan-start copy).
pub fn is_hidden_name(name: &str) -> bool {
    name.len() >= SCAN_PREFIX.len() && name[..SCAN_PREFIX.len()].eq_ignore_ascii_case(SCAN_PREFIX)
}

/// Describes a located Petri diagnostic for a message: `POU Name, transition T2 (guard line
/// 1, column 5)`.
pub fn describe(pou: &str, element: &NetElement, at: Option<&TextPosition>) -> String {
    match at {
        Some(at) => format!("POU {pou}, {element} ({at})"),
        None => format!("POU {pou}, {element}"),
    }
}

#[cfg(test)]
mod tests;
