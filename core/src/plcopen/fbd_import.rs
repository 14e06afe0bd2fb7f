//! FBD bodies → ST statements, by the rules the tools that write them use: every function
//! block instance and output variable is a statement, run in `executionOrderId` order when
//! the file gives one to each, else in the order of the data flow (a statement after the
//! blocks it reads; ties and feedback loops broken top to bottom, left to right, so a
//! feedback wire reads the previous scan's value). A function is written inline where its
//! output is used, so its result needs no variable of its own.
//!
//! The drawing is not kept yet: the POU becomes ST text (issue 16 keeps the network itself,
//! drawn at its coordinates).

use std::collections::{BTreeSet, HashMap};

use super::ld_import::read::{read_elements, Conn, El, Kind, RawBlock};
use super::xml::Node;
use super::ImportError;

/// An FBD body lowered: the statements and the instances it uses.
pub(crate) struct FbdBody {
    /// The body as ST statements, one per line.
    pub statements: String,
    /// `(instance, type)` of every function block instance in the body.
    pub instances: Vec<(String, String)>,
    /// What was left out (an output variable with no wire), with the element's place.
    pub notes: Vec<super::ImportNote>,
}

/// Lowers the FBD body `fbd` of POU `pou`.
pub(crate) fn import_fbd(fbd: &Node, pou: &str) -> Result<FbdBody, ImportError> {
    let els = read_elements(fbd, pou)?;
    let index: HashMap<&str, usize> =
        els.iter().enumerate().map(|(i, e)| (e.id.as_str(), i)).collect();
    let lower = Lower { els: &els, index: &index, pou };
    // The statements: function block instances and output variables.
    let statements: Vec<usize> = els
        .iter()
        .enumerate()
        .filter(|(_, e)| matches!(&e.kind, Kind::OutVar(_)) || instance_of(&e.kind).is_some())
        .map(|(i, _)| i)
        .collect();
    let mut deps: HashMap<usize, BTreeSet<usize>> = HashMap::new();
    for &s in &statements {
        let mut found = BTreeSet::new();
        lower.instances_read(s, &mut found, &mut BTreeSet::new())?;
        found.remove(&s);
        deps.insert(s, found);
    }
    let order = run_order(&els, &statements, &deps);
    let mut text = String::new();
    let mut instances = Vec::new();
    let mut notes = Vec::new();
    for s in order {
        match &els[s].kind {
            Kind::OutVar(target) => {
                let conn = match els[s].conns.as_slice() {
                    [conn] => conn,
                    [] => {
                        let (line, column) = els[s].at;
                        notes.push(super::ImportNote::at(line, column, format!(
                            "POU {pou}: output variable localId {} ({target}) is not wired; skipped",
                            els[s].id
                        )));
                        continue;
                    }
                    _ => return Err(lower.err(s, "an output variable with several wires".into())),
                };
                text.push_str(&format!("{target} := {};\n", lower.value(conn, &mut Vec::new())?));
            }
            Kind::Block(b) => {
                let Some(inst) = &b.instance else { continue };
                let mut args = Vec::new();
                for (pin, conns) in b.inputs.iter().chain(&b.in_outs) {
                    if pin.eq_ignore_ascii_case("EN") && conns.is_empty() {
                        continue;
                    }
                    match conns.as_slice() {
                        [] => {}
                        [c] => args.push(format!("{pin} := {}", lower.value(c, &mut Vec::new())?)),
                        _ => return Err(lower.err(s, format!("input {pin} has several wires"))),
                    }
                }
                text.push_str(&format!("{inst}({});\n", args.join(", ")));
                instances.push((inst.clone(), b.type_name.clone()));
            }
            _ => {}
        }
    }
    Ok(FbdBody { statements: text, instances, notes })
}

/// The instance name of a function block element.
fn instance_of(kind: &Kind) -> Option<&str> {
    match kind {
        Kind::Block(RawBlock { instance: Some(i), .. }) => Some(i),
        _ => None,
    }
}

struct Lower<'a> {
    els: &'a [El],
    index: &'a HashMap<&'a str, usize>,
    pou: &'a str,
}

impl Lower<'_> {
    fn err(&self, i: usize, message: String) -> ImportError {
        ImportError::Element {
            pou: self.pou.to_string(),
            local_id: self.els[i].id.clone(),
            message,
        }
    }

    fn source(&self, conn: &Conn, from: usize) -> Result<usize, ImportError> {
        self.index.get(conn.from.as_str()).copied().ok_or_else(|| {
            self.err(from, format!("a wire comes from localId {}, which does not exist", conn.from))
        })
    }

    /// The ST expression a wire carries. `path` holds the functions being written (a loop of
    /// functions alone has no value).
    fn value(&self, conn: &Conn, path: &mut Vec<usize>) -> Result<String, ImportError> {
        let at = *path.last().unwrap_or(&0);
        let i = self.source(conn, at)?;
        match &self.els[i].kind {
            Kind::InVar(expr) => Ok(operand(expr)),
            Kind::Block(b) => match &b.instance {
                Some(inst) => match &conn.param {
                    Some(p) => Ok(format!("{inst}.{p}")),
                    None => {
                        Err(self.err(i, format!("a wire from instance {inst} names no output")))
                    }
                },
                None => {
                    if path.contains(&i) {
                        return Err(self.err(
                            i,
                            "functions wired in a loop with no function block to hold a value"
                                .into(),
                        ));
                    }
                    path.push(i);
                    let mut args = Vec::new();
                    for (pin, conns) in b.inputs.iter().chain(&b.in_outs) {
                        if pin.eq_ignore_ascii_case("EN") {
                            continue;
                        }
                        match conns.as_slice() {
                            [c] => args.push(self.value(c, path)?),
                            [] => {
                                return Err(self.err(
                                    i,
                                    format!("input {pin} of {} is not wired", b.type_name),
                                ))
                            }
                            _ => return Err(self.err(i, format!("input {pin} has several wires"))),
                        }
                    }
                    path.pop();
                    let text = format!("{}({})", b.type_name, args.join(", "));
                    if text.len() > crate::limits::MAX_PROJECT_BYTES {
                        return Err(self.err(i, "this network is too large when written as ST (a function's output feeds too many others)".into()));
                    }
                    Ok(text)
                }
            },
            _ => Err(self.err(i, "this element gives no value to a wire".into())),
        }
    }

    /// The function block instances (by element) whose outputs statement `s` reads.
    fn instances_read(
        &self,
        s: usize,
        found: &mut BTreeSet<usize>,
        seen: &mut BTreeSet<usize>,
    ) -> Result<(), ImportError> {
        let conns: Vec<&Conn> = match &self.els[s].kind {
            Kind::Block(b) => b.inputs.iter().chain(&b.in_outs).flat_map(|(_, c)| c).collect(),
            _ => self.els[s].conns.iter().collect(),
        };
        for c in conns {
            let i = self.source(c, s)?;
            if instance_of(&self.els[i].kind).is_some() {
                found.insert(i);
            } else if matches!(self.els[i].kind, Kind::Block(_)) && seen.insert(i) {
                if seen.len() > crate::limits::MAX_EXPR_HEIGHT * 100 {
                    return Err(self.err(i, "too many functions in one network".into()));
                }
                self.instances_read(i, found, seen)?;
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
