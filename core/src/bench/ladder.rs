//! B4's ladder POU, built with the ladder model types as the editor builds them: `rungs`
//! rungs of [`ELEMENTS_PER_RUNG`] elements each, lowered and compiled by the product's own
//! path (`ladder::project_source` inside `run::project_simulator`).
//!
//! Every rung is a latch with permissives, the commonest rung of a real program:
//!
//! ```text
//!  | Start  Perm1  Stop   A      B      C      D        Q_k
//!  +--| |----| |----|/|----| |----|/|----| |----|/|------( )
//!  |  Q_k    Perm2  |
//!  +--| |----| |----+
//! ```
//!
//! Contacts read a pool of [`INPUTS`] inputs (a different mix on every rung) and the
//! previous rung's coil, so the rungs chain as in a sequence.

use crate::ladder::{Cell, CoilKind, ContactKind, Element, LadderPou, LadderPouKind, Rung};
use crate::project::Project;

/// Elements in every rung (7 contacts and a coil on the first row, 2 contacts in the
/// parallel branch).
pub const ELEMENTS_PER_RUNG: usize = 10;

/// Inputs the contacts read.
pub const INPUTS: usize = 64;

fn contact(kind: ContactKind, operand: String) -> Cell {
    Cell { element: Element::Contact { kind, operand }, link_down: false }
}

fn input(k: usize, salt: usize) -> String {
    format!("I{}", (k * 7 + salt * 13) % INPUTS)
}

/// Rung `k` of the benchmark POU.
fn rung(k: usize) -> Rung {
    use ContactKind::{NormallyClosed as Nc, NormallyOpen as No};
    let mut r = Rung::new(2, 8);
    r.comment = format!("latch {k}");
    let prev = if k == 0 { "I0".to_string() } else { format!("Q{}", k - 1) };
    let row0 = [
        (No, input(k, 0)),
        (No, input(k, 1)),
        (Nc, input(k, 2)),
        (No, prev),
        (Nc, input(k, 3)),
        (No, input(k, 4)),
        (Nc, input(k, 5)),
    ];
    for (c, (kind, operand)) in row0.into_iter().enumerate() {
        r.cells[0][c] = contact(kind, operand);
    }
    r.cells[0][7].element = Element::Coil { kind: CoilKind::Normal, operand: format!("Q{k}") };
    r.cells[1][0] = contact(No, format!("Q{k}"));
    r.cells[1][1] = contact(No, input(k, 6));
    // The parallel branch rejoins the first row on the left of column 2.
    r.cells[0][2].link_down = true;
    r
}

/// A project whose only program is a ladder POU of `rungs` latch rungs.
pub fn project(rungs: usize) -> Project {
    let mut declarations = String::from("VAR_INPUT\n");
    for i in 0..INPUTS {
        declarations.push_str(&format!("    I{i} : BOOL;\n"));
    }
    declarations.push_str("END_VAR\nVAR\n");
    for k in 0..rungs {
        declarations.push_str(&format!("    Q{k} : BOOL;\n"));
    }
    declarations.push_str("END_VAR\n");
    let mut p = Project::new("B4");
    p.source = String::new();
    p.ladder.push(LadderPou {
        name: "Rungs".into(),
        kind: LadderPouKind::Program,
        declarations,
        rungs: (0..rungs).map(rung).collect(),
    });
    p
}
