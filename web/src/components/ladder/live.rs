//! What the running program says about a ladder POU: the power leaving each element (from
//! the lowering's hidden `LdPow_*` variables, through the core's `power_map`) and the
//! values of the operands the diagram shows. The running PROGRAM has live values, and a
//! function block POU shows those of its first instance in it.

use std::collections::{HashMap, HashSet};

use plc_core::export::value_text;
use plc_core::ladder::{power_map, Element, LadderPou, Rung};
use plc_core::semantic::Type;
use plc_core::sim::Readout;
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

/// The operands and instance values a rung's drawing shows, each once (as written).
pub fn rung_values(rung: &Rung) -> Vec<String> {
    let mut values: Vec<String> = Vec::new();
    let mut add = |v: String| {
        if is_path(&v) && !values.iter().any(|x| x.eq_ignore_ascii_case(&v)) {
            values.push(v.trim().to_string());
        }
    };
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
    values
}

impl Probes {
    /// The probes of a POU.
    pub fn of(pou: &LadderPou) -> Self {
        let mut values: Vec<String> = Vec::new();
        for v in pou.rungs.iter().flat_map(rung_values) {
            if !values.iter().any(|x| x.eq_ignore_ascii_case(&v)) {
                values.push(v);
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

/// The first instance of function block `fb` among the running program's variables (and
/// the globals), by its path (`F1`); `None` when it has none.
pub fn first_instance(sim: &dyn Readout, fb: &str) -> Option<String> {
    let exe = sim.executable();
    let types = exe.type_table();
    exe.main_vars().iter().find_map(|e| match e.var.ty {
        Type::Fb(id) => types
            .pou_names
            .get(id as usize)
            .filter(|n| n.eq_ignore_ascii_case(fb))
            .map(|_| e.var.name.clone()),
        _ => None,
    })
}

impl LadderLive {
    /// Reads the probes from the simulator: of the running PROGRAM itself (`instance`
    /// `None`), or of one instance of a function block (`Some("F1")`), whose operands are
    /// read inside it (`F1.Start`) or, for globals, as they are.
    pub fn read(sim: &dyn Readout, probes: &Probes, instance: Option<&str>) -> Self {
        let inside = |path: &str| match instance {
            Some(i) => sim.read(&format!("{i}.{path}")).or_else(|_| sim.read(path)),
            None => sim.read(path),
        };
        let power = probes
            .power
            .iter()
            .map(|(r, row, c, var)| ((*r, *row, *c), matches!(inside(var), Ok(Value::Bool(true)))))
            .collect();
        let mut values = HashMap::new();
        let mut bools = HashMap::new();
        for path in &probes.values {
            let Ok(v) = inside(path) else { continue };
            let key = path.to_ascii_lowercase();
            if let Value::Bool(b) = v {
                bools.insert(key.clone(), b);
            }
            values.insert(key, value_text(&v));
        }
        // Clicking a contact toggles an input of the running PROGRAM: not of an instance.
        let inputs = match instance {
            Some(_) => HashSet::new(),
            None => sim
                .executable()
                .main_vars()
                .iter()
                .filter(|e| e.var.is_input())
                .map(|e| e.var.name.to_ascii_lowercase())
                .collect(),
        };
        LadderLive { power, values, bools, inputs }
    }

    /// The part of the live state that rung `index` shows: its elements' power and the
    /// values of `values` (its operands, from [`rung_values`]). Each rung's drawing reads
    /// its own slice, so a change elsewhere in the POU wakes none of its cells.
    pub fn slice(&self, index: usize, values: &[String]) -> Self {
        let power =
            self.power.iter().filter(|((r, ..), _)| *r == index).map(|(k, v)| (*k, *v)).collect();
        let mut out = LadderLive { power, ..Default::default() };
        for v in values {
            let key = v.to_ascii_lowercase();
            if let Some(text) = self.values.get(&key) {
                out.values.insert(key.clone(), text.clone());
            }
            if let Some(b) = self.bools.get(&key) {
                out.bools.insert(key.clone(), *b);
            }
            if self.inputs.contains(&key) {
                out.inputs.insert(key);
            }
        }
        out
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
