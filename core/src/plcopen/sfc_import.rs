//! SFC bodies → the textual SFC the trainer runs (`docs/sfc.md`), as Beremiz and OpenPLC
//! compile them:
//!
//! - each `<step>` becomes a `STEP` (`INITIAL_STEP` when `initialStep="true"`) with the
//!   associations of the action blocks wired to it (`qualifier`, `duration`, `indicator`);
//! - each `<transition>` a `TRANSITION FROM … TO …`, its source and target steps found by
//!   following the wires through selection and simultaneous divergences and convergences
//!   and jumps; its condition is inline ST, a named transition of the POU, or a wire from
//!   the body's own network (blocks, variables, contacts: the FBD/LD lowering);
//! - the blocks of that network run every scan in an action `COMPUTE_FUNCTION_BLOCKS`
//!   stored (`S`) by the first initial step, as Beremiz's generator does;
//! - the POU's `<actions>` become `ACTION`s; inline action bodies actions of their own.
//!
//! Macro steps, and action or transition bodies in a language other than ST or FBD, make
//! the POU one that cannot be imported yet (it is skipped with the reason).

use std::collections::{BTreeSet, HashMap};

use super::fbd_import::{import_fbd, lower_network};
use super::ld_import::read::read_elements;
use super::xml::Node;
use super::{ImportError, ImportNote};
use crate::network::lower::Lower;

/// The elements that make the chart; every other element of the body is its network.
const CHART: &[&str] = &[
    "step",
    "macroStep",
    "transition",
    "selectionDivergence",
    "selectionConvergence",
    "simultaneousDivergence",
    "simultaneousConvergence",
    "jumpStep",
    "actionBlock",
];

/// The action that runs the body's network every scan (Beremiz's name for it).
const NETWORK_ACTION: &str = "COMPUTE_FUNCTION_BLOCKS";

/// An SFC body as textual SFC.
pub(crate) struct SfcBody {
    /// The chart's lines, each with the line and column of the element it came from.
    pub lines: Vec<(String, (u32, u32))>,
    /// `(instance, type)` of every function block instance of the body's network.
    pub instances: Vec<(String, String)>,
    /// What was left out.
    pub notes: Vec<ImportNote>,
}

/// Lowers the SFC body `sfc` of the POU element `pou` named `name`.
pub(crate) fn import_sfc(sfc: &Node, pou: &Node, name: &str) -> Result<SfcBody, ImportError> {
    let chart: Vec<&Node> =
        sfc.children.iter().filter(|c| CHART.contains(&c.name.as_str())).collect();
    let network = Node {
        name: "FBD".into(),
        children: sfc
            .children
            .iter()
            .filter(|c| !CHART.contains(&c.name.as_str()))
            .cloned()
            .collect(),
        ..Node::default()
    };
    let (els, left_out) = read_elements(&network, name)?;
    let lowered = lower_network(&els, name)?;
    let reader = Chart::new(&chart, name)?;
    let wires = Lower::new(&els);
    let mut out = SfcBody { lines: Vec::new(), instances: lowered.instances, notes: lowered.notes };
    out.notes.extend(left_out);
    let mut inline_actions: Vec<(String, &Node, &Node)> = Vec::new();
    let mut network_done = lowered.statements.is_empty();

    for step in chart.iter().filter(|n| n.name == "step") {
        let step_name = reader.step_name(step)?;
        let initial = step.attr("initialStep") == Some("true");
        let keyword = if initial { "INITIAL_STEP" } else { "STEP" };
        out.lines.push((format!("{keyword} {step_name} :\n"), (step.line, step.column)));
        for block in reader.action_blocks_of(step) {
            for (k, action) in block.children_named("action").enumerate() {
                let target = if let Some(r) = action.child("reference") {
                    r.attr("name").unwrap_or("").trim().to_string()
                } else if let Some(body) = action.child("inline") {
                    let inline = format!("{step_name}_Action{}", inline_actions.len() + k + 1);
                    inline_actions.push((inline.clone(), body, action));
                    inline
                } else {
                    String::new()
                };
                if target.is_empty() {
                    return Err(
                        reader.err(block, "an action with neither a name nor a body".into())
                    );
                }
                let association = association(&target, action).map_err(|m| reader.err(block, m))?;
                out.lines.push((format!("    {association};\n"), (action.line, action.column)));
            }
        }
        if initial && !network_done {
            out.lines.push((format!("    {NETWORK_ACTION}(S);\n"), (step.line, step.column)));
            network_done = true;
        }
        out.lines.push(("END_STEP\n".into(), (step.line, step.column)));
    }
    if !network_done {
        return Err(ImportError::Pou {
            pou: name.to_string(),
            message: "the SFC body has blocks but no initial step to run them".into(),
        });
    }

    for t in chart.iter().filter(|n| n.name == "transition") {
        let from = reader.steps_before(t)?;
        let to = reader.steps_after(t)?;
        if from.is_empty() || to.is_empty() {
            let side = if from.is_empty() { "no step leads to it" } else { "it leads to no step" };
            out.notes.push(ImportNote::on(
                t,
                format!(
                    "POU {name}: transition localId {} is not connected ({side}); skipped",
                    t.attr("localId").unwrap_or("?").trim()
                ),
            ));
            continue;
        }
        let priority = match t.attr("priority").map(str::trim).filter(|p| !p.is_empty()) {
            Some(p) => {
                let p: u32 = p
                    .parse()
                    .map_err(|_| reader.err(t, format!("priority {p:?} is not a whole number")))?;
                format!(" (PRIORITY := {p})")
            }
            None => String::new(),
        };
        let head =
            format!("TRANSITION{priority} FROM {} TO {}", steps_text(&from), steps_text(&to));
        let condition =
            t.child("condition").ok_or_else(|| reader.err(t, "no <condition>".into()))?;
        let negated = condition.attr("negated") == Some("true");
        let text = match condition_of(condition, pou, &wires).map_err(|m| reader.err(t, m))? {
            Condition::Expr(e) if negated => format!("{head} := NOT ({e});\nEND_TRANSITION\n"),
            Condition::Expr(e) => format!("{head} := {e};\nEND_TRANSITION\n"),
            Condition::Body(tname, _) if negated => {
                return Err(
                    reader.err(t, format!("the negated transition {tname} has a statement body"))
                )
            }
            Condition::Body(tname, body) => {
                let head = head.replacen("TRANSITION", &format!("TRANSITION {tname}"), 1);
                format!("{head} :\n{}\nEND_TRANSITION\n", body.trim_end())
            }
        };
        out.lines.push((text, (t.line, t.column)));
    }

    if !lowered.statements.is_empty() {
        out.lines.push((format!("ACTION {NETWORK_ACTION} :\n"), (sfc.line, sfc.column)));
        out.lines.extend(lowered.statements);
        out.lines.push(("END_ACTION\n".into(), (sfc.line, sfc.column)));
    }
    for action in pou.child("actions").into_iter().flat_map(|a| a.children_named("action")) {
        let aname = action.attr("name").unwrap_or("").trim();
        let body = action
            .child("body")
            .ok_or_else(|| reader.err(action, "an action without <body>".into()))?;
        let statements = body_statements(body, name).map_err(|m| reader.err(action, m))?;
        out.lines.push((
            format!("ACTION {aname} :\n{}\nEND_ACTION\n", statements.trim_end()),
            (action.line, action.column),
        ));
    }
    for (aname, body, action) in inline_actions {
        let statements = body_statements(body, name).map_err(|m| reader.err(action, m))?;
        out.lines.push((
            format!("ACTION {aname} :\n{}\nEND_ACTION\n", statements.trim_end()),
            (action.line, action.column),
        ));
    }
    Ok(out)
}

/// `A`, or `(A, B)` for several steps.
fn steps_text(steps: &[String]) -> String {
    match steps {
        [one] => one.clone(),
        _ => format!("({})", steps.join(", ")),
    }
}

/// `Name(qualifier[, duration][, indicator])` of an `<action>` of an action block.
fn association(target: &str, action: &Node) -> Result<String, String> {
    let qualifier =
        action.attr("qualifier").map(str::trim).filter(|q| !q.is_empty()).unwrap_or("N");
    let known = ["N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"];
    let q = qualifier.to_ascii_uppercase();
    if !known.contains(&q.as_str()) {
        return Err(format!("action {target} has the unknown qualifier {qualifier:?}"));
    }
    let mut args = vec![q.clone()];
    let duration = action.attr("duration").map(str::trim).filter(|d| !d.is_empty());
    if matches!(q.as_str(), "L" | "D" | "SD" | "DS" | "SL") {
        args.push(
            duration.ok_or_else(|| format!("action {target} ({q}) has no duration"))?.to_string(),
        );
    }
    if let Some(ind) = action.attr("indicator").map(str::trim).filter(|i| !i.is_empty()) {
        args.push(ind.to_string());
    }
    Ok(format!("{target}({})", args.join(", ")))
}

/// A transition's condition.
enum Condition {
    /// A BOOL expression.
    Expr(String),
    /// A named transition whose statements assign its name.
    Body(String, String),
}

/// The condition of a transition: inline ST, a wire from the network, or a transition of
/// the POU named by reference.
fn condition_of(condition: &Node, pou: &Node, wires: &Lower<'_>) -> Result<Condition, String> {
    if let Some(point) = condition.child("connectionPointIn") {
        let conns = super::ld_import::read::conns_of(point);
        if conns.is_empty() {
            return Err("the condition's input is not wired".into());
        }
        return wires.joined(&conns).map(Condition::Expr).map_err(|e| e.to_string());
    }
    if let Some(inline) = condition.child("inline") {
        let st = inline
            .child("ST")
            .ok_or("an inline condition not written in ST (not supported yet)")?;
        return Ok(Condition::Expr(expression(&st.deep_text())?));
    }
    if let Some(r) = condition.child("reference") {
        let tname = r.attr("name").unwrap_or("").trim();
        let t = pou
            .child("transitions")
            .into_iter()
            .flat_map(|ts| ts.children_named("transition"))
            .find(|t| t.attr("name").is_some_and(|n| n.trim().eq_ignore_ascii_case(tname)))
            .ok_or_else(|| {
                format!("the condition names the transition {tname}, which the POU does not have")
            })?;
        let body = t.child("body").ok_or_else(|| format!("transition {tname} has no <body>"))?;
        let st = body.child("ST").ok_or_else(|| {
            format!("transition {tname} is not written in ST (not supported yet)")
        })?;
        let text = st.deep_text().replace("\r\n", "\n");
        return if text.contains(":=") && !text.trim_start().starts_with(":=") {
            Ok(Condition::Body(tname.to_string(), text))
        } else {
            Ok(Condition::Expr(expression(&text)?))
        };
    }
    Err("a condition with neither a wire, inline ST nor a reference".into())
}

/// An expression written as a condition's text (`:= x;`, `x;`, `x`).
fn expression(text: &str) -> Result<String, String> {
    let e = text.trim();
    let e = e.strip_prefix(":=").unwrap_or(e).trim();
    let e = e.strip_suffix(';').unwrap_or(e).trim();
    if e.is_empty() {
        return Err("an empty condition".into());
    }
    Ok(format!("({e})"))
}

/// The statements of an action body (ST, or FBD lowered).
fn body_statements(body: &Node, pou: &str) -> Result<String, String> {
    if let Some(st) = body.child("ST") {
        return Ok(st.deep_text().replace("\r\n", "\n"));
    }
    if let Some(fbd) = body.child("FBD") {
        let lowered = import_fbd(fbd, pou).map_err(|e| e.to_string())?;
        return Ok(lowered.statements.into_iter().map(|(s, _)| s).collect());
    }
    let lang = body.children.first().map_or("empty", |c| c.name.as_str());
    Err(format!("an action body in {lang} (not supported yet)"))
}

/// The chart's elements by `localId`, and the wires between them.
struct Chart<'a> {
    by_id: HashMap<&'a str, &'a Node>,
    /// For each element, the elements wired from it.
    followers: HashMap<&'a str, Vec<&'a Node>>,
    pou: &'a str,
}

impl<'a> Chart<'a> {
    fn new(chart: &[&'a Node], pou: &'a str) -> Result<Self, ImportError> {
        let mut by_id = HashMap::new();
        let mut followers: HashMap<&str, Vec<&Node>> = HashMap::new();
        let me = Chart { by_id: HashMap::new(), followers: HashMap::new(), pou };
        for n in chart {
            let id = n.attr("localId").map(str::trim).unwrap_or("");
            if id.is_empty() {
                return Err(me.err(n, format!("<{}> without localId", n.name)));
            }
            if by_id.insert(id, *n).is_some() {
                return Err(me.err(n, format!("two elements have localId {id}")));
            }
        }
        for n in chart {
            for point in n.children_named("connectionPointIn") {
                for c in point.children_named("connection") {
                    if let Some(from) = c.attr("refLocalId").map(str::trim) {
                        followers.entry(from).or_default().push(*n);
                    }
                }
            }
        }
        Ok(Chart { by_id, followers, pou })
    }

    fn err(&self, n: &Node, message: String) -> ImportError {
        ImportError::Element {
            pou: self.pou.to_string(),
            local_id: n.attr("localId").unwrap_or("?").trim().to_string(),
            message,
        }
    }

    fn step_name(&self, step: &Node) -> Result<String, ImportError> {
        let name = step.attr("name").map(str::trim).unwrap_or("");
        if name.is_empty() {
            return Err(self.err(step, "a step without a name".into()));
        }
        Ok(name.to_string())
    }

    /// The action blocks wired to `step`.
    fn action_blocks_of(&self, step: &Node) -> Vec<&'a Node> {
        let id = step.attr("localId").unwrap_or("").trim();
        self.followers
            .get(id)
            .map(|f| f.iter().filter(|n| n.name == "actionBlock").copied().collect())
            .unwrap_or_default()
    }

    /// The elements wired into `n`.
    fn inputs(&self, n: &Node) -> Result<Vec<&'a Node>, ImportError> {
        let mut out = Vec::new();
        for point in n.children_named("connectionPointIn") {
            for c in point.children_named("connection") {
                let from = c.attr("refLocalId").unwrap_or("").trim();
                let src = self.by_id.get(from).ok_or_else(|| {
                    self.err(
                        n,
                        format!("a wire comes from localId {from}, which is not a chart element"),
                    )
                })?;
                out.push(*src);
            }
        }
        Ok(out)
    }

    /// The steps transition `t` leaves (none when nothing is wired into it).
    fn steps_before(&self, t: &Node) -> Result<Vec<String>, ImportError> {
        let mut steps = BTreeSet::new();
        let mut order = Vec::new();
        let mut todo = self.inputs(t)?;
        let mut seen = 0;
        while let Some(n) = todo.pop() {
            seen += 1;
            if seen > self.by_id.len() + 1 {
                return Err(self.err(t, "the wires before this transition form a loop".into()));
            }
            match n.name.as_str() {
                "step" => {
                    let s = self.step_name(n)?;
                    if steps.insert(s.to_ascii_uppercase()) {
                        order.push(s);
                    }
                }
                "selectionDivergence" | "simultaneousConvergence" => todo.extend(self.inputs(n)?),
                other => {
                    return Err(
                        self.err(t, format!("a transition after a <{other}> (not supported yet)"))
                    )
                }
            }
        }
        order.reverse();
        Ok(order)
    }

    /// The steps transition `t` activates (none when nothing is wired from it).
    fn steps_after(&self, t: &Node) -> Result<Vec<String>, ImportError> {
        let mut steps = BTreeSet::new();
        let mut order = Vec::new();
        let id = t.attr("localId").unwrap_or("").trim();
        let mut todo: Vec<&Node> = self.followers.get(id).cloned().unwrap_or_default();
        todo.reverse();
        let mut seen = 0;
        while let Some(n) = todo.pop() {
            seen += 1;
            if seen > self.by_id.len() + 1 {
                return Err(self.err(t, "the wires after this transition form a loop".into()));
            }
            let name = match n.name.as_str() {
                "step" => self.step_name(n)?,
                "jumpStep" => {
                    let target = n.attr("targetName").map(str::trim).unwrap_or("");
                    if target.is_empty() {
                        return Err(self.err(n, "a jump without a target step".into()));
                    }
                    target.to_string()
                }
                "selectionConvergence" | "simultaneousDivergence" => {
                    let nid = n.attr("localId").unwrap_or("").trim();
                    let mut next = self.followers.get(nid).cloned().unwrap_or_default();
                    next.reverse();
                    todo.extend(next);
                    continue;
                }
                "macroStep" => return Err(self.err(n, "macro steps are not supported yet".into())),
                other => return Err(self.err(t, format!("a transition followed by a <{other}>"))),
            };
            if steps.insert(name.to_ascii_uppercase()) {
                order.push(name);
            }
        }
        Ok(order)
    }
}
