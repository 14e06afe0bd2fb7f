//! The reachability graph, built breadth-first with a state budget, and turned into a
//! Karp–Miller coverability graph when the net is unbounded.
//!
//! Every new marking is compared with the markings on its path from the initial marking
//! (its ancestors in the breadth-first tree); when it strictly covers one, the places that
//! grew get ω (`OMEGA`). Equal markings are merged, so for a bounded net the result is
//! exactly the reachability graph and the paths in the tree are shortest firing sequences.

use std::collections::HashMap;

use super::net::{Marking, PtNet};

/// The ω of coverability: "as many tokens as you like".
pub const OMEGA: u32 = u32::MAX;

/// A reachability (or coverability) graph.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ReachGraph {
    /// The markings, the initial one first.
    pub markings: Vec<Marking>,
    /// Edges `(from, transition, to)`.
    pub edges: Vec<(usize, usize, usize)>,
    /// For each marking but the first: the marking and transition it was first reached by.
    pub parent: Vec<Option<(usize, usize)>>,
    /// False when the budget stopped the exploration (markings remain unexplored).
    pub complete: bool,
    /// Whether some marking holds ω (the net is unbounded).
    pub has_omega: bool,
}

impl ReachGraph {
    /// The firing sequence (transition indices) from the initial marking to marking `m`.
    pub fn path_to(&self, mut m: usize) -> Vec<usize> {
        let mut path = Vec::new();
        while let Some(Some((from, t))) = self.parent.get(m) {
            path.push(*t);
            m = *from;
        }
        path.reverse();
        path
    }

    /// Successor lists: for each marking, `(transition, target)`.
    pub fn successors(&self) -> Vec<Vec<(usize, usize)>> {
        let mut out = vec![Vec::new(); self.markings.len()];
        for &(from, t, to) in &self.edges {
            out[from].push((t, to));
        }
        out
    }
}

/// `a` ≤ `b` component-wise (ω is the largest value).
fn covered_by(a: &[u32], b: &[u32]) -> bool {
    a.iter().zip(b).all(|(x, y)| x <= y)
}

#[cfg(test)]
/// Explores the markings reachable from the initial one, at most `budget` of them.
pub fn explore(net: &PtNet, budget: usize) -> ReachGraph {
    explore_with(net, budget, false)
}

/// [`explore`], told whether the net is `conservative`: covered by P-semiflows, so some
/// positive weighted token sum never changes. No marking of such a net strictly covers
/// another, so the Karp–Miller comparison with the ancestors (quadratic along long paths)
/// is skipped.
pub fn explore_with(net: &PtNet, budget: usize, conservative: bool) -> ReachGraph {
    let mut g = ReachGraph {
        markings: vec![net.initial.clone()],
        edges: Vec::new(),
        parent: vec![None],
        complete: true,
        has_omega: false,
    };
    let mut index: HashMap<Marking, usize> = HashMap::new();
    index.insert(net.initial.clone(), 0);
    let mut next = 0;
    while next < g.markings.len() {
        let here = next;
        next += 1;
        let m = g.markings[here].clone();
        for t in 0..net.transitions() {
            if !net.enabled(&m, t) {
                continue;
            }
            let mut target = net.fire(&m, t);
            if !conservative {
                accelerate(&g, here, &mut target, &net.capacity);
            }
            let to = match index.get(&target) {
                Some(&to) => to,
                None => {
                    if g.markings.len() >= budget.max(1) {
                        g.complete = false;
                        continue;
                    }
                    g.has_omega |= target.contains(&OMEGA);
                    g.markings.push(target.clone());
                    g.parent.push(Some((here, t)));
                    index.insert(target, g.markings.len() - 1);
                    g.markings.len() - 1
                }
            };
            g.edges.push((here, t, to));
        }
    }
    g
}

/// Karp–Miller acceleration: places that grew past an ancestor that `target` covers get ω.
/// An ancestor whose covering grew a place with a capacity is passed over: that growth
/// cannot be repeated without bound (the capacity stops it), and the places are explored
/// one marking at a time instead.
fn accelerate(g: &ReachGraph, from: usize, target: &mut Marking, capacity: &[Option<u32>]) {
    let mut node = Some(from);
    while let Some(a) = node {
        let ancestor = &g.markings[a];
        let capped_grew = target
            .iter()
            .zip(ancestor)
            .zip(capacity.iter().chain(std::iter::repeat(&None)))
            .any(|((x, y), c)| x > y && c.is_some());
        if ancestor != target && !capped_grew && covered_by(ancestor, target) {
            for (x, &y) in target.iter_mut().zip(ancestor) {
                if *x > y {
                    *x = OMEGA;
                }
            }
        }
        node = g.parent[a].map(|(p, _)| p);
    }
}

/// Strongly connected components (iterative Tarjan): the component index of every node,
/// and the number of components.
pub fn scc(succ: &[Vec<(usize, usize)>]) -> (Vec<usize>, usize) {
    let n = succ.len();
    let mut index = vec![usize::MAX; n];
    let mut low = vec![0usize; n];
    let mut on_stack = vec![false; n];
    let mut comp = vec![usize::MAX; n];
    let mut stack = Vec::new();
    let mut counter = 0;
    let mut comps = 0;
    for root in 0..n {
        if index[root] != usize::MAX {
            continue;
        }
        // Frames: (node, next successor position).
        let mut frames = vec![(root, 0usize)];
        index[root] = counter;
        low[root] = counter;
        counter += 1;
        stack.push(root);
        on_stack[root] = true;
        while let Some(&mut (v, ref mut pos)) = frames.last_mut() {
            if let Some(&(_, w)) = succ[v].get(*pos) {
                *pos += 1;
                if index[w] == usize::MAX {
                    index[w] = counter;
                    low[w] = counter;
                    counter += 1;
                    stack.push(w);
                    on_stack[w] = true;
                    frames.push((w, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
                continue;
            }
            frames.pop();
            if let Some(&(parent, _)) = frames.last() {
                low[parent] = low[parent].min(low[v]);
            }
            if low[v] == index[v] {
                while let Some(w) = stack.pop() {
                    on_stack[w] = false;
                    comp[w] = comps;
                    if w == v {
                        break;
                    }
                }
                comps += 1;
            }
        }
    }
    (comp, comps)
}
