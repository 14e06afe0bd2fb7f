//! The readable ST view of a ladder POU: one statement per coil or block, rung comments
//! kept, power flow written as plain boolean expressions.

use std::collections::HashMap;

use super::blocks::{block_code, PowerOut};
use super::lower::{jumps, pou_keywords};
use super::model::{CoilKind, ContactKind, Element, LadderPou};
use super::network::{Network, RAIL};

/// A boolean expression of the power flow.
#[derive(Debug, Clone, PartialEq)]
enum B {
    True,
    False,
    Atom(String),
    Not(Box<B>),
    And(Vec<B>),
    Or(Vec<B>),
}

fn and(a: B, b: B) -> B {
    match (a, b) {
        (B::True, x) | (x, B::True) => x,
        (B::False, _) | (_, B::False) => B::False,
        (B::And(mut xs), B::And(ys)) => {
            xs.extend(ys);
            B::And(xs)
        }
        (B::And(mut xs), y) => {
            xs.push(y);
            B::And(xs)
        }
        (x, B::And(ys)) => {
            let mut xs = vec![x];
            xs.extend(ys);
            B::And(xs)
        }
        (x, y) => B::And(vec![x, y]),
    }
}

fn or(items: Vec<B>) -> B {
    let mut out = Vec::new();
    for i in items {
        match i {
            B::True => return B::True,
            B::False => {}
            B::Or(xs) => out.extend(xs),
            x => out.push(x),
        }
    }
    match out.len() {
        0 => B::False,
        1 => out.pop().unwrap_or(B::False),
        _ => B::Or(out),
    }
}

fn render(b: &B) -> String {
    match b {
        B::True => "TRUE".into(),
        B::False => "FALSE".into(),
        B::Atom(s) => s.clone(),
        B::Not(x) => match **x {
            B::Atom(ref s) if is_simple(s) => format!("NOT {s}"),
            _ => format!("NOT ({})", render(x)),
        },
        B::And(xs) => xs
            .iter()
            .map(|x| match x {
                B::Or(_) => format!("({})", render(x)),
                _ => render(x),
            })
            .collect::<Vec<_>>()
            .join(" AND "),
        B::Or(xs) => xs.iter().map(render).collect::<Vec<_>>().join(" OR "),
    }
}

fn is_simple(s: &str) -> bool {
    s.chars().all(|c| c.is_alphanumeric() || matches!(c, '_' | '.' | '%' | '[' | ']' | ','))
}

/// Atoms that are not simple (a comparison `(a > b) AND (c < d)`) are kept in parentheses.
fn atom(s: String) -> B {
    if is_simple(&s) || (s.starts_with('(') && s.ends_with(')') && !s.contains(" AND ")) {
        B::Atom(s)
    } else {
        B::Atom(format!("({s})"))
    }
}

/// The leading name of a place (`T1` of `T1.ET`, `%QX0` of `%QX0.1`), upper case.
fn root_of(place: &str) -> String {
    place.trim().split(['.', '[']).next().unwrap_or("").trim().to_ascii_uppercase()
}

/// The variables a coil or block writes (their leading names).
fn written_names(e: &Element) -> Vec<String> {
    match e {
        Element::Coil { operand, .. } => vec![root_of(operand)],
        Element::Block(b) => b
            .instance
            .iter()
            .map(|i| root_of(i))
            .chain(b.outputs.iter().chain(&b.in_outs).map(|p| root_of(&p.operand)))
            .filter(|n| !n.is_empty())
            .collect(),
        _ => Vec::new(),
    }
}

/// Whether an expression reads one of `names`.
fn mentions(b: &B, names: &[String]) -> bool {
    match b {
        B::True | B::False => false,
        B::Atom(s) => s
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '%'))
            .any(|t| names.iter().any(|n| n.eq_ignore_ascii_case(t))),
        B::Not(x) => mentions(x, names),
        B::And(xs) | B::Or(xs) => xs.iter().any(|x| mentions(x, names)),
    }
}

/// The statements of the ST view with the rung each comes from, and the declarations of
/// the helpers the view needs (`LdEdge_0 : R_TRIG;`, `LdTmp_0 : BOOL;`).
fn view_statements(pou: &LadderPou) -> (Vec<(String, Option<usize>)>, String) {
    let mut lines: Vec<(String, Option<usize>)> = Vec::new();
    let mut decls = String::new();
    let mut edge = 0usize;
    let mut tmp = 0usize;
    let jumps = jumps(pou);
    for (id, ..) in &jumps {
        lines.push((format!("LdJmp_{id} := FALSE;"), None));
    }
    for (ri, rung) in pou.rungs.iter().enumerate() {
        let skip: Vec<String> = jumps
            .iter()
            .filter(|&&(_, s, _, t)| s < ri && ri < t)
            .map(|(id, ..)| format!("LdJmp_{id}"))
            .collect();
        let indent = if skip.is_empty() { "" } else { "    " };
        let comment = rung.comment.trim().replace("*)", "* )");
        let comment: Vec<&str> = comment.lines().collect();
        match comment.as_slice() {
            [] => {}
            [one] => lines.push((format!("(* {one} *)"), Some(ri))),
            [first, rest @ ..] => {
                lines.push((format!("(* {first}"), Some(ri)));
                for (k, l) in rest.iter().enumerate() {
                    let end = if k + 1 == rest.len() { " *)" } else { "" };
                    lines.push((format!("   {l}{end}"), Some(ri)));
                }
            }
        }
        if let Some(l) = &rung.label {
            lines.push((format!("(* label {} *)", l.trim()), Some(ri)));
        }
        if !skip.is_empty() {
            lines.push((format!("IF NOT ({}) THEN", skip.join(" OR ")), Some(ri)));
        }
        let net = Network::new(rung);
        let mut outs: HashMap<usize, B> = HashMap::new();
        for (i, e) in net.elements.iter().enumerate() {
            let input = if !net.powered[e.input] {
                B::False
            } else if e.input == RAIL {
                B::True
            } else {
                or(net
                    .feeders(e.input)
                    .map(|(j, _)| outs.get(&j).cloned().unwrap_or(B::False))
                    .collect())
            };
            // A statement that writes a variable an expression still waiting to be used has
            // read: keep that expression's value in a temporary first, so the view computes
            // what the rung computes (power is evaluated where the element stands).
            let written = written_names(e.element);
            if !written.is_empty() {
                let mut pending: Vec<usize> = outs
                    .keys()
                    .copied()
                    .filter(|&j| {
                        let node = net.elements[j].output;
                        net.elements.iter().skip(i + 1).any(|k| k.input == node)
                            || net.pins.iter().any(|p| p.block > i && p.node == node)
                    })
                    .collect();
                pending.sort_unstable();
                for j in pending {
                    let Some(value) = outs.get(&j) else { continue };
                    if !mentions(value, &written) {
                        continue;
                    }
                    let line = format!("LdTmp_{tmp} := {};", render(value));
                    lines.push((format!("{indent}{line}"), Some(ri)));
                    decls.push_str(&format!("    LdTmp_{tmp} : BOOL;\n"));
                    outs.insert(j, B::Atom(format!("LdTmp_{tmp}")));
                    tmp += 1;
                }
            }
            let mut emit = |s: String| lines.push((format!("{indent}{s}"), Some(ri)));
            let out = match e.element {
                Element::Empty | Element::Covered | Element::Wire => input,
                Element::Contact { kind, operand } => {
                    let x = operand.trim().to_string();
                    let term = match kind {
                        ContactKind::NormallyOpen => B::Atom(x),
                        ContactKind::NormallyClosed => B::Not(Box::new(B::Atom(x))),
                        ContactKind::Rising | ContactKind::Falling => {
                            let ty = if *kind == ContactKind::Rising { "R_TRIG" } else { "F_TRIG" };
                            decls.push_str(&format!("    LdEdge_{edge} : {ty};\n"));
                            emit(format!("LdEdge_{edge}(CLK := {x});"));
                            edge += 1;
                            B::Atom(format!("LdEdge_{}.Q", edge - 1))
                        }
                    };
                    and(input, term)
                }
                Element::Coil { kind, operand } => {
                    let x = operand.trim();
                    let p = render(&input);
                    match kind {
                        CoilKind::Normal => emit(format!("{x} := {p};")),
                        CoilKind::Negated => {
                            emit(format!("{x} := {};", render(&B::Not(Box::new(input.clone())))))
                        }
                        CoilKind::Set => emit(format!("IF {p} THEN {x} := TRUE; END_IF;")),
                        CoilKind::Reset => emit(format!("IF {p} THEN {x} := FALSE; END_IF;")),
                        CoilKind::Rising | CoilKind::Falling => {
                            let ty = if *kind == CoilKind::Rising { "R_TRIG" } else { "F_TRIG" };
                            decls.push_str(&format!("    LdEdge_{edge} : {ty};\n"));
                            emit(format!("LdEdge_{edge}(CLK := {p});"));
                            emit(format!("{x} := LdEdge_{edge}.Q;"));
                            edge += 1;
                        }
                    }
                    input
                }
                Element::Block(b) => {
                    let p = render(&input);
                    let wired: Vec<Option<String>> = (0..b.inputs.len())
                        .map(|k| {
                            net.pin_node(i, k).map(|n| {
                                if !net.powered[n] {
                                    return "FALSE".to_string();
                                }
                                let feed = or(net
                                    .feeders(n)
                                    .map(|(j, _)| outs.get(&j).cloned().unwrap_or(B::False))
                                    .collect());
                                render(&feed)
                            })
                        })
                        .collect();
                    let code = block_code(b, &p, &wired);
                    for s in code.statements {
                        emit(s);
                    }
                    match code.power_out {
                        PowerOut::Same => input,
                        PowerOut::And(x) => and(input, atom(x)),
                        PowerOut::AndThen(x) => match input {
                            B::True => atom(x),
                            B::Or(_) => B::Atom(format!("(({p}) AND_THEN {x})")),
                            _ => B::Atom(format!("({p} AND_THEN {x})")),
                        },
                        PowerOut::Value(x) => atom(x),
                    }
                }
                Element::Jump { .. } => {
                    if let Some((id, ..)) =
                        jumps.iter().find(|&&(_, s, row, _)| s == ri && row == e.row)
                    {
                        emit(format!("IF {} THEN LdJmp_{id} := TRUE; END_IF;", render(&input)));
                    }
                    input
                }
                Element::Return => {
                    emit(format!("IF {} THEN RETURN; END_IF;", render(&input)));
                    input
                }
            };
            outs.insert(i, out);
        }
        if !skip.is_empty() {
            lines.push(("END_IF;".to_string(), Some(ri)));
        }
    }
    let jump_decls: String =
        jumps.iter().map(|(id, ..)| format!("    LdJmp_{id} : BOOL;\n")).collect();
    decls.push_str(&jump_decls);
    (lines, decls)
}

/// The readable ST body of a ladder POU and a map from its 1-based lines to 0-based rungs.
/// A latch rung gives `Motor := (Start OR Motor) AND NOT Stop;`.
pub fn st_view(pou: &LadderPou) -> (String, Vec<(u32, usize)>) {
    let (lines, _) = view_statements(pou);
    let mut text = String::new();
    let mut map = Vec::new();
    for (i, (line, rung)) in lines.iter().enumerate() {
        text.push_str(line);
        text.push('\n');
        if let Some(r) = rung {
            map.push((i as u32 + 1, *r));
        }
    }
    (text, map)
}

/// The ST view as a complete POU (declarations, the edge and jump helpers it needs, body),
/// which compiles and behaves like the ladder POU.
pub fn st_view_pou(pou: &LadderPou) -> String {
    let (open, close) = pou_keywords(pou.kind);
    let (body, _) = st_view(pou);
    let (_, decls) = view_statements(pou);
    let helpers = if decls.is_empty() { String::new() } else { format!("VAR\n{decls}END_VAR\n") };
    format!("{open} {}\n{}\n{helpers}{body}{close}\n", pou.name, pou.declarations.trim_end())
}
