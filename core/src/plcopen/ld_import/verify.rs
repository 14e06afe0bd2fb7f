//! The check that a laid-out rung is wired as the file says: every element (and every wired
//! block input) gets its power from exactly the elements the file wires to it, looking
//! through the horizontal wires the layout added. A layout bug or a crossing the grid cannot
//! draw is reported here instead of running a different program.

use std::collections::{BTreeSet, HashMap};

use super::super::union_find::UnionFind;
use crate::ladder::{Cell, Element, Rung};

/// Who feeds something: the rail (`None`) or element indices.
pub(super) type Feeders = BTreeSet<Option<usize>>;

/// The class of every grid node `(row, column boundary)` of `cells` (index
/// `row * (columns + 1) + column`): nodes joined by vertical links, and the rail column, share
/// one. Returns the row stride and the classes.
pub(super) fn grid_classes(cells: &[Vec<Cell>]) -> (usize, Vec<usize>) {
    let rows = cells.len();
    let cols = cells.first().map_or(0, Vec::len) + 1;
    let mut uf = UnionFind::new(rows * cols);
    for r in 0..rows {
        uf.union(0, r * cols);
        for c in 0..cols - 1 {
            if cells[r].get(c).is_some_and(|x| x.link_down) && r + 1 < rows {
                uf.union(r * cols + c, (r + 1) * cols + c);
            }
        }
    }
    (cols, (0..rows * cols).map(|x| uf.find(x)).collect())
}

/// Grid nodes of a rung merged by vertical links and the rail.
struct GridNet {
    cols: usize,
    class: Vec<usize>,
}

impl GridNet {
    fn new(rung: &Rung) -> Self {
        let (cols, class) = grid_classes(&rung.cells);
        GridNet { cols, class }
    }

    fn class(&self, r: usize, c: usize) -> usize {
        self.class[r * self.cols + c]
    }
}

/// The feeders of grid node `(r, c)`: elements whose right edge is on its class, seen
/// through wires; `None` for the rail. `at` maps grid cells back to element indices.
fn grid_feeders(
    rung: &Rung,
    net: &GridNet,
    at: &HashMap<(usize, usize), usize>,
    r: usize,
    c: usize,
) -> Feeders {
    let mut out = Feeders::new();
    let mut todo = vec![net.class(r, c)];
    let mut seen = Vec::new();
    while let Some(k) = todo.pop() {
        if seen.contains(&k) {
            continue;
        }
        seen.push(k);
        if k == net.class(0, 0) {
            out.insert(None);
        }
        for rr in 0..rung.rows() {
            for cc in 0..rung.columns() {
                if net.class(rr, cc + 1) != k {
                    continue;
                }
                match &rung.cells[rr][cc].element {
                    Element::Wire => todo.push(net.class(rr, cc)),
                    Element::Empty | Element::Covered => {}
                    _ => {
                        if let Some(&i) = at.get(&(rr, cc)) {
                            out.insert(Some(i));
                        }
                    }
                }
            }
        }
    }
    out
}

/// One thing to check: a grid position whose power must come from `want`.
pub(super) struct Expect {
    /// The grid node (row, column boundary).
    pub node: (usize, usize),
    /// The feeders the file wires to it.
    pub want: Feeders,
    /// The element to blame.
    pub blame: usize,
}

/// `Err(blame)` for the first expectation the rung does not meet.
pub(super) fn check(
    rung: &Rung,
    pos: &HashMap<usize, (usize, usize)>,
    expects: &[Expect],
) -> Result<(), usize> {
    let net = GridNet::new(rung);
    let at: HashMap<(usize, usize), usize> = pos.iter().map(|(&i, &p)| (p, i)).collect();
    for e in expects {
        let got = grid_feeders(rung, &net, &at, e.node.0, e.node.1);
        if got != e.want {
            return Err(e.blame);
        }
    }
    Ok(())
}
