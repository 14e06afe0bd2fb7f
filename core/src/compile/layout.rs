//! Memory layout: sizes of types, offsets of variables and fields, addresses of globals,
//! the main instance and function frames; the initial image and the RETAIN ranges.
//!
//! An FB instance's size includes the temporaries of the FB's code, so laying out a POU
//! compiles its body once "dry" (with placeholder addresses) to count them.

use super::emit::{self, Frame};
use super::error::{add, bad, too_large, MAX_CELLS};
use super::{Code, CompileError, ConditionId, Executable, PouCode, Slot, VarEntry};
use crate::program::memory::{string_cells, string_header};
use crate::program::{Layouts, PouLayout};
use crate::semantic::ir::{Expr, InitValue, Program, Var};
use crate::semantic::types::{PouId, RefInit, RefRoot, RefStep, StructId, Type};
use crate::syntax::{PouKind, VarSection};

impl Layouts {
    fn new(p: &Program) -> Self {
        Layouts {
            pous: vec![None; p.pous.len()],
            busy: vec![false; p.pous.len()],
            structs: vec![None; p.types.structs.len()],
            frames: vec![None; p.pous.len()],
            ..Layouts::default()
        }
    }

    /// Cells taken by a value of type `ty`.
    pub fn size_of(&mut self, p: &Program, ty: Type) -> Result<u32, CompileError> {
        Ok(match ty {
            Type::Elem(_) | Type::Enum(_) | Type::Ref(_) => 1,
            Type::Str { wide, len } => {
                let bytes = u64::from(len) * if wide { 2 } else { 1 };
                if bytes > MAX_CELLS * 8 {
                    return Err(too_large(bytes / 8));
                }
                string_cells(bytes as u32)
            }
            Type::Array(a) => {
                let def = p.types.arrays.get(a as usize).ok_or_else(|| bad("array type"))?;
                let n = def.len();
                let e = u64::from(self.size_of(p, def.element)?);
                let total = n.checked_mul(e).ok_or(too_large(u64::MAX))?;
                add(0, total)?
            }
            Type::Struct(s) => {
                let offs = self.struct_offsets(p, s)?;
                offs.last().copied().unwrap_or(0)
            }
            Type::Fb(q) => {
                let l = self.pou(p, q)?;
                if !l.complete {
                    return Err(CompileError::RecursiveLayout(p.pou(q).name.clone()));
                }
                l.size
            }
            Type::Void => 0,
        })
    }

    /// Field offsets of struct `s`, followed by its size.
    pub fn struct_offsets(&mut self, p: &Program, s: StructId) -> Result<Vec<u32>, CompileError> {
        if let Some(Some(v)) = self.structs.get(s as usize) {
            return Ok(v.clone());
        }
        let def = p.types.structs.get(s as usize).ok_or_else(|| bad("struct type"))?;
        if self.structs.get(s as usize).is_none() {
            return Err(bad("struct type"));
        }
        let mut offs = Vec::with_capacity(def.fields.len() + 1);
        let mut at = 0u32;
        for f in &def.fields {
            offs.push(at);
            at = add(at, u64::from(self.size_of(p, f.ty)?))?;
        }
        offs.push(at);
        if let Some(slot) = self.structs.get_mut(s as usize) {
            *slot = Some(offs.clone());
        }
        Ok(offs)
    }

    /// The layout of POU `q` (computing it, with a dry compile, when needed). During its
    /// own dry compile a POU's layout is returned incomplete.
    pub fn pou(&mut self, p: &Program, q: PouId) -> Result<&PouLayout, CompileError> {
        let qi = q as usize;
        let pou = p.pous.get(qi).ok_or_else(|| bad("POU id"))?;
        if self.pous.get(qi).is_some_and(|l| l.is_none()) {
            if self.busy.get(qi).copied().unwrap_or(true) {
                return Err(CompileError::RecursiveLayout(pou.name.clone()));
            }
            self.busy[qi] = true;
            let mut offsets = Vec::with_capacity(pou.vars.len());
            let mut at = 0u32;
            for v in &pou.vars {
                offsets.push(at);
                let n = if v.section == VarSection::InOut { 1 } else { self.size_of(p, v.ty)? };
                at = add(at, u64::from(n))?;
            }
            self.pous[qi] = Some(PouLayout { offsets, vars_size: at, size: at, complete: false });
            let mut scratch = Code::default();
            let frame =
                if pou.kind == PouKind::FunctionBlock { Frame::Instance } else { Frame::Static };
            let mut temps = emit::compile_pou(self, p, q, &mut scratch, frame)?;
            if pou.kind == PouKind::Program {
                // A PROGRAM also runs as an instance (of a configuration, or a plant), where
                // reaching a global takes registers that its static frame does not.
                let mut scratch = Code::default();
                temps = temps.max(emit::compile_pou(self, p, q, &mut scratch, Frame::Instance)?);
            }
            if let Some(Some(l)) = self.pous.get_mut(qi) {
                l.size = add(at, u64::from(temps))?;
                l.complete = true;
            }
            self.busy[qi] = false;
        }
        self.pous.get(qi).and_then(|l| l.as_ref()).ok_or_else(|| bad("POU layout"))
    }

    /// Offset of variable `i` in POU `q`'s frame.
    pub fn var_offset(&mut self, p: &Program, q: PouId, i: u32) -> Result<u32, CompileError> {
        self.pou(p, q)?.offsets.get(i as usize).copied().ok_or_else(|| bad("variable index"))
    }

    /// Offset of field `i` of struct `s`.
    pub fn field_offset(&mut self, p: &Program, s: StructId, i: u32) -> Result<u32, CompileError> {
        self.struct_offsets(p, s)?.get(i as usize).copied().ok_or_else(|| bad("field index"))
    }

    /// POUs with a complete layout.
    fn laid_out(&self) -> Vec<PouId> {
        (0..self.pous.len() as u32)
            .filter(|&i| self.pous[i as usize].as_ref().is_some_and(|l| l.complete))
            .collect()
    }
}

/// Builds the executable (see [`super::compile`]).
pub(crate) fn build(p: &Program, main: PouId, more: &[PouId]) -> Result<Executable, CompileError> {
    for &q in std::iter::once(&main).chain(more) {
        match p.pous.get(q as usize) {
            Some(m) if m.kind == PouKind::Program => {}
            _ => return Err(CompileError::NotAProgram(q)),
        }
    }
    let mut lay = Layouts::new(p);
    let mut at = 0u32;
    let mut globals = Vec::with_capacity(p.globals.len());
    for g in &p.globals {
        globals.push(at);
        at = add(at, u64::from(lay.size_of(p, g.ty)?))?;
    }
    lay.globals = globals;
    let main_size = lay.pou(p, main)?.size;
    lay.main_base = at;
    // A configuration's PROGRAM holds its program instances as variables of PROGRAM type.
    let mut instances = Vec::new();
    for (i, v) in p.pou(main).vars.iter().enumerate() {
        if let Type::Fb(q) = v.ty {
            if p.pous.get(q as usize).is_some_and(|x| x.kind == PouKind::Program) {
                instances.push((q, add(at, u64::from(lay.var_offset(p, main, i as u32)?))?));
            }
        }
    }
    let inline = instances.len();
    at = add(at, u64::from(main_size))?;
    for &q in more {
        let size = lay.pou(p, q)?.size;
        instances.push((q, at));
        at = add(at, u64::from(size))?;
    }
    let mut exe = Executable {
        out: Code::default(),
        pous: vec![
            PouCode {
                entry: u32::MAX,
                frame: None,
                size: 0,
                library: false,
                temps: Vec::new(),
                template: Vec::new(),
                relocs: Vec::new(),
                vars: Vec::new(),
                offsets: Vec::new(),
                trusted: false,
            };
            p.pous.len()
        ],
        retained: Vec::new(),
        conditions: Vec::new(),
        condition_trusted: Vec::new(),
        main,
        main_base: lay.main_base,
        type_table: p.types.clone(),
        vars: Vec::new(),
        lay,
        instances,
    };
    exe.out.init = vec![0; at as usize];
    for (i, g) in p.globals.iter().enumerate() {
        let a = exe.lay.globals[i];
        write_init(&mut exe, p, a, g.ty, g.init.as_ref(), g.range, &mut InitCtx::default())?;
    }
    let mb = exe.main_base;
    write_instance(&mut exe, p, mb, main, None, &mut InitCtx::default())?;
    exe.pous[main as usize].frame = Some(exe.main_base);
    let more: Vec<(PouId, u32)> = exe.instances[inline..].to_vec();
    for &(q, base) in &more {
        write_instance(&mut exe, p, base, q, None, &mut InitCtx::default())?;
    }
    finish_new_pous(&mut exe, p)?;
    init_located(&mut exe, p, &p.globals)?;
    init_located(&mut exe, p, &p.pou(main).vars)?;
    // Variables and RETAIN ranges.
    let mut ranges = Vec::new();
    let mpou = p.pou(main);
    for (i, v) in mpou.vars.iter().enumerate() {
        let off = exe.lay.var_offset(p, main, i as u32)?;
        // A VAR_EXTERNAL is its global (the code reaches the global; its own cell is unused).
        let global = (v.section == VarSection::External)
            .then(|| p.globals.iter().position(|g| g.name.eq_ignore_ascii_case(&v.name)))
            .flatten()
            .and_then(|g| exe.lay.globals.get(g).copied());
        let addr = global.unwrap_or(exe.main_base + off);
        let slot = image_slot(&exe, p, v).unwrap_or(Slot { addr, ty: v.ty, bit: None });
        exe.vars.push(VarEntry { var: v.clone(), slot, global: false });
        retain_ranges(&mut exe.lay, p, v, addr, &mut ranges)?;
    }
    // Each further PROGRAM is one variable of the main scope, named as its POU.
    for &(q, base) in &more {
        let var = Var::program_instance(p, q, VarSection::Var);
        retain_ranges(&mut exe.lay, p, &var, base, &mut ranges)?;
        exe.vars.push(VarEntry {
            var,
            slot: Slot { addr: base, ty: Type::Fb(q), bit: None },
            global: false,
        });
    }
    for (i, g) in p.globals.iter().enumerate() {
        let addr = exe.lay.globals[i];
        let slot = image_slot(&exe, p, g).unwrap_or(Slot { addr, ty: g.ty, bit: None });
        exe.vars.push(VarEntry { var: g.clone(), slot, global: true });
        retain_ranges(&mut exe.lay, p, g, addr, &mut ranges)?;
    }
    crate::order::sort(&mut ranges);
    let mut merged: Vec<(u32, u32)> = Vec::new();
    for (s, n) in ranges {
        match merged.last_mut() {
            Some((ls, ln)) if *ls + *ln >= s => *ln = (*ln).max(s + n - *ls),
            _ => merged.push((s, n)),
        }
    }
    exe.retained = merged;
    let kinds: Vec<PouKind> = p.pous.iter().map(|q| q.kind).collect();
    super::trust::mark_trusted(&mut exe, &kinds);
    Ok(exe)
}

/// The slot of a located variable in the process image (`semantic::image`), when it
/// has one there.
fn image_slot(exe: &Executable, p: &Program, v: &Var) -> Option<Slot> {
    // The variable list is not written yet: the image's globals are found by their layout.
    let base = |name: &str| {
        let g = p.globals.iter().position(|g| g.name == name)?;
        exe.lay.globals.get(g).copied()
    };
    crate::program::locate::image_slot_in(base, v.location.as_ref()?, v.ty)
}

/// Writes the initial values of the located variables among `vars` into the process
/// image, where their code reads them.
fn init_located(exe: &mut Executable, p: &Program, vars: &[Var]) -> Result<(), CompileError> {
    for v in vars {
        let (Some(slot), Some(InitValue::Scalar(bits))) = (image_slot(exe, p, v), v.init.as_ref())
        else {
            continue;
        };
        let cell = exe.out.init.get_mut(slot.addr as usize).ok_or_else(|| bad("image cell"))?;
        if let (Some((n, cell_elem)), Some(ty)) = (slot.bit, v.ty.elem()) {
            *cell = crate::values::arith::put_at_bit(cell_elem, *cell, n, ty, *bits);
        }
    }
    Ok(())
}

/// Allocates frames for newly laid-out functions and compiles every laid-out POU whose
/// body has no code yet.
fn finish_new_pous(exe: &mut Executable, p: &Program) -> Result<(), CompileError> {
    for q in exe.lay.laid_out() {
        if p.pou(q).kind == PouKind::Function && exe.lay.frames[q as usize].is_none() {
            let size = exe.lay.pou(p, q)?.size;
            let base = exe.out.init.len() as u32;
            let end = add(base, u64::from(size))?;
            exe.out.init.resize(end as usize, 0);
            exe.lay.frames[q as usize] = Some(base);
            exe.pous[q as usize].frame = Some(base);
            write_instance(exe, p, base, q, None, &mut InitCtx::default())?;
        }
    }
    exe.lay.real = true;
    for q in exe.lay.laid_out() {
        let pou = p.pou(q);
        let instance = exe.instances.iter().any(|(i, _)| *i == q);
        if exe.pous[q as usize].entry != u32::MAX
            || (pou.kind == PouKind::Program && q != exe.main && !instance)
        {
            continue;
        }
        let frame = match pou.kind {
            PouKind::FunctionBlock => Frame::Instance,
            PouKind::Program if instance => Frame::Instance,
            _ => Frame::Static,
        };
        exe.pous[q as usize].entry = exe.out.code.len() as u32;
        let mut lay = std::mem::take(&mut exe.lay);
        let r = emit::compile_pou(&mut lay, p, q, &mut exe.out, frame);
        exe.lay = lay;
        r?;
        let l = exe.lay.pou(p, q)?.clone();
        let mut temps = Vec::new();
        for (i, v) in pou.vars.iter().enumerate() {
            if v.section == VarSection::Temp {
                let n = exe.lay.size_of(p, v.ty)?;
                temps.push((l.offsets[i], n));
            }
        }
        let code = &mut exe.pous[q as usize];
        code.size = l.size;
        code.library = pou.library;
        if !temps.is_empty() {
            // Template of one instance at address 0 of a scratch image.
            // A reference in it that points into the instance is moved to each instance
            // when its temporaries start over (`relocs`).
            let saved = std::mem::replace(&mut exe.out.init, vec![0; l.size as usize]);
            let mut ctx = InitCtx::default();
            let r = write_instance(exe, p, 0, q, None, &mut ctx);
            let template = std::mem::replace(&mut exe.out.init, saved);
            r?;
            exe.pous[q as usize].template = template;
            let in_temps = |c: &u32| temps.iter().any(|&(off, n)| (off..off + n).contains(c));
            exe.pous[q as usize].relocs = ctx.relocs.into_iter().filter(in_temps).collect();
        }
        exe.pous[q as usize].temps = temps;
        exe.pous[q as usize].vars = pou.vars.clone();
        exe.pous[q as usize].offsets = l.offsets;
    }
    Ok(())
}

/// What writing initial values needs besides the value: the instances being initialised
/// (outermost first), where a reference's initial value `REF(x)` finds the instance
/// holding `x`; and the cells given such a reference into an instance, which must move with
/// it (a VAR_TEMP template is written at address 0).
#[derive(Default)]
struct InitCtx {
    chain: Vec<(PouId, u32)>,
    relocs: Vec<u32>,
}

/// The address of the variable a reference's initial value points to.
fn ref_target(
    exe: &mut Executable,
    p: &Program,
    r: &RefInit,
    ctx: &InitCtx,
) -> Result<u32, CompileError> {
    let mut at = match r.root {
        RefRoot::Own(q, i) => {
            let base = ctx.chain.iter().rev().find(|(c, _)| *c == q).map(|&(_, b)| b);
            let base = base.ok_or_else(|| bad("reference initial value outside its POU"))?;
            add(base, u64::from(exe.lay.var_offset(p, q, i)?))?
        }
        RefRoot::Global(g) => {
            exe.lay.globals.get(g as usize).copied().ok_or_else(|| bad("global index"))?
        }
        RefRoot::Pending(_) => return Err(bad("unchecked reference initial value")),
    };
    for step in &r.steps {
        let off = match *step {
            RefStep::Field(s, i) => u64::from(exe.lay.field_offset(p, s, i)?),
            RefStep::Member(q, i) => u64::from(exe.lay.var_offset(p, q, i)?),
            RefStep::Element(a, k) => {
                let def = p.types.arrays.get(a as usize).ok_or_else(|| bad("array type"))?;
                let size = exe.lay.size_of(p, def.element)?;
                k.checked_mul(u64::from(size)).ok_or(too_large(k))?
            }
        };
        at = add(at, off)?;
    }
    Ok(at)
}

/// Writes the initial value of a `ty` at `addr` of the image.
fn write_init(
    exe: &mut Executable,
    p: &Program,
    addr: u32,
    ty: Type,
    init: Option<&InitValue>,
    range: Option<(i64, i64)>,
    ctx: &mut InitCtx,
) -> Result<(), CompileError> {
    let a = addr as usize;
    match ty {
        Type::Ref(_) if matches!(init, Some(InitValue::Ref(_))) => {
            let Some(InitValue::Ref(r)) = init else { return Err(bad("reference")) };
            // A reference holds its target's address plus one (0 is NULL).
            let target = ref_target(exe, p, r, ctx)?;
            if matches!(r.root, RefRoot::Own(..)) {
                ctx.relocs.push(addr);
            }
            set(exe, a, u64::from(target) + 1)
        }
        Type::Elem(_) | Type::Enum(_) | Type::Ref(_) => {
            let bits = match (init, range, ty) {
                (Some(InitValue::Scalar(b)), _, _) => *b,
                (_, Some((lo, _)), _) => lo as u64,
                (_, _, Type::Enum(e)) => p
                    .types
                    .enums
                    .get(e as usize)
                    .and_then(|d| d.values.first())
                    .map_or(0, |v| v.1 as u64),
                _ => 0,
            };
            set(exe, a, bits)
        }
        Type::Str { wide, len } => {
            let cap = len * if wide { 2 } else { 1 };
            let bytes: &[u8] = match init {
                Some(InitValue::Str(b)) => b,
                _ => &[],
            };
            let n = bytes.len().min(cap as usize) as u32;
            set(exe, a, string_header(cap, n))?;
            for (k, chunk) in bytes[..n as usize].chunks(8).enumerate() {
                let mut b = [0u8; 8];
                b[..chunk.len()].copy_from_slice(chunk);
                set(exe, a + 1 + k, u64::from_le_bytes(b))?;
            }
            Ok(())
        }
        Type::Array(id) => {
            let def = p.types.arrays.get(id as usize).ok_or_else(|| bad("array type"))?.clone();
            let esize = exe.lay.size_of(p, def.element)?;
            let items: &[InitValue] = match init {
                Some(InitValue::Array(v)) => v,
                _ => &[],
            };
            for k in 0..def.len() {
                let item = items.get(k as usize).or(def.element_init.as_ref());
                let at = add(addr, k * u64::from(esize))?;
                write_init(exe, p, at, def.element, item, def.element_range, ctx)?;
            }
            Ok(())
        }
        Type::Struct(s) => {
            let def = p.types.structs.get(s as usize).ok_or_else(|| bad("struct type"))?.clone();
            let offs = exe.lay.struct_offsets(p, s)?;
            for (i, f) in def.fields.iter().enumerate() {
                let over = match init {
                    Some(InitValue::Struct(v)) => v.get(i).and_then(|o| o.as_ref()),
                    _ => None,
                };
                let init = over.or(f.init.as_ref());
                write_init(exe, p, addr + offs[i], f.ty, init, f.range, ctx)?;
            }
            Ok(())
        }
        Type::Fb(q) => write_instance(exe, p, addr, q, init, ctx),
        Type::Void => Ok(()),
    }
}

/// Writes the initial values of an instance (or frame) of POU `q` at `addr`.
fn write_instance(
    exe: &mut Executable,
    p: &Program,
    addr: u32,
    q: PouId,
    init: Option<&InitValue>,
    ctx: &mut InitCtx,
) -> Result<(), CompileError> {
    ctx.chain.push((q, addr));
    let r = write_members(exe, p, addr, q, init, ctx);
    ctx.chain.pop();
    r
}

/// The members' part of [`write_instance`].
fn write_members(
    exe: &mut Executable,
    p: &Program,
    addr: u32,
    q: PouId,
    init: Option<&InitValue>,
    ctx: &mut InitCtx,
) -> Result<(), CompileError> {
    let pou = p.pous.get(q as usize).ok_or_else(|| bad("POU id"))?;
    for (i, v) in pou.vars.iter().enumerate() {
        let off = exe.lay.var_offset(p, q, i as u32)?;
        if v.section == VarSection::InOut {
            continue;
        }
        let over = match init {
            Some(InitValue::Struct(o)) => o.get(i).and_then(|x| x.as_ref()),
            _ => None,
        };
        write_init(exe, p, addr + off, v.ty, over.or(v.init.as_ref()), v.range, ctx)?;
    }
    Ok(())
}

fn set(exe: &mut Executable, a: usize, bits: u64) -> Result<(), CompileError> {
    let c = exe.out.init.get_mut(a).ok_or_else(|| bad("image address"))?;
    *c = bits;
    Ok(())
}

/// Collects the RETAIN cell ranges of variable `v` at `addr` (recursing into FB instances).
fn retain_ranges(
    lay: &mut Layouts,
    p: &Program,
    v: &Var,
    addr: u32,
    out: &mut Vec<(u32, u32)>,
) -> Result<(), CompileError> {
    if v.retain {
        out.push((addr, lay.size_of(p, v.ty)?));
        return Ok(());
    }
    retain_in_type(lay, p, v.ty, addr, out)
}

fn retain_in_type(
    lay: &mut Layouts,
    p: &Program,
    ty: Type,
    addr: u32,
    out: &mut Vec<(u32, u32)>,
) -> Result<(), CompileError> {
    match ty {
        Type::Fb(q) => {
            let pou = p.pous.get(q as usize).ok_or_else(|| bad("POU id"))?;
            if !pou.vars.iter().any(|v| v.retain || matches!(v.ty, Type::Fb(_) | Type::Array(_))) {
                return Ok(());
            }
            for (i, v) in pou.vars.iter().enumerate() {
                let off = lay.var_offset(p, q, i as u32)?;
                retain_ranges(lay, p, v, addr + off, out)?;
            }
            Ok(())
        }
        Type::Array(a) => {
            let def = p.types.arrays.get(a as usize).ok_or_else(|| bad("array type"))?;
            let (elem, n) = (def.element, def.len());
            if !matches!(elem, Type::Fb(_)) {
                return Ok(());
            }
            let es = lay.size_of(p, elem)?;
            for k in 0..n {
                retain_in_type(lay, p, elem, addr + (k as u32) * es, out)?;
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// See [`Executable::compile_condition`].
pub(crate) fn compile_condition(
    exe: &mut Executable,
    p: &Program,
    cond: &Expr,
) -> Result<ConditionId, CompileError> {
    // Dry run to count temporaries, then reserve them at the end of the image.
    let main = exe.main;
    let mut scratch = Code::default();
    let was_real = exe.lay.real;
    exe.lay.real = false;
    let mut lay = std::mem::take(&mut exe.lay);
    let r = emit::compile_condition(&mut lay, p, main, &mut scratch, 0, cond);
    exe.lay = lay;
    exe.lay.real = was_real;
    let temps = r?;
    finish_new_pous(exe, p)?;
    let start = exe.out.init.len() as u32;
    let end = add(start, u64::from(temps))?;
    exe.out.init.resize(end as usize, 0);
    let entry = exe.out.code.len() as u32;
    let mut lay = std::mem::take(&mut exe.lay);
    let r = emit::compile_condition(&mut lay, p, main, &mut exe.out, start - exe.main_base, cond);
    exe.lay = lay;
    r?;
    exe.conditions.push(entry);
    let kinds: Vec<PouKind> = p.pous.iter().map(|q| q.kind).collect();
    super::trust::mark_trusted(exe, &kinds);
    Ok(ConditionId(exe.conditions.len() as u32 - 1))
}
