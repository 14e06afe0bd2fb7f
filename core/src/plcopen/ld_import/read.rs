//! LD and FBD body XML → the network model (elements with their positions, pins and
//! wires, [`crate::network::model`]), and its logical view (connectors resolved) for the
//! grid layout and the lowering.

use super::super::xml::Node;
use super::super::{ImportError, ImportNote};
use crate::ladder::{CoilKind, ContactKind};
pub(crate) use crate::network::logical::{Conn, El, Kind, RawBlock};
use crate::network::model::{NetElement, NetKind, Pin, PinModifier, Wire};

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

/// The wires into a `connectionPointIn`, logically.
pub(crate) fn conns_of(point: &Node) -> Vec<Conn> {
    wires_of(point).into_iter().map(|w| Conn { from: w.from, param: w.param }).collect()
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
    err: &dyn Fn(String) -> ImportError,
) -> Result<Vec<Pin>, ImportError> {
    let mut out = Vec::new();
    let Some(sec) = n.child(section) else { return Ok(out) };
    for v in sec.children_named("variable") {
        let name = v.attr("formalParameter").unwrap_or("").trim().to_string();
        if name.is_empty() {
            return Err(err(format!("a block pin in <{section}> without formalParameter")));
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
        let err = |message: String| ImportError::Element {
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
                    return Err(err("a contact without a variable".into()));
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
                    return Err(err("a coil without a variable".into()));
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
                    return Err(err("a block without typeName".into()));
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
                    return Err(err(format!("a <{}> without a name", n.name)));
                }
                if n.name == "connector" {
                    NetKind::Connector { name }
                } else {
                    NetKind::Continuation { name }
                }
            }
            "documentation" | "addData" => continue,
            other => {
                let id = if id.is_empty() { String::new() } else { format!(" localId {id}") };
                notes.push(ImportNote::on(
                    n,
                    format!(
                        "POU {pou}: <{other}>{id} is not an element the trainer runs; left out"
                    ),
                ));
                continue;
            }
        };
        if id.is_empty() && !matches!(kind, NetKind::Comment { .. }) {
            return Err(err(format!("<{}> without localId", n.name)));
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

/// Reads the elements of an LD or FBD body, with connectors and continuations resolved,
/// and the notes on elements left out.
pub(crate) fn read_elements(
    body: &Node,
    pou: &str,
) -> Result<(Vec<El>, Vec<ImportNote>), ImportError> {
    let (network, notes) = read_network(body, pou)?;
    let els = crate::network::logical(&network).map_err(|e| ImportError::Element {
        pou: pou.to_string(),
        local_id: e.element,
        message: e.message,
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
