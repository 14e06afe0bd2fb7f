//! LD bodies → rungs: builds the electrical graph from `refLocalId` wiring, splits it into
//! networks, reduces each network to a series-parallel tree and lays the tree onto the grid.

#![allow(clippy::needless_range_loop)] // grid code reads best with explicit indices

use super::xml::Node;
use super::ImportError;
use crate::ladder::{Block, Cell, CoilKind, ContactKind, Element, Pin, Rung};
use crate::ladder::{DEFAULT_COLUMNS, DEFAULT_ROWS};
use std::collections::{BTreeMap, HashMap};

/// A wire end: the element it comes from and the output pin named, if any.
#[derive(Debug, Clone)]
struct Conn {
    from: String,
    param: Option<String>,
}

#[derive(Debug, Clone)]
enum Kind {
    LeftRail,
    RightRail,
    Leaf(Element),
    Block { block: Block, power_in: Vec<Conn>, pin_inputs: Vec<(String, Vec<Conn>)> },
    InVar(String),
    OutVar(String),
    Comment(String),
    Label(String),
}

#[derive(Debug, Clone)]
struct El {
    id: String,
    y: f64,
    kind: Kind,
    conns: Vec<Conn>,
}

fn conns_of(point: &Node) -> Vec<Conn> {
    point
        .children_named("connection")
        .filter_map(|c| {
            Some(Conn {
                from: c.attr("refLocalId")?.to_string(),
                param: c.attr("formalParameter").filter(|p| !p.is_empty()).map(str::to_string),
            })
        })
        .collect()
}

fn all_conns_in(n: &Node) -> Vec<Conn> {
    n.children_named("connectionPointIn").flat_map(conns_of).collect()
}

fn y_of(n: &Node) -> f64 {
    n.child("position").and_then(|p| p.attr("y")).and_then(|y| y.trim().parse().ok()).unwrap_or(0.0)
}

fn text_of(n: &Node, child: &str) -> String {
    n.child(child).map(|v| v.deep_text().trim().to_string()).unwrap_or_default()
}

/// Union-find over small integer node ids.
#[derive(Default)]
struct Uf(Vec<usize>);

impl Uf {
    fn add(&mut self) -> usize {
        self.0.push(self.0.len());
        self.0.len() - 1
    }
    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }
    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.0[b] = a;
        }
    }
}

/// A series-parallel tree over element indices.
#[derive(Debug, Clone)]
enum Sp {
    Leaf(usize),
    Pad(usize),
    Series(Vec<Sp>),
    Par(Vec<Sp>),
}

fn read_elements(ld: &Node, pou: &str) -> Result<Vec<El>, ImportError> {
    let mut els = Vec::new();
    for n in &ld.children {
        let id = n.attr("localId").unwrap_or("").to_string();
        let err = |message: String| ImportError::Element {
            pou: pou.to_string(),
            local_id: if id.is_empty() { "?".into() } else { id.clone() },
            message,
        };
        let kind = match n.name.as_str() {
            "leftPowerRail" => Kind::LeftRail,
            "rightPowerRail" => Kind::RightRail,
            "contact" => {
                let operand = text_of(n, "variable");
                if operand.is_empty() {
                    return Err(err("a contact without a variable".into()));
                }
                let kind = match (n.attr("edge"), n.attr("negated") == Some("true")) {
                    (Some("rising"), _) => ContactKind::Rising,
                    (Some("falling"), _) => ContactKind::Falling,
                    (_, true) => ContactKind::NormallyClosed,
                    _ => ContactKind::NormallyOpen,
                };
                Kind::Leaf(Element::Contact { kind, operand })
            }
            "coil" => {
                let operand = text_of(n, "variable");
                if operand.is_empty() {
                    return Err(err("a coil without a variable".into()));
                }
                let kind = match (n.attr("storage"), n.attr("edge"), n.attr("negated")) {
                    (Some("set"), _, _) => CoilKind::Set,
                    (Some("reset"), _, _) => CoilKind::Reset,
                    (_, Some("rising"), _) => CoilKind::Rising,
                    (_, Some("falling"), _) => CoilKind::Falling,
                    (_, _, Some("true")) => CoilKind::Negated,
                    _ => CoilKind::Normal,
                };
                Kind::Leaf(Element::Coil { kind, operand })
            }
            "block" => {
                let type_name = n.attr("typeName").unwrap_or("").to_string();
                if type_name.is_empty() {
                    return Err(err("a block without typeName".into()));
                }
                let instance = n.attr("instanceName").filter(|s| !s.is_empty()).map(str::to_string);
                let mut pin_inputs = Vec::new();
                if let Some(iv) = n.child("inputVariables") {
                    for v in iv.children_named("variable") {
                        let p = v.attr("formalParameter").unwrap_or("").to_string();
                        pin_inputs.push((
                            p,
                            v.child("connectionPointIn").map(conns_of).unwrap_or_default(),
                        ));
                    }
                }
                if n.child("inOutVariables").is_some_and(|v| v.child("variable").is_some()) {
                    return Err(err(format!("block {type_name}: in-out pins are not supported")));
                }
                let mut block = Block::new(&type_name, None);
                block.instance = instance;
                Kind::Block { block, power_in: Vec::new(), pin_inputs }
            }
            "inVariable" => Kind::InVar(text_of(n, "expression")),
            "outVariable" => Kind::OutVar(text_of(n, "expression")),
            "comment" => {
                Kind::Comment(n.child("content").map(super::import::doc_text).unwrap_or_default())
            }
            "label" => Kind::Label(n.attr("label").unwrap_or("").to_string()),
            "jump" => {
                Kind::Leaf(Element::Jump { label: n.attr("label").unwrap_or("").to_string() })
            }
            "return" => Kind::Leaf(Element::Return),
            "documentation" | "addData" => continue,
            other => {
                return Err(err(format!("<{other}> elements are not supported in LD bodies yet")))
            }
        };
        if id.is_empty() {
            if matches!(kind, Kind::Comment(_)) {
                // Comments are never referenced; an id is not needed.
            } else {
                return Err(err(format!("<{}> without localId", n.name)));
            }
        }
        let conns = all_conns_in(n);
        els.push(El { id, y: y_of(n), kind, conns });
    }
    Ok(els)
}

/// Lays out one LD body as rungs.
pub(crate) fn import_ld(
    ld: &Node,
    pou: &str,
    warnings: &mut Vec<String>,
) -> Result<Vec<Rung>, ImportError> {
    let mut els = read_elements(ld, pou)?;
    let mut index: HashMap<String, usize> = HashMap::new();
    for (i, e) in els.iter().enumerate() {
        if e.id.is_empty() {
            continue;
        }
        if index.insert(e.id.clone(), i).is_some() && !matches!(els[i].kind, Kind::Comment(_)) {
            return Err(ImportError::Element {
                pou: pou.into(),
                local_id: e.id.clone(),
                message: "duplicate localId".into(),
            });
        }
    }
    let err = |id: &str, message: String| ImportError::Element {
        pou: pou.to_string(),
        local_id: id.to_string(),
        message,
    };
    let lookup = |c: &Conn, at: &str| -> Result<usize, ImportError> {
        index.get(&c.from).copied().ok_or_else(|| {
            err(at, format!("connection refers to localId {}, which does not exist", c.from))
        })
    };

    // Blocks: sort pins into the power input and operand inputs.
    let mut consumed = vec![false; els.len()];
    for i in 0..els.len() {
        let Kind::Block { pin_inputs, .. } = &els[i].kind else { continue };
        let pin_inputs = pin_inputs.clone();
        let id = els[i].id.clone();
        let mut power: Option<Vec<Conn>> = None;
        let mut inputs = Vec::new();
        for (pin, conns) in pin_inputs {
            if conns.is_empty() {
                continue;
            }
            let srcs = conns.iter().map(|c| lookup(c, &id)).collect::<Result<Vec<_>, _>>()?;
            if let [s] = srcs[..] {
                if let Kind::InVar(expr) = &els[s].kind {
                    inputs.push(Pin::operand(&pin, expr));
                    consumed[s] = true;
                    continue;
                }
            }
            if srcs.iter().any(|&s| matches!(els[s].kind, Kind::InVar(_) | Kind::OutVar(_))) {
                return Err(err(&id, format!("input {pin} mixes variables and power wires")));
            }
            if power.is_none() {
                power = Some(conns);
                continue;
            }
            // A second power input fed straight from the rail by one contact becomes an
            // operand (`R` ← `Reset` or `NOT Reset`).
            let simple = match srcs[..] {
                [s] => match (&els[s].kind, els[s].conns.as_slice()) {
                    (Kind::Leaf(Element::Contact { kind, operand }), [c])
                        if index
                            .get(&c.from)
                            .is_some_and(|&r| matches!(els[r].kind, Kind::LeftRail)) =>
                    {
                        match kind {
                            ContactKind::NormallyOpen => Some((s, operand.clone())),
                            ContactKind::NormallyClosed => Some((s, format!("NOT {operand}"))),
                            _ => None,
                        }
                    }
                    _ => None,
                },
                _ => None,
            };
            match simple {
                Some((s, operand)) => {
                    consumed[s] = true;
                    warnings.push(format!(
                        "POU {pou}: input {pin} of block localId {id} was driven by contact localId {}; it became the operand {operand}",
                        els[s].id
                    ));
                    inputs.push(Pin::operand(&pin, &operand));
                }
                None => {
                    return Err(err(
                        &id,
                        format!("input {pin} is a second power input driven by a ladder network; only one power input per block can be laid out"),
                    ))
                }
            }
        }
        if let Kind::Block { block, power_in, .. } = &mut els[i].kind {
            block.inputs = inputs;
            *power_in = power.unwrap_or_default();
        }
    }
    // Output pins from outVariables.
    for i in 0..els.len() {
        let Kind::OutVar(expr) = &els[i].kind else { continue };
        let expr = expr.clone();
        let id = els[i].id.clone();
        let conns = els[i].conns.clone();
        let [c] = conns.as_slice() else {
            if conns.is_empty() {
                warnings.push(format!(
                    "POU {pou}: outVariable localId {id} ({expr}) is not connected; skipped"
                ));
                continue;
            }
            return Err(err(&id, "an outVariable with several connections".into()));
        };
        let s = lookup(c, &id)?;
        let Kind::Block { block, .. } = &mut els[s].kind else {
            return Err(err(
                &id,
                "an outVariable fed by power (not by a block output) is not supported".into(),
            ));
        };
        let pin = c.param.clone().unwrap_or_else(|| "OUT".into());
        block.outputs.push(Pin::operand(&pin, &expr));
    }
    for e in &mut els {
        if let Kind::Block { block, .. } = &mut e.kind {
            block.height = (block.inputs.len().max(block.outputs.len()) + 1) as u32;
        }
    }

    // The electrical graph: element i is an edge from in_node[i] to out_node[i].
    let mut uf = Uf::default();
    let s_node = uf.add();
    let t_node = uf.add();
    let n = els.len();
    let mut in_node = vec![usize::MAX; n];
    let mut out_node = vec![usize::MAX; n];
    let is_edge = |k: &Kind| matches!(k, Kind::Leaf(_) | Kind::Block { .. });
    for i in 0..n {
        if is_edge(&els[i].kind) && !consumed[i] {
            in_node[i] = uf.add();
            out_node[i] = uf.add();
        }
    }
    let mut power_out_pin: HashMap<usize, String> = HashMap::new();
    for i in 0..n {
        let power_conns: Vec<Conn> = match &els[i].kind {
            Kind::Leaf(_) | Kind::RightRail if !consumed[i] => els[i].conns.clone(),
            Kind::Block { power_in, .. } if !consumed[i] => power_in.clone(),
            _ => continue,
        };
        let target = if matches!(els[i].kind, Kind::RightRail) { t_node } else { in_node[i] };
        for c in &power_conns {
            let s = lookup(c, &els[i].id)?;
            let src = match &els[s].kind {
                Kind::LeftRail => s_node,
                Kind::Leaf(_) | Kind::Block { .. } if !consumed[s] => {
                    if matches!(els[s].kind, Kind::Block { .. }) {
                        if let Some(p) = &c.param {
                            let prev = power_out_pin.entry(s).or_insert_with(|| p.clone());
                            if prev != p {
                                return Err(err(&els[s].id, format!("two outputs ({prev} and {p}) of the block carry power; only one can be laid out")));
                            }
                        }
                    }
                    out_node[s]
                }
                Kind::Leaf(_) | Kind::Block { .. } => continue,
                _ => {
                    return Err(err(
                        &els[i].id,
                        format!("power input wired to localId {}, which is not a rail, contact, coil or block", els[s].id),
                    ))
                }
            };
            uf.union(target, src);
        }
    }
    // Alive edges; prune dangling parts with warnings.
    let mut alive: Vec<usize> = (0..n).filter(|&i| is_edge(&els[i].kind) && !consumed[i]).collect();
    loop {
        let s = uf.find(s_node);
        let t = uf.find(t_node);
        let mut ins: HashMap<usize, usize> = HashMap::new();
        let mut outs: HashMap<usize, usize> = HashMap::new();
        for &i in &alive {
            *outs.entry(uf.find(in_node[i])).or_default() += 1;
            *ins.entry(uf.find(out_node[i])).or_default() += 1;
        }
        let mut changed = false;
        let mut keep = Vec::new();
        for &i in &alive {
            let a = uf.find(in_node[i]);
            let b = uf.find(out_node[i]);
            let terminal = !matches!(els[i].kind, Kind::Leaf(Element::Contact { .. }));
            if a != s && !ins.contains_key(&a) {
                warnings.push(format!(
                    "POU {pou}: element localId {} is not connected to the left rail; skipped",
                    els[i].id
                ));
                changed = true;
                continue;
            }
            if b != t && !outs.contains_key(&b) {
                if terminal {
                    uf.union(t_node, out_node[i]);
                } else {
                    warnings.push(format!(
                        "POU {pou}: contact localId {} leads nowhere; skipped",
                        els[i].id
                    ));
                    changed = true;
                    continue;
                }
            }
            keep.push(i);
        }
        alive = keep;
        // Re-check after merging terminals into T.
        if !changed {
            break;
        }
    }
    let s = uf.find(s_node);
    let t = uf.find(t_node);

    // Networks: edges sharing an internal node.
    let mut comp = Uf::default();
    for _ in 0..alive.len() {
        comp.add();
    }
    let mut by_node: HashMap<usize, usize> = HashMap::new();
    for (k, &i) in alive.iter().enumerate() {
        for node in [uf.find(in_node[i]), uf.find(out_node[i])] {
            if node == s || node == t {
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
    networks.sort_by(|a, b| a.0.total_cmp(&b.0));

    let mut rungs = Vec::new();
    for (_, edges) in &networks {
        let mut work: Vec<(usize, usize, Sp)> = edges
            .iter()
            .map(|&i| (uf.find(in_node[i]), uf.find(out_node[i]), Sp::Leaf(i)))
            .collect();
        let tree = reduce(&mut work, s, t, &els).map_err(|i| {
            err(
                &els[i].id,
                "the network is not series-parallel, so it cannot be laid out on the rung grid"
                    .into(),
            )
        })?;
        rungs.push(layout(tree, &els));
    }
    for (r, rung) in rungs.iter().enumerate() {
        if rung.rows() > DEFAULT_ROWS as usize || rung.columns() > DEFAULT_COLUMNS as usize {
            warnings.push(format!(
                "POU {pou}: rung {} needs {}×{} cells, more than the default {DEFAULT_ROWS}×{DEFAULT_COLUMNS} grid",
                r + 1,
                rung.rows(),
                rung.columns()
            ));
        }
    }
    // Comments and labels go to the first rung below them.
    for e in &els {
        let ((Kind::Comment(text), y) | (Kind::Label(text), y)) = (&e.kind, e.y) else { continue };
        if rungs.is_empty() {
            warnings
                .push(format!("POU {pou}: comment or label localId {} has no rung; dropped", e.id));
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
    Ok(rungs)
}

fn min_y(sp: &Sp, els: &[El]) -> f64 {
    match sp {
        Sp::Leaf(i) => els[*i].y,
        Sp::Pad(_) => f64::INFINITY,
        Sp::Series(v) | Sp::Par(v) => v.iter().map(|x| min_y(x, els)).fold(f64::INFINITY, f64::min),
    }
}

fn first_leaf(sp: &Sp) -> Option<usize> {
    match sp {
        Sp::Leaf(i) => Some(*i),
        Sp::Pad(_) => None,
        Sp::Series(v) | Sp::Par(v) => v.iter().find_map(first_leaf),
    }
}

/// Series-parallel reduction of a two-terminal network; on failure, the element index to
/// blame.
fn reduce(work: &mut Vec<(usize, usize, Sp)>, s: usize, t: usize, els: &[El]) -> Result<Sp, usize> {
    loop {
        if let [(a, b, _)] = work.as_slice() {
            if *a == s && *b == t {
                return Ok(work.pop().map(|x| x.2).unwrap_or(Sp::Series(Vec::new())));
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
            g.sort_by(|x, y| min_y(x, els).total_cmp(&min_y(y, els)));
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
            return Err(blame.unwrap_or(0));
        }
    }
}

fn size(sp: &Sp, els: &[El]) -> (usize, usize) {
    match sp {
        Sp::Leaf(i) => match &els[*i].kind {
            Kind::Block { block, .. } => (1, block.height.max(1) as usize),
            _ => (1, 1),
        },
        Sp::Pad(w) => (*w, 1),
        Sp::Series(v) => {
            v.iter().map(|x| size(x, els)).fold((0, 1), |(w, h), (a, b)| (w + a, h.max(b)))
        }
        Sp::Par(v) => {
            v.iter().map(|x| size(x, els)).fold((0, 0), |(w, h), (a, b)| (w.max(a), h + b))
        }
    }
}

fn place(sp: &Sp, row: usize, col: usize, at_end: bool, els: &[El], grid: &mut [Vec<Cell>]) {
    match sp {
        Sp::Leaf(i) => {
            let element = match &els[*i].kind {
                Kind::Leaf(e) => e.clone(),
                Kind::Block { block, .. } => {
                    for r in 1..block.height.max(1) as usize {
                        grid[row + r][col].element = Element::Covered;
                    }
                    Element::Block(block.clone())
                }
                _ => Element::Empty,
            };
            grid[row][col].element = element;
        }
        Sp::Pad(w) => {
            for c in col..col + w {
                grid[row][c].element = Element::Wire;
            }
        }
        Sp::Series(v) => {
            let mut c = col;
            for (k, item) in v.iter().enumerate() {
                place(item, row, c, at_end && k + 1 == v.len(), els, grid);
                c += size(item, els).0;
            }
        }
        Sp::Par(v) => {
            let width = size(sp, els).0;
            let mut r = row;
            let mut last_top = row;
            for b in v {
                let (w, h) = size(b, els);
                if at_end {
                    // Outputs are right-aligned; the wire runs from the fork.
                    for c in col..col + width - w {
                        grid[r][c].element = Element::Wire;
                    }
                    place(b, r, col + width - w, true, els, grid);
                } else {
                    place(b, r, col, false, els, grid);
                    for c in col + w..col + width {
                        grid[r][c].element = Element::Wire;
                    }
                }
                last_top = r;
                r += h;
            }
            for rr in row..last_top {
                grid[rr][col].link_down = true;
                if !at_end {
                    grid[rr][col + width].link_down = true;
                }
            }
        }
    }
}

fn layout(tree: Sp, els: &[El]) -> Rung {
    let (w, _) = size(&tree, els);
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
    let (w, h) = size(&tree, els);
    let mut rung = Rung::new(h as u32, w as u32);
    place(&tree, 0, 0, true, els, &mut rung.cells);
    rung
}
