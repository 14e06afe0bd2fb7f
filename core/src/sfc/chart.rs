//! The chart: one SFC body resolved to indices (steps, transitions, actions and their
//! associations), with every check that needs only names: duplicate and clashing names,
//! unknown steps and actions, initial steps per network, unused actions, equal priorities.
//! Types are left to the checker; reachability to `structure.rs`.

use std::collections::HashMap;

use crate::diagnostics::{Code, Diagnostic};
use crate::syntax::ast::sfc::*;
use crate::syntax::ast::{Ident, Pou};

/// The variables an SFC body can name: the POU's own and the globals (upper-case keys).
#[derive(Debug, Default)]
pub(super) struct Scope {
    /// Variables declared in the POU (any section), as declared.
    pub locals: HashMap<String, Ident>,
    /// Global variables of the file, as declared.
    pub globals: HashMap<String, Ident>,
    /// Every name as declared, the POU's in declaration order, then the globals (for
    /// `did you mean`).
    pub order: Vec<String>,
}

impl Scope {
    fn knows(&self, key: &str) -> bool {
        self.locals.contains_key(key) || self.globals.contains_key(key)
    }
}

/// The name among `candidates` that `name` probably misspells.
fn closest(name: &str, candidates: &[String]) -> Option<String> {
    crate::diagnostics::suggest::closest(name, candidates.iter().map(String::as_str))
        .map(str::to_string)
}

/// A transition with its steps resolved.
#[derive(Debug)]
pub(super) struct Transition<'a> {
    /// The transition as written.
    pub ast: &'a SfcTransition,
    /// Indices of the steps it leaves.
    pub from: Vec<usize>,
    /// Indices of the steps it activates.
    pub to: Vec<usize>,
    /// Both lists resolved and non-empty (only valid transitions take part in the chart).
    pub valid: bool,
}

impl Transition<'_> {
    /// How messages name it: `T1`, or `FROM a TO b` when it has no name.
    pub fn describe(&self) -> String {
        match &self.ast.name {
            Some(n) => format!("transition `{}`", n.name),
            None => {
                let list = |ids: &[Ident]| {
                    let names: Vec<&str> = ids.iter().map(|i| i.name.as_str()).collect();
                    if names.len() == 1 {
                        names.join("")
                    } else {
                        format!("({})", names.join(", "))
                    }
                };
                format!("transition `FROM {} TO {}`", list(&self.ast.from), list(&self.ast.to))
            }
        }
    }
}

/// What an action is.
#[derive(Debug)]
pub(super) enum ActionKind<'a> {
    /// `ACTION name : … END_ACTION` of the body.
    Declared(&'a SfcAction),
    /// A BOOL variable used as an action (it follows the action's Q).
    Boolean,
}

/// One association of an action with a step.
#[derive(Debug, Clone, Copy)]
pub(super) struct Use<'a> {
    /// The step's index.
    pub step: usize,
    /// The association as written.
    pub assoc: &'a ActionAssociation,
}

/// An action and every association that drives its one action control.
#[derive(Debug)]
pub(super) struct Action<'a> {
    /// The name as first written.
    pub name: &'a Ident,
    /// Declared or boolean.
    pub kind: ActionKind<'a>,
    /// Its associations in source order.
    pub uses: Vec<Use<'a>>,
}

/// One SFC body, resolved.
#[derive(Debug)]
pub(super) struct Chart<'a> {
    /// The POU the body belongs to.
    pub pou: &'a Pou,
    /// The steps in source order.
    pub steps: Vec<&'a SfcStep>,
    /// The transitions in source order.
    pub transitions: Vec<Transition<'a>>,
    /// Declared actions in source order, then boolean actions in order of first use.
    pub actions: Vec<Action<'a>>,
}

/// Resolves `body` of `pou`, reporting every problem found from names alone.
pub(super) fn resolve<'a>(
    pou: &'a Pou,
    body: &'a SfcBody,
    scope: &Scope,
    diags: &mut Vec<Diagnostic>,
) -> Chart<'a> {
    let mut chart = Chart { pou, steps: Vec::new(), transitions: Vec::new(), actions: Vec::new() };
    let mut names: HashMap<String, (&str, &Ident)> = HashMap::new();
    let mut claim = |id: &'a Ident, what: &'static str, diags: &mut Vec<Diagnostic>| -> bool {
        if id.name.is_empty() {
            return false;
        }
        let key = id.key();
        if let Some((other, first)) = names.get(&key) {
            let msg = crate::msg!(
                AlreadyNameChartGiveAnother,
                name = id.name,
                other = other,
                name2 = first.name,
                what = what
            );
            diags.push(Diagnostic::error(Code::SfcDuplicateName, id.span, msg));
            return false;
        }
        if scope.locals.contains_key(&key) || scope.globals.contains_key(&key) {
            let whose = if scope.locals.contains_key(&key) {
                format!("a variable of `{}`", pou.name.name)
            } else {
                "a global variable".to_string()
            };
            let msg = crate::msg!(
                CannotAlsoNameStepsTransitions,
                name = id.name,
                whose = whose,
                what = what
            );
            diags.push(Diagnostic::error(Code::SfcDuplicateName, id.span, msg));
            return false;
        }
        names.insert(key, (what, id));
        true
    };
    let mut step_index = HashMap::new();
    let mut action_index = HashMap::new();
    // Steps and actions whose name was refused: their uses are not reported again.
    let mut rejected = Vec::new();
    for element in &body.elements {
        match element {
            SfcElement::Step(s) => {
                if !claim(&s.name, "step", diags) {
                    rejected.push(s.name.key());
                } else {
                    step_index.insert(s.name.key(), chart.steps.len());
                    chart.steps.push(s);
                }
            }
            SfcElement::Action(a) => {
                if !claim(&a.name, "action", diags) {
                    rejected.push(a.name.key());
                } else {
                    action_index.insert(a.name.key(), chart.actions.len());
                    let kind = ActionKind::Declared(a);
                    chart.actions.push(Action { name: &a.name, kind, uses: Vec::new() });
                }
            }
            SfcElement::Transition(t) => {
                if let Some(name) = &t.name {
                    claim(name, "transition", diags);
                }
            }
        }
    }
    let step_names: Vec<String> = chart.steps.iter().map(|s| s.name.name.clone()).collect();
    for element in &body.elements {
        if let SfcElement::Transition(t) = element {
            let steps = Steps { index: &step_index, names: &step_names, rejected: &rejected };
            let from = step_list(&t.from, &steps, "FROM", diags);
            let to = step_list(&t.to, &steps, "TO", diags);
            let valid = from.is_some() && to.is_some() && !t.from.is_empty();
            let (from, to) = (from.unwrap_or_default(), to.unwrap_or_default());
            chart.transitions.push(Transition { ast: t, from, to, valid });
        }
    }
    for (step, s) in chart.steps.iter().enumerate() {
        for assoc in &s.associations {
            let key = assoc.action.key();
            for ind in &assoc.indicators {
                if !scope.knows(&ind.key()) {
                    let msg = format!("indicator `{}` is not a declared variable", ind.name);
                    let hint = closest(&ind.name, &scope.order);
                    let d = Diagnostic::error(Code::UndeclaredName, ind.span, msg);
                    diags.push(d.suggesting(hint.as_deref()));
                }
            }
            let index = match action_index.get(&key) {
                Some(&i) => i,
                None if scope.knows(&key) => {
                    action_index.insert(key, chart.actions.len());
                    let kind = ActionKind::Boolean;
                    chart.actions.push(Action { name: &assoc.action, kind, uses: Vec::new() });
                    chart.actions.len() - 1
                }
                None if rejected.contains(&key) => continue,
                None => {
                    let name = &assoc.action.name;
                    let mut known: Vec<String> =
                        chart.actions.iter().map(|a| a.name.name.clone()).collect();
                    known.extend(scope.order.iter().cloned());
                    let hint = closest(name, &known);
                    let span = assoc.action.span;
                    let d = match &hint {
                        Some(_) => {
                            let msg = crate::msg!(NeitherActionChartNorVariable, name = name);
                            Diagnostic::error(Code::SfcUnknownAction, span, msg)
                                .suggesting(hint.as_deref())
                        }
                        None => {
                            let msg = crate::msg!(NeitherActionChartNorVariable2, name = name);
                            Diagnostic::error(Code::SfcUnknownAction, span, msg)
                        }
                    };
                    diags.push(d);
                    continue;
                }
            };
            chart.actions[index].uses.push(Use { step, assoc });
        }
    }
    if chart.steps.is_empty() {
        let msg = crate::msg!(SfcBodyHasNoInitial, name = pou.name.name);
        diags.push(Diagnostic::error(Code::SfcNoInitialStep, pou.name.span, msg));
    }
    check_networks(&chart, diags);
    for a in &chart.actions {
        if let (ActionKind::Declared(decl), true) = (&a.kind, a.uses.is_empty()) {
            let msg = crate::msg!(NoStepUsesActionSo, name = a.name.name);
            diags.push(Diagnostic::warning(Code::SfcUnusedAction, decl.header, msg));
        }
    }
    check_priorities(&chart, diags);
    chart
}

/// The steps of a chart, for resolving FROM and TO lists.
struct Steps<'s> {
    /// Step index by upper-case name.
    index: &'s HashMap<String, usize>,
    /// The names as written, in order.
    names: &'s [String],
    /// Names refused (their uses are not reported again).
    rejected: &'s [String],
}

/// Resolves a FROM or TO list; `None` when a name is unknown or listed twice.
fn step_list(
    ids: &[Ident],
    steps: &Steps<'_>,
    which: &str,
    diags: &mut Vec<Diagnostic>,
) -> Option<Vec<usize>> {
    let (index, rejected) = (steps.index, steps.rejected);
    let mut out = Vec::new();
    let mut ok = true;
    for id in ids {
        match index.get(&id.key()) {
            Some(&i) if out.contains(&i) => {
                let msg = crate::msg!(StepListedTwiceAfter, name = id.name, which = which);
                diags.push(Diagnostic::error(Code::SfcStepListedTwice, id.span, msg));
                ok = false;
            }
            Some(&i) => out.push(i),
            None if rejected.contains(&id.key()) => ok = false,
            None => {
                let hint = closest(&id.name, steps.names);
                let msg = match hint {
                    Some(_) => crate::msg!(NoStepInChart, name = &id.name),
                    None => crate::msg!(NoStepInChartDeclare, name = &id.name),
                };
                let d = Diagnostic::error(Code::SfcUnknownStep, id.span, msg);
                diags.push(d.suggesting(hint.as_deref()));
                ok = false;
            }
        }
    }
    ok.then_some(out)
}

/// The root of `i`'s set in a union-find forest.
fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Each SFC network (steps linked by transitions) needs exactly one initial step.
fn check_networks(chart: &Chart, diags: &mut Vec<Diagnostic>) {
    let n = chart.steps.len();
    let mut parent: Vec<usize> = (0..n).collect();
    for t in chart.transitions.iter().filter(|t| t.valid) {
        let mut all = t.from.iter().chain(&t.to);
        if let Some(&first) = all.next() {
            for &other in all {
                let (a, b) = (find(&mut parent, first), find(&mut parent, other));
                parent[b] = a;
            }
        }
    }
    let mut networks: Vec<(usize, Vec<usize>)> = Vec::new();
    for i in 0..n {
        let root = find(&mut parent, i);
        match networks.iter_mut().find(|(r, _)| *r == root) {
            Some((_, members)) => members.push(i),
            None => networks.push((root, vec![i])),
        }
    }
    for (_, members) in networks {
        let initials: Vec<usize> =
            members.iter().copied().filter(|&i| chart.steps[i].initial).collect();
        match initials.split_first() {
            None => {
                let names: Vec<String> = members
                    .iter()
                    .take(4)
                    .map(|&i| format!("`{}`", chart.steps[i].name.name))
                    .collect();
                let more = if members.len() > 4 { ", …" } else { "" };
                let msg = format!(
                    "none of the steps {}{more} is an INITIAL_STEP, so they can never become active; write INITIAL_STEP for the step this sequence starts in",
                    names.join(", ")
                );
                let step = chart.steps[members[0]];
                diags.push(Diagnostic::error(Code::SfcNoInitialStep, step.header, msg));
            }
            Some((&first, rest)) => {
                for &extra in rest {
                    let step = chart.steps[extra];
                    let msg = crate::msg!(
                        AlreadyInitialStepNetwork,
                        name = &chart.steps[first].name.name
                    );
                    diags.push(Diagnostic::error(Code::SfcSecondInitialStep, step.header, msg));
                }
            }
        }
    }
}

/// Transitions that leave the same step with the same written priority: source order
/// decides between them, which is rarely what the author meant.
fn check_priorities(chart: &Chart, diags: &mut Vec<Diagnostic>) {
    let valid: Vec<&Transition> = chart.transitions.iter().filter(|t| t.valid).collect();
    for (i, t) in valid.iter().enumerate() {
        let Some((p, span)) = t.ast.priority else { continue };
        let earlier = valid[..i].iter().find(|u| {
            u.ast.priority.is_some_and(|(q, _)| q == p) && u.from.iter().any(|s| t.from.contains(s))
        });
        if let Some(u) = earlier {
            let msg = crate::msg!(
                HasSamePriorityLeavesSame,
                describe = (t.describe()).to_string(),
                p = p,
                describe2 = (u.describe()).to_string()
            );
            diags.push(Diagnostic::warning(Code::SfcSamePriority, span, msg));
        }
    }
}
