//! LD bodies → rungs. The stages, one file each:
//! - `read`: XML elements and their `refLocalId` wiring (connectors resolved);
//! - `pins`: block pins sorted into power, wired inputs, variables and data wires;
//! - here: the electrical graph, split into networks (one rung each, ordered top to bottom
//!   and so that a block feeding another by a data wire runs first);
//! - `layout`: each network reduced to a series-parallel tree and laid onto the grid, with
//!   the networks of wired block inputs below;
//! - `verify`: the laid-out rung is checked against the file's wiring.

#![allow(clippy::needless_range_loop)] // graph code reads best with explicit indices

mod layout;
mod pins;
pub(crate) mod read;
mod verify;

use std::collections::{BTreeMap, HashMap};

use super::union_find::UnionFind;
use super::xml::Node;
use super::{ImportError, ImportNote};
use crate::diagnostics::Said;
use crate::ladder::catalog::Catalog;
use crate::ladder::{Element, Rung, DEFAULT_COLUMNS, DEFAULT_ROWS};
use layout::{Grid, Parts, PinJob, Sp};
use read::{Conn, El, Kind};
use verify::{Expect, Feeders};

/// A laid-out LD body.
pub(crate) struct LdBody {
    /// The rungs, top to bottom.
    pub rungs: Vec<Rung>,
    /// Declarations (`    name : TYPE;`) of the variables created for data wires from
    /// function outputs.
    pub declarations: Vec<String>,
    /// Where each placed element came from.
    pub origins: Vec<Origin>,
}

/// A placed element's cell (rung, row, column) and its line and column in the file.
pub(crate) type Origin = ((usize, usize, usize), (u32, u32));

/// The electrical graph: element `i` is an edge `in_node[i]` → `out_node[i]`; wired block
/// inputs consume `pin_node[(block, input)]`.
struct Graph {
    s: usize,
    t: usize,
    in_node: Vec<usize>,
    out_node: Vec<usize>,
    pin_node: HashMap<(usize, usize), usize>,
    alive: Vec<usize>,
}

impl Graph {
    /// The file's feeders of node `n` among `edges`.
    fn feeders(&self, n: usize, edges: &[usize]) -> Feeders {
        let mut f: Feeders =
            edges.iter().filter(|&&j| self.out_node[j] == n).map(|&j| Some(j)).collect();
        if n == self.s {
            f.insert(None);
        }
        f
    }
}

/// Lays out one LD body as rungs. `declarations` are the POU's own (for the types of data
/// wires); `catalog` knows the project's block types.
pub(crate) fn import_ld(
    ld: &Node,
    pou: &str,
    catalog: &Catalog,
    declarations: &str,
    warnings: &mut Vec<ImportNote>,
) -> Result<LdBody, ImportError> {
    let (mut els, left_out) = read::read_elements(ld, pou)?;
    warnings.extend(left_out);
    // The grid's blocks read their pins as they are: a negated or edge-triggered pin keeps
    // the network off the grid.
    for e in &els {
        if let Kind::Block(b) = &e.kind {
            if let Some((p, _)) = b.modified.first() {
                return Err(ImportError::Element {
                    pou: pou.into(),
                    local_id: e.id.clone(),
                    message: crate::msg!(PlcopenPinModified, pin = p),
                });
            }
        }
    }
    let mut index: HashMap<String, usize> = HashMap::new();
    for (i, e) in els.iter().enumerate() {
        if e.id.is_empty() {
            continue;
        }
        if index.insert(e.id.clone(), i).is_some() && !matches!(els[i].kind, Kind::Comment(_)) {
            return Err(ImportError::Element {
                pou: pou.into(),
                local_id: e.id.clone(),
                message: crate::msg!(PlcopenDuplicateLocalId),
            });
        }
    }
    let mut ctx = pins::Ctx { pou, catalog, scope: catalog.scope(declarations) };
    let sorted = pins::sort_pins(&mut els, &mut index, &mut ctx, warnings)?;
    let err = |id: &str, message: Said| ImportError::Element {
        pou: pou.to_string(),
        local_id: id.to_string(),
        message,
    };
    let graph = build_graph(&els, &index, &sorted.blocks, pou, warnings)?;
    let parts = Parts { els: &els, blocks: &sorted.blocks };

    // Networks: edges sharing an internal node (a wired input joins its block's network).
    let alive = &graph.alive;
    let mut comp = UnionFind::default();
    for _ in 0..alive.len() {
        comp.add();
    }
    let mut by_node: HashMap<usize, usize> = HashMap::new();
    for (k, &i) in alive.iter().enumerate() {
        let mut nodes = vec![graph.in_node[i], graph.out_node[i]];
        nodes.extend(graph.pin_node.iter().filter(|((b, _), _)| *b == i).map(|(_, &n)| n));
        for node in nodes {
            if node == graph.s || node == graph.t {
                continue;
            }
            match by_node.get(&node) {
                Some(&other) => comp.union(other, k),
                None => {
                    by_node.insert(node, k);
                }
            }
        }
    }
    let mut groups: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for k in 0..alive.len() {
        let root = comp.find(k);
        groups.entry(root).or_default().push(alive[k]);
    }
    let mut networks: Vec<(f64, Vec<usize>)> = groups
        .into_values()
        .map(|g| (g.iter().map(|&i| els[i].y).fold(f64::INFINITY, f64::min), g))
        .collect();
    crate::order::sort_by(&mut networks, |a, b| a.0.total_cmp(&b.0));
    order_by_data(&mut networks, &sorted.data);

    let mut rungs = Vec::new();
    let mut origins = Vec::new();
    for (_, edges) in &networks {
        let (rung, pos) =
            layout_network(&graph, edges, &parts).map_err(|(i, m)| err(&els[i].id, m))?;
        for (&i, &(r, c)) in &pos {
            if let Some(e) = els.get(i) {
                origins.push(((rungs.len(), r, c), e.at));
            }
        }
        for &(a, b) in &sorted.data {
            if let (Some(&(_, ca)), Some(&(_, cb))) = (pos.get(&a), pos.get(&b)) {
                if ca >= cb {
                    return Err(err(
                        &els[b].id,
                        crate::msg!(PlcopenDataWireRunsFirst, source = &els[a].id),
                    ));
                }
            }
        }
        rungs.push(rung);
    }
    for (r, rung) in rungs.iter().enumerate() {
        if rung.rows() > DEFAULT_ROWS as usize || rung.columns() > DEFAULT_COLUMNS as usize {
            warnings.push(ImportNote::on(
                ld,
                crate::msg!(
                    PlcopenRungTooLarge,
                    pou = pou,
                    rung = r + 1,
                    rows = rung.rows(),
                    columns = rung.columns(),
                    default_rows = DEFAULT_ROWS,
                    default_columns = DEFAULT_COLUMNS
                ),
            ));
        }
    }
    // Comments and labels go to the first rung below them.
    for e in &els {
        let ((Kind::Comment(text), y) | (Kind::Label(text), y)) = (&e.kind, e.y) else { continue };
        if rungs.is_empty() {
            let message = crate::msg!(PlcopenCommentNoRung, pou = pou, id = &e.id);
            warnings.push(ImportNote::at(e.at.0, e.at.1, message));
            continue;
        }
        let r = networks.iter().position(|(top, _)| *top >= y).unwrap_or(rungs.len() - 1);
        if matches!(e.kind, Kind::Label(_)) {
            rungs[r].label = Some(text.clone());
        } else if rungs[r].comment.is_empty() {
            rungs[r].comment = text.clone();
        } else {
            rungs[r].comment.push('\n');
            rungs[r].comment.push_str(text);
        }
    }
    origins.sort_unstable();
    Ok(LdBody { rungs, declarations: sorted.declarations, origins })
}

/// Builds the electrical graph and drops what no power reaches (with warnings).
fn build_graph(
    els: &[El],
    index: &HashMap<String, usize>,
    blocks: &HashMap<usize, pins::BlockEl>,
    pou: &str,
    warnings: &mut Vec<ImportNote>,
) -> Result<Graph, ImportError> {
    let err = |id: &str, message: Said| ImportError::Element {
        pou: pou.to_string(),
        local_id: id.to_string(),
        message,
    };
    let mut uf = UnionFind::default();
    let s_node = uf.add();
    let t_node = uf.add();
    let n = els.len();
    let mut in_node = vec![usize::MAX; n];
    let mut out_node = vec![usize::MAX; n];
    let is_edge = |i: usize| matches!(els[i].kind, Kind::Leaf(_)) || blocks.contains_key(&i);
    for i in 0..n {
        if is_edge(i) {
            in_node[i] = uf.add();
            out_node[i] = uf.add();
        }
    }
    let mut pin_node: HashMap<(usize, usize), usize> = HashMap::new();
    for (&b, el) in blocks {
        for (k, _) in &el.wired {
            pin_node.insert((b, *k), uf.add());
        }
    }
    let source = |c: &Conn, at: &str| -> Result<Option<usize>, ImportError> {
        let s = *index
            .get(&c.from)
            .ok_or_else(|| err(at, crate::msg!(PlcopenMissingLocalId, id = &c.from)))?;
        match &els[s].kind {
            Kind::LeftRail => Ok(None),
            Kind::Leaf(_) => Ok(Some(s)),
            Kind::Block(_) => {
                let el = blocks.get(&s).ok_or_else(|| err(at, crate::msg!(PlcopenBlockNotRead)))?;
                if let Some(p) = &c.param {
                    let out = el.block.power_output();
                    if !p.eq_ignore_ascii_case(out) {
                        return Err(err(
                            at,
                            crate::msg!(
                                PlcopenPowerFromOtherOutput,
                                pin = p,
                                id = &els[s].id,
                                output = out
                            ),
                        ));
                    }
                }
                Ok(Some(s))
            }
            _ => Err(err(at, crate::msg!(PlcopenPowerFromNonPower, id = &els[s].id))),
        }
    };
    for i in 0..n {
        let (target, conns): (usize, &[Conn]) = match &els[i].kind {
            Kind::RightRail => (t_node, &els[i].conns),
            Kind::Leaf(_) => (in_node[i], &els[i].conns),
            Kind::Block(_) => match blocks.get(&i) {
                Some(b) => (in_node[i], &b.power),
                None => continue,
            },
            _ => continue,
        };
        for c in conns {
            let src = match source(c, &els[i].id)? {
                None => s_node,
                Some(s) => out_node[s],
            };
            uf.union(target, src);
        }
        if let Some(b) = blocks.get(&i) {
            for (k, conns) in &b.wired {
                for c in conns {
                    let src = match source(c, &els[i].id)? {
                        None => s_node,
                        Some(s) => out_node[s],
                    };
                    if let Some(&p) = pin_node.get(&(i, *k)) {
                        uf.union(p, src);
                    }
                }
            }
        }
    }
    // Alive edges; prune dangling parts with warnings.
    let mut alive: Vec<usize> = (0..n).filter(|&i| is_edge(i)).collect();
    loop {
        let s = uf.find(s_node);
        let t = uf.find(t_node);
        let mut ins: HashMap<usize, usize> = HashMap::new();
        let mut outs: HashMap<usize, usize> = HashMap::new();
        for &i in &alive {
            *outs.entry(uf.find(in_node[i])).or_default() += 1;
            *ins.entry(uf.find(out_node[i])).or_default() += 1;
            for ((b, _), &p) in &pin_node {
                if *b == i {
                    *outs.entry(uf.find(p)).or_default() += 1;
                }
            }
        }
        let mut changed = false;
        let mut keep = Vec::new();
        for &i in &alive {
            let a = uf.find(in_node[i]);
            let b = uf.find(out_node[i]);
            let terminal = !matches!(els[i].kind, Kind::Leaf(Element::Contact { .. }));
            if a != s && !ins.contains_key(&a) {
                warnings.push(ImportNote::at(
                    els[i].at.0,
                    els[i].at.1,
                    crate::msg!(PlcopenNotConnectedToLeftRail, pou = pou, id = &els[i].id),
                ));
                changed = true;
                continue;
            }
            if b != t && !outs.contains_key(&b) {
                if terminal {
                    uf.union(t_node, out_node[i]);
                } else {
                    warnings.push(ImportNote::at(
                        els[i].at.0,
                        els[i].at.1,
                        crate::msg!(PlcopenContactLeadsNowhere, pou = pou, id = &els[i].id),
                    ));
                    changed = true;
                    continue;
                }
            }
            keep.push(i);
        }
        alive = keep;
        if !changed {
            break;
        }
    }
    let s = uf.find(s_node);
    let t = uf.find(t_node);
    for i in 0..n {
        if in_node[i] != usize::MAX {
            in_node[i] = uf.find(in_node[i]);
            out_node[i] = uf.find(out_node[i]);
        }
    }
    let pin_node = pin_node.into_iter().map(|(k, v)| (k, uf.find(v))).collect();
    Ok(Graph { s, t, in_node, out_node, pin_node, alive })
}

/// Puts a network holding a block that another network's block reads by a data wire
/// before that network (keeping the top-to-bottom order otherwise).
fn order_by_data(networks: &mut Vec<(f64, Vec<usize>)>, data: &[(usize, usize)]) {
    let net_of = |networks: &[(f64, Vec<usize>)], el: usize| {
        networks.iter().position(|(_, e)| e.contains(&el))
    };
    let mut out: Vec<(f64, Vec<usize>)> = Vec::new();
    let mut rest = std::mem::take(networks);
    while !rest.is_empty() {
        // The first network that needs nothing still waiting (else the first one: a loop).
        let pick = (0..rest.len())
            .find(|&k| {
                !data.iter().any(|&(a, b)| {
                    net_of(&rest, b) == Some(k) && net_of(&rest, a).is_some_and(|na| na != k)
                })
            })
            .unwrap_or(0);
        out.push(rest.remove(pick));
    }
    *networks = out;
}

/// Grid `(row, column)` of each placed element.
type Positions = HashMap<usize, (usize, usize)>;

/// Lays out one network: the part reaching the coils, then each wired input's network.
/// On failure: the element to blame and why.
fn layout_network(
    g: &Graph,
    edges: &[usize],
    parts: &Parts<'_>,
) -> Result<(Rung, Positions), (usize, Said)> {
    let not_sp = || crate::msg!(PlcopenNotSeriesParallel);
    // The cone of the coils.
    let mut reach = vec![g.t];
    loop {
        let before = reach.len();
        for &i in edges {
            if reach.contains(&g.out_node[i]) && !reach.contains(&g.in_node[i]) {
                reach.push(g.in_node[i]);
            }
        }
        if reach.len() == before {
            break;
        }
    }
    let main: Vec<usize> =
        edges.iter().copied().filter(|&i| reach.contains(&g.out_node[i])).collect();
    let first = edges.first().copied().unwrap_or(0);
    if main.is_empty() {
        return Err((first, crate::msg!(PlcopenNothingReachesCoil)));
    }
    let work: Vec<(usize, usize, Sp)> =
        main.iter().map(|&i| (g.in_node[i], g.out_node[i], Sp::Leaf(i))).collect();
    let tree = layout::reduce(work, g.s, g.t, parts).map_err(|b| (b.unwrap_or(first), not_sp()))?;
    let mut grid = layout::main_grid(tree, parts).map_err(|()| (first, not_sp()))?;
    // Wired inputs, block by block as they are placed.
    let mut done: Vec<(usize, usize)> = Vec::new();
    loop {
        let next = g
            .pin_node
            .keys()
            .filter(|k| grid.pos.contains_key(&k.0) && !done.contains(k))
            .min_by_key(|&&(b, k)| (grid.pos[&b].1, grid.pos[&b].0, k))
            .copied();
        let Some(key) = next else { break };
        wire_input(g, edges, parts, &mut grid, key, &done)?;
        done.push(key);
    }
    if let Some(&missing) = edges.iter().find(|i| !grid.pos.contains_key(i)) {
        return Err((missing, crate::msg!(PlcopenElementNotPlaced)));
    }
    let rung = layout::into_rung(grid.clone());
    let mut expects = Vec::new();
    for &i in edges {
        let (r, c) = grid.pos[&i];
        expects.push(Expect { node: (r, c), want: g.feeders(g.in_node[i], edges), blame: i });
    }
    for &(b, k) in &done {
        let (r, c) = grid.pos[&b];
        let row = wired_row(&grid, b, k).unwrap_or(0);
        expects.push(Expect {
            node: (r + row, c),
            want: g.feeders(g.pin_node[&(b, k)], edges),
            blame: b,
        });
    }
    verify::check(&rung, &grid.pos, &expects)
        .map_err(|i| (i, crate::msg!(PlcopenWiringCrosses)))?;
    Ok((rung, grid.pos))
}

/// The wired row of input `k` of the block placed for element `b`.
fn wired_row(grid: &Grid, b: usize, k: usize) -> Option<usize> {
    let (r, c) = grid.pos.get(&b)?;
    match &grid.cells[*r][*c].element {
        Element::Block(blk) => blk.inputs.get(k)?.wired_row.map(|w| w as usize),
        _ => None,
    }
}

/// Lays out the network of wired input `k` of block element `b` below the block and wires it.
fn wire_input(
    g: &Graph,
    edges: &[usize],
    parts: &Parts<'_>,
    grid: &mut Grid,
    (b, k): (usize, usize),
    done: &[(usize, usize)],
) -> Result<(), (usize, Said)> {
    let pin = g.pin_node[&(b, k)];
    let placed = |i: usize| grid.pos.contains_key(&i);
    // The input's own cone: unplaced edges reaching the pin node; taps where it meets the
    // rail or placed elements.
    let mut nodes = vec![pin];
    let mut cone: Vec<usize> = Vec::new();
    loop {
        let before = cone.len();
        for &i in edges {
            if !placed(i) && !cone.contains(&i) && nodes.contains(&g.out_node[i]) {
                cone.push(i);
                if !nodes.contains(&g.in_node[i]) {
                    nodes.push(g.in_node[i]);
                }
            }
        }
        if cone.len() == before {
            break;
        }
    }
    let v = usize::MAX - 1;
    let mut node_pos: HashMap<usize, (usize, usize)> = HashMap::new();
    for &i in edges.iter().filter(|&&i| placed(i)) {
        let (r, c) = grid.pos[&i];
        let here = (r, c + 1);
        node_pos.entry(g.out_node[i]).and_modify(|p| *p = (*p).min(here)).or_insert(here);
    }
    let mut work: Vec<(usize, usize, Sp)> =
        cone.iter().map(|&i| (g.in_node[i], g.out_node[i], Sp::Leaf(i))).collect();
    for &u in &nodes {
        if u == g.s || node_pos.contains_key(&u) {
            work.push((v, u, Sp::Tap(u)));
        }
    }
    let tree = layout::reduce(work, v, pin, parts)
        .map_err(|x| (x.unwrap_or(b), crate::msg!(PlcopenInputNotSeriesParallel)))?;
    let (rb, cb) = grid.pos[&b];
    let mut pins: Vec<(usize, usize)> = done
        .iter()
        .filter_map(|&(bb, kk)| {
            let (r, c) = grid.pos.get(&bb)?;
            Some((r + wired_row(grid, bb, kk)?, *c))
        })
        .collect();
    crate::order::sort(&mut pins);
    let job = PinJob { node_pos: &node_pos, rail: g.s, pins };
    let limit = grid.cells.len() + layout::tree_height(&tree, parts) + 1;
    for top in rb + 1..=limit {
        let mut trial = grid.clone();
        if try_wire(&mut trial, &tree, (rb, cb), k, top, &job, parts).is_ok() {
            *grid = trial;
            return Ok(());
        }
    }
    Err((b, crate::msg!(PlcopenInputDoesNotFit)))
}

/// Places a wired input's tree with its top row on `top` and grows the block to that row.
fn try_wire(
    grid: &mut Grid,
    tree: &Sp,
    (rb, cb): (usize, usize),
    k: usize,
    top: usize,
    job: &PinJob<'_>,
    parts: &Parts<'_>,
) -> Result<(), ()> {
    let w = (top - rb) as u32;
    let Element::Block(mut blk) = grid.cells[rb][cb].element.clone() else { return Err(()) };
    let height = blk.height.max(1).max(w + 1);
    grid.ensure_rows(top + layout::tree_height(tree, parts));
    for r in rb + blk.height.max(1) as usize..rb + height as usize {
        if r < grid.cells.len() && !matches!(grid.cells[r][cb].element, Element::Empty) {
            return Err(());
        }
    }
    grid.place_right(tree, top, cb, job, parts)?;
    for r in rb + blk.height.max(1) as usize..rb + height as usize {
        grid.cells[r][cb].element = Element::Covered;
    }
    blk.height = height;
    if let Some(p) = blk.inputs.get_mut(k) {
        p.wired_row = Some(w);
    }
    grid.cells[rb][cb].element = Element::Block(blk);
    Ok(())
}
