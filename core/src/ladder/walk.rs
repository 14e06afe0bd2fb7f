//! The one walk over a ladder POU that says what each rung element stands for in ST: the
//! jump flags, the rungs a taken jump skips, contacts (with edge detectors), coils, blocks,
//! jumps and returns, in evaluation order. The lowering (`lower.rs`: every element's power
//! in a hidden variable, for the compiler and the live view) and the readable ST view
//! (`st_view.rs`: power as plain boolean expressions) are two [`RungWriter`]s of this walk,
//! so they cannot disagree on what a rung does.

use super::blocks::{block_code, PowerOut};
use super::model::{CoilKind, ContactKind, Element, LadderPou, Rung};
use super::network::{Network, RAIL};

/// The grid cell an element stands in: `(rung, row, column)`, 0-based.
pub(crate) type At = (usize, usize, usize);

/// A contact's condition, ANDed with the power reaching it.
pub(crate) enum Term {
    /// The BOOL value itself (a normally open contact, an edge detector's `Q`).
    Is(String),
    /// Its negation (a normally closed contact).
    Not(String),
}

/// How one rendering of the walk writes power expressions and statements.
pub(crate) trait RungWriter {
    /// An expression of power.
    type Power: Clone;
    /// TRUE (the left rail) or FALSE (no power).
    fn constant(&mut self, on: bool) -> Self::Power;
    /// The OR of the power of the elements feeding one node.
    fn any(&mut self, feeds: Vec<Self::Power>) -> Self::Power;
    /// `power AND term`.
    fn and_term(&mut self, power: Self::Power, term: Term) -> Self::Power;
    /// The power leaving a block, given the power reaching it.
    fn block_out(&mut self, power: Self::Power, out: PowerOut) -> Self::Power;
    /// A power expression as ST text.
    fn text(&self, power: &Self::Power) -> String;
    /// `NOT power` as ST text (a negated coil).
    fn negated(&self, power: &Self::Power) -> String;
    /// The power leaving the element at `at`: the lowering stores it in the cell's hidden
    /// variable and names that; the view keeps the expression.
    fn hold(&mut self, at: At, power: Self::Power) -> Self::Power;
    /// A statement of the element at `at`.
    fn statement(&mut self, at: At, text: String);
    /// A line of the POU body that belongs to no element (the jump flags' reset).
    fn line(&mut self, text: String);
    /// A declaration of a helper variable (`LdEdge_0 : R_TRIG;`).
    fn declare(&mut self, text: String);
    /// The start of rung `index`; `skip` is the condition of the jumps that skip it
    /// (`LdJmp_0 OR LdJmp_2`), empty when none does.
    fn start_rung(&mut self, index: usize, rung: &Rung, skip: &str);
    /// The end of rung `index`.
    fn end_rung(&mut self, index: usize, skip: &str);
    /// Called before the statements of element `i` when it writes variables (a coil, a
    /// block): `outs` are the powers of the elements before it, which the writer may
    /// replace (the view keeps a value that reads a written variable in a temporary).
    fn before_writes(&mut self, _at: At, _net: &Network<'_>, _i: usize, _outs: &mut [Self::Power]) {
    }
}

/// Jumps of a POU: `(jump id, source rung, source row, target rung)`, forward jumps only.
pub(crate) fn jumps(pou: &LadderPou) -> Vec<(usize, usize, usize, usize)> {
    let mut out = Vec::new();
    for (ri, rung) in pou.rungs.iter().enumerate() {
        for e in Network::new(rung).elements {
            if let Element::Jump { label } = e.element {
                let target = pou.rungs.iter().position(|r| {
                    r.label.as_deref().is_some_and(|l| l.trim().eq_ignore_ascii_case(label.trim()))
                });
                if let Some(t) = target.filter(|&t| t > ri) {
                    out.push((out.len(), ri, e.row, t));
                }
            }
        }
    }
    out
}

/// Whether an element writes variables (its statements assign something).
fn writes(e: &Element) -> bool {
    matches!(e, Element::Coil { .. } | Element::Block(_))
}

/// Walks `pou` rung by rung, element by element, telling `w` what each stands for.
/// Elements no power reaches get FALSE.
pub(crate) fn walk<W: RungWriter>(pou: &LadderPou, w: &mut W) {
    let jumps = jumps(pou);
    for (id, ..) in &jumps {
        w.line(format!("LdJmp_{id} := FALSE;"));
    }
    let mut edge = 0usize;
    let mut new_edge = |w: &mut W, ty: &str| {
        w.declare(format!("LdEdge_{edge} : {ty};"));
        edge += 1;
        format!("LdEdge_{}", edge - 1)
    };
    for (ri, rung) in pou.rungs.iter().enumerate() {
        let skip: Vec<String> = jumps
            .iter()
            .filter(|&&(_, s, _, t)| s < ri && ri < t)
            .map(|(id, ..)| format!("LdJmp_{id}"))
            .collect();
        let skip = skip.join(" OR ");
        w.start_rung(ri, rung, &skip);
        let net = Network::new(rung);
        let mut outs: Vec<W::Power> = Vec::with_capacity(net.elements.len());
        let feed = |w: &mut W, outs: &[W::Power], node: usize| {
            if !net.powered[node] {
                w.constant(false)
            } else if node == RAIL {
                w.constant(true)
            } else {
                let feeds =
                    net.feeders(node).map(|(j, _)| outs.get(j).cloned()).collect::<Option<_>>();
                match feeds {
                    Some(feeds) => w.any(feeds),
                    None => w.constant(false),
                }
            }
        };
        for (i, e) in net.elements.iter().enumerate() {
            let at = (ri, e.row, e.col);
            let input = feed(w, &outs, e.input);
            if writes(e.element) {
                w.before_writes(at, &net, i, &mut outs);
            }
            let out = match e.element {
                Element::Empty | Element::Covered | Element::Wire => w.hold(at, input),
                Element::Contact { kind, operand } => {
                    let x = operand.trim().to_string();
                    let term = match kind {
                        ContactKind::NormallyOpen => Term::Is(x),
                        ContactKind::NormallyClosed => Term::Not(x),
                        ContactKind::Rising | ContactKind::Falling => {
                            let ty = if *kind == ContactKind::Rising { "R_TRIG" } else { "F_TRIG" };
                            let name = new_edge(w, ty);
                            w.statement(at, format!("{name}(CLK := {x});"));
                            Term::Is(format!("{name}.Q"))
                        }
                    };
                    let p = w.and_term(input, term);
                    w.hold(at, p)
                }
                Element::Coil { kind, operand } => {
                    let x = operand.trim();
                    let p = w.hold(at, input);
                    let t = w.text(&p);
                    match kind {
                        CoilKind::Normal => w.statement(at, format!("{x} := {t};")),
                        CoilKind::Negated => {
                            let n = w.negated(&p);
                            w.statement(at, format!("{x} := {n};"))
                        }
                        CoilKind::Set => {
                            w.statement(at, format!("IF {t} THEN {x} := TRUE; END_IF;"))
                        }
                        CoilKind::Reset => {
                            w.statement(at, format!("IF {t} THEN {x} := FALSE; END_IF;"))
                        }
                        CoilKind::Rising | CoilKind::Falling => {
                            let ty = if *kind == CoilKind::Rising { "R_TRIG" } else { "F_TRIG" };
                            let name = new_edge(w, ty);
                            w.statement(at, format!("{name}(CLK := {t});"));
                            w.statement(at, format!("{x} := {name}.Q;"));
                        }
                    }
                    p
                }
                Element::Block(b) => {
                    let wired: Vec<Option<String>> = (0..b.inputs.len())
                        .map(|k| {
                            net.pin_node(i, k).map(|n| {
                                let p = feed(w, &outs, n);
                                w.text(&p)
                            })
                        })
                        .collect();
                    let code = block_code(b, &w.text(&input), &wired);
                    for s in code.statements {
                        w.statement(at, s);
                    }
                    let p = w.block_out(input, code.power_out);
                    w.hold(at, p)
                }
                Element::Jump { .. } => {
                    let p = w.hold(at, input);
                    if let Some((id, ..)) =
                        jumps.iter().find(|&&(_, s, row, _)| s == ri && row == e.row)
                    {
                        let t = w.text(&p);
                        w.statement(at, format!("IF {t} THEN LdJmp_{id} := TRUE; END_IF;"));
                    }
                    p
                }
                Element::Return => {
                    let p = w.hold(at, input);
                    let t = w.text(&p);
                    w.statement(at, format!("IF {t} THEN RETURN; END_IF;"));
                    p
                }
            };
            outs.push(out);
        }
        w.end_rung(ri, &skip);
    }
    for (id, ..) in &jumps {
        w.declare(format!("LdJmp_{id} : BOOL;"));
    }
}
