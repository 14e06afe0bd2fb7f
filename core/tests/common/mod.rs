#![allow(clippy::unwrap_used, clippy::expect_used, dead_code)]
//! Helpers shared by the ladder tests: a compact text form of rung grids, block and POU
//! builders, and simulator shortcuts.

use plc_core::ladder::*;
use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::sim::Simulator;
use plc_core::vm::Value;

/// Parses a test grid: whitespace-separated cells; `.` empty, `-` wire, `[X]` NO, `[/X]` NC,
/// `[P:X]`/`[N:X]` edge contacts, `(X)`, `(/X)`, `(S:X)`, `(R:X)`, `(P:X)` coils, `#`
/// covered, `B` a block placeholder; a leading `+` sets `link_down`.
pub fn rung(rows: &[&str]) -> Rung {
    let cells = rows
        .iter()
        .map(|row| {
            row.split_whitespace()
                .map(|tok| {
                    let (link, t) = match tok.strip_prefix('+') {
                        Some(t) => (true, t),
                        None => (false, tok),
                    };
                    let element = if t == "." || t == "B" {
                        Element::Empty
                    } else if t == "-" {
                        Element::Wire
                    } else if t == "#" {
                        Element::Covered
                    } else if let Some(x) = t.strip_prefix('[').and_then(|x| x.strip_suffix(']')) {
                        let (kind, op) = match x.split_once(':') {
                            Some(("P", o)) => (ContactKind::Rising, o),
                            Some(("N", o)) => (ContactKind::Falling, o),
                            _ => match x.strip_prefix('/') {
                                Some(o) => (ContactKind::NormallyClosed, o),
                                None => (ContactKind::NormallyOpen, x),
                            },
                        };
                        Element::Contact { kind, operand: op.to_string() }
                    } else if let Some(x) = t.strip_prefix('(').and_then(|x| x.strip_suffix(')')) {
                        let (kind, op) = match x.split_once(':') {
                            Some(("S", o)) => (CoilKind::Set, o),
                            Some(("R", o)) => (CoilKind::Reset, o),
                            Some(("P", o)) => (CoilKind::Rising, o),
                            Some(("N", o)) => (CoilKind::Falling, o),
                            _ => match x.strip_prefix('/') {
                                Some(o) => (CoilKind::Negated, o),
                                None => (CoilKind::Normal, x),
                            },
                        };
                        Element::Coil { kind, operand: op.to_string() }
                    } else {
                        panic!("bad token {t}")
                    };
                    Cell { element, link_down: link }
                })
                .collect()
        })
        .collect();
    Rung { comment: String::new(), label: None, cells }
}

pub fn block(
    ty: &str,
    inst: Option<&str>,
    inputs: &[(&str, &str)],
    outputs: &[(&str, &str)],
) -> Element {
    let pins = |v: &[(&str, &str)]| v.iter().map(|(n, o)| Pin::operand(n, o)).collect();
    let mut b = Block::new(ty, inst);
    b.inputs = pins(inputs);
    b.outputs = pins(outputs);
    Element::Block(b)
}

pub fn pou(decls: &str, rungs: Vec<Rung>) -> LadderPou {
    LadderPou {
        name: "Main".into(),
        kind: LadderPouKind::Program,
        declarations: decls.into(),
        rungs,
    }
}

pub fn project(p: LadderPou) -> Project {
    let mut project = Project::new("t");
    project.source = String::new();
    project.ladder = vec![p];
    project
}

pub fn sim(p: &LadderPou) -> Simulator {
    project_simulator(&project(p.clone()), None)
        .unwrap_or_else(|e| panic!("{e:?}\n{}", lower(p).st))
}

pub fn b(s: &Simulator, path: &str) -> bool {
    match s.read(path).unwrap() {
        Value::Bool(v) => v,
        other => panic!("{path} is {other:?}"),
    }
}

pub fn int(s: &Simulator, path: &str) -> i128 {
    match s.read(path).unwrap() {
        Value::Int(v, _) => v,
        other => panic!("{path} is {other:?}"),
    }
}

/// A project holding `source` (ST POUs the rungs may call) and one ladder POU.
pub fn project_with(source: &str, p: LadderPou) -> Project {
    let mut project = project(p);
    project.source = source.to_string();
    project
}

/// A simulator for PROGRAM Main of a project with ST `source` and ladder POU `p`.
pub fn sim_with(source: &str, p: &LadderPou) -> Simulator {
    project_simulator(&project_with(source, p.clone()), Some("Main"))
        .unwrap_or_else(|e| panic!("{e:?}\n{}", lower(p).st))
}

/// Puts `e` at `(row, col)` of rung `r`.
pub fn put(mut r: Rung, row: usize, col: usize, e: Element) -> Rung {
    r.cells[row][col].element = e;
    r
}

/// Sets a BOOL variable.
pub fn set(s: &mut Simulator, path: &str, v: bool) {
    s.write(path, if v { "TRUE" } else { "FALSE" }).unwrap();
}
