//! CASE OF code generation (seed 000): one INT step variable per process, one CASE branch
//! per place with its actions and one `IF guard THEN …` per transition leaving it, in
//! priority order (an ELSIF chain, so a process takes at most one transition per scan).
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
//! the copy of its step variable taken at step 3. In the flag style (the seed's
//! `Pn_Start`/`Pn_End`) each process moves only itself: while it waits at a shared
//! transition it holds `<Process>_End`, and the deciding process raises `<Process>_Start`,
//! which it handles later in the same scan.

use std::ops::Range;

use serde::Serialize;

use super::components::ProcessPlan;
use super::diagnostic::{NetElement, PetriDiagnostic, TextPart, TextPosition};
use super::model::{PetriPou, SyncStyle};
use super::net::PtNet;
use crate::diagnostics::Code;

/// Prefix of the hidden scan-start copies of step variables.
pub const SCAN_PREFIX: &str = "PnScan_";

/// Where a generated line comes from.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LineSource {
    /// The net element.
    pub element: NetElement,
    /// The element's text the line holds, when it holds user text (guard, actions…).
    pub part: Option<TextPart>,
    /// 1-based line inside that text.
    pub text_line: u32,
    /// Characters on the generated line before the text starts.
    pub column_shift: u32,
}

/// A process as the UI sees it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct ProcessEntry {
    /// Its name.
    pub name: String,
    /// Its INT step variable.
    pub step_variable: String,
    /// Ids of its places.
    pub places: Vec<String>,
}

/// Where a place's token is read: it is marked when `step_variable = value`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PlaceEntry {
    /// The place's id.
    pub id: String,
    /// The step variable of the first process containing it.
    pub step_variable: String,
    /// The place's CASE label.
    pub value: i64,
}

/// A macro-place as the UI sees it: marked when any of its places is.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct MacroEntry {
    /// Its id.
    pub id: String,
    /// Ids of its places.
    pub places: Vec<String>,
}

/// How to read the marking from the running program's variables.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PlaceMap {
    /// The processes, in the order their CASE statements run.
    pub processes: Vec<ProcessEntry>,
    /// Every place, in net order.
    pub places: Vec<PlaceEntry>,
    /// The macro-places.
    pub macro_places: Vec<MacroEntry>,
}

impl PlaceMap {
    /// The marking (tokens per place, net order) given a way to read INT variables.
    pub fn marking(&self, mut read: impl FnMut(&str) -> Option<i64>) -> Vec<u32> {
        self.places.iter().map(|p| u32::from(read(&p.step_variable) == Some(p.value))).collect()
    }
}

/// A generated PROGRAM with its maps.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    /// The complete POU as ST text.
    pub st: String,
    /// Per line of `st` (index 0 is line 1): where it comes from.
    pub lines: Vec<Option<LineSource>>,
    /// 1-based lines of `st` holding the user's declarations (end exclusive).
    pub declaration_lines: Range<u32>,
    /// Place → step variable and value.
    pub place_map: PlaceMap,
}

impl Generated {
    /// The element behind 1-based `line` and `column` of [`Generated::st`], and the position
    /// inside the element's text when the line holds user text.
    pub fn locate(&self, line: u32, column: u32) -> Option<(NetElement, Option<TextPosition>)> {
        let src = self.lines.get(line.checked_sub(1)? as usize)?.as_ref()?;
        let at = src.part.map(|part| TextPosition {
            part,
            line: src.text_line,
            column: column.saturating_sub(src.column_shift).max(1),
        });
        Some((src.element.clone(), at))
    }
}

struct Out {
    lines: Vec<String>,
    origin: Vec<Option<LineSource>>,
}

impl Out {
    fn line(&mut self, indent: usize, text: impl Into<String>, element: Option<&NetElement>) {
        let text = text.into();
        for l in text.lines() {
            self.lines.push(format!("{}{}", "    ".repeat(indent), l).trim_end().to_string());
            self.origin.push(element.map(|e| LineSource {
                element: e.clone(),
                part: None,
                text_line: 0,
                column_shift: 0,
            }));
        }
    }

    fn blank(&mut self) {
        self.lines.push(String::new());
        self.origin.push(None);
    }

    /// User text, line by line, mapped back to `element`.
    fn text(&mut self, indent: usize, text: &str, element: &NetElement, part: TextPart) {
        let pad = "    ".repeat(indent);
        for (i, l) in text.trim_end().lines().enumerate() {
            if i == 0 && l.trim().is_empty() {
                continue;
            }
            self.lines.push(format!("{pad}{l}").trim_end().to_string());
            self.origin.push(Some(LineSource {
                element: element.clone(),
                part: Some(part),
                text_line: i as u32 + 1,
                column_shift: pad.len() as u32,
            }));
        }
    }

    /// `prefix guard suffix` on one line when the guard is one plain line, else the guard on
    /// lines of its own between `prefix (` and `) suffix`.
    fn condition(
        &mut self,
        indent: usize,
        prefix: &str,
        guard: &str,
        suffix: &str,
        element: &NetElement,
        part: TextPart,
    ) {
        let plain = !guard.contains('\n') && !guard.contains("//");
        if plain {
            let pad = "    ".repeat(indent);
            let lead = guard.len() - guard.trim_start().len();
            self.lines
                .push(format!("{pad}{prefix}{}{suffix}", guard.trim()).trim_end().to_string());
            self.origin.push(Some(LineSource {
                element: element.clone(),
                part: Some(part),
                text_line: 1,
                column_shift: (pad.len() + prefix.chars().count()) as u32 - lead as u32,
            }));
        } else {
            self.line(indent, format!("{prefix}("), Some(element));
            self.text(indent + 1, guard, element, part);
            self.line(indent, format!("){suffix}"), Some(element));
        }
    }
}

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
        ts.sort_by_key(|&t| (self.pou.net.transitions[t].priority, t));
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
            list.sort_unstable();
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
                        format!(
                            "process {} waits here for two shared transitions ({} and {}); one \
                             _Start flag cannot tell them apart: use the step-variable style",
                            plans[c].name,
                            pou.net.transitions[pair[0].1].id,
                            pou.net.transitions[pair[1].1].id
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
    Ok(emit(&ctx))
}

fn declarations(ctx: &Ctx<'_>, out: &mut Out) {
    let pou = ctx.pou;
    let initial = |c: usize| ctx.plans[c].places.iter().copied().find(|&p| ctx.net.initial[p] > 0);
    let retain = if pou.options.retain { "VAR RETAIN" } else { "VAR" };
    out.line(0, format!("{retain} (* step variables of the net's processes *)"), None);
    for (c, plan) in ctx.plans.iter().enumerate() {
        let start = initial(c).map_or(0, |p| ctx.label(p));
        let places: Vec<String> = plan
            .places
            .iter()
            .map(|&p| format!("{} = {}", ctx.label(p), ctx.net.place_names[p]))
            .collect();
        out.line(
            1,
            format!(
                "{} : INT := {start}; (* process {}: {} *)",
                plan.step_variable,
                plan.name,
                comment(&places.join(", "))
            ),
            None,
        );
        if let Some(w) = &ctx.waiting {
            let mut seen = Vec::new();
            for &(q, _) in &w[c] {
                if !seen.contains(&q) {
                    seen.push(q);
                    let end = ctx.flags(c, q).1;
                    let init = if initial(c) == Some(q) { "TRUE" } else { "FALSE" };
                    out.line(
                        1,
                        format!(
                            "{end} : BOOL := {init}; (* {} waits at {} *)",
                            plan.name, ctx.net.place_names[q]
                        ),
                        None,
                    );
                }
            }
        }
    }
    out.line(0, "END_VAR", None);
    let scans: Vec<usize> =
        (0..ctx.plans.len()).filter(|&c| ctx.moved_by_others[c] && ctx.waiting.is_none()).collect();
    let starts: Vec<(usize, usize)> = match &ctx.waiting {
        Some(w) => {
            let mut v: Vec<(usize, usize)> = w
                .iter()
                .enumerate()
                .flat_map(|(c, l)| l.iter().map(move |&(q, _)| (c, q)))
                .collect();
            v.dedup();
            v
        }
        None => Vec::new(),
    };
    if !scans.is_empty() || !starts.is_empty() {
        out.line(0, "VAR (* generated by the Petri net compiler *)", None);
        for c in scans {
            out.line(
                1,
                format!("{} : INT; (* {} at the start of the scan *)", ctx.scan(c), ctx.var(c)),
                None,
            );
        }
        for (c, q) in starts {
            out.line(
                1,
                format!(
                    "{} : BOOL; (* move {} on from {} *)",
                    ctx.flags(c, q).0,
                    ctx.plans[c].name,
                    ctx.net.place_names[q]
                ),
                None,
            );
        }
        out.line(0, "END_VAR", None);
    }
}

fn emergency(ctx: &Ctx<'_>, out: &mut Out) {
    let Some(e) = &ctx.pou.net.emergency else { return };
    let Some(target) = ctx.pou.net.places.iter().position(|p| p.id == e.place) else { return };
    let here = NetElement::Emergency;
    out.line(0, format!("(* emergency: while the condition holds, every process goes to its emergency place ({}) *)", comment(&ctx.net.place_names[target])), Some(&here));
    out.condition(0, "IF ", &e.condition, " THEN", &here, TextPart::Condition);
    for (c, plan) in ctx.plans.iter().enumerate() {
        let dest = if plan.places.contains(&target) {
            Some(target)
        } else {
            plan.places.iter().copied().find(|&p| ctx.net.initial[p] > 0)
        };
        let Some(dest) = dest else { continue };
        out.line(1, format!("{} := {};", ctx.var(c), ctx.label(dest)), Some(&here));
        if let Some(w) = &ctx.waiting {
            let mut seen = Vec::new();
            for &(q, _) in &w[c] {
                if !seen.contains(&q) {
                    seen.push(q);
                    let value = if q == dest { "TRUE" } else { "FALSE" };
                    out.line(1, format!("{} := {value};", ctx.flags(c, q).1), Some(&here));
                }
            }
        }
    }
    out.line(0, "END_IF;", Some(&here));
}

fn branch(ctx: &Ctx<'_>, out: &mut Out, c: usize, p: usize) {
    let place = &ctx.pou.net.places[p];
    let pe = NetElement::Place(place.id.clone());
    let in_macro = ctx
        .pou
        .net
        .macro_places
        .iter()
        .find(|m| m.places.contains(&place.id))
        .map(|m| {
            format!(
                " (in macro-place {})",
                comment(if m.name.trim().is_empty() { &m.id } else { m.name.trim() })
            )
        })
        .unwrap_or_default();
    out.line(1, format!("{}: (* {}{in_macro} *)", place.label, ctx.place_text(p)), Some(&pe));
    if ctx.owner[p] == c {
        out.text(2, &place.actions, &pe, TextPart::Actions);
    } else if !place.actions.trim().is_empty() {
        out.line(
            2,
            format!("(* its actions run in process {} *)", ctx.plans[ctx.owner[p]].name),
            Some(&pe),
        );
    }
    let mut keyword = "IF ";
    if ctx.is_waiting(c, p) {
        let w = ctx.waiting.as_ref().map_or(&[][..], |w| &w[c][..]);
        if let Some(&(_, t)) = w.iter().find(|&&(q, _)| q == p) {
            let te = NetElement::Transition(ctx.pou.net.transitions[t].id.clone());
            let start = ctx.flags(c, p).0;
            let to = ctx.touch[t].iter().find(|&&(d, ..)| d == c).map_or(p, |&(.., o)| o);
            out.line(
                2,
                format!(
                    "IF {start} THEN (* {} decided by process {} *)",
                    ctx.transition_text(t),
                    ctx.leader(t).map_or("", |l| ctx.plans[l].name.as_str())
                ),
                Some(&te),
            );
            out.line(3, format!("{start} := FALSE;"), Some(&te));
            for s in ctx.move_self(c, p, to) {
                out.line(3, s, Some(&te));
            }
            keyword = "ELSIF ";
        }
    }
    for t in ctx.decided(c, p) {
        let tr = &ctx.pou.net.transitions[t];
        let te = NetElement::Transition(tr.id.clone());
        let (conds, stmts) = ctx.fire(t);
        let note = format!(" (* {} *)", ctx.transition_text(t));
        let extra = conds.join(" AND ");
        let guard = tr.guard.trim();
        if guard.is_empty() {
            let cond = if extra.is_empty() { "TRUE".to_string() } else { extra };
            out.line(2, format!("{keyword}{cond} THEN{note}"), Some(&te));
        } else if extra.is_empty() {
            out.condition(2, keyword, &tr.guard, &format!(" THEN{note}"), &te, TextPart::Guard);
        } else {
            out.condition(
                2,
                &format!("{keyword}("),
                &tr.guard,
                &format!(") AND {extra} THEN{note}"),
                &te,
                TextPart::Guard,
            );
        }
        for s in stmts {
            out.line(3, s, Some(&te));
        }
        keyword = "ELSIF ";
    }
    if keyword == "ELSIF " {
        out.line(2, "END_IF;", Some(&pe));
    }
}

fn emit(ctx: &Ctx<'_>) -> Generated {
    let pou = ctx.pou;
    let mut out = Out { lines: Vec::new(), origin: Vec::new() };
    out.line(0, format!("(* Generated from the Petri net {} by the CASE OF method: edit the net, not this text. *)", comment(&pou.name)), None);
    out.line(0, format!("PROGRAM {}", pou.name.trim()), None);
    let decl_start = out.lines.len() as u32 + 1;
    out.text(0, &pou.declarations, &NetElement::Declarations, TextPart::Text);
    let decl_end = out.lines.len() as u32 + 1;
    declarations(ctx, &mut out);
    out.blank();
    if !pou.prologue.trim().is_empty() {
        out.text(0, &pou.prologue, &NetElement::Prologue, TextPart::Text);
    }
    emergency(ctx, &mut out);
    let scans: Vec<usize> =
        (0..ctx.plans.len()).filter(|&c| ctx.moved_by_others[c] && ctx.waiting.is_none()).collect();
    if !scans.is_empty() {
        out.line(0, "(* the marking at the start of the scan: a process moved by another one runs its new place from the next scan *)", None);
        for &c in &scans {
            out.line(0, format!("{} := {};", ctx.scan(c), ctx.var(c)), None);
        }
    }
    for (c, plan) in ctx.plans.iter().enumerate() {
        out.line(
            0,
            format!(
                "(* ---- process {} (step variable {}) ---- *)",
                comment(&plan.name),
                plan.step_variable
            ),
            None,
        );
        let selector = if scans.contains(&c) { ctx.scan(c) } else { plan.step_variable.clone() };
        out.line(0, format!("CASE {selector} OF"), None);
        for &p in &plan.places {
            branch(ctx, &mut out, c, p);
        }
        out.line(0, "END_CASE;", None);
    }
    if !pou.epilogue.trim().is_empty() {
        out.text(0, &pou.epilogue, &NetElement::Epilogue, TextPart::Text);
    }
    out.line(0, "END_PROGRAM", None);
    let mut st = out.lines.join("\n");
    st.push('\n');
    let place_map = PlaceMap {
        processes: ctx
            .plans
            .iter()
            .map(|plan| ProcessEntry {
                name: plan.name.clone(),
                step_variable: plan.step_variable.clone(),
                places: plan.places.iter().map(|&p| pou.net.places[p].id.clone()).collect(),
            })
            .collect(),
        places: (0..ctx.net.places())
            .map(|p| PlaceEntry {
                id: pou.net.places[p].id.clone(),
                step_variable: ctx
                    .plans
                    .get(ctx.owner[p])
                    .map_or_else(String::new, |plan| plan.step_variable.clone()),
                value: ctx.label(p),
            })
            .collect(),
        macro_places: pou
            .net
            .macro_places
            .iter()
            .map(|m| MacroEntry { id: m.id.clone(), places: m.places.clone() })
            .collect(),
    };
    Generated { st, lines: out.origin, declaration_lines: decl_start..decl_end, place_map }
}
