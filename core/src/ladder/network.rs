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

/// A block input wired to a contact network: it consumes the power of `node`.
#[derive(Debug, Clone)]
pub(crate) struct PinSink {
    /// Index of the block in [`Network::elements`].
    pub block: usize,
    /// Index of the pin in the block's inputs.
    pub pin: usize,
    /// Grid row of the pin (the block's row plus its `wired_row`).
    pub row: usize,
    /// The block's column.
    pub col: usize,
    /// The node whose power the pin takes.
    pub node: usize,
}

/// A rung's nodes and elements.
#[derive(Debug)]
pub(crate) struct Network<'a> {
    /// Elements in evaluation order: column by column, top to bottom.
    pub elements: Vec<Placed<'a>>,
    /// Wired block inputs, in the order of their blocks.
    pub pins: Vec<PinSink>,
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
        let mut pins = Vec::new();
        for (i, e) in elements.iter().enumerate() {
            let Element::Block(b) = e.element else { continue };
            for (k, p) in b.inputs.iter().enumerate() {
                let Some(w) = p.wired_row else { continue };
                let row = e.row + w as usize;
                if w == 0 || w >= b.height.max(1) || row >= rows {
                    continue; // reported by validation
                }
                pins.push(PinSink { block: i, pin: k, row, col: e.col, node: node[e.col][row] });
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
        Network { elements, pins, powered, conditioned, place }
    }

    /// Whether some element or wired block input takes its power from `node`.
    pub fn consumed(&self, node: usize) -> bool {
        self.elements.iter().any(|e| e.input == node) || self.pins.iter().any(|p| p.node == node)
    }

    /// The wired input `pin` of the block at `elements[block]`, if it is wired and in the grid.
    pub fn pin_node(&self, block: usize, pin: usize) -> Option<usize> {
        self.pins.iter().find(|p| p.block == block && p.pin == pin).map(|p| p.node)
    }

    /// The powered elements feeding `node`.
    pub fn feeders(&self, node: usize) -> impl Iterator<Item = (usize, &Placed<'a>)> {
        self.elements
            .iter()
            .enumerate()
            .filter(move |(_, e)| e.output == node && self.powered[e.input])
    }

    /// `None` when the network feeding every output (a coil, jump or return, a wired block
    /// input, or a block with nothing after it) is series-parallel between the rail and that
    /// output; otherwise the node where the reduction got stuck. Each output is checked on its
    /// own cone, so outputs may share the beginning of their paths (a timer's output feeding
    /// both a coil and another block's reset input).
    pub fn non_series_parallel(&self) -> Option<usize> {
        let n = self.place.len();
        let live: Vec<&Placed<'a>> =
            self.elements.iter().filter(|e| self.powered[e.input]).collect();
        // Sinks get ids from `n` up; every output gets its own.
        let mut next_sink = n;
        let mut edges: Vec<(usize, usize)> = Vec::new();
        for e in &live {
            if is_terminal(e.element) {
                edges.push((e.input, next_sink));
                next_sink += 1;
            } else {
                edges.push((e.input, e.output));
            }
        }
        for p in self.pins.iter().filter(|p| self.powered[p.node]) {
            edges.push((p.node, next_sink));
            next_sink += 1;
        }
        let mut sinks: Vec<usize> = (n..next_sink).collect();
        // Dead ends (a block with nothing after it) are outputs too.
        let mut ends: Vec<usize> = edges
            .iter()
            .map(|&(_, v)| v)
            .filter(|&v| v < n && !edges.iter().any(|&(u, _)| u == v))
            .collect();
        crate::order::sort(&mut ends);
        ends.dedup();
        sinks.extend(ends);
        for sink in sinks {
            // The cone of the sink: every edge from which it can be reached.
            let mut reach = vec![false; next_sink];
            reach[sink] = true;
            loop {
                let mut changed = false;
                for &(u, v) in &edges {
                    if reach[v] && !reach[u] {
                        reach[u] = true;
                        changed = true;
                    }
                }
                if !changed {
                    break;
                }
            }
            let cone: Vec<(usize, usize)> =
                edges.iter().copied().filter(|&(_, v)| reach[v]).collect();
            if let Some(node) = self.stuck_node(cone, sink) {
                return Some(node);
            }
        }
        None
    }

    /// Series-parallel reduction of `edges` between the rail and `sink`: `None` when it
    /// reduces to one edge, else the leftmost node where it got stuck.
    fn stuck_node(&self, mut edges: Vec<(usize, usize)>, sink: usize) -> Option<usize> {
        loop {
            let before = edges.len();
            crate::order::sort(&mut edges);
            edges.dedup();
            let mut changed = edges.len() != before;
            let mut inner: Vec<usize> = edges
                .iter()
                .flat_map(|&(u, v)| [u, v])
                .filter(|&x| x != RAIL && x != sink)
                .collect();
            crate::order::sort(&mut inner);
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
        let n = self.place.len();
        edges
            .iter()
            .flat_map(|&(u, v)| [u, v])
            .filter(|&x| x != RAIL && x != sink && x < n)
            .min_by_key(|&x| {
                let (r, c) = self.place[x];
                (c, r)
            })
    }
}
