//! The limits the engines keep, in one place, so that no program, file or value a user
//! hands the trainer can exhaust the stack, the memory or the time: each is a named
//! constant, and going past one is a located diagnostic (or a FAULT at run time), never a
//! crash. `docs/reliability.md` lists them with the reason for each figure.
//!
//! The recursive passes (parser, checker, compiler, the drop of a syntax tree) use about
//! 8 KiB of stack per level of an expression or statement in a debug build and far less
//! optimised; the figures keep every pass inside a 1 MiB stack (the default of a wasm32
//! module) with room to spare.

/// The deepest nesting of expressions, statements and initializers the parser accepts
/// (parentheses, unary operators, nested IF/CASE/loops, nested array initializers).
pub const MAX_NESTING: usize = 100;

/// The tallest expression tree the parser builds: a chain `a + b + … ` of this many
/// operators, a postfix chain `a.b.c…` or `a[0][0]…` of this many steps, or any mix with
/// nesting. Far beyond a hand-written expression; a longer one is split over statements.
pub const MAX_EXPR_HEIGHT: usize = 100;

/// The deepest element nesting read from an XML document (PLCopen XML, PNML). Real files
/// nest about 15 deep.
pub const MAX_XML_DEPTH: usize = 200;

/// The deepest nesting of data types: FB instances inside FBs, structs inside structs,
/// arrays of arrays. Laying out and reading such a type recurses once per level.
pub const MAX_TYPE_NESTING: usize = 64;

/// The shortest scan cycle of the virtual clock, in milliseconds.
pub const MIN_CYCLE_MS: u64 = 1;

/// The longest scan cycle of the virtual clock, in milliseconds (one minute).
pub const MAX_CYCLE_MS: u64 = 60_000;

/// A scan cycle given in milliseconds (a project setting, `plc run --cycle-ms`, the page's
/// cycle time) as nanoseconds for the simulator, or why it cannot be one.
pub fn cycle_ns(ms: u64) -> Result<i64, String> {
    if (MIN_CYCLE_MS..=MAX_CYCLE_MS).contains(&ms) {
        // At most 6e13 ns: far inside i64.
        Ok(ms as i64 * 1_000_000)
    } else {
        Err(format!("a scan cycle is {MIN_CYCLE_MS} to {MAX_CYCLE_MS} ms, not {ms} ms"))
    }
}

/// Watchdog charge of work that grows with its operands (issue 11: a loop of whole-array
/// copies or FIND on 64 KB strings ran for hours on a budget counted in instructions):
/// one unit, the cost of one instruction, per this many cells an array copy moves.
pub const WATCHDOG_CELLS_PER_UNIT: u64 = 8;

/// … and per this many bytes a string instruction reads or writes (string functions
/// look at every byte; FIND is linear, Knuth–Morris–Pratt).
pub const WATCHDOG_BYTES_PER_UNIT: u64 = 8;
