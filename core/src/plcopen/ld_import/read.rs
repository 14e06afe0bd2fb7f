//! LD body XML → a flat list of elements with their `refLocalId` wiring. Connector /
//! continuation pairs are resolved here: a wire from a continuation becomes the wires into
//! the connector of the same name, so later stages never see them.

use std::collections::HashMap;

use super::super::xml::Node;
use super::super::ImportError;
use crate::ladder::{CoilKind, ContactKind, Element};

/// A wire end: the element it comes from and the output pin named, if any.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Conn {
    pub from: String,
    pub param: Option<String>,
}

/// A block as written: its pins and what is wired to them.
#[derive(Debug, Clone)]
pub(crate) struct RawBlock {
    pub type_name: String,
    pub instance: Option<String>,
    /// `(formalParameter, wires)` of the input pins, in document order.
    pub inputs: Vec<(String, Vec<Conn>)>,
    /// `(formalParameter, wires)` of the in-out pins.
    pub in_outs: Vec<(String, Vec<Conn>)>,
    /// The input pins that are negated or edge-triggered, and how.
    pub modified: Vec<(String, PinModifier)>,
}

/// How an input pin changes the value wired to it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum PinModifier {
    /// `negated="true"`: the pin reads NOT the value.
    Negated,
    /// `edge="rising"`: the pin reads the value's rising edge.
    Rising,
    /// `edge="falling"`: the pin reads its falling edge.
    Falling,
}

#[derive(Debug, Clone)]
pub(crate) enum Kind {
    LeftRail,
    RightRail,
    /// A contact, coil, jump or return.
    Leaf(Element),
    Block(RawBlock),
    /// An `inVariable` or `inOutVariable`: a value for a block pin.
    InVar(String),
    OutVar(String),
    Comment(String),
    Label(String),
}

#[derive(Debug, Clone)]
pub(crate) struct El {
    pub id: String,
    /// 1-based line and column of the element in the file.
    pub at: (u32, u32),
    /// Its `position`'s x.
    pub x: f64,
    /// Its `executionOrderId` (0: none).
    pub order: u32,
    pub y: f64,
    pub kind: Kind,
    /// Wires into the element's `connectionPointIn`s (power for leaves, rails and
    /// outVariables).
    pub conns: Vec<Conn>,
}

/// The wires into a `connectionPointIn`.
pub(crate) fn conns_of(point: &Node) -> Vec<Conn> {
    point
        .children_named("connection")
        .filter_map(|c| {
            Some(Conn {
                from: c.attr("refLocalId")?.trim().to_string(),
                param: c.attr("formalParameter").filter(|p| !p.is_empty()).map(str::to_string),
            })
        })
        .collect()
}

fn all_conns_in(n: &Node) -> Vec<Conn> {
    n.children_named("connectionPointIn").flat_map(conns_of).collect()
}

fn y_of(n: &Node) -> f64 {
    n.child("position").and_then(|p| p.attr("y")).and_then(|y| y.trim().parse().ok()).unwrap_or(0.0)
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

/// The pins of `section` with their wires; the negated or edge-triggered ones are added to
/// `modified`.
fn pin_list(
    n: &Node,
    type_name: &str,
    section: &str,
    modified: &mut Vec<(String, PinModifier)>,
    err: &dyn Fn(String) -> ImportError,
) -> Result<Vec<(String, Vec<Conn>)>, ImportError> {
    let mut out = Vec::new();
    let Some(sec) = n.child(section) else { return Ok(out) };
    for v in sec.children_named("variable") {
        let p = v.attr("formalParameter").unwrap_or("").trim().to_string();
        if p.is_empty() {
            return Err(err(format!("a block pin in <{section}> without formalParameter")));
        }
        let edge = v.attr("edge").unwrap_or("none");
        let redundant = edge_is_redundant(type_name, &p, edge);
        let modifier = match (v.attr("negated") == Some("true"), edge) {
            (true, _) => Some(PinModifier::Negated),
            (false, "rising") if !redundant => Some(PinModifier::Rising),
            (false, "falling") => Some(PinModifier::Falling),
            _ => None,
        };
        if let Some(m) = modifier {
            modified.push((p.clone(), m));
        }
        out.push((p, v.child("connectionPointIn").map(conns_of).unwrap_or_default()));
    }
    Ok(out)
}

/// Reads the elements of an LD body, with connectors and continuations resolved.
pub(crate) fn read_elements(ld: &Node, pou: &str) -> Result<Vec<El>, ImportError> {
    let mut els = Vec::new();
    let mut connectors: HashMap<String, Vec<Conn>> = HashMap::new();
    // Continuations by localId: (name in upper case, name as written).
    let mut continuations: HashMap<String, (String, String)> = HashMap::new();
    for n in &ld.children {
        let id = n.attr("localId").unwrap_or("").trim().to_string();
        let err = |message: String| ImportError::Element {
            pou: pou.to_string(),
            local_id: if id.is_empty() { "?".into() } else { id.clone() },
            message,
        };
        let kind = match n.name.as_str() {
            "leftPowerRail" => Kind::LeftRail,
            "rightPowerRail" => Kind::RightRail,
            "contact" => {
                let operand = text_of(n, "variable");
                if operand.is_empty() {
                    return Err(err("a contact without a variable".into()));
                }
                let kind = match (n.attr("edge"), n.attr("negated") == Some("true")) {
                    (Some("rising"), _) => ContactKind::Rising,
                    (Some("falling"), _) => ContactKind::Falling,
                    (_, true) => ContactKind::NormallyClosed,
                    _ => ContactKind::NormallyOpen,
                };
                Kind::Leaf(Element::Contact { kind, operand })
            }
            "coil" => {
                let operand = text_of(n, "variable");
                if operand.is_empty() {
                    return Err(err("a coil without a variable".into()));
                }
                let kind = match (n.attr("storage"), n.attr("edge"), n.attr("negated")) {
                    (Some("set"), _, _) => CoilKind::Set,
                    (Some("reset"), _, _) => CoilKind::Reset,
                    (_, Some("rising"), _) => CoilKind::Rising,
                    (_, Some("falling"), _) => CoilKind::Falling,
                    (_, _, Some("true")) => CoilKind::Negated,
                    _ => CoilKind::Normal,
                };
                Kind::Leaf(Element::Coil { kind, operand })
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
                let mut modified = Vec::new();
                Kind::Block(RawBlock {
                    inputs: pin_list(n, &type_name, "inputVariables", &mut modified, &err)?,
                    in_outs: pin_list(n, &type_name, "inOutVariables", &mut modified, &err)?,
                    type_name,
                    instance,
                    modified,
                })
            }
            "inVariable" | "inOutVariable" => Kind::InVar(text_of(n, "expression")),
            "outVariable" => Kind::OutVar(text_of(n, "expression")),
            "comment" => Kind::Comment(n.child("content").map(comment_text).unwrap_or_default()),
            "label" => Kind::Label(n.attr("label").unwrap_or("").to_string()),
            "jump" => {
                Kind::Leaf(Element::Jump { label: n.attr("label").unwrap_or("").to_string() })
            }
            "return" => Kind::Leaf(Element::Return),
            "connector" | "continuation" => {
                let spelled = n.attr("name").unwrap_or("").trim().to_string();
                let name = spelled.to_ascii_uppercase();
                if name.is_empty() {
                    return Err(err(format!("a <{}> without a name", n.name)));
                }
                if n.name == "connector" {
                    if connectors.insert(name.clone(), all_conns_in(n)).is_some() {
                        return Err(err(format!("two connectors are named {spelled}")));
                    }
                } else if id.is_empty() {
                    return Err(err("a <continuation> without localId".into()));
                } else {
                    continuations.insert(id.clone(), (name, spelled));
                }
                continue;
            }
            "documentation" | "addData" => continue,
            other => {
                return Err(err(format!("<{other}> elements are not supported in LD bodies yet")))
            }
        };
        if id.is_empty() && !matches!(kind, Kind::Comment(_)) {
            return Err(err(format!("<{}> without localId", n.name)));
        }
        let conns = if matches!(kind, Kind::Block(_)) { Vec::new() } else { all_conns_in(n) };
        let x = n.child("position").and_then(|p| p.attr("x")).and_then(|x| x.trim().parse().ok());
        let order = n.attr("executionOrderId").and_then(|o| o.trim().parse().ok()).unwrap_or(0);
        els.push(El {
            id,
            at: (n.line, n.column),
            x: x.unwrap_or(0.0),
            order,
            y: y_of(n),
            kind,
            conns,
        });
    }
    if !continuations.is_empty() {
        let resolve = |list: &mut Vec<Conn>, at: &str| -> Result<(), ImportError> {
            resolve_continuations(list, &connectors, &continuations).map_err(|message| {
                ImportError::Element { pou: pou.to_string(), local_id: at.to_string(), message }
            })
        };
        for e in &mut els {
            resolve(&mut e.conns, &e.id)?;
            if let Kind::Block(b) = &mut e.kind {
                for (_, list) in b.inputs.iter_mut().chain(b.in_outs.iter_mut()) {
                    resolve(list, &e.id)?;
                }
            }
        }
    }
    Ok(els)
}

/// Replaces wires from continuations by the wires into their connectors.
fn resolve_continuations(
    list: &mut Vec<Conn>,
    connectors: &HashMap<String, Vec<Conn>>,
    continuations: &HashMap<String, (String, String)>,
) -> Result<(), String> {
    for _ in 0..64 {
        if !list.iter().any(|c| continuations.contains_key(&c.from)) {
            return Ok(());
        }
        let mut next = Vec::new();
        for c in list.drain(..) {
            match continuations.get(&c.from) {
                Some((key, name)) => match connectors.get(key) {
                    Some(src) => next.extend(src.iter().cloned()),
                    None => {
                        return Err(format!(
                            "continuation {name} (localId {}) has no connector of that name",
                            c.from
                        ))
                    }
                },
                None => next.push(c),
            }
        }
        *list = next;
    }
    Err("connectors and continuations form a loop".into())
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
