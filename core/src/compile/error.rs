//! Why a program could not be compiled, and the size arithmetic that reports it.

use std::fmt;

use crate::semantic::types::PouId;

/// Why a program could not be compiled.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum CompileError {
    /// The memory image would exceed the compiler's limit of cells (`MAX_CELLS`).
    MemoryTooLarge {
        /// Cells needed (at least).
        cells: u64,
    },
    /// The POU to run is not a PROGRAM of the program.
    NotAProgram(PouId),
    /// FB types contain each other (or a function frame contains an FB that calls it).
    RecursiveLayout(String),
    /// A construct the compiler does not support (a checker/compiler mismatch), said as a
    /// message so it reads in every language.
    Unsupported(Box<crate::diagnostics::Said>),
}

impl fmt::Display for CompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl CompileError {
    /// The error as a message, with its English text (what it displays as).
    pub fn said(&self) -> crate::diagnostics::Said {
        match self {
            CompileError::MemoryTooLarge { cells } => {
                crate::msg!(ProgramNeedsMemoryCells, cells = cells, max = MAX_CELLS)
            }
            CompileError::NotAProgram(id) => crate::msg!(PouNotProgram, id = id),
            CompileError::RecursiveLayout(name) => crate::msg!(LayoutContainsItself, name = name),
            CompileError::Unsupported(what) => crate::msg!(NotSupportedByCompiler, what = &**what),
        }
    }
}

impl std::error::Error for CompileError {}

pub use crate::limits::MAX_CELLS;

pub(crate) fn too_large(cells: u64) -> CompileError {
    CompileError::MemoryTooLarge { cells }
}

/// Adds sizes, failing past [`MAX_CELLS`].
pub(crate) fn add(a: u32, b: u64) -> Result<u32, CompileError> {
    let s = u64::from(a) + b;
    if s > MAX_CELLS {
        return Err(too_large(s));
    }
    Ok(s as u32)
}

/// A compiler-invariant failure described as an unsupported construct.
pub(crate) fn bad(what: &str) -> CompileError {
    CompileError::Unsupported(Box::new(crate::msg!(CompileInvalidInIr, what = what)))
}
