//! The values on a network's wires while its POU runs, for the view that draws it: read
//! from the variables the lowered program keeps (operands, instance outputs, the edge
//! detectors of edge contacts) and carried through contacts and coils by power flow. A
//! function's output has no variable of its own (it is written inline): the view works out
//! the BOOL ones (AND, OR, XOR, NOT, MOVE) from their inputs and `ENO` from `EN`, and asks
//! for the others by their ST expression, which the simulator watches
//! ([`function_watches`]). An SFC step's outputs carry whether it is active.

use std::collections::{HashMap, HashSet};

use super::model::{NetElement, NetKind, NetworkPou, Wire};
use crate::ladder::{CoilKind, ContactKind};
use crate::vm::Value;

/// The value at each output pin of the network's elements, keyed by (`localId`, pin name;
/// empty for the one output of an element that is not a block, and for the value an output
/// variable is written). `read` gives a variable's
/// value by its path (`Start`, `T1.Q`), or `None`.
pub fn output_values(
    pou: &NetworkPou,
    read: &dyn Fn(&str) -> Option<Value>,
) -> HashMap<(String, String), Value> {
    let mut eval = Eval {
        by_id: pou.elements.iter().map(|e| (e.id.as_str(), e)).collect(),
        pou,
        read,
        memo: HashMap::new(),
        visiting: HashSet::new(),
        watches: function_watches(pou)
            .into_iter()
            .map(|((id, pin), text)| ((id, pin.to_ascii_uppercase()), text))
            .collect(),
    };
    let mut out = HashMap::new();
    for e in &pou.elements {
        for pin in &e.outputs {
            if let Some(v) = eval.output(e, &pin.name) {
                out.insert((e.id.clone(), pin.name.clone()), v);
            }
        }
        // An output variable shows what it is written: the wire's value, else its own.
        if let NetKind::OutVar { expr } = &e.kind {
            let wires: Vec<&Wire> = e.inputs.iter().flat_map(|p| p.wires.iter()).collect();
            let v = match wires.as_slice() {
                [w] => eval.wire(w),
                _ => None,
            };
            if let Some(v) = v.or_else(|| read(expr.trim())) {
                out.insert((e.id.clone(), String::new()), v);
            }
        }
    }
    out
}

/// The ST expression of each function output of the network (`(localId, pin)` → `ADD(N,
/// 5)`), for a simulator watch ([`crate::sim::Simulator::add_watch`]): the outputs of
/// built-in functions fed by variables, instances, contacts and other built-ins only (a
/// FUNCTION of the project may write globals, so it is never evaluated twice). `read` in
/// [`output_values`] is asked for these texts too.
pub fn function_watches(pou: &NetworkPou) -> Vec<((String, String), String)> {
    let Ok(els) = super::logical(&pou.elements) else { return Vec::new() };
    let lower = super::lower::Lower::new(&els);
    let by_id: HashMap<&str, &NetElement> =
        pou.elements.iter().map(|e| (e.id.as_str(), e)).collect();
    let mut out = Vec::new();
    for e in &pou.elements {
        let NetKind::Block { instance: None, .. } = &e.kind else { continue };
        if !built_in_all_the_way(e, &by_id, &mut HashSet::new()) {
            continue;
        }
        for pin in e.outputs.iter().filter(|p| !p.name.eq_ignore_ascii_case("ENO")) {
            let conn = super::logical::Conn { from: e.id.clone(), param: Some(pin.name.clone()) };
            if let Ok(text) = lower.joined(&[conn]) {
                out.push(((e.id.clone(), pin.name.clone()), text));
            }
        }
    }
    out
}

/// Whether function `e` and every function wired into it are built-ins.
fn built_in_all_the_way<'a>(
    e: &'a NetElement,
    by_id: &HashMap<&str, &'a NetElement>,
    seen: &mut HashSet<&'a str>,
) -> bool {
    let NetKind::Block { type_name, instance: None } = &e.kind else { return true };
    if !seen.insert(e.id.as_str()) {
        return true;
    }
    if seen.len() > 2 * crate::limits::MAX_EXPR_HEIGHT
        || !crate::semantic::is_builtin(&type_name.trim().to_ascii_uppercase())
    {
        return false;
    }
    e.inputs.iter().flat_map(|p| &p.wires).all(|w| {
        by_id.get(w.from.as_str()).is_none_or(|src| built_in_all_the_way(src, by_id, seen))
    })
}

/// The value a wire carries, from [`output_values`].
pub fn wire_value<'a>(
    values: &'a HashMap<(String, String), Value>,
    wire: &Wire,
) -> Option<&'a Value> {
    let pin = wire.param.clone().unwrap_or_default();
    values.get(&(wire.from.clone(), pin.clone())).or_else(|| {
        // A wire from an element with one output may name its pin or not.
        (!pin.is_empty()).then(|| values.get(&(wire.from.clone(), String::new()))).flatten()
    })
}

struct Eval<'a> {
    by_id: HashMap<&'a str, &'a NetElement>,
    pou: &'a NetworkPou,
    read: &'a dyn Fn(&str) -> Option<Value>,
    memo: HashMap<(String, String), Option<Value>>,
    visiting: HashSet<(String, String)>,
    /// [`function_watches`], pins in upper case.
    watches: HashMap<(String, String), String>,
}

impl<'a> Eval<'a> {
    fn output(&mut self, e: &'a NetElement, pin: &str) -> Option<Value> {
        let key = (e.id.clone(), pin.to_ascii_uppercase());
        if let Some(v) = self.memo.get(&key) {
            return v.clone();
        }
        // A loop has no value; nor has a chain longer than any network that runs (the
        // lowering refuses those), so the view never recurses deeper than that.
        if self.visiting.len() > 2 * crate::limits::MAX_EXPR_HEIGHT
            || !self.visiting.insert(key.clone())
        {
            return None;
        }
        let v = self.compute(e, pin);
        self.visiting.remove(&key);
        self.memo.insert(key, v.clone());
        v
    }

    fn compute(&mut self, e: &'a NetElement, pin: &str) -> Option<Value> {
        let read = self.read;
        match &e.kind {
            NetKind::LeftRail => Some(Value::Bool(true)),
            NetKind::Contact { operand, contact } => {
                let power = self.power_in(e)?;
                let term = match contact {
                    ContactKind::NormallyOpen => truth(read(operand.trim())?)?,
                    ContactKind::NormallyClosed => !truth(read(operand.trim())?)?,
                    ContactKind::Rising | ContactKind::Falling => {
                        truth(read(&format!("{}.Q", super::lower::edge_name(&e.id)))?)?
                    }
                };
                Some(Value::Bool(power && term))
            }
            NetKind::Coil { coil, operand } => match self.power_in(e) {
                Some(p) => Some(Value::Bool(p)),
                // Power from a function (no variable of its own): a plain coil's variable
                // holds it.
                None if *coil == CoilKind::Normal => read(operand.trim()),
                None => None,
            },
            NetKind::InVar { expr } | NetKind::InOutVar { expr } => {
                constant(expr).or_else(|| read(expr.trim()))
            }
            NetKind::Block { instance, .. } => {
                if pin.eq_ignore_ascii_case("ENO") {
                    let en = e.inputs.iter().find(|p| p.name.eq_ignore_ascii_case("EN"));
                    return match en {
                        Some(p) if !p.wires.is_empty() => self.joined(&p.wires).map(Value::Bool),
                        _ => Some(Value::Bool(true)),
                    };
                }
                match instance {
                    Some(inst) => read(&format!("{inst}.{pin}")),
                    None => self.function(e).or_else(|| {
                        let text = self.watches.get(&(e.id.clone(), pin.to_ascii_uppercase()))?;
                        read(text)
                    }),
                }
            }
            NetKind::Continuation { name } => {
                let connector = self.pou.elements.iter().find(|c| {
                    matches!(&c.kind, NetKind::Connector { name: n } if n.eq_ignore_ascii_case(name))
                })?;
                let wires: Vec<&'a Wire> =
                    connector.inputs.iter().flat_map(|p| p.wires.iter()).collect();
                match wires.as_slice() {
                    [one] => self.wire(one),
                    _ => self.joined_refs(&wires).map(Value::Bool),
                }
            }
            // A step is lit while it is active (its flag `Name.X`).
            NetKind::Step { name, .. } => read(&format!("{}.X", name.trim())),
            _ => None,
        }
    }

    /// The output of a BOOL function the view can tell from its inputs (AND, OR, XOR,
    /// NOT, MOVE); `None` for the others.
    fn function(&mut self, e: &'a NetElement) -> Option<Value> {
        let NetKind::Block { type_name, .. } = &e.kind else { return None };
        let mut inputs = Vec::new();
        for p in e.inputs.iter().filter(|p| !p.name.eq_ignore_ascii_case("EN")) {
            let [w] = p.wires.as_slice() else { return None };
            let v = truth(self.wire(w)?)?;
            inputs.push(if p.modifier == Some(super::model::PinModifier::Negated) {
                !v
            } else {
                v
            });
        }
        let v = match type_name.to_ascii_uppercase().as_str() {
            "AND" => inputs.iter().all(|b| *b),
            "OR" => inputs.iter().any(|b| *b),
            "XOR" => inputs.iter().filter(|b| **b).count() % 2 == 1,
            "NOT" if inputs.len() == 1 => !inputs[0],
            "MOVE" if inputs.len() == 1 => inputs[0],
            _ => return None,
        };
        Some(Value::Bool(v))
    }

    fn wire(&mut self, w: &Wire) -> Option<Value> {
        let from = *self.by_id.get(w.from.as_str())?;
        let pin = w.param.clone().unwrap_or_default();
        let v = self.output(from, &pin);
        if v.is_none() && !pin.is_empty() && from.outputs.len() == 1 {
            return self.output(from, "");
        }
        v
    }

    /// The power at the left of `e`: the OR of the wires into it (FALSE when none).
    fn power_in(&mut self, e: &'a NetElement) -> Option<bool> {
        let wires: Vec<&'a Wire> = e.inputs.iter().flat_map(|p| p.wires.iter()).collect();
        self.joined_refs(&wires)
    }

    fn joined(&mut self, wires: &'a [Wire]) -> Option<bool> {
        let refs: Vec<&'a Wire> = wires.iter().collect();
        self.joined_refs(&refs)
    }

    fn joined_refs(&mut self, wires: &[&'a Wire]) -> Option<bool> {
        let mut any = false;
        for w in wires {
            any |= truth(self.wire(w)?)?;
        }
        Some(any)
    }
}

fn truth(v: Value) -> Option<bool> {
    match v {
        Value::Bool(b) => Some(b),
        _ => None,
    }
}

/// The value of a BOOL constant (`TRUE`, `FALSE`, `BOOL#1`).
fn constant(expr: &str) -> Option<Value> {
    match expr.trim().to_ascii_uppercase().as_str() {
        "TRUE" | "BOOL#TRUE" | "BOOL#1" => Some(Value::Bool(true)),
        "FALSE" | "BOOL#FALSE" | "BOOL#0" => Some(Value::Bool(false)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::network::model::{NetworkLanguage, NetworkPouKind, Pin};

    fn el(id: &str, kind: NetKind, from: &[&str]) -> NetElement {
        let pin = |wires: Vec<Wire>| Pin {
            name: String::new(),
            dx: 0.0,
            dy: 0.0,
            wires,
            modifier: None,
            in_out: false,
        };
        let wires =
            from.iter().map(|f| Wire { from: f.to_string(), param: None, points: Vec::new() });
        NetElement {
            id: id.into(),
            kind,
            x: 0.0,
            y: 0.0,
            width: 0.0,
            height: 0.0,
            order: 0,
            inputs: if from.is_empty() { Vec::new() } else { vec![pin(wires.collect())] },
            outputs: vec![pin(Vec::new())],
            at: (0, 0),
        }
    }

    #[test]
    fn power_flows_through_contacts_and_coils() {
        let contact = |op: &str, kind| NetKind::Contact { operand: op.into(), contact: kind };
        let pou = NetworkPou {
            name: "Main".into(),
            kind: NetworkPouKind::Program,
            return_type: None,
            language: NetworkLanguage::Ld,
            declarations: String::new(),
            elements: vec![
                el("1", NetKind::LeftRail, &[]),
                el("2", contact("A", ContactKind::NormallyOpen), &["1"]),
                el("3", contact("B", ContactKind::NormallyClosed), &["1"]),
                el("4", NetKind::Coil { operand: "Y".into(), coil: CoilKind::Normal }, &["2", "3"]),
                el("5", contact("C", ContactKind::NormallyOpen), &["4"]),
            ],
            actions: Vec::new(),
            transitions: Vec::new(),
        };
        let read = |a: bool, b: bool, c: bool| {
            move |name: &str| match name {
                "A" => Some(Value::Bool(a)),
                "B" => Some(Value::Bool(b)),
                "C" => Some(Value::Bool(c)),
                _ => None,
            }
        };
        let at = |v: &HashMap<(String, String), Value>, id: &str| {
            v.get(&(id.to_string(), String::new())).cloned()
        };
        let v = output_values(&pou, &read(false, true, true));
        assert_eq!(at(&v, "2"), Some(Value::Bool(false)));
        assert_eq!(at(&v, "4"), Some(Value::Bool(false)));
        assert_eq!(at(&v, "5"), Some(Value::Bool(false)));
        let v = output_values(&pou, &read(true, true, true));
        assert_eq!(at(&v, "4"), Some(Value::Bool(true)), "the coil passes the power on");
        assert_eq!(at(&v, "5"), Some(Value::Bool(true)));
        let v = output_values(&pou, &read(false, false, false));
        assert_eq!(at(&v, "4"), Some(Value::Bool(true)), "through the closed contact");
        assert_eq!(at(&v, "5"), Some(Value::Bool(false)));
    }
}
