//! The electrical view of a rung shared by validation, lowering and the ST view: nodes
//! merged by vertical links, elements as edges between nodes, power reachability.

use super::model::{Element, Rung};

/// The node id of the left rail.
pub(crate) const RAIL: usize = 0;

/// One element of a rung placed in the grid.
#[derive(Debug, Clone)]
pub(crate) struct Placed<'a> {
    pub row: usize,
    pub col: usize,
    pub element: &'a Element,
    /// Node on the element's left.
    pub input: usize,
    /// Node on the element's right.
    pub output: usize,
}

/// A rung's nodes and elements.
#[derive(Debug)]
pub(crate) struct Network<'a> {
    /// Elements in evaluation order: column by column, top to bottom.
    pub elements: Vec<Placed<'a>>,
    /// Whether power from the rail reaches a node.
    pub powered: Vec<bool>,
    /// Whether every power path to a node passes a condition (contact or block).
    pub conditioned: Vec<bool>,
    /// Topmost `(row, col)` of each node.
    pub place: Vec<(usize, usize)>,
}

/// Whether an element ends its row (nothing may follow it).
pub(crate) fn is_terminal(e: &Element) -> bool {
    matches!(e, Element::Coil { .. } | Element::Jump { .. } | Element::Return)
}

impl<'a> Network<'a> {
    /// Builds the network of a rung (rows of unequal length are read as far as they go).
    #[allow(clippy::needless_range_loop)]
    pub fn new(rung: &'a Rung) -> Self {
        let rows = rung.rows();
        let cols = rung.cells.iter().map(Vec::len).max().unwrap_or(0);
        let mut node = Vec::with_capacity(cols + 1);
        let mut place = vec![(0, 0)];
        node.push(vec![RAIL; rows]);
        for c in 1..=cols {
            let mut col = Vec::with_capacity(rows);
            for r in 0..rows {
                let linked = r > 0 && rung.cell(r - 1, c).is_some_and(|cell| cell.link_down);
                if linked {
                    let above = col[r - 1];
                    col.push(above);
                } else {
                    col.push(place.len());
                    place.push((r, c));
                }
            }
            node.push(col);
        }
        let mut elements = Vec::new();
        for c in 0..cols {
            for r in 0..rows {
                let Some(cell) = rung.cell(r, c) else { continue };
                if matches!(cell.element, Element::Empty | Element::Covered) {
                    continue;
                }
                elements.push(Placed {
                    row: r,
                    col: c,
                    element: &cell.element,
                    input: node[c][r],
                    output: node[c + 1][r],
                });
            }
        }
        let n = place.len();
        let mut powered = vec![false; n];
        let mut conditioned = vec![true; n];
        powered[RAIL] = true;
        conditioned[RAIL] = false;
        for e in &elements {
            if !powered[e.input] {
                continue;
            }
            let cond = conditioned[e.input]
                || matches!(e.element, Element::Contact { .. } | Element::Block(_));
            if !powered[e.output] {
                powered[e.output] = true;
                conditioned[e.output] = cond;
            } else {
                conditioned[e.output] &= cond;
            }
        }
        Network { elements, powered, conditioned, place }
    }

    /// Whether some element takes its power from `node`.
    pub fn consumed(&self, node: usize) -> bool {
        self.elements.iter().any(|e| e.input == node)
    }

    /// The powered elements feeding `node`.
    pub fn feeders(&self, node: usize) -> impl Iterator<Item = (usize, &Placed<'a>)> {
        self.elements
            .iter()
            .enumerate()
            .filter(move |(_, e)| e.output == node && self.powered[e.input])
    }

    /// `None` when the powered part of the network is series-parallel; otherwise the node
    /// where the reduction got stuck.
    pub fn non_series_parallel(&self) -> Option<usize> {
        let sink = self.place.len();
        let mut edges: Vec<(usize, usize)> = Vec::new();
        for e in self.elements.iter().filter(|e| self.powered[e.input]) {
            let out = if is_terminal(e.element) { sink } else { e.output };
            edges.push((e.input, out));
        }
        // Dead ends (a block with nothing after it) end at the sink.
        let ends: Vec<usize> = edges
            .iter()
            .map(|&(_, v)| v)
            .filter(|&v| v != sink && !edges.iter().any(|&(u, _)| u == v))
            .collect();
        for edge in &mut edges {
            if ends.contains(&edge.1) {
                edge.1 = sink;
            }
        }
        loop {
            let before = edges.len();
            edges.sort_unstable();
            edges.dedup();
            let mut changed = edges.len() != before;
            let mut inner: Vec<usize> = edges
                .iter()
                .flat_map(|&(u, v)| [u, v])
                .filter(|&x| x != RAIL && x != sink)
                .collect();
            inner.sort_unstable();
            inner.dedup();
            for x in inner {
                let ins: Vec<usize> = (0..edges.len()).filter(|&i| edges[i].1 == x).collect();
                let outs: Vec<usize> = (0..edges.len()).filter(|&i| edges[i].0 == x).collect();
                if ins.len() == 1 && outs.len() == 1 {
                    let (a, b) = (edges[ins[0]].0, edges[outs[0]].1);
                    edges[ins[0]] = (a, b);
                    edges.remove(outs[0]);
                    changed = true;
                    break;
                }
            }
            if !changed {
                break;
            }
        }
        if edges.len() <= 1 {
            return None;
        }
        edges.iter().flat_map(|&(u, v)| [u, v]).filter(|&x| x != RAIL && x != sink).min_by_key(
            |&x| {
                let (r, c) = self.place[x];
                (c, r)
            },
        )
    }
}
