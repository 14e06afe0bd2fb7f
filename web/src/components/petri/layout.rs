//! Where a net's places and transitions are drawn: at the positions stored in the model
//! when every place and transition has one, else by a simple deterministic layered layout.
//!
//! The layered layout (a small Sugiyama): breadth-first layers from the initially marked
//! places along the arcs (places and transitions alternate), then a few sweeps ordering
//! each layer by the mean position of its neighbours in the layer before (downwards) and
//! after (upwards), ties kept in model order; layers are centred under the widest one.

use std::collections::HashMap;
use std::collections::VecDeque;

use plc_core::petri::Net;

/// A point in the drawing's coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Point {
    /// Horizontal coordinate.
    pub x: f64,
    /// Vertical coordinate.
    pub y: f64,
}

/// The centres of a net's places and transitions, in model order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct NetLayout {
    /// Per place.
    pub places: Vec<Point>,
    /// Per transition.
    pub transitions: Vec<Point>,
    /// True when the layout was computed (the model had no positions).
    pub automatic: bool,
}

/// Distance between two elements of a layer.
pub const LAYER_DX: f64 = 130.0;
/// Distance between two layers.
pub const LAYER_DY: f64 = 80.0;
/// Where the first layer and element are placed.
const ORIGIN: f64 = 60.0;
/// Ordering sweeps (each one down and one up).
const SWEEPS: usize = 3;

/// The layout of a net (see the module comment).
pub fn layout(net: &Net) -> NetLayout {
    let stored_places: Option<Vec<Point>> =
        net.places.iter().map(|p| p.position.map(|q| Point { x: q.x, y: q.y })).collect();
    let stored_transitions: Option<Vec<Point>> =
        net.transitions.iter().map(|t| t.position.map(|q| Point { x: q.x, y: q.y })).collect();
    match (stored_places, stored_transitions) {
        (Some(places), Some(transitions)) => NetLayout { places, transitions, automatic: false },
        _ => layered(net),
    }
}

/// The nodes' neighbours: places are `0..P`, transitions `P..P+T`.
fn neighbours(net: &Net) -> (Vec<Vec<usize>>, Vec<Vec<usize>>) {
    let n_p = net.places.len();
    let mut index: HashMap<&str, usize> = HashMap::new();
    for (i, t) in net.transitions.iter().enumerate().rev() {
        index.insert(t.id.as_str(), n_p + i);
    }
    for (i, p) in net.places.iter().enumerate().rev() {
        index.insert(p.id.as_str(), i);
    }
    let n = n_p + net.transitions.len();
    let mut succ = vec![Vec::new(); n];
    let mut pred = vec![Vec::new(); n];
    for arc in &net.arcs {
        let (Some(&a), Some(&b)) = (index.get(arc.from.as_str()), index.get(arc.to.as_str()))
        else {
            continue;
        };
        if a != b && !succ[a].contains(&b) {
            succ[a].push(b);
            pred[b].push(a);
        }
    }
    (succ, pred)
}

/// Breadth-first search from `starts` (all on layer 0) over nodes not reached yet.
fn visit(
    starts: &[usize],
    succ: &[Vec<usize>],
    layer: &mut [Option<usize>],
    order: &mut Vec<usize>,
) {
    let mut queue: VecDeque<usize> = VecDeque::new();
    for &s in starts {
        if layer[s].is_none() {
            layer[s] = Some(0);
            order.push(s);
            queue.push_back(s);
        }
    }
    while let Some(u) = queue.pop_front() {
        let next = layer[u].unwrap_or(0) + 1;
        for &v in &succ[u] {
            if layer[v].is_none() {
                layer[v] = Some(next);
                order.push(v);
                queue.push_back(v);
            }
        }
    }
}

/// Breadth-first layers from the marked places, then from each node not reached yet.
fn layers(net: &Net, succ: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = succ.len();
    let mut layer: Vec<Option<usize>> = vec![None; n];
    let mut order: Vec<usize> = Vec::with_capacity(n);
    let marked: Vec<usize> = (0..net.places.len()).filter(|&p| net.places[p].tokens > 0).collect();
    visit(&marked, succ, &mut layer, &mut order);
    for s in 0..n {
        visit(&[s], succ, &mut layer, &mut order);
    }
    let depth = layer.iter().flatten().max().map_or(0, |d| d + 1);
    let mut out = vec![Vec::new(); depth];
    for v in order {
        if let Some(l) = layer[v] {
            out[l].push(v);
        }
    }
    out
}

/// Orders layer `l` by the mean position of each node's neighbours in `reference`.
fn order_by(layer: &mut [usize], neighbours: &[Vec<usize>], reference: &[usize]) {
    let pos: HashMap<usize, usize> = reference.iter().enumerate().map(|(i, &v)| (v, i)).collect();
    let mut keyed: Vec<(f64, usize, usize)> = layer
        .iter()
        .enumerate()
        .map(|(i, &v)| {
            let ps: Vec<f64> =
                neighbours[v].iter().filter_map(|u| pos.get(u)).map(|&p| p as f64).collect();
            let key =
                if ps.is_empty() { i as f64 } else { ps.iter().sum::<f64>() / ps.len() as f64 };
            (key, i, v)
        })
        .collect();
    plc_core::order::sort_by(&mut keyed, |a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    for (slot, (_, _, v)) in layer.iter_mut().zip(keyed) {
        *slot = v;
    }
}

fn layered(net: &Net) -> NetLayout {
    let (succ, pred) = neighbours(net);
    let mut layers = layers(net, &succ);
    for _ in 0..SWEEPS {
        for l in 1..layers.len() {
            let (before, rest) = layers.split_at_mut(l);
            order_by(&mut rest[0], &pred, &before[l - 1]);
        }
        for l in (0..layers.len().saturating_sub(1)).rev() {
            let (head, after) = layers.split_at_mut(l + 1);
            order_by(&mut head[l], &succ, &after[0]);
        }
    }
    let widest = layers.iter().map(Vec::len).max().unwrap_or(0) as f64;
    let n_p = net.places.len();
    let mut places = vec![Point::default(); n_p];
    let mut transitions = vec![Point::default(); net.transitions.len()];
    for (l, nodes) in layers.iter().enumerate() {
        let shift = (widest - nodes.len() as f64) / 2.0;
        for (i, &v) in nodes.iter().enumerate() {
            let p = Point {
                x: ORIGIN + (i as f64 + shift) * LAYER_DX,
                y: ORIGIN + l as f64 * LAYER_DY,
            };
            if v < n_p {
                places[v] = p;
            } else {
                transitions[v - n_p] = p;
            }
        }
    }
    NetLayout { places, transitions, automatic: true }
}

#[cfg(test)]
mod tests;
