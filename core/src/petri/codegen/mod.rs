//! CASE OF code generation (K. Franczok, "A method for modelling sequential and concurrent
//! processes in the PLC environment", PAR 2014): one INT step variable per process, one
//! CASE branch per place with its actions and one `IF guard THEN …` per transition leaving
//! it, in priority order (an ELSIF chain, so a process takes at most one transition per
//! scan).
//!
//! The per-scan firing rule the code implements exactly (`docs/petri.md` explains it):
//! 1. the prologue runs;
//! 2. if the emergency condition holds, every process is put in its emergency place;
//! 3. let M be the marking now. The processes run in order; process c runs the branch of
//!    its place p marked in M: p's actions (in the first process containing p), then the
//!    transitions that c decides from p, by priority; the first one whose guard is TRUE,
//!    whose other input places are marked in M and whose tokens no transition fired
//!    earlier in this scan has taken, fires. A transition shared by several processes (a
//!    fork or a join) is decided by the first of them, and moves all of them at once;
//!    the places it marks run from the next scan on;
//! 4. the epilogue runs.
//!
//! In the step-variable style the deciding process reads and writes the others' step
//! variables; a process that another one can move selects its branch on `PnScan_<var>`,
//! the copy of its step variable taken at step 3. In the flag style (the paper's
//! `Pn_Start`/`Pn_End`) each process moves only itself: while it waits at a shared
//! transition it holds `<Process>_End`, and the deciding process raises `<Process>_Start`,
//! which it handles later in the same scan.

mod emit;
mod maps;

pub use maps::{Generated, LineSource, MacroEntry, PlaceEntry, PlaceMap, ProcessEntry};

use super::components::ProcessPlan;
use super::diagnostic::{NetElement, PetriDiagnostic};
use super::model::{PetriPou, SyncStyle};
use super::net::PtNet;
use crate::diagnostics::Code;

/// Prefix of the hidden scan-start copies of step variables.
pub const SCAN_PREFIX: &str = "PnScan_";

/// Text safe inside a `(* … *)` comment.
fn comment(s: &str) -> String {
    s.replace("(*", "( *").replace("*)", "* )").replace('\n', " ")
}

struct Ctx<'a> {
    pou: &'a PetriPou,
    net: &'a PtNet,
    plans: &'a [ProcessPlan],
    /// Per transition: `(process, input place, output place)` for every process it touches.
    touch: Vec<Vec<(usize, usize, usize)>>,
    /// Per place: the first process containing it.
    owner: Vec<usize>,
    /// Per process: whether another process can move it (it selects on its scan copy).
    moved_by_others: Vec<bool>,
    /// Flag style: per process, its waiting places `(place, transition)`.
    waiting: Option<Vec<Vec<(usize, usize)>>>,
}

impl Ctx<'_> {
    fn label(&self, p: usize) -> i64 {
        self.pou.net.places[p].label
    }

    fn var(&self, c: usize) -> &str {
        &self.plans[c].step_variable
    }

    fn scan(&self, c: usize) -> String {
        format!("{SCAN_PREFIX}{}", self.var(c))
    }

    fn leader(&self, t: usize) -> Option<usize> {
        self.touch[t].first().map(|x| x.0)
    }

    fn place_text(&self, p: usize) -> String {
        let place = &self.pou.net.places[p];
        let mut s = self.net.place_names[p].clone();
        if !place.comment.trim().is_empty() {
            s.push_str(": ");
            s.push_str(place.comment.trim());
        }
        comment(&s)
    }

    fn transition_text(&self, t: usize) -> String {
        let names = |list: &[(usize, u32)]| {
            list.iter()
                .map(|&(p, _)| self.net.place_names[p].as_str())
                .collect::<Vec<_>>()
                .join(", ")
        };
        let tr = &self.pou.net.transitions[t];
        let mut s = format!(
            "{}: {} -> {}",
            self.net.transition_names[t],
            names(&self.net.pre[t]),
            names(&self.net.post[t])
        );
        if !tr.comment.trim().is_empty() {
            s.push_str(" (");
            s.push_str(tr.comment.trim());
            s.push(')');
        }
        comment(&s)
    }

    /// The transitions process `c` decides from place `p`, in priority order.
    fn decided(&self, c: usize, p: usize) -> Vec<usize> {
        let mut ts: Vec<usize> = (0..self.net.transitions())
            .filter(|&t| self.touch[t].first().is_some_and(|&(d, q, _)| d == c && q == p))
            .collect();
        crate::order::sort_by_key(&mut ts, |&t| (self.pou.net.transitions[t].priority, t));
        ts
    }

    /// Flag names `(start, end)` of process `c` waiting at place `q`.
    fn flags(&self, c: usize, q: usize) -> (String, String) {
        let name = &self.plans[c].name;
        let waiting = self.waiting.as_ref().map_or(&[][..], |w| &w[c][..]);
        let mut places: Vec<usize> = waiting.iter().map(|&(p, _)| p).collect();
        places.dedup();
        if places.len() <= 1 {
            (format!("{name}_Start"), format!("{name}_End"))
        } else {
            let l = self.label(q);
            let suffix = if l < 0 { format!("M{}", -l) } else { l.to_string() };
            (format!("{name}_Start_{suffix}"), format!("{name}_End_{suffix}"))
        }
    }

    fn is_waiting(&self, c: usize, q: usize) -> bool {
        self.waiting.as_ref().is_some_and(|w| w[c].iter().any(|&(p, _)| p == q))
    }

    /// Statements moving process `c` itself from `from` to `to` (with its state flags).
    fn move_self(&self, c: usize, from: usize, to: usize) -> Vec<String> {
        let mut s = Vec::new();
        if self.is_waiting(c, from) {
            s.push(format!("{} := FALSE;", self.flags(c, from).1));
        }
        s.push(format!("{} := {};", self.var(c), self.label(to)));
        if self.is_waiting(c, to) {
            s.push(format!("{} := TRUE;", self.flags(c, to).1));
        }
        s
    }

    /// The extra conditions and the statements of transition `t`, decided by its leader.
    fn fire(&self, t: usize) -> (Vec<String>, Vec<String>) {
        let mut conds = Vec::new();
        let mut stmts = Vec::new();
        let Some(&(lead, p, out)) = self.touch[t].first() else { return (conds, stmts) };
        if self.waiting.is_none() {
            // Own token taken earlier in this scan by a transition another process decides?
            let contested = (0..self.net.transitions()).any(|u| {
                self.leader(u) != Some(lead)
                    && self.touch[u].iter().any(|&(c, q, _)| c == lead && q == p)
            });
            if contested {
                conds.push(format!("{} = {}", self.var(lead), self.label(p)));
            }
            stmts.push(format!("{} := {};", self.var(lead), self.label(out)));
            for &(c, q, o) in &self.touch[t][1..] {
                let early = (0..self.net.transitions()).any(|u| {
                    self.leader(u).is_some_and(|l| l < lead)
                        && self.touch[u].iter().any(|&(d, ..)| d == c)
                });
                if early {
                    conds.push(format!("{} = {}", self.scan(c), self.label(q)));
                }
                conds.push(format!("{} = {}", self.var(c), self.label(q)));
                stmts.push(format!("{} := {};", self.var(c), self.label(o)));
            }
        } else {
            stmts.extend(self.move_self(lead, p, out));
            for &(c, q, _) in &self.touch[t][1..] {
                let (start, end) = self.flags(c, q);
                conds.push(end);
                stmts.push(format!("{start} := TRUE;"));
            }
        }
        (conds, stmts)
    }
}

/// Generates the PROGRAM for `pou` over its processes. Fails only for flag-style code that
/// cannot tell two shared transitions apart at one place (E0513).
pub fn generate(
    pou: &PetriPou,
    net: &PtNet,
    plans: &[ProcessPlan],
) -> Result<Generated, Vec<PetriDiagnostic>> {
    let n_p = net.places();
    let mut owner = vec![usize::MAX; n_p];
    for (c, plan) in plans.iter().enumerate() {
        for &p in &plan.places {
            if owner[p] == usize::MAX {
                owner[p] = c;
            }
        }
    }
    let touch: Vec<Vec<(usize, usize, usize)>> = (0..net.transitions())
        .map(|t| {
            plans
                .iter()
                .enumerate()
                .filter_map(|(c, plan)| {
                    let i = net.pre[t].iter().map(|&(p, _)| p).find(|p| plan.places.contains(p))?;
                    let o =
                        net.post[t].iter().map(|&(p, _)| p).find(|p| plan.places.contains(p))?;
                    Some((c, i, o))
                })
                .collect()
        })
        .collect();
    let mut moved_by_others = vec![false; plans.len()];
    for tt in &touch {
        for &(c, ..) in tt.iter().skip(1) {
            moved_by_others[c] = true;
        }
    }
    let waiting = (pou.options.sync == SyncStyle::Flags).then(|| {
        let mut w: Vec<Vec<(usize, usize)>> = vec![Vec::new(); plans.len()];
        for (t, tt) in touch.iter().enumerate() {
            for &(c, q, _) in tt.iter().skip(1) {
                w[c].push((q, t));
            }
        }
        for list in &mut w {
            crate::order::sort(list);
        }
        w
    });
    if let Some(w) = &waiting {
        let mut diags = Vec::new();
        for (c, list) in w.iter().enumerate() {
            for pair in list.windows(2) {
                if pair[0].0 == pair[1].0 {
                    diags.push(PetriDiagnostic::error(
                        Code::PetriFlagsAmbiguous,
                        NetElement::Place(pou.net.places[pair[0].0].id.clone()),
                        crate::msg!(
                            PetriFlagsAmbiguous,
                            process = plans[c].name,
                            first = pou.net.transitions[pair[0].1].id,
                            second = pou.net.transitions[pair[1].1].id
                        ),
                    ));
                }
            }
        }
        if !diags.is_empty() {
            return Err(diags);
        }
    }
    let ctx = Ctx { pou, net, plans, touch, owner, moved_by_others, waiting };
    Ok(emit::emit(&ctx))
}
