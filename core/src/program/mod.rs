//! The compiled program: what the compiler writes and the VM runs. The instruction set
//! (`op`, with its side tables), the memory image's cell format (`memory`), and the
//! [`Executable`] container: code, initial image, memory layout, debug map and the
//! variable locator. Data only: nothing here compiles or executes.

mod layout;
pub(crate) mod locate;
pub(crate) mod memory;
pub(crate) mod op;
pub(crate) mod refpath;
mod tables;
pub(crate) mod verify;

use crate::diagnostics::Span;
use crate::semantic::ir::Var;
use crate::semantic::types::{Elem, PouId, Type, TypeTable};
use op::{CaseTable, DimInfo, ElemSite, Op};

pub(crate) use layout::{Layouts, PouLayout};
pub use memory::Memory;

/// Where a variable (or a part of one) lives, and its type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Slot {
    /// The absolute cell address (of the header cell for strings, of the first cell for
    /// aggregates, of the integral cell for a bit).
    pub addr: u32,
    /// The type of the value at this slot (BOOL for a bit).
    pub ty: Type,
    /// For a bit access: the bit number and the type of the cell holding it; for a
    /// located variable of a wider type (in the process image, `semantic::image`): its
    /// first bit in the image cell, with `Elem::LWord`.
    pub bit: Option<(u32, Elem)>,
}

/// A variable of the main program (or a global) with its slot.
#[derive(Debug, Clone, PartialEq)]
pub struct VarEntry {
    /// The declaration.
    pub var: Var,
    /// Where it lives.
    pub slot: Slot,
    /// True for a global variable.
    pub global: bool,
}

/// One entry of the debug map: code from `pc` on belongs to statement `span` of `pou`
/// (until the next entry).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DebugEntry {
    /// First instruction.
    pub pc: u32,
    /// The statement's source span.
    pub span: Span,
    /// The POU.
    pub pou: PouId,
}

/// Identifies a compiled breakpoint condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ConditionId(pub u32);

/// Per-POU facts the VM needs.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PouCode {
    /// First instruction of the body (`u32::MAX` when not compiled).
    pub entry: u32,
    /// Address of the static frame (functions and the main program).
    pub frame: Option<u32>,
    /// Frame size in cells.
    pub size: u32,
    /// Standard-library POU.
    pub library: bool,
    /// VAR_TEMP ranges `(offset, cells)` re-initialised on every call.
    pub temps: Vec<(u32, u32)>,
    /// The initial image of one instance (only for POUs with VAR_TEMP).
    pub template: Vec<u64>,
    /// Cells of `temps` whose template holds a reference into the instance (an initial
    /// value `REF(x)`), counted from the instance's start: the instance's address is added
    /// when they are copied.
    pub relocs: Vec<u32>,
    /// The POU's variables (for reading FB instances and locating paths).
    pub vars: Vec<Var>,
    /// Their offsets in the frame.
    pub offsets: Vec<u32>,
    /// The inner loop may run this POU's code without operand checks (`trust.rs`).
    pub trusted: bool,
}

/// The code and tables that the emitter appends to.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Code {
    /// The instructions of every POU and condition.
    pub code: Vec<Op>,
    /// Array dimensions for `Op::Index`.
    pub dims: Vec<DimInfo>,
    /// Element-access sites for `Op::LoadElem` and its kin.
    pub sites: Vec<ElemSite>,
    /// Where each site is in `sites` (equal accesses share one entry).
    pub site_index: std::collections::HashMap<ElemSite, u32>,
    /// CASE tables.
    pub cases: Vec<CaseTable>,
    /// Types for `Op::ToStr`.
    pub types: Vec<Type>,
    /// The debug map.
    pub debug: Vec<DebugEntry>,
    /// The initial memory image.
    pub init: Vec<u64>,
}

/// A compiled program: code, initial memory image, layout and debug map.
#[derive(Debug, Clone)]
pub struct Executable {
    pub(crate) out: Code,
    pub(crate) pous: Vec<PouCode>,
    pub(crate) retained: Vec<(u32, u32)>,
    pub(crate) conditions: Vec<u32>,
    /// Per condition: the inner loop may run its code without operand checks.
    pub(crate) condition_trusted: Vec<bool>,
    pub(crate) main: PouId,
    pub(crate) main_base: u32,
    pub(crate) type_table: TypeTable,
    pub(crate) vars: Vec<VarEntry>,
    pub(crate) lay: Layouts,
    /// Further PROGRAM instances run after the main one (a plant): `(POU, instance base)`,
    /// each compiled like a function block's body, relative to its base.
    pub(crate) instances: Vec<(PouId, u32)>,
}

impl Executable {
    /// The initial memory image (every variable at its initial value).
    pub fn initial_image(&self) -> &[u64] {
        &self.out.init
    }

    /// Cell ranges `(start, len)` kept over a warm restart (RETAIN variables).
    pub fn retained(&self) -> &[(u32, u32)] {
        &self.retained
    }

    /// The debug map, sorted by instruction index.
    pub fn debug_map(&self) -> &[DebugEntry] {
        &self.out.debug
    }

    /// The statement and POU that instruction `pc` belongs to.
    pub fn statement_at(&self, pc: usize) -> Option<(Span, PouId)> {
        let k = self.out.debug.partition_point(|e| e.pc as usize <= pc);
        let e = self.out.debug.get(k.checked_sub(1)?)?;
        Some((e.span, e.pou))
    }

    /// The spans of every compiled statement of POU `pou`, sorted and without duplicates
    /// (the lines the UI can mark).
    pub fn statement_spans(&self, pou: PouId) -> Vec<Span> {
        let mut v: Vec<Span> =
            self.out.debug.iter().filter(|e| e.pou == pou).map(|e| e.span).collect();
        crate::order::sort_by_key(&mut v, |s| (s.start, s.end));
        v.dedup();
        v
    }

    /// The main program.
    pub fn main_pou(&self) -> PouId {
        self.main
    }

    /// The main program's variables, then the globals, with their slots.
    pub fn main_vars(&self) -> &[VarEntry] {
        &self.vars
    }

    /// The derived types of the program.
    pub fn type_table(&self) -> &TypeTable {
        &self.type_table
    }

    /// The number of instructions (for statistics and tests).
    pub fn code_len(&self) -> usize {
        self.out.code.len()
    }

    /// Resolves a variable path (`Name`, `Name.field`, `Arr[3]`, `Arr[1,2]`, `Fb.Q`,
    /// `Name.3`) case-insensitively against the main program's variables, then the globals.
    pub fn locate(&self, path: &str) -> Option<Slot> {
        locate::locate(self, path)
    }
}
