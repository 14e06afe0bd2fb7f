//! Reading one traced scan: memory at any point of it, the last write of a variable
//! before a point, the frame (and block instance) a write happened in, and the IR
//! statement a write came from with the places its expression and its enclosing
//! conditions read.

use crate::compile::{Executable, Slot};
use crate::diagnostics::Span;
use crate::program::locate::{element_size, image_slot_at};
use crate::program::memory::Memory;
use crate::semantic::ir::{CallArg, Expr, ExprKind, Place, Stmt, StmtKind};
use crate::semantic::types::{dim_len, PouId, Type};
use crate::semantic::Program;
use crate::sim::TracedScan;
use crate::syntax::VarSection;
use crate::values::arith;
use crate::vm::{Cause, TraceEvent};

/// Where a write happened, in user code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Frame {
    /// The instruction of user code (the call of a library block, for a write inside it).
    pub pc: u32,
    /// Its frame.
    pub base: u32,
    /// The library block written inside: its POU and instance frame.
    pub block: Option<(PouId, u32)>,
}

/// What wrote a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Writer {
    /// The program, at event `index`, in `frame`.
    Program {
        /// The event.
        index: usize,
        /// Where.
        frame: Frame,
    },
    /// The simulator, at event `index`.
    Outside {
        /// The event.
        index: usize,
        /// Why.
        cause: Cause,
    },
}

/// A traced scan with the executable it ran.
pub(super) struct Scan<'a> {
    pub traced: &'a TracedScan,
    pub exe: &'a Executable,
    pub program: &'a Program,
}

impl<'a> Scan<'a> {
    pub fn new(traced: &'a TracedScan) -> Scan<'a> {
        Scan { traced, exe: traced.view.executable(), program: traced.view.program() }
    }

    fn events(&self) -> &[TraceEvent] {
        &self.traced.events
    }

    /// Memory just before event `index` (every event before it applied).
    pub fn memory_at(&self, index: usize) -> Memory {
        let mut cells = self.traced.before.clone();
        cells.resize(cells.len().max(self.traced.view.memory().cells.len()), 0);
        for e in self.events().iter().take(index) {
            if let TraceEvent::Store { addr, value, .. }
            | TraceEvent::External { addr, value, .. } = *e
            {
                if let Some(c) = cells.get_mut(addr as usize) {
                    *c = value;
                }
            }
        }
        Memory { cells }
    }

    /// The value stored by event `index`, when it is a store.
    pub fn stored(&self, index: usize) -> Option<u64> {
        match self.events().get(index)? {
            TraceEvent::Store { value, .. } => Some(*value),
            _ => None,
        }
    }

    /// The cells a slot's value lives in.
    pub fn cells_of(&self, slot: &Slot) -> Vec<u32> {
        let n = if slot.bit.is_some() { 1 } else { element_size(self.exe, slot.ty).unwrap_or(1) };
        (slot.addr..slot.addr.saturating_add(n.max(1))).collect()
    }

    /// The last write of `slot` before event `limit`. A write of the cell holding a bit
    /// counts when it changed that bit, or when its statement assigns that very bit.
    pub fn last_write(&self, slot: &Slot, limit: usize) -> Option<Writer> {
        let cells = self.cells_of(slot);
        let events = self.events();
        let mut index = limit.min(events.len());
        while index > 0 {
            index -= 1;
            let (addr, value) = match events[index] {
                TraceEvent::Store { addr, value, .. }
                | TraceEvent::External { addr, value, .. } => (addr, value),
                _ => continue,
            };
            if !cells.contains(&addr) {
                continue;
            }
            if let Some((n, elem)) = slot.bit {
                let width =
                    if elem == crate::semantic::Elem::LWord { bit_width(slot.ty) } else { 1 };
                let before = self.memory_at(index).cells.get(addr as usize).copied().unwrap_or(0);
                let mask = if width >= 64 { u64::MAX } else { ((1u64 << width) - 1) << n };
                let changed = (before ^ value) & mask != 0;
                if !changed && !self.assigns(index, slot) {
                    continue;
                }
            }
            return Some(match events[index] {
                TraceEvent::External { cause, .. } => Writer::Outside { index, cause },
                _ => Writer::Program { index, frame: self.frame_of(index)? },
            });
        }
        None
    }

    /// Whether the statement of store event `index` assigns `slot` itself.
    fn assigns(&self, index: usize, slot: &Slot) -> bool {
        let Some(frame) = self.frame_of(index) else { return false };
        if frame.block.is_some() {
            return false;
        }
        let Some((span, pou)) = self.exe.statement_at(frame.pc as usize) else { return false };
        let Some((stmt, _)) = find_statement(self.program, pou, span) else { return false };
        let StmtKind::Assign(place, _) = &stmt.kind else { return false };
        let mem = self.memory_at(index);
        self.resolve(pou, frame.base, place, &mem).is_some_and(|s| s == *slot)
    }

    /// The user frame of the write at event `index`: for a write inside a standard
    /// library block, the call of that block in user code.
    pub fn frame_of(&self, index: usize) -> Option<Frame> {
        let TraceEvent::Store { pc, base, .. } = *self.events().get(index)? else { return None };
        let mut stack: Vec<(u32, u32, PouId, u32)> = Vec::new();
        for e in self.events().iter().take(index) {
            match *e {
                TraceEvent::Call { pc, caller, pou, base } => stack.push((pc, caller, pou, base)),
                TraceEvent::Return => {
                    stack.pop();
                }
                _ => {}
            }
        }
        let library = |pc: u32| {
            self.exe
                .statement_at(pc as usize)
                .and_then(|(_, pou)| self.exe.pous.get(pou as usize))
                .is_some_and(|p| p.library)
        };
        if !library(pc) {
            return Some(Frame { pc, base, block: None });
        }
        // The outermost library call made from user code.
        let call = stack.iter().find(|(pc, ..)| !library(*pc))?;
        Some(Frame { pc: call.0, base: call.1, block: Some((call.2, call.3)) })
    }

    /// The latest event before `before` entering the debug entry of `span` (of POU `pou`)
    /// in the frame at `base`.
    pub fn entry_of(&self, span: Span, pou: PouId, base: u32, before: usize) -> Option<usize> {
        let events = self.events();
        (0..before.min(events.len())).rev().find(|&i| match events[i] {
            TraceEvent::Enter { pc, base: b } => {
                b == base && self.exe.statement_at(pc as usize) == Some((span, pou))
            }
            _ => false,
        })
    }

    /// The path prefix of variables of POU `pou` in the frame at `base` (`""` for the
    /// main program, `LampDelay.` for an instance, `Plant.` for a plant).
    pub fn prefix(&self, pou: PouId, base: u32) -> String {
        if base == self.exe.main_base {
            return String::new();
        }
        if let Some(p) = crate::program::refpath::path_of(self.exe, base, Type::Fb(pou)) {
            return format!("{p}.");
        }
        format!("{}.", self.program.pou(pou).name)
    }

    /// Where `place` (of POU `pou` running in the frame at `base`) is in `mem`, when it
    /// can be told without running code (no dereference, indices of constants and
    /// variables).
    pub fn resolve(&self, pou: PouId, base: u32, place: &Place, mem: &Memory) -> Option<Slot> {
        let exe = self.exe;
        match place {
            Place::Local(i) => {
                let code = exe.pous.get(pou as usize)?;
                let var = code.vars.get(*i as usize)?;
                match var.section {
                    VarSection::InOut => None,
                    VarSection::External => global(exe, &var.name),
                    _ => match &var.location {
                        Some(loc) => image_slot_at(exe, loc, var.ty).or(Some(Slot {
                            addr: base.wrapping_add(*code.offsets.get(*i as usize)?),
                            ty: var.ty,
                            bit: None,
                        })),
                        None => Some(Slot {
                            addr: base.wrapping_add(*code.offsets.get(*i as usize)?),
                            ty: var.ty,
                            bit: None,
                        }),
                    },
                }
            }
            Place::Global(i) => {
                let var = self.program.globals.get(*i as usize)?;
                global(exe, &var.name).or_else(|| {
                    Some(Slot { addr: *exe.lay.globals.get(*i as usize)?, ty: var.ty, bit: None })
                })
            }
            Place::Field(inner, i) => {
                let s = self.resolve(pou, base, inner, mem)?;
                if s.bit.is_some() {
                    return None;
                }
                match s.ty {
                    Type::Struct(st) => {
                        let def = exe.type_table.structs.get(st as usize)?;
                        let off = exe.lay.cached_struct(st)?.get(*i as usize)?;
                        Some(Slot {
                            addr: s.addr + off,
                            ty: def.fields.get(*i as usize)?.ty,
                            bit: None,
                        })
                    }
                    Type::Fb(q) => {
                        let code = exe.pous.get(q as usize)?;
                        let var = code.vars.get(*i as usize)?;
                        match var.section {
                            VarSection::InOut => None,
                            VarSection::External => global(exe, &var.name),
                            _ => var
                                .location
                                .as_ref()
                                .and_then(|l| image_slot_at(exe, l, var.ty))
                                .or(Some(Slot {
                                    addr: s.addr + code.offsets.get(*i as usize)?,
                                    ty: var.ty,
                                    bit: None,
                                })),
                        }
                    }
                    _ => None,
                }
            }
            Place::Element(inner, arr, idx) => {
                let s = self.resolve(pou, base, inner, mem)?;
                let def = exe.type_table.arrays.get(*arr as usize)?;
                if idx.len() != def.dims.len() || s.bit.is_some() {
                    return None;
                }
                let esize = element_size(exe, def.element)?;
                let mut flat: u64 = 0;
                for (e, (lo, hi)) in idx.iter().zip(&def.dims) {
                    let i = self.number(pou, base, e, mem)?;
                    if i < *lo || i > *hi {
                        return None;
                    }
                    flat = flat.checked_mul(dim_len(*lo, *hi))?.checked_add(dim_len(*lo, i) - 1)?;
                }
                let addr = u64::from(s.addr).checked_add(flat.checked_mul(u64::from(esize))?)?;
                Some(Slot { addr: u32::try_from(addr).ok()?, ty: def.element, bit: None })
            }
            Place::Bit(inner, n, elem) => {
                let s = self.resolve(pou, base, inner, mem)?;
                (s.bit.is_none()).then_some(Slot {
                    addr: s.addr,
                    ty: Type::BOOL,
                    bit: Some((*n, *elem)),
                })
            }
            Place::Slice(inner, n, elem) => {
                let s = self.resolve(pou, base, inner, mem)?;
                Some(Slot {
                    addr: s.addr,
                    ty: Type::Elem(*elem),
                    bit: Some((*n, crate::semantic::Elem::LWord)),
                })
            }
            Place::Deref(_) => None,
        }
    }

    /// The integer value of an index expression made of constants and variables.
    fn number(&self, pou: PouId, base: u32, e: &Expr, mem: &Memory) -> Option<i64> {
        let Type::Elem(elem) = e.ty else { return None };
        match &e.kind {
            ExprKind::Const(bits) => i64::try_from(arith::to_i128(elem, *bits)).ok(),
            ExprKind::Load(p) => {
                let s = self.resolve(pou, base, p, mem)?;
                match crate::vm::read(mem, self.exe, &s) {
                    crate::vm::Value::Int(v, _) => i64::try_from(v).ok(),
                    _ => None,
                }
            }
            ExprKind::Convert(inner) => self.number(pou, base, inner, mem),
            _ => None,
        }
    }
}

/// The slot of global `name` (located globals in the process image).
fn global(exe: &Executable, name: &str) -> Option<Slot> {
    exe.vars.iter().find(|e| e.global && e.var.name.eq_ignore_ascii_case(name)).map(|e| e.slot)
}

/// Bits of a value of type `ty` kept in a process-image cell.
fn bit_width(ty: Type) -> u32 {
    match ty {
        Type::Elem(e) => e.bits(),
        _ => 64,
    }
}

/// A statement enclosing another, and which of its parts holds it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ancestor<'p> {
    pub stmt: &'p Stmt,
    /// For IF: the branch (`branches.len()` for ELSE); for CASE: the arm.
    pub part: usize,
}

/// The statements of POU `pou` with span `span` (generated code may give several
/// statements one span), each with the statements enclosing it, outermost first.
pub(super) fn find_statements(
    program: &Program,
    pou: PouId,
    span: Span,
) -> Vec<(&Stmt, Vec<Ancestor<'_>>)> {
    let mut out = Vec::new();
    if let Some(pou) = program.pous.get(pou as usize) {
        find_in(&pou.body, span, &mut Vec::new(), &mut out);
    }
    out
}

/// The first of [`find_statements`].
pub(super) fn find_statement(
    program: &Program,
    pou: PouId,
    span: Span,
) -> Option<(&Stmt, Vec<Ancestor<'_>>)> {
    find_statements(program, pou, span).into_iter().next()
}

fn find_in<'p>(
    body: &'p [Stmt],
    span: Span,
    path: &mut Vec<Ancestor<'p>>,
    out: &mut Vec<(&'p Stmt, Vec<Ancestor<'p>>)>,
) {
    // Generated code (SFC, IL) does not nest its spans as its statements nest: the whole
    // body is searched.
    for s in body {
        let parts: Vec<&'p [Stmt]> = match &s.kind {
            StmtKind::If { branches, else_body } => {
                branches.iter().map(|(_, b)| b.as_slice()).chain([else_body.as_slice()]).collect()
            }
            StmtKind::Case { arms, else_body, .. } => {
                arms.iter().map(|(_, b)| b.as_slice()).chain([else_body.as_slice()]).collect()
            }
            StmtKind::For { body, .. }
            | StmtKind::While { body, .. }
            | StmtKind::Repeat { body, .. } => vec![body.as_slice()],
            _ => Vec::new(),
        };
        for (k, part) in parts.iter().enumerate() {
            path.push(Ancestor { stmt: s, part: k });
            find_in(part, span, path, out);
            path.pop();
        }
        if s.span == span {
            out.push((s, path.clone()));
        }
    }
}

/// A place an expression reads, with the expression's span (its text in the source).
pub(super) type Read<'p> = (&'p Place, Span);

/// Every place `e` reads, in source order (indices of elements too).
pub(super) fn reads<'p>(e: &'p Expr, out: &mut Vec<Read<'p>>) {
    match &e.kind {
        ExprKind::Load(p) => {
            place_reads(p, out);
            out.push((p, e.span));
        }
        ExprKind::Unary(_, a) | ExprKind::Convert(a) | ExprKind::Trunc(a) => reads(a, out),
        ExprKind::Binary(_, a, b) => {
            reads(a, out);
            reads(b, out);
        }
        ExprKind::Call { args, .. } => {
            for a in args {
                if let CallArg::In(_, e) = a {
                    reads(e, out);
                }
            }
        }
        ExprKind::Builtin { args, .. } => {
            for a in args {
                reads(a, out);
            }
        }
        ExprKind::Const(_) | ExprKind::ConstStr(_) | ExprKind::Sys(_) | ExprKind::RefOf(_) => {}
    }
}

/// The places the indices of `p` read.
pub(super) fn place_reads<'p>(p: &'p Place, out: &mut Vec<Read<'p>>) {
    match p {
        Place::Element(inner, _, idx) => {
            place_reads(inner, out);
            for e in idx {
                reads(e, out);
            }
        }
        Place::Field(inner, _) | Place::Bit(inner, ..) | Place::Slice(inner, ..) => {
            place_reads(inner, out)
        }
        Place::Deref(e) => reads(e, out),
        Place::Local(_) | Place::Global(_) => {}
    }
}

/// The conditions that decided that `ancestor`'s part ran: an IF's conditions up to the
/// branch taken, a CASE's selector, a loop's condition.
pub(super) fn deciding<'p>(ancestor: &Ancestor<'p>) -> Vec<&'p Expr> {
    match &ancestor.stmt.kind {
        StmtKind::If { branches, .. } => {
            branches.iter().take(ancestor.part + 1).map(|(c, _)| c).collect()
        }
        StmtKind::Case { selector, .. } => vec![selector],
        StmtKind::While { cond, .. } => vec![cond],
        StmtKind::Repeat { until, .. } => vec![until],
        _ => Vec::new(),
    }
}
