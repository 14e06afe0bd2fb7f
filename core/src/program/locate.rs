//! The variable locator: resolves a textual path (`Tank.Level`, `Arr[1,2]`, `Timer.Q`,
//! `Flags.3`) to a [`Slot`], case-insensitively, against the main program's variables and
//! then the globals. Used by the simulator's `--set`, forcing and the variables table.

use super::{Executable, Slot};
use crate::semantic::types::{dim_len, Type};
use crate::syntax::VarSection;

/// One step of a path.
enum Step<'a> {
    Name(&'a str),
    Bit(u32),
    Index(Vec<i64>),
}

fn parse(path: &str) -> Option<Vec<Step<'_>>> {
    let s = path.trim();
    let mut steps = Vec::new();
    let mut rest = s;
    let mut first = true;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('[') {
            let close = r.bytes().position(|b| b == b']')?;
            let idx: Option<Vec<i64>> =
                r[..close].split(',').map(|t| t.trim().parse::<i64>().ok()).collect();
            steps.push(Step::Index(idx?));
            rest = &r[close + 1..];
            continue;
        }
        let r = if first { rest } else { rest.strip_prefix('.')? };
        first = false;
        // Bytes, not chars: the page and the plants locate by name on every scan, and a
        // search for a set of chars is many times slower in the size-optimised wasm build.
        let end = r.bytes().position(|b| b == b'.' || b == b'[').unwrap_or(r.len());
        let word = r[..end].trim();
        if word.is_empty() {
            return None;
        }
        if word.bytes().all(|b| b.is_ascii_digit()) {
            steps.push(Step::Bit(word.parse().ok()?));
        } else {
            steps.push(Step::Name(word));
        }
        rest = &r[end..];
    }
    Some(steps)
}

/// The slot of the main program's variable or the global named `name` (a program's own
/// variable first).
fn variable(exe: &Executable, name: &str) -> Option<Slot> {
    // The length first: a cheap test that rules out most names without a call.
    let named = |global: bool| {
        exe.vars.iter().find(|v| {
            v.global == global
                && v.var.name.len() == name.len()
                && v.var.name.eq_ignore_ascii_case(name)
        })
    };
    let entry = named(false).or_else(|| named(true))?;
    (entry.var.section != VarSection::InOut).then_some(entry.slot)
}

/// See [`Executable::locate`].
pub(crate) fn locate(exe: &Executable, path: &str) -> Option<Slot> {
    // A plain name (the panels and the plants read most variables so, on every scan) is
    // looked up without taking the path apart.
    let plain = path.trim();
    if !plain.is_empty() && plain.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
        if plain.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        return variable(exe, plain);
    }
    locate_path(exe, path)
}

/// [`locate`] for a path of more than one step (kept out of line: the plain names that are
/// looked up on every scan then run, and V8 optimises, only the small part).
#[inline(never)]
fn locate_path(exe: &Executable, path: &str) -> Option<Slot> {
    let steps = parse(path)?;
    let mut it = steps.into_iter();
    let Some(Step::Name(first)) = it.next() else {
        return None;
    };
    let mut slot = variable(exe, first)?;
    for step in it {
        if slot.bit.is_some() {
            return None;
        }
        slot = match (step, slot.ty) {
            (Step::Name(n), Type::Struct(s)) => {
                let def = exe.type_table.structs.get(s as usize)?;
                let i = def.fields.iter().position(|f| f.name.eq_ignore_ascii_case(n))?;
                let off = exe.lay.cached_struct(s)?.get(i)?;
                Slot { addr: slot.addr + off, ty: def.fields[i].ty, bit: None }
            }
            (Step::Name(n), Type::Fb(q)) => {
                let code = exe.pous.get(q as usize)?;
                let i = code.vars.iter().position(|v| v.name.eq_ignore_ascii_case(n))?;
                let v = &code.vars[i];
                match v.section {
                    VarSection::InOut => return None,
                    // A VAR_EXTERNAL member is the global of its name.
                    VarSection::External => {
                        exe.vars
                            .iter()
                            .find(|e| e.global && e.var.name.eq_ignore_ascii_case(n))?
                            .slot
                    }
                    _ => match image_slot(exe, v) {
                        Some(s) => s,
                        None => {
                            Slot { addr: slot.addr + code.offsets.get(i)?, ty: v.ty, bit: None }
                        }
                    },
                }
            }
            (Step::Bit(n), Type::Elem(e)) if e.is_integral() && n < e.bits() => {
                Slot { addr: slot.addr, ty: Type::BOOL, bit: Some((n, e)) }
            }
            (Step::Index(idx), Type::Array(a)) => {
                let def = exe.type_table.arrays.get(a as usize)?;
                if idx.len() != def.dims.len() {
                    return None;
                }
                let esize = element_size(exe, def.element)?;
                let mut flat: u64 = 0;
                for (i, (lo, hi)) in idx.iter().zip(&def.dims) {
                    if i < lo || i > hi {
                        return None;
                    }
                    let offset = dim_len(*lo, *i) - 1;
                    flat = flat.checked_mul(dim_len(*lo, *hi))?.checked_add(offset)?;
                }
                let addr = u64::from(slot.addr).checked_add(flat.checked_mul(u64::from(esize))?)?;
                Slot { addr: u32::try_from(addr).ok()?, ty: def.element, bit: None }
            }
            _ => return None,
        };
    }
    Some(slot)
}

/// Cells taken by a value of `ty`, from the layout already computed.
pub(crate) fn element_size(exe: &Executable, ty: Type) -> Option<u32> {
    Some(match ty {
        Type::Elem(_) | Type::Enum(_) | Type::Ref(_) => 1,
        Type::Str { wide, len } => super::memory::string_cells(len * if wide { 2 } else { 1 }),
        Type::Array(a) => {
            let def = exe.type_table.arrays.get(a as usize)?;
            u32::try_from(def.len()).ok()? * element_size(exe, def.element)?
        }
        Type::Struct(s) => *exe.lay.cached_struct(s)?.last()?,
        Type::Fb(q) => exe.pous.get(q as usize)?.size,
        Type::Void => 0,
    })
}

/// The slot of a located member in the process image (`semantic::image`), if it has one.
fn image_slot(exe: &Executable, v: &crate::semantic::ir::Var) -> Option<Slot> {
    image_slot_at(exe, v.location.as_ref()?, v.ty)
}

/// The slot of a value of type `ty` at address `loc` of the process image, if the address
/// is in the image.
pub(crate) fn image_slot_at(
    exe: &Executable,
    loc: &crate::syntax::DirectAddress,
    ty: Type,
) -> Option<Slot> {
    let image =
        |name: &str| exe.vars.iter().find(|e| e.global && e.var.name == name).map(|e| e.slot.addr);
    image_slot_in(image, loc, ty)
}

/// The slot of a value of type `ty` at address `loc` of the process image, the image of
/// each area starting at `base(its hidden global's name)`.
pub(crate) fn image_slot_in(
    base: impl Fn(&str) -> Option<u32>,
    loc: &crate::syntax::DirectAddress,
    ty: Type,
) -> Option<Slot> {
    let Type::Elem(_) = ty else { return None };
    let (cell, shift) = crate::semantic::image_spot(loc)?;
    let start = base(crate::semantic::image_name(loc.area))?;
    Some(Slot { addr: start + cell, ty, bit: Some((shift, crate::semantic::Elem::LWord)) })
}
