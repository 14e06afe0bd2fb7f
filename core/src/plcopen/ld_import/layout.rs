//! A network → a rung grid. The part that reaches the coils is reduced to a series-parallel
//! tree and laid out from the left rail (parallel outputs right-aligned, as the editors draw
//! them). Each wired block input then gets its own network laid out on free rows below and
//! ending on the block's left edge: its branches start at the rail or tap the node of an
//! element already placed (a timer's output feeding a reset input), joined by vertical links.
//! Every placement only writes into empty cells and only links nodes that are free, so a
//! network that does not fit is reported instead of being miswired.

#![allow(clippy::needless_range_loop)] // grid code reads best with explicit indices

use std::collections::{BTreeMap, HashMap};

use super::pins::BlockEl;
use super::read::El;
use crate::ladder::{Cell, Element, Rung, DEFAULT_COLUMNS};

/// A series-parallel tree over element indices.
#[derive(Debug, Clone)]
pub(super) enum Sp {
    Leaf(usize),
    /// Wires padding a row.
    Pad(usize),
    /// The start of a branch of a wired input's network at an already placed node.
    Tap(usize),
    Series(Vec<Sp>),
    Par(Vec<Sp>),
}

/// The elements and sorted blocks of a body.
pub(super) struct Parts<'a> {
    pub els: &'a [El],
    pub blocks: &'a HashMap<usize, BlockEl>,
}

impl Parts<'_> {
    fn min_y(&self, sp: &Sp) -> f64 {
        match sp {
            Sp::Leaf(i) => self.els[*i].y,
            Sp::Pad(_) | Sp::Tap(_) => f64::INFINITY,
            Sp::Series(v) | Sp::Par(v) => {
                v.iter().map(|x| self.min_y(x)).fold(f64::INFINITY, f64::min)
            }
        }
    }

    fn height_of(&self, i: usize) -> usize {
        self.blocks.get(&i).map_or(1, |b| b.block.height.max(1) as usize)
    }

    /// Width and height of a tree (taps take no width of their own).
    pub fn size(&self, sp: &Sp) -> (usize, usize) {
        match sp {
            Sp::Leaf(i) => (1, self.height_of(*i)),
            Sp::Pad(w) => (*w, 1),
            Sp::Tap(_) => (0, 1),
            Sp::Series(v) => {
                v.iter().map(|x| self.size(x)).fold((0, 1), |(w, h), (a, b)| (w + a, h.max(b)))
            }
            Sp::Par(v) => {
                v.iter().map(|x| self.size(x)).fold((0, 0), |(w, h), (a, b)| (w.max(a), h + b))
            }
        }
    }

    /// The model element of leaf `i`.
    fn element(&self, i: usize) -> Element {
        match (&self.els[i].kind, self.blocks.get(&i)) {
            (_, Some(b)) => Element::Block(b.block.clone()),
            (super::read::Kind::Leaf(e), None) => e.clone(),
            _ => Element::Empty,
        }
    }
}

fn first_leaf(sp: &Sp) -> Option<usize> {
    match sp {
        Sp::Leaf(i) => Some(*i),
        Sp::Pad(_) | Sp::Tap(_) => None,
        Sp::Series(v) | Sp::Par(v) => v.iter().find_map(first_leaf),
    }
}

/// Series-parallel reduction of a two-terminal network `s` → `t`; on failure, the element
/// index to blame (if any).
pub(super) fn reduce(
    mut work: Vec<(usize, usize, Sp)>,
    s: usize,
    t: usize,
    parts: &Parts<'_>,
) -> Result<Sp, Option<usize>> {
    loop {
        if let [(a, b, _)] = work.as_slice() {
            if *a == s && *b == t {
                return Ok(work.pop().map_or(Sp::Series(Vec::new()), |x| x.2));
            }
        }
        let mut changed = false;
        // Parallel edges.
        let mut groups: BTreeMap<(usize, usize), Vec<Sp>> = BTreeMap::new();
        let mut order = Vec::new();
        for (a, b, sp) in work.drain(..) {
            if !groups.contains_key(&(a, b)) {
                order.push((a, b));
            }
            groups.entry((a, b)).or_default().push(sp);
        }
        for key in order {
            let Some(mut g) = groups.remove(&key) else { continue };
            if g.len() == 1 {
                if let Some(sp) = g.pop() {
                    work.push((key.0, key.1, sp));
                }
                continue;
            }
            changed = true;
            crate::order::sort_by(&mut g, |x, y| parts.min_y(x).total_cmp(&parts.min_y(y)));
            let mut flat = Vec::new();
            for sp in g {
                match sp {
                    Sp::Par(v) => flat.extend(v),
                    other => flat.push(other),
                }
            }
            work.push((key.0, key.1, Sp::Par(flat)));
        }
        // Series: an internal node with one edge in and one edge out.
        let mut k = 0;
        while k < work.len() {
            let v = work[k].1;
            if v == s || v == t {
                k += 1;
                continue;
            }
            let ins: Vec<usize> = (0..work.len()).filter(|&j| work[j].1 == v).collect();
            let outs: Vec<usize> = (0..work.len()).filter(|&j| work[j].0 == v).collect();
            if let ([i], [o]) = (ins.as_slice(), outs.as_slice()) {
                if i != o {
                    let (i, o) = (*i, *o);
                    let (hi, lo) = if i > o { (i, o) } else { (o, i) };
                    let e_hi = work.remove(hi);
                    let e_lo = work.remove(lo);
                    let (first, second) = if i > o { (e_hi, e_lo) } else { (e_lo, e_hi) };
                    let mut items = Vec::new();
                    for sp in [first.2, second.2] {
                        match sp {
                            Sp::Series(v) => items.extend(v),
                            other => items.push(other),
                        }
                    }
                    work.push((first.0, second.1, Sp::Series(items)));
                    changed = true;
                    k = 0;
                    continue;
                }
            }
            k += 1;
        }
        if !changed {
            // Blame an element at a node that blocks the reduction.
            let blame = work
                .iter()
                .find(|(a, b, _)| {
                    let bad = |v: usize| {
                        v != s
                            && v != t
                            && (work.iter().filter(|e| e.1 == v).count() != 1
                                || work.iter().filter(|e| e.0 == v).count() != 1)
                    };
                    bad(*a) || bad(*b) || a == b
                })
                .or_else(|| work.first())
                .and_then(|e| first_leaf(&e.2));
            return Err(blame);
        }
    }
}

/// A rung being laid out: its cells and where each element went.
#[derive(Debug, Clone)]
pub(super) struct Grid {
    pub cells: Vec<Vec<Cell>>,
    /// `(row, column)` of each placed element.
    pub pos: HashMap<usize, (usize, usize)>,
}

impl Grid {
    fn new(rows: usize, cols: usize) -> Self {
        Grid { cells: vec![vec![Cell::default(); cols]; rows], pos: HashMap::new() }
    }

    fn cols(&self) -> usize {
        self.cells.first().map_or(0, Vec::len)
    }

    pub fn ensure_rows(&mut self, rows: usize) {
        let cols = self.cols();
        while self.cells.len() < rows {
            self.cells.push(vec![Cell::default(); cols]);
        }
    }

    fn is_empty(&self, r: usize, c: usize) -> bool {
        self.cells.get(r).and_then(|row| row.get(c)).is_some_and(|x| x.element == Element::Empty)
    }

    fn put(&mut self, r: usize, c: usize, e: Element) -> Result<(), ()> {
        if !self.is_empty(r, c) {
            return Err(());
        }
        self.cells[r][c].element = e;
        Ok(())
    }

    fn leaf(&mut self, i: usize, r: usize, c: usize, parts: &Parts<'_>) -> Result<(), ()> {
        let e = parts.element(i);
        if let Element::Block(b) = &e {
            for k in 1..b.height.max(1) as usize {
                self.ensure_rows(r + k + 1);
                self.put(r + k, c, Element::Covered)?;
            }
        }
        self.put(r, c, e)?;
        self.pos.insert(i, (r, c));
        Ok(())
    }

    /// Lays `sp` out from `(row, col)`; `at_end` right-aligns parallel outputs.
    pub fn place(
        &mut self,
        sp: &Sp,
        row: usize,
        col: usize,
        at_end: bool,
        parts: &Parts<'_>,
    ) -> Result<(), ()> {
        match sp {
            Sp::Leaf(i) => self.leaf(*i, row, col, parts),
            Sp::Pad(w) => (col..col + w).try_for_each(|c| self.put(row, c, Element::Wire)),
            Sp::Tap(_) => Err(()),
            Sp::Series(v) => {
                let mut c = col;
                for (k, item) in v.iter().enumerate() {
                    self.place(item, row, c, at_end && k + 1 == v.len(), parts)?;
                    c += parts.size(item).0;
                }
                Ok(())
            }
            Sp::Par(v) => {
                let width = parts.size(sp).0;
                let tops = stacked(row, v.iter().map(|b| parts.size(b).1));
                let last_top = tops.last().copied().unwrap_or(row);
                self.ensure_rows(row + parts.size(sp).1);
                if col + width > self.cols() || (!at_end && col + width >= self.cols()) {
                    return Err(());
                }
                let nodes = Nodes::new(self, &[]);
                let mut sides = vec![col];
                if !at_end {
                    sides.push(col + width);
                }
                for &c in &sides {
                    let to = nodes.class(row, c);
                    if (row..=last_top).any(|rr| !nodes.joinable(rr, c, to)) {
                        return Err(());
                    }
                }
                for (b, &r) in v.iter().zip(&tops) {
                    let w = parts.size(b).0;
                    if at_end {
                        // Outputs are right-aligned; the wire runs from the fork.
                        for c in col..col + width - w {
                            self.put(r, c, Element::Wire)?;
                        }
                        self.place(b, r, col + width - w, true, parts)?;
                    } else {
                        self.place(b, r, col, false, parts)?;
                        for c in col + w..col + width {
                            self.put(r, c, Element::Wire)?;
                        }
                    }
                }
                for &c in &sides {
                    self.link(row, last_top, c);
                }
                Ok(())
            }
        }
    }
}

/// Lays out the tree of the part of a network that reaches the coils, padded to the default
/// width.
pub(super) fn main_grid(tree: Sp, parts: &Parts<'_>) -> Result<Grid, ()> {
    let (w, _) = parts.size(&tree);
    let tree = if w < DEFAULT_COLUMNS as usize {
        let pad = Sp::Pad(DEFAULT_COLUMNS as usize - w);
        match tree {
            Sp::Series(mut v) => {
                let last = v.pop();
                v.push(pad);
                v.extend(last);
                Sp::Series(v)
            }
            other => Sp::Series(vec![pad, other]),
        }
    } else {
        tree
    };
    let (w, h) = parts.size(&tree);
    let mut grid = Grid::new(h, w);
    grid.place(&tree, 0, 0, true, parts)?;
    Ok(grid)
}

/// Grid nodes merged by vertical links and the rail, and which of them are used.
struct Nodes {
    class: Vec<usize>,
    used: Vec<bool>,
    cols: usize,
}

impl Nodes {
    fn new(grid: &Grid, pins: &[(usize, usize)]) -> Self {
        let rows = grid.cells.len();
        let (cols, class) = super::verify::grid_classes(&grid.cells);
        let id = |r: usize, c: usize| r * cols + c;
        let mut used = vec![false; rows * cols];
        for r in 0..rows {
            for c in 0..cols - 1 {
                if !matches!(grid.cells[r][c].element, Element::Empty | Element::Covered) {
                    used[id(r, c)] = true;
                    used[id(r, c + 1)] = true;
                }
            }
        }
        for &(r, c) in pins {
            if r < rows && c < cols {
                used[id(r, c)] = true;
            }
        }
        let mut class_used = vec![false; rows * cols];
        for x in 0..rows * cols {
            if used[x] {
                class_used[class[x]] = true;
            }
        }
        // The rail is always in use.
        if let Some(&k) = class.first() {
            class_used[k] = true;
        }
        Nodes { class, used: class_used, cols }
    }

    fn class(&self, r: usize, c: usize) -> usize {
        self.class[r * self.cols + c]
    }

    /// Whether node `(r, c)` may be joined to the node of class `to`.
    fn joinable(&self, r: usize, c: usize, to: usize) -> bool {
        let k = self.class(r, c);
        k == to || !self.used[k]
    }
}

/// Where a wired input's network goes: the grid positions of the nodes it may tap.
pub(super) struct PinJob<'a> {
    /// Grid position of each placed node (the right edge of an element feeding it).
    pub node_pos: &'a HashMap<usize, (usize, usize)>,
    /// The rail's node id.
    pub rail: usize,
    /// The pin nodes already wired, as grid positions (they must not be joined).
    pub pins: Vec<(usize, usize)>,
}

impl Grid {
    /// Links rows `a` and `b` at column `c` (either order).
    fn link(&mut self, a: usize, b: usize, c: usize) {
        for rr in a.min(b)..a.max(b) {
            if let Some(cell) = self.cells.get_mut(rr).and_then(|row| row.get_mut(c)) {
                cell.link_down = true;
            }
        }
    }

    /// Lays out a wired input's network `sp` with its right end on column boundary `end` and
    /// its top branch on `row`: branches start at their taps.
    pub fn place_right(
        &mut self,
        sp: &Sp,
        row: usize,
        end: usize,
        job: &PinJob<'_>,
        parts: &Parts<'_>,
    ) -> Result<(), ()> {
        match sp {
            Sp::Tap(u) => self.tap(*u, row, end, job),
            Sp::Leaf(_) | Sp::Pad(_) => {
                let w = parts.size(sp).0;
                if w > end {
                    return Err(());
                }
                self.place(sp, row, end - w, false, parts)
            }
            Sp::Series(items) => {
                let mut e = end;
                for (k, item) in items.iter().enumerate().rev() {
                    if k == 0 {
                        self.place_right(item, row, e, job, parts)?;
                    } else {
                        let w = parts.size(item).0;
                        if w > e {
                            return Err(());
                        }
                        self.place(item, row, e - w, false, parts)?;
                        e -= w;
                    }
                }
                Ok(())
            }
            Sp::Par(branches) => {
                let tops = stacked(row, branches.iter().map(|b| tree_height(b, parts)));
                let last_top = tops.last().copied().unwrap_or(row);
                self.ensure_rows(row + tree_height(sp, parts));
                let nodes = Nodes::new(self, &job.pins);
                let to = nodes.class(row, end);
                if (row..=last_top).any(|rr| !nodes.joinable(rr, end, to)) {
                    return Err(());
                }
                for (b, &r) in branches.iter().zip(&tops) {
                    self.place_right(b, r, end, job, parts)?;
                }
                self.link(row, last_top, end);
                Ok(())
            }
        }
    }

    /// The start of a branch at node `u`: wires from the node's column to `end` on `row`, and
    /// a vertical link from where the node is to `row`.
    fn tap(&mut self, u: usize, row: usize, end: usize, job: &PinJob<'_>) -> Result<(), ()> {
        let (ru, cu) = if u == job.rail { (row, 0) } else { *job.node_pos.get(&u).ok_or(())? };
        if cu > end {
            return Err(());
        }
        if ru != row {
            // Nothing else may lead into the branch's start, and the rows the link passes
            // must be free or already this node.
            if cu > 0
                && !matches!(self.cells[row][cu - 1].element, Element::Empty | Element::Covered)
            {
                return Err(());
            }
            let nodes = Nodes::new(self, &job.pins);
            let to = nodes.class(ru, cu);
            let (lo, hi) = (ru.min(row), ru.max(row));
            if (lo..=hi).filter(|&rr| rr != row).any(|rr| !nodes.joinable(rr, cu, to)) {
                return Err(());
            }
        }
        for c in cu..end {
            self.put(row, c, Element::Wire)?;
        }
        if ru != row {
            self.link(ru, row, cu);
        }
        Ok(())
    }
}

/// The top rows of branches of these heights stacked from `row` down.
fn stacked(row: usize, heights: impl Iterator<Item = usize>) -> Vec<usize> {
    heights
        .scan(row, |r, h| {
            let top = *r;
            *r += h;
            Some(top)
        })
        .collect()
}

/// Rows a wired input's tree needs.
pub(super) fn tree_height(sp: &Sp, parts: &Parts<'_>) -> usize {
    match sp {
        Sp::Tap(_) => 1,
        Sp::Leaf(_) | Sp::Pad(_) => parts.size(sp).1,
        Sp::Series(v) => v.iter().map(|x| tree_height(x, parts)).max().unwrap_or(1),
        Sp::Par(v) => v.iter().map(|x| tree_height(x, parts)).sum(),
    }
}

/// The finished rung.
pub(super) fn into_rung(grid: Grid) -> Rung {
    Rung { comment: String::new(), label: None, cells: grid.cells }
}
