//! Ladder POU → `<pou>` with an `<LD>` body: elements at grid positions, wired per the grid.

use super::decl_xml::{section_tag, vars_xml};
use super::union_find::UnionFind;
use super::xml::esc;
use crate::ladder::{CoilKind, ContactKind, Element, LadderPou, LadderPouKind};
use crate::syntax::ast::Item;
use std::fmt::Write;

const X0: i64 = 100;
const DX: i64 = 80;
const DY: i64 = 40;

/// One ladder POU as a `<pou>` element.
pub(crate) fn ld_pou_xml(lp: &LadderPou) -> String {
    let pou_type = match lp.kind {
        LadderPouKind::Program => "program",
        LadderPouKind::FunctionBlock => "functionBlock",
    };
    let mut out = format!(
        "      <pou name=\"{}\" pouType=\"{pou_type}\">\n        <interface>\n",
        esc(&lp.name)
    );
    let wrapped = format!("PROGRAM X\n{}\nEND_PROGRAM\n", lp.declarations);
    let (file, _) = crate::syntax::parse(&wrapped);
    for item in &file.items {
        if let Item::Pou(p) = item {
            for b in &p.var_blocks {
                out.push_str(&vars_xml(b, &wrapped, section_tag(b.section), "          "));
            }
        }
    }
    out.push_str("        </interface>\n        <body>\n          <LD>\n");
    let mut next_id = 1usize;
    let mut y0: i64 = 20;
    let mut body = String::new();
    for rung in &lp.rungs {
        // Rows of unequal length (a damaged file) are padded so every cell can be read.
        let cols = rung.cells.iter().map(Vec::len).max().unwrap_or(0);
        let mut padded = rung.clone();
        for row in &mut padded.cells {
            row.resize(cols, Default::default());
        }
        let rung = &padded;
        let rows = rung.rows();
        if rows == 0 || cols == 0 {
            continue;
        }
        let mut id = || {
            next_id += 1;
            next_id - 1
        };
        if let Some(label) = &rung.label {
            let _ = writeln!(body, "            <label localId=\"{}\" height=\"20\" width=\"80\" label=\"{}\">\n              <position x=\"{X0}\" y=\"{y0}\"/>\n            </label>", id(), esc(label));
            y0 += DY;
        }
        if !rung.comment.is_empty() {
            let _ = writeln!(body, "            <comment localId=\"{}\" height=\"30\" width=\"400\">\n              <position x=\"{X0}\" y=\"{y0}\"/>\n              <content>\n                <xhtml:p><![CDATA[{}]]></xhtml:p>\n              </content>\n            </comment>", id(), rung.comment.replace("]]>", "]] >"));
            y0 += DY;
        }
        // Nodes (row, col) for col in 0..=cols.
        let node = |r: usize, c: usize| r * (cols + 1) + c;
        let mut uf = UnionFind::new(rows * (cols + 1));
        for r in 0..rows {
            uf.union(node(0, 0), node(r, 0));
            for c in 0..cols {
                let cell = &rung.cells[r][c];
                if cell.element == Element::Wire {
                    uf.union(node(r, c), node(r, c + 1));
                }
                if cell.link_down && r + 1 < rows {
                    uf.union(node(r, c), node(r + 1, c));
                }
            }
        }
        let left_id = id();
        let right_id = id();
        // Elements and their ids.
        let mut items: Vec<(usize, usize, usize)> = Vec::new(); // (row, col, localId)
        for r in 0..rows {
            for c in 0..cols {
                if matches!(
                    rung.cells[r][c].element,
                    Element::Contact { .. }
                        | Element::Coil { .. }
                        | Element::Block(_)
                        | Element::Jump { .. }
                        | Element::Return
                ) {
                    items.push((r, c, id()));
                }
            }
        }
        let rail_root = uf.find(node(0, 0));
        let sources_of = |uf: &mut UnionFind, n: usize| -> Vec<(usize, Option<String>)> {
            let root = uf.find(n);
            let mut v = Vec::new();
            if root == rail_root {
                v.push((left_id, None));
            }
            for &(r, c, eid) in &items {
                if uf.find(node(r, c + 1)) == root {
                    let param = match &rung.cells[r][c].element {
                        Element::Block(b) => Some(b.power_output().to_string()),
                        _ => None,
                    };
                    v.push((eid, param));
                }
            }
            v
        };
        // `row`: the pin's row on its element (0 for the power input), for its position.
        let conn_at = |srcs: &[(usize, Option<String>)], indent: &str, row: usize| -> String {
            let rel_y = row * 20 + 10;
            let mut s = format!(
                "{indent}<connectionPointIn>\n{indent}  <relPosition x=\"0\" y=\"{rel_y}\"/>\n"
            );
            for (sid, p) in srcs {
                match p {
                    Some(p) => {
                        let _ = writeln!(
                            s,
                            "{indent}  <connection refLocalId=\"{sid}\" formalParameter=\"{}\"/>",
                            esc(p)
                        );
                    }
                    None => {
                        let _ = writeln!(s, "{indent}  <connection refLocalId=\"{sid}\"/>");
                    }
                }
            }
            let _ = writeln!(s, "{indent}</connectionPointIn>");
            s
        };
        let conn_xml = |srcs: &[(usize, Option<String>)], indent: &str| conn_at(srcs, indent, 0);
        // Data wires: an input reading `Inst.PIN` of a block placed in an earlier column of
        // this rung is wired to that block's output (unless PIN carries its power).
        let instances: Vec<(String, usize, usize, String)> = items
            .iter()
            .filter_map(|&(r, c, eid)| match &rung.cells[r][c].element {
                Element::Block(b) => b.instance.as_ref().map(|i| {
                    (i.trim().to_ascii_uppercase(), c, eid, b.power_output().to_ascii_uppercase())
                }),
                _ => None,
            })
            .collect();
        let data_source = |operand: &str, col: usize| -> Option<(usize, String)> {
            let (inst, pin) = operand.trim().split_once('.')?;
            let pin = pin.trim();
            if pin.is_empty() || !pin.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_') {
                return None;
            }
            let (_, _, eid, _) = instances.iter().find(|(i, c, _, out)| {
                *i == inst.trim().to_ascii_uppercase()
                    && *c < col
                    && *out != pin.to_ascii_uppercase()
            })?;
            Some((*eid, pin.to_string()))
        };
        let mut data_reads: std::collections::HashMap<usize, Vec<String>> = Default::default();
        for &(r, c, _) in &items {
            if let Element::Block(b) = &rung.cells[r][c].element {
                for p in b.inputs.iter().filter(|p| p.wired_row.is_none()) {
                    if let Some((sid, pin)) = data_source(&p.operand, c) {
                        data_reads.entry(sid).or_default().push(pin);
                    }
                }
            }
        }
        let height = rows as i64 * DY;
        let _ = writeln!(body, "            <leftPowerRail localId=\"{left_id}\" height=\"{height}\" width=\"10\">\n              <position x=\"{}\" y=\"{y0}\"/>\n              <connectionPointOut formalParameter=\"\">\n                <relPosition x=\"10\" y=\"20\"/>\n              </connectionPointOut>\n            </leftPowerRail>", X0 - 20);
        let mut extra = String::new();
        for &(r, c, eid) in &items {
            let x = X0 + c as i64 * DX;
            let y = y0 + r as i64 * DY;
            let srcs = sources_of(&mut uf, node(r, c));
            let cin = conn_xml(&srcs, "              ");
            match &rung.cells[r][c].element {
                Element::Contact { kind, operand } => {
                    let attrs = contact_attrs(*kind);
                    let _ = write!(body, "            <contact localId=\"{eid}\" height=\"20\" width=\"21\"{attrs}>\n              <position x=\"{x}\" y=\"{y}\"/>\n{cin}              <connectionPointOut>\n                <relPosition x=\"21\" y=\"10\"/>\n              </connectionPointOut>\n              <variable>{}</variable>\n            </contact>\n", esc(operand));
                }
                Element::Coil { kind, operand } => {
                    let attrs = coil_attrs(*kind);
                    let _ = write!(body, "            <coil localId=\"{eid}\" height=\"20\" width=\"21\"{attrs}>\n              <position x=\"{x}\" y=\"{y}\"/>\n{cin}              <connectionPointOut>\n                <relPosition x=\"21\" y=\"10\"/>\n              </connectionPointOut>\n              <variable>{}</variable>\n            </coil>\n", esc(operand));
                }
                Element::Jump { label } => {
                    let _ = write!(body, "            <jump localId=\"{eid}\" height=\"20\" width=\"40\" label=\"{}\">\n              <position x=\"{x}\" y=\"{y}\"/>\n{cin}            </jump>\n", esc(label));
                }
                Element::Return => {
                    let _ = write!(body, "            <return localId=\"{eid}\" height=\"20\" width=\"40\">\n              <position x=\"{x}\" y=\"{y}\"/>\n{cin}            </return>\n");
                }
                Element::Block(b) => {
                    let (pin_in, pin_out) = (b.power_input(), b.power_output());
                    let h = b.height.max(1) as i64 * DY;
                    let _ = write!(body, "            <block localId=\"{eid}\" height=\"{h}\" width=\"60\" typeName=\"{}\"", esc(&b.type_name));
                    if let Some(inst) = &b.instance {
                        let _ = write!(body, " instanceName=\"{}\"", esc(inst));
                    }
                    let _ = write!(body, ">\n              <position x=\"{x}\" y=\"{y}\"/>\n              <inputVariables>\n                <variable formalParameter=\"{}\">\n{}                </variable>\n", esc(pin_in), conn_xml(&srcs, "                  "));
                    let in_var = |extra: &mut String,
                                  next_id: &mut usize,
                                  k: usize,
                                  operand: &str| {
                        let vid = *next_id;
                        *next_id += 1;
                        let _ = write!(extra, "            <inVariable localId=\"{vid}\" height=\"20\" width=\"60\">\n              <position x=\"{}\" y=\"{}\"/>\n              <connectionPointOut>\n                <relPosition x=\"60\" y=\"10\"/>\n              </connectionPointOut>\n              <expression>{}</expression>\n            </inVariable>\n", x - 70, y + (k as i64 + 1) * 20, esc(operand));
                        vid
                    };
                    for (k, p) in b.inputs.iter().enumerate() {
                        let wires = match (p.wired_row, data_source(&p.operand, c)) {
                            (Some(w), _) if r + (w as usize) < rows => {
                                sources_of(&mut uf, node(r + w as usize, c))
                            }
                            (Some(_), _) => Vec::new(),
                            (None, Some((sid, pin))) => vec![(sid, Some(pin))],
                            (None, None) => {
                                vec![(in_var(&mut extra, &mut next_id, k, &p.operand), None)]
                            }
                        };
                        let _ = write!(body, "                <variable formalParameter=\"{}\">\n{}                </variable>\n", esc(&p.name), conn_at(&wires, "                  ", k + 1));
                    }
                    body.push_str("              </inputVariables>\n");
                    if b.in_outs.is_empty() {
                        body.push_str("              <inOutVariables/>\n");
                    } else {
                        body.push_str("              <inOutVariables>\n");
                        for (k, p) in b.in_outs.iter().enumerate() {
                            let vid =
                                in_var(&mut extra, &mut next_id, b.inputs.len() + k, &p.operand);
                            let _ = write!(body, "                <variable formalParameter=\"{}\">\n{}                  <connectionPointOut>\n                    <relPosition x=\"60\" y=\"{}\"/>\n                  </connectionPointOut>\n                </variable>\n", esc(&p.name), conn_at(&[(vid, None)], "                  ", b.inputs.len() + k + 1), (b.inputs.len() + k + 1) * 20 + 10);
                        }
                        body.push_str("              </inOutVariables>\n");
                    }
                    let _ = write!(body, "              <outputVariables>\n                <variable formalParameter=\"{}\">\n                  <connectionPointOut>\n                    <relPosition x=\"60\" y=\"10\"/>\n                  </connectionPointOut>\n                </variable>\n", esc(pin_out));
                    let mut declared: Vec<String> = vec![pin_out.to_ascii_uppercase()];
                    let read_here = data_reads.get(&eid).cloned().unwrap_or_default();
                    for (k, name) in b
                        .outputs
                        .iter()
                        .map(|p| p.name.trim())
                        .chain(read_here.iter().map(String::as_str))
                        .enumerate()
                    {
                        if declared.contains(&name.to_ascii_uppercase()) {
                            continue;
                        }
                        declared.push(name.to_ascii_uppercase());
                        let _ = write!(body, "                <variable formalParameter=\"{}\">\n                  <connectionPointOut>\n                    <relPosition x=\"60\" y=\"{}\"/>\n                  </connectionPointOut>\n                </variable>\n", esc(name), (k + 1) * 20 + 10);
                    }
                    for (k, p) in b.outputs.iter().enumerate() {
                        let vid = next_id;
                        next_id += 1;
                        let _ = write!(extra, "            <outVariable localId=\"{vid}\" height=\"20\" width=\"60\">\n              <position x=\"{}\" y=\"{}\"/>\n              <connectionPointIn>\n                <relPosition x=\"0\" y=\"10\"/>\n                <connection refLocalId=\"{eid}\" formalParameter=\"{}\"/>\n              </connectionPointIn>\n              <expression>{}</expression>\n            </outVariable>\n", x + 70, y + (k as i64 + 1) * 20, esc(p.name.trim()), esc(&p.operand));
                    }
                    body.push_str("              </outputVariables>\n            </block>\n");
                }
                _ => {}
            }
        }
        body.push_str(&extra);
        // The right rail takes every output on the right edge.
        let mut rsrcs = Vec::new();
        for r in 0..rows {
            for s in sources_of(&mut uf, node(r, cols)) {
                if s.0 != left_id && !rsrcs.iter().any(|x: &(usize, Option<String>)| x.0 == s.0) {
                    rsrcs.push(s);
                }
            }
        }
        let _ = write!(body, "            <rightPowerRail localId=\"{right_id}\" height=\"{height}\" width=\"10\">\n              <position x=\"{}\" y=\"{y0}\"/>\n{}            </rightPowerRail>\n", X0 + cols as i64 * DX + 20, conn_xml(&rsrcs, "              "));
        y0 += height + DY;
    }
    out.push_str(&body);
    out.push_str("          </LD>\n        </body>\n      </pou>\n");
    out
}

/// The attributes of a `<contact>` of `kind`.
pub(crate) fn contact_attrs(kind: ContactKind) -> &'static str {
    match kind {
        ContactKind::NormallyOpen => " negated=\"false\"",
        ContactKind::NormallyClosed => " negated=\"true\"",
        ContactKind::Rising => " negated=\"false\" edge=\"rising\"",
        ContactKind::Falling => " negated=\"false\" edge=\"falling\"",
    }
}

/// The attributes of a `<coil>` of `kind`.
pub(crate) fn coil_attrs(kind: CoilKind) -> &'static str {
    match kind {
        CoilKind::Normal => " negated=\"false\"",
        CoilKind::Negated => " negated=\"true\"",
        CoilKind::Set => " negated=\"false\" storage=\"set\"",
        CoilKind::Reset => " negated=\"false\" storage=\"reset\"",
        CoilKind::Rising => " negated=\"false\" edge=\"rising\"",
        CoilKind::Falling => " negated=\"false\" edge=\"falling\"",
    }
}
