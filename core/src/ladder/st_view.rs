//! The readable ST view of a ladder POU: one statement per coil or block, rung comments
//! kept, power flow written as plain boolean expressions.

use super::blocks::PowerOut;
use super::lower::pou_keywords;
use super::model::{Element, LadderPou, Rung};
use super::network::Network;
use super::walk::{walk, At, RungWriter, Term};

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

/// The view's writer: power as boolean expressions, statements with the rung they are in.
struct View {
    lines: Vec<(String, Option<usize>)>,
    decls: String,
    indent: &'static str,
    tmp: usize,
}

impl RungWriter for View {
    type Power = B;

    fn constant(&mut self, on: bool) -> B {
        if on {
            B::True
        } else {
            B::False
        }
    }

    fn any(&mut self, feeds: Vec<B>) -> B {
        or(feeds)
    }

    fn and_term(&mut self, power: B, term: Term) -> B {
        match term {
            Term::Is(x) => and(power, B::Atom(x)),
            Term::Not(x) => and(power, B::Not(Box::new(B::Atom(x)))),
        }
    }

    fn block_out(&mut self, power: B, out: PowerOut) -> B {
        match out {
            PowerOut::Same => power,
            PowerOut::And(x) => and(power, atom(x)),
            PowerOut::AndThen(x) => match power {
                B::True => atom(x),
                B::Or(_) => B::Atom(format!("(({}) AND_THEN {x})", render(&power))),
                _ => B::Atom(format!("({} AND_THEN {x})", render(&power))),
            },
            PowerOut::Value(x) => atom(x),
        }
    }

    fn text(&self, power: &B) -> String {
        render(power)
    }

    fn negated(&self, power: &B) -> String {
        render(&B::Not(Box::new(power.clone())))
    }

    fn hold(&mut self, _at: At, power: B) -> B {
        power
    }

    fn statement(&mut self, (rung, ..): At, text: String) {
        self.lines.push((format!("{}{text}", self.indent), Some(rung)));
    }

    fn line(&mut self, text: String) {
        self.lines.push((text, None));
    }

    fn declare(&mut self, text: String) {
        self.decls.push_str(&format!("    {text}\n"));
    }

    fn start_rung(&mut self, ri: usize, rung: &Rung, skip: &str) {
        self.indent = if skip.is_empty() { "" } else { "    " };
        let comment = rung.comment.trim().replace("*)", "* )");
        let comment: Vec<&str> = comment.lines().collect();
        match comment.as_slice() {
            [] => {}
            [one] => self.lines.push((format!("(* {one} *)"), Some(ri))),
            [first, rest @ ..] => {
                self.lines.push((format!("(* {first}"), Some(ri)));
                for (k, l) in rest.iter().enumerate() {
                    let end = if k + 1 == rest.len() { " *)" } else { "" };
                    self.lines.push((format!("   {l}{end}"), Some(ri)));
                }
            }
        }
        if let Some(l) = &rung.label {
            self.lines.push((format!("(* label {} *)", l.trim()), Some(ri)));
        }
        if !skip.is_empty() {
            self.lines.push((format!("IF NOT ({skip}) THEN"), Some(ri)));
        }
    }

    fn end_rung(&mut self, ri: usize, skip: &str) {
        if !skip.is_empty() {
            self.lines.push(("END_IF;".to_string(), Some(ri)));
        }
    }

    /// A statement that writes a variable an expression still waiting to be used has read:
    /// keep that expression's value in a temporary first, so the view computes what the
    /// rung computes (power is evaluated where the element stands).
    fn before_writes(&mut self, at: At, net: &Network<'_>, i: usize, outs: &mut [B]) {
        let Some(e) = net.elements.get(i) else { return };
        let written = written_names(e.element);
        for (j, value) in outs.iter_mut().enumerate() {
            let Some(node) = net.elements.get(j).map(|p| p.output) else { continue };
            let pending = net.elements.iter().skip(i + 1).any(|k| k.input == node)
                || net.pins.iter().any(|p| p.block > i && p.node == node);
            if !pending || !mentions(value, &written) {
                continue;
            }
            let line = format!("LdTmp_{} := {};", self.tmp, render(value));
            self.statement(at, line);
            self.declare(format!("LdTmp_{} : BOOL;", self.tmp));
            *value = B::Atom(format!("LdTmp_{}", self.tmp));
            self.tmp += 1;
        }
    }
}

/// The statements of the ST view with the rung each comes from, and the declarations of
/// the helpers the view needs (`LdEdge_0 : R_TRIG;`, `LdTmp_0 : BOOL;`).
pub(super) fn view_statements(pou: &LadderPou) -> (Vec<(String, Option<usize>)>, String) {
    let mut w = View { lines: Vec::new(), decls: String::new(), indent: "", tmp: 0 };
    walk(pou, &mut w);
    (w.lines, w.decls)
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
