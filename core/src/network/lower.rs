//! Networks → ST statements, by the rules the tools that draw them use (SEMANTICS
//! "imported LD/FBD networks"): every function block instance, output variable and coil is
//! a statement, run in `executionOrderId` order when each has its own, else in the order of
//! the data flow (a statement after the instances it reads; ties and feedback loops broken
//! top to bottom, left to right, so a feedback wire reads the previous scan's value). A
//! function is written inline where its output is used, so its result needs no variable of
//! its own; power flows through contacts as AND, meets as OR, and passes through coils.

use std::collections::{BTreeSet, HashMap};

use super::logical::{Conn, El, Kind, RawBlock};
use super::model::PinModifier;
use super::NetError;
use crate::ladder::{CoilKind, ContactKind, Element};

/// A network lowered: its statements and the instances they use.
#[derive(Debug, Clone, PartialEq)]
pub struct Lowered {
    /// ST statements, one per line, each with the index (in the logical view) of the
    /// element it was written from.
    pub statements: Vec<(String, usize)>,
    /// `(instance, type)` of every function block instance (and edge detector) used.
    pub instances: Vec<(String, String)>,
    /// What was left out (an output variable with no wire), by element index, as data to
    /// be shown in any language.
    pub notes: Vec<(usize, crate::diagnostics::Said)>,
}

/// Lowers the logical view `els` of a network of POU `pou` to statements: function block calls, output
/// variable assignments and, for LD, coils (each written from the power at its left) and
/// the edge detectors of edge contacts.
pub fn lower(els: &[El], pou: &str) -> Result<Lowered, NetError> {
    let lower = Lower::new(els);
    let statements: Vec<usize> =
        els.iter().enumerate().filter(|(_, e)| is_statement(&e.kind)).map(|(i, _)| i).collect();
    let mut deps: HashMap<usize, BTreeSet<usize>> = HashMap::new();
    for &s in &statements {
        let mut found = BTreeSet::new();
        lower.instances_read(s, &mut found, &mut BTreeSet::new())?;
        found.remove(&s);
        deps.insert(s, found);
    }
    let order = run_order(els, &statements, &deps);
    let mut text = Vec::new();
    let mut instances = Vec::new();
    let mut notes = Vec::new();
    for s in order {
        let at = s;
        match &els[s].kind {
            Kind::OutVar(target) => {
                if els[s].conns.is_empty() {
                    notes.push((
                        s,
                        crate::msg!(
                            NetOutputNotWired,
                            pou = pou,
                            id = &els[s].id,
                            variable = target
                        ),
                    ));
                    continue;
                }
                let value = lower.joined(&els[s].conns)?;
                let assign = format!("{target} := {value};");
                let line = match lower.function_enable(&els[s].conns)? {
                    Some(en) => format!("IF {en} THEN {assign} END_IF;\n"),
                    None => format!("{assign}\n"),
                };
                text.push((line, at));
            }
            Kind::Block(b) => {
                let Some(inst) = &b.instance else { continue };
                let mut args = Vec::new();
                let mut edges = String::new();
                let mut enable = None;
                for (pin, conns) in b.inputs.iter().chain(&b.in_outs) {
                    if conns.is_empty() {
                        continue;
                    }
                    let mut v = lower.joined(conns)?;
                    match modifier(b, pin) {
                        Some(PinModifier::Negated) => v = format!("NOT ({v})"),
                        Some(edge) => {
                            let name = format!("{}{pin}", edge_name(&els[s].id));
                            let ty = if edge == PinModifier::Rising { "R_TRIG" } else { "F_TRIG" };
                            instances.push((name.clone(), ty.to_string()));
                            edges.push_str(&format!("{name}(CLK := {v}); "));
                            v = format!("{name}.Q");
                        }
                        None => {}
                    }
                    if pin.eq_ignore_ascii_case("EN") {
                        enable = Some(v).filter(|e| e != "TRUE");
                    } else {
                        args.push(format!("{pin} := {v}"));
                    }
                }
                let call = format!("{edges}{inst}({});", args.join(", "));
                let line = match enable {
                    Some(en) => format!("IF {en} THEN {call} END_IF;\n"),
                    None => format!("{call}\n"),
                };
                text.push((line, at));
                instances.push((inst.clone(), b.type_name.clone()));
            }
            Kind::Leaf(Element::Coil { kind, operand }) => {
                let power = lower.power_in(s)?;
                let line = match kind {
                    CoilKind::Normal => format!("{operand} := {power};\n"),
                    CoilKind::Negated => format!("{operand} := NOT ({power});\n"),
                    CoilKind::Set => format!("IF {power} THEN {operand} := TRUE; END_IF;\n"),
                    CoilKind::Reset => format!("IF {power} THEN {operand} := FALSE; END_IF;\n"),
                    CoilKind::Rising | CoilKind::Falling => {
                        let (edge, ty) = edge_instance(&els[s]);
                        instances.push((edge.clone(), ty.to_string()));
                        format!("{edge}(CLK := {power}); {operand} := {edge}.Q;\n")
                    }
                };
                text.push((line, at));
            }
            Kind::Leaf(Element::Contact { operand, .. }) => {
                let (edge, ty) = edge_instance(&els[s]);
                instances.push((edge.clone(), ty.to_string()));
                text.push((format!("{edge}(CLK := {});\n", operand.trim()), at));
            }
            Kind::Leaf(Element::Jump { .. } | Element::Return) => {
                return Err(lower.err(s, crate::msg!(NetJumpOutsideGrid)))
            }
            _ => {}
        }
    }
    Ok(Lowered { statements: text, instances, notes })
}

/// How input `pin` of block `b` changes what is wired to it.
fn modifier(b: &RawBlock, pin: &str) -> Option<PinModifier> {
    b.modified.iter().find(|(p, _)| p.eq_ignore_ascii_case(pin)).map(|(_, m)| *m)
}

/// Whether an element is a statement of its network: a function block instance, an output
/// variable, a coil, an edge contact (its edge detector), a jump or a return.
fn is_statement(kind: &Kind) -> bool {
    match kind {
        Kind::OutVar(_) => true,
        Kind::Block(b) => b.instance.is_some(),
        Kind::Leaf(Element::Contact { kind, .. }) => {
            matches!(kind, ContactKind::Rising | ContactKind::Falling)
        }
        Kind::Leaf(_) => true,
        _ => false,
    }
}

/// The edge detector of an edge contact or coil: its instance name and type.
fn edge_instance(el: &El) -> (String, &'static str) {
    let falling = matches!(
        el.kind,
        Kind::Leaf(
            Element::Contact { kind: ContactKind::Falling, .. }
                | Element::Coil { kind: CoilKind::Falling, .. }
        )
    );
    (edge_name(&el.id), if falling { "F_TRIG" } else { "R_TRIG" })
}

/// The name of the edge detector of the edge contact or coil `id` (a hidden instance).
pub fn edge_name(id: &str) -> String {
    let id: String = id.chars().filter(char::is_ascii_alphanumeric).collect();
    format!("{EDGE_PREFIX}{id}")
}

/// The prefix of the hidden edge detectors' names.
pub const EDGE_PREFIX: &str = "LdEdge";

/// Whether `name` is a hidden variable of a lowered network (an edge detector).
pub fn is_hidden_name(name: &str) -> bool {
    name.len() > EDGE_PREFIX.len()
        && name.is_char_boundary(EDGE_PREFIX.len())
        && name[..EDGE_PREFIX.len()].eq_ignore_ascii_case(EDGE_PREFIX)
}

/// The instance name of a function block element.
fn instance_of(kind: &Kind) -> Option<&str> {
    match kind {
        Kind::Block(RawBlock { instance: Some(i), .. }) => Some(i),
        _ => None,
    }
}

/// The values wires carry in a network, as ST expressions.
pub struct Lower<'a> {
    els: &'a [El],
    index: HashMap<&'a str, usize>,
}

impl<'a> Lower<'a> {
    /// The logical view `els` of a network.
    pub fn new(els: &'a [El]) -> Self {
        let index = els.iter().enumerate().map(|(i, e)| (e.id.as_str(), i)).collect();
        Lower { els, index }
    }

    /// The ST expression of the wires `conns` into one pin from outside the network (an
    /// SFC transition's condition): their OR when several meet there (power flow joining).
    pub fn joined(&self, conns: &[Conn]) -> Result<String, NetError> {
        let parts =
            conns.iter().map(|c| self.value(c, &mut Vec::new())).collect::<Result<Vec<_>, _>>()?;
        Ok(match parts.as_slice() {
            [one] => one.clone(),
            _ => format!("({})", parts.join(" OR ")),
        })
    }

    fn err(&self, i: usize, said: crate::diagnostics::Said) -> NetError {
        NetError::new(self.els.get(i).map_or_else(|| "?".to_string(), |e| e.id.clone()), said)
    }

    fn source(&self, conn: &Conn, from: usize) -> Result<usize, NetError> {
        self.index
            .get(conn.from.as_str())
            .copied()
            .ok_or_else(|| self.err(from, crate::msg!(NetWireFromMissing, id = &conn.from)))
    }

    /// The ST expression a wire carries. `path` holds the functions and contacts being
    /// written (a loop of them alone has no value).
    fn value(&self, conn: &Conn, path: &mut Vec<usize>) -> Result<String, NetError> {
        let at = *path.last().unwrap_or(&usize::MAX);
        let i = self.source(conn, at)?;
        match &self.els[i].kind {
            Kind::InVar(expr) => Ok(operand(expr)),
            Kind::LeftRail => Ok("TRUE".into()),
            Kind::Leaf(element) => self.power_through(i, element, path),
            Kind::Block(b)
                if conn.param.as_deref().is_some_and(|p| p.eq_ignore_ascii_case("ENO")) =>
            {
                if path.contains(&i) {
                    return Err(self.err(i, crate::msg!(NetEnoToOwnEn)));
                }
                path.push(i);
                let en = self.enable_in(b, path);
                path.pop();
                Ok(en?.unwrap_or_else(|| "TRUE".into()))
            }
            Kind::Block(b) => match &b.instance {
                Some(inst) => match &conn.param {
                    Some(p) => Ok(format!("{inst}.{p}")),
                    None => Err(self.err(i, crate::msg!(NetWireNamesNoOutput, name = inst))),
                },
                None => {
                    if path.contains(&i) {
                        return Err(self.err(i, crate::msg!(NetFunctionLoop)));
                    }
                    if path.len() > crate::limits::MAX_EXPR_HEIGHT {
                        return Err(self
                            .err(i, crate::msg!(NetTooDeep, n = crate::limits::MAX_EXPR_HEIGHT)));
                    }
                    path.push(i);
                    let mut args = Vec::new();
                    let mut pins = Vec::new();
                    for (pin, conns) in b.inputs.iter().chain(&b.in_outs) {
                        if pin.eq_ignore_ascii_case("EN") {
                            continue;
                        }
                        pins.push(pin.as_str());
                        let negated = match modifier(b, pin) {
                            None => false,
                            Some(PinModifier::Negated) => true,
                            Some(_) => {
                                return Err(
                                    self.err(i, crate::msg!(NetEdgeOnFunctionInput, pin = pin))
                                )
                            }
                        };
                        let at = args.len();
                        match conns.as_slice() {
                            [c] => args.push(self.value(c, path)?),
                            [] => {
                                return Err(self.err(
                                    i,
                                    crate::msg!(NetInputNotWired, pin = pin, ty = &b.type_name),
                                ))
                            }
                            several => {
                                let parts = several
                                    .iter()
                                    .map(|c| self.value(c, path))
                                    .collect::<Result<Vec<_>, _>>()?;
                                args.push(format!("({})", parts.join(" OR ")));
                            }
                        }
                        if negated {
                            args[at] = format!("NOT ({})", args[at]);
                        }
                    }
                    // A wired EN: the function runs only when it is TRUE and gives its
                    // type's initial value otherwise (as matiec runs OpenPLC's networks).
                    let enable = self.enable_in(b, path);
                    path.pop();
                    let text = match enable? {
                        Some(en) => {
                            let formal = pins.iter().zip(&args).map(|(p, a)| format!("{p} := {a}"));
                            let list: Vec<String> =
                                std::iter::once(format!("EN := {en}")).chain(formal).collect();
                            format!("{}({})", b.type_name, list.join(", "))
                        }
                        None => format!("{}({})", b.type_name, args.join(", ")),
                    };
                    if text.len() > crate::limits::MAX_PROJECT_BYTES {
                        return Err(self.err(i, crate::msg!(NetTooLargeFanout)));
                    }
                    Ok(text)
                }
            },
            _ => Err(self.err(i, crate::msg!(NetNoValue))),
        }
    }

    /// The power out of a contact or coil `i` (a coil passes on the power at its left).
    fn power_through(
        &self,
        i: usize,
        element: &crate::ladder::Element,
        path: &mut Vec<usize>,
    ) -> Result<String, NetError> {
        if path.contains(&i) {
            return Err(self.err(i, crate::msg!(NetContactLoop)));
        }
        if path.len() > crate::limits::MAX_EXPR_HEIGHT {
            return Err(self.err(i, crate::msg!(NetTooManyContacts)));
        }
        path.push(i);
        let power = self.power_along(i, path);
        path.pop();
        let power = power?;
        let term = match element {
            Element::Contact { kind: ContactKind::NormallyOpen, operand: o } => operand(o),
            Element::Contact { kind: ContactKind::NormallyClosed, operand: o } => {
                format!("NOT {}", operand(o))
            }
            Element::Contact { .. } => format!("{}.Q", edge_instance(&self.els[i]).0),
            Element::Coil { .. } => return Ok(power),
            _ => return Err(self.err(i, crate::msg!(NetNoValue))),
        };
        let text = if power == "TRUE" { term } else { format!("{power} AND {term}") };
        if text.len() > crate::limits::MAX_PROJECT_BYTES {
            return Err(self.err(i, crate::msg!(NetTooLarge)));
        }
        Ok(text)
    }

    /// The power at the left of contact or coil `i`: the OR of the wires that meet there
    /// (FALSE when none does).
    fn power_along(&self, i: usize, path: &mut Vec<usize>) -> Result<String, NetError> {
        let ins = &self.els[i].conns;
        match ins.as_slice() {
            // Nothing at its left: an open circuit, never powered.
            [] => Ok("FALSE".into()),
            [c] => self.value(c, path),
            _ => ins
                .iter()
                .map(|c| self.value(c, path))
                .collect::<Result<Vec<_>, _>>()
                .map(|p| format!("({})", p.join(" OR "))),
        }
    }

    /// The power at the left of coil `i`.
    fn power_in(&self, i: usize) -> Result<String, NetError> {
        self.power_along(i, &mut vec![i])
    }

    /// When the wires `conns` come from one function (no instance) whose EN is wired, the
    /// value of that EN: the function writes its output only when it is TRUE.
    fn function_enable(&self, conns: &[Conn]) -> Result<Option<String>, NetError> {
        let [conn] = conns else { return Ok(None) };
        let i = self.source(conn, usize::MAX)?;
        let Kind::Block(b) = &self.els[i].kind else { return Ok(None) };
        if b.instance.is_some()
            || conn.param.as_deref().is_some_and(|p| p.eq_ignore_ascii_case("ENO"))
        {
            return Ok(None);
        }
        self.enable_of(b)
    }

    /// The value of block `b`'s EN input when it is wired (and not plainly TRUE).
    fn enable_of(&self, b: &RawBlock) -> Result<Option<String>, NetError> {
        self.enable_in(b, &mut Vec::new())
    }

    /// [`Self::enable_of`] while the elements of `path` are being written (a loop through
    /// them has no value).
    fn enable_in(&self, b: &RawBlock, path: &mut Vec<usize>) -> Result<Option<String>, NetError> {
        let en = b.inputs.iter().find(|(pin, _)| pin.eq_ignore_ascii_case("EN"));
        match en {
            Some((_, conns)) if !conns.is_empty() => {
                let parts =
                    conns.iter().map(|c| self.value(c, path)).collect::<Result<Vec<_>, _>>()?;
                let v = match parts.as_slice() {
                    [one] => one.clone(),
                    _ => format!("({})", parts.join(" OR ")),
                };
                let v = match modifier(b, "EN") {
                    Some(PinModifier::Negated) => format!("NOT ({v})"),
                    _ => v,
                };
                Ok(Some(v).filter(|e| e != "TRUE"))
            }
            _ => Ok(None),
        }
    }

    /// The function block instances (by element) whose outputs statement `s` reads.
    fn instances_read(
        &self,
        s: usize,
        found: &mut BTreeSet<usize>,
        seen: &mut BTreeSet<usize>,
    ) -> Result<(), NetError> {
        // A worklist, not recursion: a long chain of functions must not exhaust the stack.
        let mut todo = vec![s];
        while let Some(at) = todo.pop() {
            let conns: Vec<&Conn> = match &self.els[at].kind {
                Kind::Block(b) => b.inputs.iter().chain(&b.in_outs).flat_map(|(_, c)| c).collect(),
                _ => self.els[at].conns.iter().collect(),
            };
            for c in conns {
                let i = self.source(c, at)?;
                let kind = &self.els[i].kind;
                if is_statement(kind) && !matches!(kind, Kind::Leaf(Element::Coil { .. })) {
                    found.insert(i);
                }
                if instance_of(kind).is_none()
                    && matches!(kind, Kind::Block(_) | Kind::Leaf(_))
                    && seen.insert(i)
                {
                    if seen.len() > crate::limits::MAX_EXPR_HEIGHT * 100 {
                        return Err(self.err(i, crate::msg!(NetTooManyFunctions)));
                    }
                    todo.push(i);
                }
            }
        }
        Ok(())
    }
}

/// A variable or constant as an operand: parenthesised unless it is one word.
fn operand(expr: &str) -> String {
    let e = expr.trim();
    if e.chars().all(|c| c.is_alphanumeric() || "_.#[]%".contains(c)) {
        e.to_string()
    } else {
        format!("({e})")
    }
}

/// The statements in run order: by `executionOrderId` when every statement has its own,
/// else each after the instances it reads, ties (and loops) taken top to bottom, left to
/// right.
fn run_order(
    els: &[El],
    statements: &[usize],
    deps: &HashMap<usize, BTreeSet<usize>>,
) -> Vec<usize> {
    let by_place = |a: &usize, b: &usize| {
        let (ea, eb) = (&els[*a], &els[*b]);
        ea.y.total_cmp(&eb.y).then(ea.x.total_cmp(&eb.x)).then(a.cmp(b))
    };
    let orders: BTreeSet<u32> = statements.iter().map(|&s| els[s].order).collect();
    if orders.len() == statements.len() && !orders.contains(&0) {
        let mut v = statements.to_vec();
        crate::order::sort_by_key(&mut v, |&s| els[s].order);
        return v;
    }
    let mut left: Vec<usize> = statements.to_vec();
    crate::order::sort_by(&mut left, by_place);
    let mut done: BTreeSet<usize> = BTreeSet::new();
    let mut out = Vec::new();
    while !left.is_empty() {
        let ready = left
            .iter()
            .position(|s| {
                deps.get(s).is_none_or(|d| d.iter().all(|x| done.contains(x) || !left.contains(x)))
            })
            .unwrap_or(0);
        let s = left.remove(ready);
        done.insert(s);
        out.push(s);
    }
    out
}
