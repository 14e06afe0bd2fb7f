//! Block pins as tools wire them → the ladder model's blocks: which input takes the rung's
//! power and which output passes it on, which inputs are bound to variables, which are
//! wired to contact networks, and which are data wires from another block's output.
//!
//! Data wires become operands: `T1.ET` for an output of a function block instance, or a
//! variable declared for the wire (`ADD_12_OUT : INT;`, typed from the function) for an
//! output of a function, as Beremiz's own compiler does with its temporaries.

use std::collections::HashMap;

use super::super::{ImportError, ImportNote};
use super::read::{Conn, El, Kind, RawBlock};
use crate::diagnostics::Said;
use crate::ladder::catalog::{BlockKind, Catalog, Scope, TypeKey};
use crate::ladder::{is_comparison, standard_fb_power, Block, CoilKind, ContactKind, Element, Pin};

/// A block after its pins were sorted.
#[derive(Debug, Clone)]
pub(super) struct BlockEl {
    /// The model block (wired inputs have `wired_row` set once laid out).
    pub block: Block,
    /// Wires into the power input.
    pub power: Vec<Conn>,
    /// Wired inputs: index into `block.inputs`, and their wires.
    pub wired: Vec<(usize, Vec<Conn>)>,
}

/// What the pins stage produces.
pub(super) struct Pins {
    /// Sorted blocks by element index.
    pub blocks: HashMap<usize, BlockEl>,
    /// Data wires: (source block element, consumer block element).
    pub data: Vec<(usize, usize)>,
    /// Declarations of the variables created for data wires from functions.
    pub declarations: Vec<String>,
}

/// What the pins stage needs to know about the project.
pub(super) struct Ctx<'a> {
    pub pou: &'a str,
    pub catalog: &'a Catalog,
    pub scope: Scope,
}

fn err(pou: &str, id: &str, message: Said) -> ImportError {
    ImportError::Element { pou: pou.to_string(), local_id: id.to_string(), message }
}

/// The output pin that carries power out of block `i`, from how other elements use it.
fn power_output(
    els: &[El],
    index: &HashMap<String, usize>,
    i: usize,
    pou: &str,
) -> Result<String, ImportError> {
    let Kind::Block(raw) = &els[i].kind else { return Ok(String::new()) };
    let id = &els[i].id;
    let mut found: Vec<String> = Vec::new();
    let note = |found: &mut Vec<String>, p: &Option<String>| {
        let p = p.clone().unwrap_or_else(|| default_power_out(raw).to_string());
        if !found.iter().any(|f| f.eq_ignore_ascii_case(&p)) {
            found.push(p);
        }
    };
    for e in els {
        if matches!(e.kind, Kind::Leaf(_) | Kind::RightRail) {
            for c in e.conns.iter().filter(|c| &c.from == id) {
                note(&mut found, &c.param);
            }
        }
    }
    if found.is_empty() {
        // Blocks in series: an output into another block's power input.
        for e in els {
            let Kind::Block(other) = &e.kind else { continue };
            let power_pin = default_power_in(other);
            for (pin, conns) in &other.inputs {
                let is_power =
                    pin.eq_ignore_ascii_case("EN") || pin.eq_ignore_ascii_case(power_pin);
                for c in conns.iter().filter(|c| &c.from == id && is_power) {
                    note(&mut found, &c.param);
                }
            }
        }
    }
    let _ = index;
    match found.as_slice() {
        [] => Ok(default_power_out(raw).to_string()),
        [one] => Ok(one.clone()),
        [a, b, ..] => Err(err(
            pou,
            id,
            crate::msg!(PlcopenTwoPowerOutputs, first = a, second = b, ty = &raw.type_name),
        )),
    }
}

fn default_power_in(raw: &RawBlock) -> &'static str {
    standard_fb_power(&raw.type_name).map_or("EN", |(i, _)| i)
}

fn default_power_out(raw: &RawBlock) -> &'static str {
    match standard_fb_power(&raw.type_name) {
        Some((_, o)) => o,
        None if is_comparison(&raw.type_name) => "OUT",
        None => "ENO",
    }
}

/// Whether a wire carries power: from a rail, contact or coil, or from the power output of a
/// block.
fn is_power(
    c: &Conn,
    els: &[El],
    index: &HashMap<String, usize>,
    outs: &HashMap<usize, String>,
) -> bool {
    let Some(&s) = index.get(&c.from) else { return false };
    match &els[s].kind {
        Kind::LeftRail | Kind::Leaf(_) => true,
        Kind::Block(_) => match (&c.param, outs.get(&s)) {
            (None, _) => true,
            (Some(p), Some(o)) => p.eq_ignore_ascii_case(o),
            _ => false,
        },
        _ => false,
    }
}

/// Sorts the pins of every block; may add elements (a contact for a variable wired into a
/// power input, a coil for an outVariable fed by power).
pub(super) fn sort_pins(
    els: &mut Vec<El>,
    index: &mut HashMap<String, usize>,
    ctx: &mut Ctx<'_>,
    warnings: &mut Vec<ImportNote>,
) -> Result<Pins, ImportError> {
    let pou = ctx.pou;
    let lookup =
        |index: &HashMap<String, usize>, c: &Conn, at: &str| -> Result<usize, ImportError> {
            index
                .get(&c.from)
                .copied()
                .ok_or_else(|| err(pou, at, crate::msg!(PlcopenMissingLocalId, id = &c.from)))
        };
    // Every wire must name an existing element.
    for e in els.iter() {
        let mut all: Vec<&Conn> = e.conns.iter().collect();
        if let Kind::Block(b) = &e.kind {
            all.extend(b.inputs.iter().chain(&b.in_outs).flat_map(|(_, c)| c));
        }
        for c in all {
            lookup(index, c, &e.id)?;
        }
    }
    let mut outs: HashMap<usize, String> = HashMap::new();
    for i in 0..els.len() {
        if matches!(els[i].kind, Kind::Block(_)) {
            outs.insert(i, power_output(els, index, i, pou)?);
        }
    }
    let mut pins = Pins { blocks: HashMap::new(), data: Vec::new(), declarations: Vec::new() };
    let rail = els.iter().position(|e| matches!(e.kind, Kind::LeftRail));
    let block_ids: Vec<usize> =
        (0..els.len()).filter(|&i| matches!(els[i].kind, Kind::Block(_))).collect();
    for &i in &block_ids {
        let Kind::Block(raw) = &els[i].kind else { continue };
        let block = Block::new(&raw.type_name, raw.instance.as_deref());
        pins.blocks.insert(i, BlockEl { block, power: Vec::new(), wired: Vec::new() });
    }
    bind_out_variables(els, index, &mut pins, &outs, pou, warnings)?;
    for &i in &block_ids {
        let Kind::Block(raw) = els[i].kind.clone() else { continue };
        let id = els[i].id.clone();
        let fed = |conns: &[Conn], els: &[El], index: &HashMap<String, usize>| {
            !conns.is_empty() && conns.iter().all(|c| is_power(c, els, index, &outs))
        };
        // The power input.
        let en =
            raw.inputs.iter().position(|(p, c)| p.eq_ignore_ascii_case("EN") && fed(c, els, index));
        let own =
            raw.inputs.iter().position(|(p, _)| p.eq_ignore_ascii_case(default_power_in(&raw)));
        let power_at = en.or(own.filter(|&k| fed(&raw.inputs[k].1, els, index))).or_else(|| {
            raw.inputs.iter().position(|(p, c)| fed(c, els, index) && !p.eq_ignore_ascii_case("EN"))
        });
        let mut block = match pins.blocks.get(&i) {
            Some(b) => b.block.clone(),
            None => Block::new(&raw.type_name, raw.instance.as_deref()),
        };
        let power;
        let mut power_pin = default_power_in(&raw).to_string();
        match power_at {
            Some(k) => {
                power_pin = raw.inputs[k].0.clone();
                power = raw.inputs[k].1.clone();
            }
            None => {
                // No power wire: a variable on the power input reads as a contact, and a
                // block with nothing on it runs on every scan from the rail.
                let var = own.and_then(|k| {
                    let [c] = raw.inputs[k].1.as_slice() else { return None };
                    let s = index.get(&c.from).copied()?;
                    match &els[s].kind {
                        Kind::InVar(e) => Some((k, e.clone())),
                        _ => None,
                    }
                });
                let rail_id = match rail {
                    Some(r) => els[r].id.clone(),
                    None => return Err(err(pou, &id, crate::msg!(PlcopenBlockNoPower))),
                };
                let rail_conn = Conn { from: rail_id, param: None };
                match var {
                    Some((k, expr)) => {
                        power_pin = raw.inputs[k].0.clone();
                        let cid = format!("{id}.{power_pin}");
                        let at = els[i].at;
                        warnings.push(ImportNote::at(
                            at.0,
                            at.1,
                            crate::msg!(
                                PlcopenInputBecameContact,
                                pou = pou,
                                pin = &power_pin,
                                id = &id,
                                variable = &expr
                            ),
                        ));
                        els.push(El {
                            id: cid.clone(),
                            at,
                            x: els[i].x,
                            order: 0,
                            y: els[i].y,
                            kind: Kind::Leaf(Element::Contact {
                                kind: ContactKind::NormallyOpen,
                                operand: expr,
                            }),
                            conns: vec![rail_conn],
                        });
                        index.insert(cid.clone(), els.len() - 1);
                        power = vec![Conn { from: cid, param: None }];
                    }
                    None => {
                        let at = els[i].at;
                        warnings.push(ImportNote::at(
                            at.0,
                            at.1,
                            crate::msg!(
                                PlcopenBlockTiedToRail,
                                pou = pou,
                                id = &id,
                                ty = &raw.type_name
                            ),
                        ));
                        power = vec![rail_conn];
                    }
                }
            }
        }
        if !power_pin.eq_ignore_ascii_case(default_power_in(&raw)) {
            block.power_in = Some(power_pin.clone());
        }
        let out_pin = outs.get(&i).cloned().unwrap_or_default();
        let mut wired = Vec::new();
        for (pin, conns) in &raw.inputs {
            if pin.eq_ignore_ascii_case(&power_pin) || conns.is_empty() {
                continue;
            }
            if pin.eq_ignore_ascii_case("EN") {
                return Err(err(pou, &id, crate::msg!(PlcopenEnNotPower)));
            }
            let srcs: Vec<usize> =
                conns.iter().map(|c| lookup(index, c, &id)).collect::<Result<_, _>>()?;
            if let ([s], [c]) = (srcs.as_slice(), conns.as_slice()) {
                match &els[*s].kind {
                    Kind::InVar(expr) => {
                        block.inputs.push(Pin::operand(pin, expr));
                        continue;
                    }
                    Kind::Block(_) if !is_power(c, els, index, &outs) => {
                        let operand = data_operand(els, &mut pins, *s, c, ctx, &outs)?;
                        pins.data.push((*s, i));
                        block.inputs.push(Pin::operand(pin, &operand));
                        continue;
                    }
                    _ => {}
                }
            }
            if fed(conns, els, index) {
                wired.push((block.inputs.len(), conns.clone()));
                block.inputs.push(Pin::wired(pin, 0));
                continue;
            }
            return Err(err(pou, &id, crate::msg!(PlcopenInputMixesSources, pin = pin)));
        }
        for (pin, conns) in &raw.in_outs {
            let srcs: Vec<usize> =
                conns.iter().map(|c| lookup(index, c, &id)).collect::<Result<_, _>>()?;
            match srcs.as_slice() {
                [] => {}
                [s] => match &els[*s].kind {
                    Kind::InVar(expr) => block.in_outs.push(Pin::operand(pin, expr)),
                    _ => {
                        return Err(err(
                            pou,
                            &id,
                            crate::msg!(PlcopenInOutNeedsVariable, pin = pin),
                        ))
                    }
                },
                _ => return Err(err(pou, &id, crate::msg!(PlcopenInOutSeveralWires, pin = pin))),
            }
        }
        let probe = Block { power_out: None, ..block.clone() };
        if !out_pin.eq_ignore_ascii_case(probe.power_output()) {
            block.power_out = Some(out_pin.clone());
        } else if !block.has_enable() && probe.power_output().eq_ignore_ascii_case("ENO") {
            // Power enters at a BOOL input and nothing takes it out: the type's first BOOL
            // output carries it, as for the standard FBs.
            if let Some(q) = ctx.catalog.block(&raw.type_name).and_then(|t| {
                t.outputs
                    .iter()
                    .find(|p| p.ty.as_ref().is_some_and(TypeKey::is_bool))
                    .map(|p| p.name.clone())
            }) {
                block.power_out = Some(q);
            }
        }
        if let Some(entry) = pins.blocks.get_mut(&i) {
            // Data wires sorted meanwhile may have bound more outputs of this block.
            block.outputs = std::mem::take(&mut entry.block.outputs);
            *entry = BlockEl { block, power, wired };
        }
    }
    for b in pins.blocks.values_mut() {
        let rows = b.block.inputs.len().max(b.block.outputs.len() + b.block.in_outs.len());
        b.block.height = (rows + 1) as u32;
    }
    Ok(pins)
}

/// outVariables: block outputs bound to variables; one fed by power becomes a coil.
fn bind_out_variables(
    els: &mut [El],
    index: &HashMap<String, usize>,
    pins: &mut Pins,
    outs: &HashMap<usize, String>,
    pou: &str,
    warnings: &mut Vec<ImportNote>,
) -> Result<(), ImportError> {
    for i in 0..els.len() {
        let Kind::OutVar(expr) = els[i].kind.clone() else { continue };
        let id = els[i].id.clone();
        let conns = els[i].conns.clone();
        let [c] = conns.as_slice() else {
            if conns.is_empty() {
                let at = els[i].at;
                warnings.push(ImportNote::at(
                    at.0,
                    at.1,
                    crate::msg!(
                        PlcopenOutVariableNotConnected,
                        pou = pou,
                        id = &id,
                        variable = &expr
                    ),
                ));
                continue;
            }
            return Err(err(pou, &id, crate::msg!(PlcopenOutVariableSeveral)));
        };
        let s = index
            .get(&c.from)
            .copied()
            .ok_or_else(|| err(pou, &id, crate::msg!(PlcopenMissingLocalId, id = &c.from)))?;
        if let Some(b) = pins.blocks.get_mut(&s) {
            let pin =
                c.param.clone().or_else(|| outs.get(&s).cloned()).unwrap_or_else(|| "OUT".into());
            let in_out = match &els[s].kind {
                Kind::Block(raw) => {
                    raw.in_outs.iter().find(|(p, _)| p.eq_ignore_ascii_case(&pin)).cloned()
                }
                _ => None,
            };
            if let Some((_, conns)) = in_out {
                // The in-out's output is the variable passed in; another one is not written.
                let passed = conns.first().and_then(|c| index.get(&c.from)).map(|&v| &els[v].kind);
                if !matches!(passed, Some(Kind::InVar(e)) if e.eq_ignore_ascii_case(&expr)) {
                    let at = els[i].at;
                    warnings.push(ImportNote::at(
                        at.0,
                        at.1,
                        crate::msg!(
                            PlcopenOutVariableOtherInOut,
                            pou = pou,
                            id = &id,
                            variable = &expr,
                            pin = &pin
                        ),
                    ));
                }
                continue;
            }
            if pin.eq_ignore_ascii_case("ENO") {
                return Err(err(pou, &id, crate::msg!(PlcopenOutVariableOnEno)));
            }
            if !b
                .block
                .outputs
                .iter()
                .any(|p| p.name.eq_ignore_ascii_case(&pin) && p.operand.eq_ignore_ascii_case(&expr))
            {
                b.block.outputs.push(Pin::operand(&pin, &expr));
            }
            continue;
        }
        match &els[s].kind {
            Kind::LeftRail | Kind::Leaf(_) => {
                let at = els[i].at;
                warnings.push(ImportNote::at(
                    at.0,
                    at.1,
                    crate::msg!(
                        PlcopenOutVariableBecameCoil,
                        pou = pou,
                        id = &id,
                        variable = &expr
                    ),
                ));
                els[i].kind = Kind::Leaf(Element::Coil { kind: CoilKind::Normal, operand: expr });
            }
            _ => {
                return Err(err(
                    pou,
                    &id,
                    crate::msg!(PlcopenOutVariableNotBlockOutput, variable = &expr, id = &c.from),
                ))
            }
        }
    }
    Ok(())
}

/// The operand that stands for output `c.param` of block `s` on a data wire.
fn data_operand(
    els: &[El],
    pins: &mut Pins,
    s: usize,
    c: &Conn,
    ctx: &mut Ctx<'_>,
    outs: &HashMap<usize, String>,
) -> Result<String, ImportError> {
    let Kind::Block(raw) = &els[s].kind else { return Ok(String::new()) };
    let pin = c.param.clone().or_else(|| outs.get(&s).cloned()).unwrap_or_else(|| "OUT".into());
    if let Some(inst) = &raw.instance {
        return Ok(format!("{inst}.{pin}"));
    }
    if let Some(b) = pins.blocks.get(&s) {
        if let Some(p) = b.block.outputs.iter().find(|p| p.name.eq_ignore_ascii_case(&pin)) {
            return Ok(p.operand.clone());
        }
    }
    let ty = function_output_type(els, pins, s, &pin, ctx, outs).ok_or_else(|| {
        err(
            ctx.pou,
            &els[s].id,
            crate::msg!(PlcopenOutputTypeUnknown, pin = &pin, ty = &raw.type_name),
        )
    })?;
    let base: String = format!("{}_{}_{}", raw.type_name, els[s].id, pin)
        .chars()
        .map(|ch| if ch.is_ascii_alphanumeric() { ch } else { '_' })
        .collect();
    let mut name = base.clone();
    let mut n = 2;
    while ctx.scope.contains_key(&name.to_ascii_uppercase()) {
        name = format!("{base}_{n}");
        n += 1;
    }
    ctx.scope.insert(name.to_ascii_uppercase(), ty.clone());
    pins.declarations.push(format!("    {name} : {ty};"));
    if let Some(b) = pins.blocks.get_mut(&s) {
        b.block.outputs.push(Pin::operand(&pin, &name));
    }
    Ok(name)
}

/// The type of output `pin` of function block element `s`, from its declaration or inputs.
fn function_output_type(
    els: &[El],
    pins: &Pins,
    s: usize,
    pin: &str,
    ctx: &Ctx<'_>,
    outs: &HashMap<usize, String>,
) -> Option<TypeKey> {
    let Kind::Block(raw) = &els[s].kind else { return None };
    if let Some(t) = ctx.catalog.block(&raw.type_name) {
        if t.kind == BlockKind::Function {
            return t.output(pin)?.ty.clone();
        }
    }
    if is_comparison(&raw.type_name) {
        return Some(TypeKey::Named("BOOL".into()));
    }
    let upper = raw.type_name.to_ascii_uppercase();
    match upper.as_str() {
        "BCD_TO_INT" => return Some(TypeKey::Named("INT".into())),
        "INT_TO_BCD" => return Some(TypeKey::Named("WORD".into())),
        _ => {}
    }
    // A conversion gives the type its name ends in: `BOOL_TO_INT` gives INT.
    if crate::ladder::blocks::is_conversion(&upper) {
        let (_, to) = upper.split_once("_TO_")?;
        return Some(TypeKey::Named(to.to_string()));
    }
    // ADD, MOVE, SQRT, SHL, …: the type of their (widest) typed input.
    let _ = (pins, outs);
    let mut best: Option<TypeKey> = None;
    for (p, conns) in &raw.inputs {
        if p.eq_ignore_ascii_case("EN") || p.eq_ignore_ascii_case("N") {
            continue;
        }
        let [c] = conns.as_slice() else { continue };
        let Some(src) = els.iter().find(|e| e.id == c.from) else { continue };
        let ty = match &src.kind {
            Kind::InVar(expr) => {
                ctx.catalog.place_type(&ctx.scope, expr).or_else(|| typed_literal(expr))
            }
            // Power from the rail or through contacts and coils is BOOL.
            Kind::LeftRail | Kind::Leaf(_) => Some(TypeKey::Named("BOOL".into())),
            Kind::Block(b) => match &b.instance {
                Some(inst) => ctx.catalog.place_type(
                    &ctx.scope,
                    &format!("{inst}.{}", c.param.as_deref().unwrap_or("OUT")),
                ),
                None => None,
            },
            _ => None,
        };
        if let Some(t) = ty {
            best = match best {
                Some(b) if crate::ladder::catalog::fits(&t, &b) => Some(b),
                _ => Some(t),
            };
        }
    }
    best
}

/// The type of a literal written with a type prefix (`INT#5`) or of an unambiguous one.
fn typed_literal(expr: &str) -> Option<TypeKey> {
    let e = crate::syntax::parse_expression(expr).ok()?;
    let crate::syntax::ExprKind::Literal(lit) = &e.kind else { return None };
    if let Some(p) = &lit.type_prefix {
        return Some(TypeKey::Named(p.name.to_ascii_uppercase()));
    }
    use crate::syntax::ast::LiteralValue as V;
    Some(TypeKey::Named(
        match lit.value {
            V::Real(_) => "REAL",
            V::Time(_) => "TIME",
            V::Bool(_) => "BOOL",
            _ => return None,
        }
        .into(),
    ))
}
