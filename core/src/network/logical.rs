//! The logical view of a network: its elements with their wiring only, connectors and
//! continuations resolved (a wire from a continuation becomes the wires into the connector
//! of the same name), which both the rung grid layout and the lowering read.

use std::collections::HashMap;

use super::model::{NetElement, NetKind, PinModifier, Wire};
use super::NetError;
use crate::ladder::Element;

/// A wire end: the element it comes from and the output pin named, if any.
#[derive(Debug, Clone, PartialEq)]
pub struct Conn {
    /// The `localId` of the element.
    pub from: String,
    /// Its output pin, when it has several.
    pub param: Option<String>,
}

/// A block as written: its pins and what is wired to them.
#[derive(Debug, Clone)]
pub struct RawBlock {
    /// Its type.
    pub type_name: String,
    /// Its instance (function blocks).
    pub instance: Option<String>,
    /// `(formalParameter, wires)` of the input pins, in document order.
    pub inputs: Vec<(String, Vec<Conn>)>,
    /// `(formalParameter, wires)` of the in-out pins.
    pub in_outs: Vec<(String, Vec<Conn>)>,
    /// The input pins that are negated or edge-triggered, and how.
    pub modified: Vec<(String, PinModifier)>,
}

/// What an element is, for its logic.
#[derive(Debug, Clone)]
pub enum Kind {
    /// The left power rail.
    LeftRail,
    /// The right power rail.
    RightRail,
    /// A contact, coil, jump or return.
    Leaf(Element),
    /// A function or function block.
    Block(RawBlock),
    /// An `inVariable` or `inOutVariable`: a value for a block pin.
    InVar(String),
    /// An `outVariable`.
    OutVar(String),
    /// A comment.
    Comment(String),
    /// A label.
    Label(String),
}

/// An element of the logical view.
#[derive(Debug, Clone)]
pub struct El {
    /// Its `localId`.
    pub id: String,
    /// 1-based line and column of the element in the file it came from (0, 0: none).
    pub at: (u32, u32),
    /// Its position's x.
    pub x: f64,
    /// Its `executionOrderId` (0: none).
    pub order: u32,
    /// Its position's y.
    pub y: f64,
    /// What it is.
    pub kind: Kind,
    /// Wires into the element's inputs (power for leaves, rails and output variables;
    /// blocks keep theirs by pin).
    pub conns: Vec<Conn>,
}

fn conns(wires: &[Wire]) -> Vec<Conn> {
    wires.iter().map(|w| Conn { from: w.from.clone(), param: w.param.clone() }).collect()
}

/// The logical view of `elements`.
pub fn logical(elements: &[NetElement]) -> Result<Vec<El>, NetError> {
    let mut els = Vec::new();
    let mut connectors: HashMap<String, Vec<Conn>> = HashMap::new();
    // Continuations by localId: (name in upper case, name as written).
    let mut continuations: HashMap<String, (String, String)> = HashMap::new();
    for n in elements {
        let err = |said: crate::diagnostics::Said| NetError::new(n.id.clone(), said);
        let all_in: Vec<Conn> = n.inputs.iter().flat_map(|p| conns(&p.wires)).collect();
        let kind = match &n.kind {
            NetKind::LeftRail => Kind::LeftRail,
            NetKind::RightRail => Kind::RightRail,
            NetKind::Contact { operand, contact } => {
                Kind::Leaf(Element::Contact { kind: *contact, operand: operand.clone() })
            }
            NetKind::Coil { operand, coil } => {
                Kind::Leaf(Element::Coil { kind: *coil, operand: operand.clone() })
            }
            NetKind::Block { type_name, instance } => {
                let pins = |in_out: bool| {
                    n.inputs
                        .iter()
                        .filter(|p| p.in_out == in_out)
                        .map(|p| (p.name.clone(), conns(&p.wires)))
                        .collect()
                };
                Kind::Block(RawBlock {
                    type_name: type_name.clone(),
                    instance: instance.clone(),
                    inputs: pins(false),
                    in_outs: pins(true),
                    modified: n
                        .inputs
                        .iter()
                        .filter_map(|p| Some((p.name.clone(), p.modifier?)))
                        .collect(),
                })
            }
            NetKind::InVar { expr } | NetKind::InOutVar { expr } => Kind::InVar(expr.clone()),
            NetKind::OutVar { expr } => Kind::OutVar(expr.clone()),
            NetKind::Comment { text } => Kind::Comment(text.clone()),
            NetKind::Label { label } => Kind::Label(label.clone()),
            NetKind::Jump { label } => Kind::Leaf(Element::Jump { label: label.clone() }),
            NetKind::Return => Kind::Leaf(Element::Return),
            NetKind::Connector { name } => {
                if connectors.insert(name.to_ascii_uppercase(), all_in).is_some() {
                    return Err(err(crate::msg!(NetTwoConnectors, name = name)));
                }
                continue;
            }
            NetKind::Continuation { name } => {
                continuations.insert(n.id.clone(), (name.to_ascii_uppercase(), name.clone()));
                continue;
            }
            // The chart of an SFC body is read by `chart`; its network is what is left.
            NetKind::Step { .. }
            | NetKind::Transition { .. }
            | NetKind::SelectionDivergence
            | NetKind::SelectionConvergence
            | NetKind::SimultaneousDivergence
            | NetKind::SimultaneousConvergence
            | NetKind::JumpStep { .. }
            | NetKind::ActionBlock { .. } => continue,
        };
        let conns = if matches!(kind, Kind::Block(_)) { Vec::new() } else { all_in };
        els.push(El { id: n.id.clone(), at: n.at, x: n.x, order: n.order, y: n.y, kind, conns });
    }
    if !continuations.is_empty() {
        let resolve = |list: &mut Vec<Conn>, at: &str| -> Result<(), NetError> {
            resolve_continuations(list, &connectors, &continuations)
                .map_err(|said| NetError::new(at.to_string(), said))
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
) -> Result<(), crate::diagnostics::Said> {
    for _ in 0..64 {
        if !list.iter().any(|c| continuations.contains_key(&c.from)) {
            return Ok(());
        }
        let mut next = Vec::new();
        for c in list.drain(..) {
            match continuations.get(&c.from) {
                Some((key, name)) => match connectors.get(key) {
                    Some(src) => next.extend(src.iter().cloned()),
                    None => return Err(crate::msg!(NetNoConnector, name = name, id = &c.from)),
                },
                None => next.push(c),
            }
        }
        *list = next;
    }
    Err(crate::msg!(NetConnectorLoop))
}
