//! LD and FBD body XML → the network model (elements with their positions, pins and
//! wires, [`crate::network::model`]), and its logical view (connectors resolved) for the
//! grid layout and the lowering.

use super::super::xml::Node;
use super::super::{ImportError, ImportNote};
use crate::diagnostics::Said;
use crate::ladder::{CoilKind, ContactKind};
pub(crate) use crate::network::logical::{Conn, El, Kind, RawBlock};
use crate::network::model::{
    NetElement, NetKind, Pin, PinModifier, SfcAction, SfcActionBody, SfcCondition, Wire,
};

/// A number attribute (0 when missing or not a number).
fn num(n: Option<&Node>, attr: &str) -> f64 {
    n.and_then(|n| n.attr(attr))
        .and_then(|v| v.trim().parse().ok())
        .filter(|v: &f64| v.is_finite())
        .unwrap_or(0.0)
}

/// The `<relPosition>` of a connection point.
fn rel(point: &Node) -> (f64, f64) {
    let r = point.child("relPosition");
    (num(r, "x"), num(r, "y"))
}

/// The wires into a `connectionPointIn`, with the points they are drawn through.
fn wires_of(point: &Node) -> Vec<Wire> {
    point
        .children_named("connection")
        .filter_map(|c| {
            Some(Wire {
                from: c.attr("refLocalId")?.trim().to_string(),
                param: c.attr("formalParameter").filter(|p| !p.is_empty()).map(str::to_string),
                points: c
                    .children_named("position")
                    .map(|p| (num(Some(p), "x"), num(Some(p), "y")))
                    .collect(),
            })
        })
        .collect()
}

/// One pin per `connectionPointIn` of an element that is not a block.
fn input_points(n: &Node) -> Vec<Pin> {
    n.children_named("connectionPointIn")
        .map(|p| {
            let (dx, dy) = rel(p);
            Pin { name: String::new(), dx, dy, wires: wires_of(p), modifier: None, in_out: false }
        })
        .collect()
}

/// One pin per `connectionPointOut` of an element that is not a block.
fn output_points(n: &Node) -> Vec<Pin> {
    n.children_named("connectionPointOut")
        .map(|p| {
            let (dx, dy) = rel(p);
            Pin { name: String::new(), dx, dy, wires: Vec::new(), modifier: None, in_out: false }
        })
        .collect()
}

fn text_of(n: &Node, child: &str) -> String {
    n.child(child).map(|v| v.deep_text().trim().to_string()).unwrap_or_default()
}

/// Whether a rising-edge modifier on input `pin` of `type_name` changes nothing: a counter
/// counts rising edges of CU and CD anyway.
fn edge_is_redundant(type_name: &str, pin: &str, edge: &str) -> bool {
    edge == "rising"
        && matches!(
            (type_name.to_ascii_uppercase().as_str(), pin.to_ascii_uppercase().as_str()),
            ("CTU" | "CTUD", "CU") | ("CTD" | "CTUD", "CD")
        )
}

/// The pins of a block's `section` (`inputVariables`, `inOutVariables`, `outputVariables`).
fn block_pins(
    n: &Node,
    type_name: &str,
    section: &str,
    err: &dyn Fn(Said) -> ImportError,
) -> Result<Vec<Pin>, ImportError> {
    let mut out = Vec::new();
    let Some(sec) = n.child(section) else { return Ok(out) };
    for v in sec.children_named("variable") {
        let name = v.attr("formalParameter").unwrap_or("").trim().to_string();
        if name.is_empty() {
            return Err(err(crate::msg!(PlcopenPinWithoutFormalParameter, section = section)));
        }
        let edge = v.attr("edge").unwrap_or("none");
        let redundant = edge_is_redundant(type_name, &name, edge);
        let modifier = match (v.attr("negated") == Some("true"), edge) {
            _ if section == "outputVariables" => None,
            (true, _) => Some(PinModifier::Negated),
            (false, "rising") if !redundant => Some(PinModifier::Rising),
            (false, "falling") => Some(PinModifier::Falling),
            _ => None,
        };
        let point = v.child("connectionPointIn").or_else(|| v.child("connectionPointOut"));
        let (dx, dy) = point.map(rel).unwrap_or((0.0, 0.0));
        let wires = v.child("connectionPointIn").map(wires_of).unwrap_or_default();
        out.push(Pin { name, dx, dy, wires, modifier, in_out: section == "inOutVariables" });
    }
    Ok(out)
}

/// Reads the elements of an LD or FBD body as the network model, with a note for each
/// element of a kind the trainer does not know (a vendor's own, an action block), which is
/// left out.
pub(crate) fn read_network(
    body: &Node,
    pou: &str,
) -> Result<(Vec<NetElement>, Vec<ImportNote>), ImportError> {
    let mut els = Vec::new();
    let mut notes = Vec::new();
    for n in &body.children {
        let id = n.attr("localId").unwrap_or("").trim().to_string();
        let err = |message: Said| ImportError::Element {
            pou: pou.to_string(),
            local_id: if id.is_empty() { "?".into() } else { id.clone() },
            message,
        };
        let mut inputs = input_points(n);
        let mut outputs = output_points(n);
        let kind = match n.name.as_str() {
            "leftPowerRail" => NetKind::LeftRail,
            "rightPowerRail" => NetKind::RightRail,
            "contact" => {
                let operand = text_of(n, "variable");
                if operand.is_empty() {
                    return Err(err(crate::msg!(PlcopenContactWithoutVariable)));
                }
                let contact = match (n.attr("edge"), n.attr("negated") == Some("true")) {
                    (Some("rising"), _) => ContactKind::Rising,
                    (Some("falling"), _) => ContactKind::Falling,
                    (_, true) => ContactKind::NormallyClosed,
                    _ => ContactKind::NormallyOpen,
                };
                NetKind::Contact { operand, contact }
            }
            "coil" => {
                let operand = text_of(n, "variable");
                if operand.is_empty() {
                    return Err(err(crate::msg!(PlcopenCoilWithoutVariable)));
                }
                let coil = match (n.attr("storage"), n.attr("edge"), n.attr("negated")) {
                    (Some("set"), _, _) => CoilKind::Set,
                    (Some("reset"), _, _) => CoilKind::Reset,
                    (_, Some("rising"), _) => CoilKind::Rising,
                    (_, Some("falling"), _) => CoilKind::Falling,
                    (_, _, Some("true")) => CoilKind::Negated,
                    _ => CoilKind::Normal,
                };
                NetKind::Coil { operand, coil }
            }
            "block" => {
                let type_name = n.attr("typeName").unwrap_or("").trim().to_string();
                if type_name.is_empty() {
                    return Err(err(crate::msg!(PlcopenBlockWithoutTypeName)));
                }
                let instance = n
                    .attr("instanceName")
                    .map(str::trim)
                    .filter(|s| !s.is_empty())
                    .map(str::to_string);
                inputs = block_pins(n, &type_name, "inputVariables", &err)?;
                let in_outs = block_pins(n, &type_name, "inOutVariables", &err)?;
                outputs = block_pins(n, &type_name, "outputVariables", &err)?;
                outputs.extend(in_outs.iter().map(|p| Pin { wires: Vec::new(), ..p.clone() }));
                inputs.extend(in_outs);
                NetKind::Block { type_name, instance }
            }
            "inVariable" => NetKind::InVar { expr: text_of(n, "expression") },
            "inOutVariable" => NetKind::InOutVar { expr: text_of(n, "expression") },
            "outVariable" => NetKind::OutVar { expr: text_of(n, "expression") },
            "comment" => {
                NetKind::Comment { text: n.child("content").map(comment_text).unwrap_or_default() }
            }
            "label" => NetKind::Label { label: n.attr("label").unwrap_or("").to_string() },
            "jump" => NetKind::Jump { label: n.attr("label").unwrap_or("").to_string() },
            "return" => NetKind::Return,
            "connector" | "continuation" => {
                let name = n.attr("name").unwrap_or("").trim().to_string();
                if name.is_empty() {
                    return Err(err(crate::msg!(PlcopenElementWithoutName, element = &n.name)));
                }
                if n.name == "connector" {
                    NetKind::Connector { name }
                } else {
                    NetKind::Continuation { name }
                }
            }
            "documentation" | "addData" => continue,
            chart if body.name == "SFC" && CHART.contains(&chart) => {
                chart_element(n, &mut inputs, &mut outputs, &mut notes, pou).map_err(err)?
            }
            other => {
                let said = if id.is_empty() {
                    crate::msg!(PlcopenNotRunLeftOutNoId, pou = pou, element = other)
                } else {
                    crate::msg!(PlcopenNotRunLeftOut, pou = pou, element = other, id = &id)
                };
                notes.push(ImportNote::on(n, said));
                continue;
            }
        };
        if id.is_empty() && !matches!(kind, NetKind::Comment { .. }) {
            return Err(err(crate::msg!(PlcopenElementWithoutLocalId, element = &n.name)));
        }
        let position = n.child("position");
        els.push(NetElement {
            id,
            kind,
            x: num(position, "x"),
            y: num(position, "y"),
            width: num(Some(n), "width"),
            height: num(Some(n), "height"),
            order: n.attr("executionOrderId").and_then(|o| o.trim().parse().ok()).unwrap_or(0),
            inputs,
            outputs,
            at: (n.line, n.column),
        });
    }
    Ok((els, notes))
}

/// The elements of an SFC body that make its chart (the others are its network).
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

/// An element of an SFC chart: its kind, with the pins the generic reading misses (a
/// step's `action` output, a wired transition condition's `condition` input).
fn chart_element(
    n: &Node,
    inputs: &mut Vec<Pin>,
    outputs: &mut Vec<Pin>,
    notes: &mut Vec<ImportNote>,
    pou: &str,
) -> Result<NetKind, Said> {
    let pin = |name: &str, p: &Node, wires: Vec<Wire>| {
        let (dx, dy) = rel(p);
        Pin { name: name.into(), dx, dy, wires, modifier: None, in_out: false }
    };
    // The attribute `attr`, or `missing` when it is absent or blank.
    let named = |attr: &str, missing: fn() -> Said| {
        let v = n.attr(attr).map(str::trim).unwrap_or("");
        if v.is_empty() {
            Err(missing())
        } else {
            Ok(v.to_string())
        }
    };
    Ok(match n.name.as_str() {
        "step" => {
            if let Some(p) = n.child("connectionPointOutAction") {
                outputs.push(pin("action", p, Vec::new()));
            }
            NetKind::Step {
                name: named("name", || crate::msg!(PlcopenStepWithoutName))?,
                initial: n.attr("initialStep") == Some("true"),
            }
        }
        "macroStep" => return Err(crate::msg!(PlcopenMacroStepsNotSupported)),
        "transition" => {
            let c = n
                .child("condition")
                .ok_or_else(|| crate::msg!(PlcopenTransitionWithoutCondition))?;
            let condition = if let Some(p) = c.child("connectionPointIn") {
                inputs.push(pin("condition", p, wires_of(p)));
                SfcCondition::Wired
            } else if let Some(inline) = c.child("inline") {
                let st =
                    inline.child("ST").ok_or_else(|| crate::msg!(PlcopenInlineConditionNotSt))?;
                SfcCondition::Inline { st: st.deep_text().replace("\r\n", "\n").trim().to_string() }
            } else if let Some(r) = c.child("reference") {
                SfcCondition::Reference { name: r.attr("name").unwrap_or("").trim().to_string() }
            } else {
                return Err(crate::msg!(PlcopenConditionWithoutSource));
            };
            let priority = match n.attr("priority").map(str::trim).filter(|p| !p.is_empty()) {
                Some(p) => Some(p.parse().map_err(|_| {
                    crate::msg!(PlcopenPriorityNotWholeNumber, priority = format!("{p:?}"))
                })?),
                None => None,
            };
            NetKind::Transition { condition, negated: c.attr("negated") == Some("true"), priority }
        }
        "selectionDivergence" => NetKind::SelectionDivergence,
        "selectionConvergence" => NetKind::SelectionConvergence,
        "simultaneousDivergence" => NetKind::SimultaneousDivergence,
        "simultaneousConvergence" => NetKind::SimultaneousConvergence,
        "jumpStep" => NetKind::JumpStep {
            target: named("targetName", || crate::msg!(PlcopenJumpWithoutTarget))?,
        },
        _ => {
            let mut actions = Vec::new();
            for a in n.children_named("action") {
                let action = if let Some(r) = a.child("reference") {
                    let name = r.attr("name").unwrap_or("").trim().to_string();
                    if name.is_empty() {
                        return Err(crate::msg!(PlcopenActionWithoutNameOrBody));
                    }
                    SfcActionBody::Reference { name }
                } else if let Some(body) = a.child("inline") {
                    let st = body_st(body, pou, notes)?;
                    SfcActionBody::Inline { st }
                } else {
                    return Err(crate::msg!(PlcopenActionWithoutNameOrBody));
                };
                let text = |attr: &str| {
                    a.attr(attr).map(str::trim).filter(|d| !d.is_empty()).map(str::to_string)
                };
                actions.push(SfcAction {
                    qualifier: text("qualifier").unwrap_or_else(|| "N".into()).to_ascii_uppercase(),
                    duration: text("duration"),
                    indicator: text("indicator"),
                    action,
                });
            }
            NetKind::ActionBlock { actions }
        }
    })
}

/// The ST of an action or transition `<body>` (or an `<inline>` block), FBD lowered.
pub(crate) fn body_st(body: &Node, pou: &str, notes: &mut Vec<ImportNote>) -> Result<String, Said> {
    if let Some(st) = body.child("ST") {
        return Ok(st.deep_text().replace("\r\n", "\n"));
    }
    if let Some(fbd) = body.child("FBD") {
        let (els, left_out) = read_elements(fbd, pou).map_err(|e| e.said())?;
        let lowered = crate::network::lower(&els, pou)
            .map_err(|e| crate::msg!(NetElementSays, element = &e.element, message = e.said()))?;
        notes.push(ImportNote::on(fbd, crate::msg!(PlcopenFbdActionAsSt, pou = pou)));
        notes.extend(left_out);
        return Ok(lowered.statements.into_iter().map(|(s, _)| s).collect());
    }
    Err(match body.children.first() {
        Some(lang) => crate::msg!(PlcopenActionBodyLanguage, language = &lang.name),
        None => crate::msg!(PlcopenActionBodyEmpty),
    })
}

/// Reads the elements of an LD or FBD body, with connectors and continuations resolved,
/// and the notes on elements left out.
pub(crate) fn read_elements(
    body: &Node,
    pou: &str,
) -> Result<(Vec<El>, Vec<ImportNote>), ImportError> {
    let (network, notes) = read_network(body, pou)?;
    let els = crate::network::logical(&network).map_err(|e| ImportError::Element {
        pou: pou.to_string(),
        message: e.said(),
        local_id: e.element,
    })?;
    Ok((els, notes))
}

/// A comment's text: its lines with runs of blanks folded, blank lines dropped, and no `*)`
/// (which would end the ST comment it becomes).
fn comment_text(content: &Node) -> String {
    content
        .deep_text()
        .replace("\r\n", "\n")
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" ").replace("*)", "* )"))
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("\n")
}
