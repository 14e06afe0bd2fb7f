//! What the running program says about a ladder POU: the power leaving each element (from
//! the lowering's hidden `LdPow_*` variables, through the core's `power_map`) and the
//! values of the operands the diagram shows. Only the running PROGRAM has live values.

use std::collections::{HashMap, HashSet};

use plc_core::export::value_text;
use plc_core::ladder::{power_map, Element, LadderPou};
use plc_core::sim::Simulator;
use plc_core::vm::Value;

use super::geometry::instance_values;

/// The variables a ladder POU's view reads on every scan.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Probes {
    /// `(rung, row, col, power variable)` per element.
    pub power: Vec<(usize, usize, usize, String)>,
    /// Operands and instance outputs whose values the view shows.
    pub values: Vec<String>,
}

/// Whether an operand text names something readable (not a literal or an expression).
fn is_path(text: &str) -> bool {
    let t = text.trim();
    t.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && !t.contains('#')
        && !t.eq_ignore_ascii_case("TRUE")
        && !t.eq_ignore_ascii_case("FALSE")
        && t.chars().all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '[' | ']'))
}

impl Probes {
    /// The probes of a POU.
    pub fn of(pou: &LadderPou) -> Self {
        let mut values: Vec<String> = Vec::new();
        let mut add = |v: String| {
            if is_path(&v) && !values.iter().any(|x| x.eq_ignore_ascii_case(&v)) {
                values.push(v.trim().to_string());
            }
        };
        for rung in &pou.rungs {
            for cell in rung.cells.iter().flatten() {
                match &cell.element {
                    Element::Contact { operand, .. } | Element::Coil { operand, .. } => {
                        add(operand.clone())
                    }
                    Element::Block(b) => {
                        for p in b.inputs.iter().chain(&b.outputs).chain(&b.in_outs) {
                            add(p.operand.clone());
                        }
                        if let Some(inst) = &b.instance {
                            for v in instance_values(&b.type_name) {
                                add(format!("{}.{v}", inst.trim()));
                            }
                        }
                    }
                    _ => {}
                }
            }
        }
        Probes { power: power_map(pou), values }
    }
}

/// The live state of a ladder POU after the last scan.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LadderLive {
    /// Power leaving the element at `(rung, row, col)`.
    pub power: HashMap<(usize, usize, usize), bool>,
    /// Value text by operand (lower case).
    pub values: HashMap<String, String>,
    /// BOOL operands by name (lower case).
    pub bools: HashMap<String, bool>,
    /// The running program's inputs (lower case): contacts on them toggle when clicked.
    pub inputs: HashSet<String>,
}

impl LadderLive {
    /// Reads the probes from the simulator.
    pub fn read(sim: &Simulator, probes: &Probes) -> Self {
        let power = probes
            .power
            .iter()
            .map(|(r, row, c, var)| {
                ((*r, *row, *c), matches!(sim.read(var), Ok(Value::Bool(true))))
            })
            .collect();
        let mut values = HashMap::new();
        let mut bools = HashMap::new();
        for path in &probes.values {
            let Ok(v) = sim.read(path) else { continue };
            let key = path.to_ascii_lowercase();
            if let Value::Bool(b) = v {
                bools.insert(key.clone(), b);
            }
            values.insert(key, value_text(&v));
        }
        let inputs = sim
            .executable()
            .main_vars()
            .iter()
            .filter(|e| e.var.is_input())
            .map(|e| e.var.name.to_ascii_lowercase())
            .collect();
        LadderLive { power, values, bools, inputs }
    }

    /// The power leaving an element.
    pub fn powered(&self, rung: usize, row: usize, col: usize) -> bool {
        self.power.get(&(rung, row, col)).copied().unwrap_or(false)
    }

    /// The value of a BOOL operand.
    pub fn bool_of(&self, operand: &str) -> Option<bool> {
        self.bools.get(&operand.trim().to_ascii_lowercase()).copied()
    }

    /// The value text of an operand.
    pub fn value_of(&self, operand: &str) -> Option<&str> {
        self.values.get(&operand.trim().to_ascii_lowercase()).map(String::as_str)
    }

    /// Whether clicking a contact on `operand` toggles an input of the running program.
    pub fn is_input(&self, operand: &str) -> bool {
        self.inputs.contains(&operand.trim().to_ascii_lowercase())
    }
}
