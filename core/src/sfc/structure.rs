//! Static checks of a chart's structure, conditions ignored (so an over-approximation: a
//! step reported unreachable is unreachable whatever the conditions do; an unsafe firing is
//! possible if the conditions allow it).
//!
//! The situations (sets of active steps) reachable from the initial steps are explored
//! breadth first, firing one transition at a time, up to [`MAX_SITUATIONS`]. When the
//! chart is safe this covers the simultaneous firings of the runtime too: transitions that
//! fire together leave disjoint steps, and each one's effect does not depend on the others.
//! Reported: the first transition found (on a shortest firing sequence) that can activate a
//! step that is already active (unsafe, W0021),
//! steps that can never become active (W0020) and transitions whose steps are never active
//! together (W0022). When the budget cuts the search, unreachable steps come from a
//! structural fixpoint instead (always exact about "never") and dead transitions are not
//! reported.

use std::collections::HashMap;

use super::chart::Chart;
use crate::diagnostics::{Code, Diagnostic};

pub(super) use crate::limits::SFC_MAX_SITUATIONS as MAX_SITUATIONS;

/// A set of active steps.
type Situation = Vec<u64>;

fn has(m: &Situation, i: usize) -> bool {
    m[i / 64] >> (i % 64) & 1 == 1
}

fn set(m: &mut Situation, i: usize, on: bool) {
    if on {
        m[i / 64] |= 1 << (i % 64);
    } else {
        m[i / 64] &= !(1 << (i % 64));
    }
}

/// Reports unsafe firings, unreachable steps and dead transitions of `chart`.
pub(super) fn check(chart: &Chart, diags: &mut Vec<Diagnostic>) {
    let n = chart.steps.len();
    if n == 0 {
        return;
    }
    let words = n.div_ceil(64);
    let mut initial = vec![0u64; words];
    for (i, s) in chart.steps.iter().enumerate() {
        set(&mut initial, i, s.initial);
    }
    let transitions: Vec<usize> =
        (0..chart.transitions.len()).filter(|&t| chart.transitions[t].valid).collect();
    let mut seen: HashMap<Situation, usize> = HashMap::new();
    let mut situations = vec![initial.clone()];
    let mut parent: Vec<Option<(usize, usize)>> = vec![None];
    seen.insert(initial, 0);
    let mut reached = vec![false; n];
    let mut enabled = vec![false; chart.transitions.len()];
    let mut unsafe_reported = false;
    let mut complete = true;
    let mut next_index = 0;
    while next_index < situations.len() {
        let here = next_index;
        next_index += 1;
        let m = situations[here].clone();
        for (i, r) in reached.iter_mut().enumerate() {
            *r |= has(&m, i);
        }
        for &t in &transitions {
            let tr = &chart.transitions[t];
            if !tr.from.iter().all(|&s| has(&m, s)) {
                continue;
            }
            enabled[t] = true;
            let mut after = m.clone();
            for &s in &tr.from {
                set(&mut after, s, false);
            }
            for &s in &tr.to {
                if has(&m, s) && !tr.from.contains(&s) && !unsafe_reported {
                    // Only the first (shortest) one: the others usually follow from it.
                    unsafe_reported = true;
                    let path = path_to(chart, &parent, here);
                    let msg = crate::msg!(
                        CanActivateStepWhileAlready,
                        describe = (tr.describe()).to_string(),
                        name = (chart.steps[s].name.name).to_string(),
                        path = path
                    );
                    diags.push(Diagnostic::warning(Code::SfcUnsafe, tr.ast.header, msg));
                }
                set(&mut after, s, true);
            }
            if seen.contains_key(&after) {
                continue;
            }
            if situations.len() >= MAX_SITUATIONS {
                complete = false;
                continue;
            }
            seen.insert(after.clone(), situations.len());
            situations.push(after);
            parent.push(Some((here, t)));
        }
    }
    if !complete {
        reached = structural_reach(chart);
    }
    for (i, s) in chart.steps.iter().enumerate() {
        if !reached[i] {
            let msg = crate::msg!(StepCanNeverBecomeActive, name = s.name.name);
            diags.push(Diagnostic::warning(Code::SfcUnreachableStep, s.header, msg));
        }
    }
    if !complete {
        return;
    }
    for &t in &transitions {
        let tr = &chart.transitions[t];
        if !enabled[t] && tr.from.iter().all(|&s| reached[s]) {
            let names: Vec<String> =
                tr.from.iter().map(|&s| format!("`{}`", chart.steps[s].name.name)).collect();
            let msg = crate::msg!(
                CanNeverFireStepsAre,
                describe = (tr.describe()).to_string(),
                join = (names.join(", ")).to_string()
            );
            diags.push(Diagnostic::warning(Code::SfcDeadTransition, tr.ast.header, msg));
        }
    }
}

/// "after firing T1, T2" or "from the start": the transitions that lead to situation `i`.
fn path_to(chart: &Chart, parent: &[Option<(usize, usize)>], mut i: usize) -> String {
    let mut fired = Vec::new();
    while let Some(Some((p, t))) = parent.get(i) {
        fired.push(chart.transitions[*t].describe());
        i = *p;
    }
    if fired.is_empty() {
        return "right from the start".to_string();
    }
    fired.reverse();
    if fired.len() > 6 {
        let skipped = fired.len() - 6;
        fired.drain(..skipped);
        format!("after firing …, {}", fired.join(", "))
    } else {
        format!("after firing {}", fired.join(", "))
    }
}

/// Steps that some transition can reach, when every transition whose steps can each be
/// active may fire (a cheap over-approximation, used when the exploration is cut short).
fn structural_reach(chart: &Chart) -> Vec<bool> {
    let mut reached: Vec<bool> = chart.steps.iter().map(|s| s.initial).collect();
    loop {
        let mut changed = false;
        for t in chart.transitions.iter().filter(|t| t.valid) {
            if t.from.iter().all(|&s| reached[s]) {
                for &s in &t.to {
                    if !reached[s] {
                        reached[s] = true;
                        changed = true;
                    }
                }
            }
        }
        if !changed {
            return reached;
        }
    }
}
