//! The compiler: checked IR → [`Executable`] (bytecode, memory layout, initial image,
//! debug map, variable locator).
//!
//! One executable form serves every front-end (ST, ladder, Petri nets). The compiler lays
//! out every variable in one flat image of cells (see `program::memory`): globals first, then
//! the main PROGRAM's instance, then one static frame per FUNCTION (functions never
//! recurse, the checker guarantees it), then constant strings and breakpoint-condition
//! temporaries. FB instances live inline in their parent (instance, struct or array) and
//! carry their own temporaries, so an FB body addresses everything relative to its
//! instance.
//!
//! It must not execute code or look at source text; it never panics: anything it cannot
//! compile is a [`CompileError`].

mod emit;
mod error;
mod expr;
mod fuse;
mod layout;
mod stmt;
#[cfg(test)]
pub(crate) mod testkit;
#[cfg(test)]
mod tests;
mod trust;

use crate::semantic::ir::{Expr, Program};
use crate::semantic::types::PouId;

pub(crate) use crate::program::{Code, PouCode};
pub use crate::program::{ConditionId, DebugEntry, Executable, Slot, VarEntry};
pub use error::CompileError;

/// Compiles `program` to run PROGRAM `main`.
pub fn compile(program: &Program, main: PouId) -> Result<Executable, CompileError> {
    layout::build(program, main, &[])
}

/// Compiles PROGRAM `main` and, after it, the PROGRAMs `more` (each one instance, named
/// as its POU: `Plant.Level`), all in one memory image; see [`Executable::instances`].
pub fn compile_with_programs(
    program: &Program,
    main: PouId,
    more: &[PouId],
) -> Result<Executable, CompileError> {
    layout::build(program, main, more)
}

impl Executable {
    /// Appends code evaluating the BOOL expression `cond` in the main program's scope.
    pub fn compile_condition(
        &mut self,
        program: &Program,
        cond: &Expr,
    ) -> Result<ConditionId, CompileError> {
        layout::compile_condition(self, program, cond)
    }
}
