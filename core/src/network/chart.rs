//! An SFC network POU → the textual SFC the trainer runs (`docs/sfc.md`), as Beremiz and
//! OpenPLC compile such a chart:
//!
//! - each step becomes a `STEP` (`INITIAL_STEP` for the initial one) with the
//!   associations of the action blocks wired to its `action` output (qualifier, duration,
//!   indicator);
//! - each transition a `TRANSITION FROM … TO …`, its source and target steps found by
//!   following the wires through selection and simultaneous divergences and convergences
//!   and jumps; its condition is inline ST, a named transition of the POU, or the value
//!   wired to its `condition` input from the chart's own LD/FBD elements;
//! - the blocks of that network run every scan in the action `COMPUTE_FUNCTION_BLOCKS`,
//!   stored (`S`) by the first initial step, as Beremiz's generator does;
//! - the POU's named actions become `ACTION`s, inline action bodies actions of their own.

use std::collections::{BTreeSet, HashMap};

use super::logical::Conn;
use super::model::{NetElement, NetKind, NetworkPou, SfcActionBody, SfcCondition};
use super::NetError;
use crate::diagnostics::Said;

/// The action that runs the body's network every scan (Beremiz's name for it).
pub const NETWORK_ACTION: &str = "COMPUTE_FUNCTION_BLOCKS";

/// An SFC body as textual SFC.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartText {
    /// The chart's text in pieces, each with the `localId` of the element it came from.
    pub lines: Vec<(String, Option<String>)>,
    /// `(instance, type)` of every function block instance of the body's network.
    pub instances: Vec<(String, String)>,
    /// What was left out (a transition wired to no step), by element, as data to be shown
    /// in any language.
    pub notes: Vec<(String, Said)>,
}

/// The textual SFC of the SFC network POU `pou`.
pub fn chart_text(pou: &NetworkPou) -> Result<ChartText, NetError> {
    let name = pou.name.as_str();
    let els = super::logical(&pou.elements)?;
    let lowered = super::lower(&els, name)?;
    let wires = super::lower::Lower::new(&els);
    let chart = Chart::new(&pou.elements)?;
    let network_id = |i: usize| els.get(i).map(|e| e.id.clone());
    let mut out = ChartText {
        lines: Vec::new(),
        instances: lowered.instances,
        notes: lowered.notes.into_iter().filter_map(|(i, m)| Some((network_id(i)?, m))).collect(),
    };
    let mut inline_actions: Vec<(String, &str, &str)> = Vec::new();
    let mut network_done = lowered.statements.is_empty();

    for step in pou.elements.iter() {
        let NetKind::Step { name: step_name, initial } = &step.kind else { continue };
        let at = Some(step.id.clone());
        let keyword = if *initial { "INITIAL_STEP" } else { "STEP" };
        out.lines.push((format!("{keyword} {step_name} :\n"), at.clone()));
        for block in chart.action_blocks_of(&step.id) {
            let NetKind::ActionBlock { actions } = &block.kind else { continue };
            for action in actions {
                let target = match &action.action {
                    SfcActionBody::Reference { name } => name.clone(),
                    SfcActionBody::Inline { st } => {
                        let inline = format!("{step_name}_Action{}", inline_actions.len() + 1);
                        inline_actions.push((inline.clone(), st, &block.id));
                        inline
                    }
                };
                let q = action.qualifier.to_ascii_uppercase();
                if !QUALIFIERS.contains(&q.as_str()) {
                    return Err(chart.err(
                        &block.id,
                        crate::msg!(
                            NetUnknownQualifier,
                            name = &target,
                            q = format!("{:?}", action.qualifier)
                        ),
                    ));
                }
                let mut args = vec![q.clone()];
                if matches!(q.as_str(), "L" | "D" | "SD" | "DS" | "SL") {
                    let duration = action.duration.as_deref().ok_or_else(|| {
                        chart.err(&block.id, crate::msg!(NetNoDuration, name = &target, q = &q))
                    })?;
                    args.push(duration.to_string());
                }
                if let Some(ind) = &action.indicator {
                    args.push(ind.clone());
                }
                out.lines.push((
                    format!("    {target}({});\n", args.join(", ")),
                    Some(block.id.clone()),
                ));
            }
        }
        if *initial && !network_done {
            out.lines.push((format!("    {NETWORK_ACTION}(S);\n"), at.clone()));
            network_done = true;
        }
        out.lines.push(("END_STEP\n".into(), at));
    }
    if !network_done {
        return Err(NetError::new(String::new(), crate::msg!(NetNoInitialStep)));
    }

    for t in &pou.elements {
        let NetKind::Transition { condition, negated, priority } = &t.kind else { continue };
        let from = chart.steps_before(t)?;
        let to = chart.steps_after(t)?;
        if from.is_empty() || to.is_empty() {
            let side = if from.is_empty() {
                crate::phrase!(NetNoStepLeadsToIt)
            } else {
                crate::phrase!(NetLeadsToNoStep)
            };
            out.notes.push((
                t.id.clone(),
                crate::msg!(NetTransitionNotConnected, pou = name, id = &t.id, side = side),
            ));
            continue;
        }
        let priority = priority.map(|p| format!(" (PRIORITY := {p})")).unwrap_or_default();
        let head =
            format!("TRANSITION{priority} FROM {} TO {}", steps_text(&from), steps_text(&to));
        let text = match condition_of(t, condition, pou, &wires).map_err(|m| chart.err(&t.id, m))? {
            Condition::Expr(e) if *negated => format!("{head} := NOT ({e});\nEND_TRANSITION\n"),
            Condition::Expr(e) => format!("{head} := {e};\nEND_TRANSITION\n"),
            Condition::Body(tname, _) if *negated => {
                return Err(chart.err(&t.id, crate::msg!(NetNegatedBody, name = &tname)))
            }
            Condition::Body(tname, body) => {
                let head = head.replacen("TRANSITION", &format!("TRANSITION {tname}"), 1);
                format!("{head} :\n{}\nEND_TRANSITION\n", body.trim_end())
            }
        };
        out.lines.push((text, Some(t.id.clone())));
    }

    if !lowered.statements.is_empty() {
        out.lines.push((format!("ACTION {NETWORK_ACTION} :\n"), None));
        out.lines.extend(lowered.statements.into_iter().map(|(s, i)| (s, network_id(i))));
        out.lines.push(("END_ACTION\n".into(), None));
    }
    for action in &pou.actions {
        out.lines.push((
            format!("ACTION {} :\n{}\nEND_ACTION\n", action.name, action.st.trim_end()),
            None,
        ));
    }
    for (aname, st, block) in inline_actions {
        out.lines.push((
            format!("ACTION {aname} :\n{}\nEND_ACTION\n", st.trim_end()),
            Some(block.to_string()),
        ));
    }
    Ok(out)
}

/// The qualifiers an action association may have.
const QUALIFIERS: &[&str] = &["N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"];

/// `A`, or `(A, B)` for several steps.
fn steps_text(steps: &[String]) -> String {
    match steps {
        [one] => one.clone(),
        _ => format!("({})", steps.join(", ")),
    }
}

/// A transition's condition.
enum Condition {
    /// A BOOL expression.
    Expr(String),
    /// A named transition whose statements assign its name.
    Body(String, String),
}

/// The condition of transition `t`: inline ST, the value wired to it, or a transition of
/// the POU named by reference.
fn condition_of(
    t: &NetElement,
    condition: &SfcCondition,
    pou: &NetworkPou,
    wires: &super::lower::Lower<'_>,
) -> Result<Condition, Said> {
    match condition {
        SfcCondition::Wired => {
            let conns: Vec<Conn> = t
                .inputs
                .iter()
                .filter(|p| p.name == "condition")
                .flat_map(|p| &p.wires)
                .map(|w| Conn { from: w.from.clone(), param: w.param.clone() })
                .collect();
            if conns.is_empty() {
                return Err(crate::msg!(NetConditionNotWired));
            }
            wires
                .joined(&conns)
                .map(Condition::Expr)
                .map_err(|e| crate::msg!(NetElementSays, element = &e.element, message = e.said()))
        }
        SfcCondition::Inline { st } => Ok(Condition::Expr(expression(st)?)),
        SfcCondition::Reference { name } => {
            let named = pou
                .transitions
                .iter()
                .find(|n| n.name.eq_ignore_ascii_case(name))
                .ok_or_else(|| crate::msg!(NetNoSuchTransition, name = name))?;
            let text = named.st.replace("\r\n", "\n");
            if text.contains(":=") && !text.trim_start().starts_with(":=") {
                Ok(Condition::Body(named.name.clone(), text))
            } else {
                Ok(Condition::Expr(expression(&text)?))
            }
        }
    }
}

/// An expression written as a condition's text (`:= x;`, `x;`, `x`).
fn expression(text: &str) -> Result<String, Said> {
    let e = text.trim();
    let e = e.strip_prefix(":=").unwrap_or(e).trim();
    let e = e.strip_suffix(';').unwrap_or(e).trim();
    if e.is_empty() {
        return Err(crate::msg!(NetEmptyCondition));
    }
    Ok(format!("({e})"))
}

/// The chart's elements by `localId`, and the wires between them.
struct Chart<'a> {
    by_id: HashMap<&'a str, &'a NetElement>,
    /// For each element, the chart elements wired from it.
    followers: HashMap<&'a str, Vec<&'a NetElement>>,
}

impl<'a> Chart<'a> {
    fn new(elements: &'a [NetElement]) -> Result<Self, NetError> {
        let chart: Vec<&NetElement> = elements.iter().filter(|e| e.kind.is_chart()).collect();
        let mut by_id = HashMap::new();
        let mut followers: HashMap<&str, Vec<&NetElement>> = HashMap::new();
        for n in &chart {
            if by_id.insert(n.id.as_str(), *n).is_some() {
                return Err(NetError::new(n.id.clone(), crate::msg!(NetSameLocalId, id = &n.id)));
            }
        }
        for n in &chart {
            for pin in n.inputs.iter().filter(|p| p.name != "condition") {
                for w in &pin.wires {
                    followers.entry(w.from.as_str()).or_default().push(*n);
                }
            }
        }
        Ok(Chart { by_id, followers })
    }

    fn err(&self, id: &str, said: Said) -> NetError {
        NetError::new(id.to_string(), said)
    }

    /// The action blocks wired to step `id`.
    fn action_blocks_of(&self, id: &str) -> Vec<&'a NetElement> {
        self.followers
            .get(id)
            .map(|f| {
                f.iter()
                    .filter(|n| matches!(n.kind, NetKind::ActionBlock { .. }))
                    .copied()
                    .collect()
            })
            .unwrap_or_default()
    }

    /// The chart elements wired into `n`'s chart input.
    fn inputs(&self, n: &NetElement) -> Result<Vec<&'a NetElement>, NetError> {
        let mut out = Vec::new();
        for pin in n.inputs.iter().filter(|p| p.name != "condition") {
            for w in &pin.wires {
                let src = self.by_id.get(w.from.as_str()).ok_or_else(|| {
                    self.err(&n.id, crate::msg!(NetWireFromNotChart, id = &w.from))
                })?;
                out.push(*src);
            }
        }
        Ok(out)
    }

    /// The steps transition `t` leaves (none when nothing is wired into it).
    fn steps_before(&self, t: &NetElement) -> Result<Vec<String>, NetError> {
        let mut steps = BTreeSet::new();
        let mut order = Vec::new();
        let mut todo = self.inputs(t)?;
        let mut seen = 0;
        while let Some(n) = todo.pop() {
            seen += 1;
            if seen > self.by_id.len() + 1 {
                return Err(self.err(&t.id, crate::msg!(NetLoopBefore)));
            }
            match &n.kind {
                NetKind::Step { name, .. } => {
                    if steps.insert(name.to_ascii_uppercase()) {
                        order.push(name.clone());
                    }
                }
                NetKind::SelectionDivergence | NetKind::SimultaneousConvergence => {
                    todo.extend(self.inputs(n)?)
                }
                _ => {
                    return Err(
                        self.err(&t.id, crate::msg!(NetTransitionAfter, kind = describe(&n.kind)))
                    )
                }
            }
        }
        order.reverse();
        Ok(order)
    }

    /// The steps transition `t` activates (none when nothing is wired from it).
    fn steps_after(&self, t: &NetElement) -> Result<Vec<String>, NetError> {
        let mut steps = BTreeSet::new();
        let mut order = Vec::new();
        let mut todo: Vec<&NetElement> =
            self.followers.get(t.id.as_str()).cloned().unwrap_or_default();
        todo.reverse();
        let mut seen = 0;
        while let Some(n) = todo.pop() {
            seen += 1;
            if seen > self.by_id.len() + 1 {
                return Err(self.err(&t.id, crate::msg!(NetLoopAfter)));
            }
            let name = match &n.kind {
                NetKind::Step { name, .. } => name.clone(),
                NetKind::JumpStep { target } => target.clone(),
                NetKind::SelectionConvergence | NetKind::SimultaneousDivergence => {
                    let mut next = self.followers.get(n.id.as_str()).cloned().unwrap_or_default();
                    next.reverse();
                    todo.extend(next);
                    continue;
                }
                other => {
                    return Err(self
                        .err(&t.id, crate::msg!(NetTransitionFollowedBy, kind = describe(other))))
                }
            };
            if steps.insert(name.to_ascii_uppercase()) {
                order.push(name);
            }
        }
        Ok(order)
    }
}

/// What a chart element is, in words.
fn describe(kind: &NetKind) -> crate::diagnostics::Phrase {
    match kind {
        NetKind::Transition { .. } => crate::phrase!(NetKindTransition),
        NetKind::SelectionDivergence => crate::phrase!(NetKindSelectionDivergence),
        NetKind::SelectionConvergence => crate::phrase!(NetKindSelectionConvergence),
        NetKind::SimultaneousDivergence => crate::phrase!(NetKindSimultaneousDivergence),
        NetKind::SimultaneousConvergence => crate::phrase!(NetKindSimultaneousConvergence),
        NetKind::ActionBlock { .. } => crate::phrase!(NetKindActionBlock),
        NetKind::JumpStep { .. } => crate::phrase!(NetKindJump),
        NetKind::Step { .. } => crate::phrase!(NetKindStep),
        _ => crate::phrase!(NetKindOther),
    }
}
