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
pub fn cycle_ns(ms: u64) -> Result<i64, crate::diagnostics::Said> {
    if (MIN_CYCLE_MS..=MAX_CYCLE_MS).contains(&ms) {
        // At most 6e13 ns: far inside i64.
        Ok(ms as i64 * 1_000_000)
    } else {
        Err(crate::msg!(ScanCycleRange, min = MIN_CYCLE_MS, max = MAX_CYCLE_MS, ms = ms))
    }
}

/// Watchdog charge of work that grows with its operands (issue 11: a loop of whole-array
/// copies or FIND on 64 KB strings ran for hours on a budget counted in instructions):
/// one unit, the cost of one instruction, per this many cells an array copy moves.
pub const WATCHDOG_CELLS_PER_UNIT: u64 = 8;

/// … and per this many bytes a string instruction reads or writes (string functions
/// look at every byte; FIND is linear, Knuth–Morris–Pratt).
pub const WATCHDOG_BYTES_PER_UNIT: u64 = 8;

/// The most memory the timeline's recording may use, in bytes (estimated per sample: 16
/// bytes per elementary value, 16 plus the declared length for a string). A trace keeps
/// fewer samples than asked when its samples are large.
pub const TRACE_BUDGET_BYTES: usize = 32 << 20;

/// The most memory the recording of a run's history may use, in bytes (snapshots of the
/// memory image and the changes from outside; `sim/record.rs`).
pub const RECORD_BUDGET_BYTES: usize = 48 << 20;

/// The history a recording keeps, in scans, when the budget affords it: one simulated
/// hour at 10 ms.
pub const RECORD_SCANS: u64 = 360_000;

/// The fewest scans between two snapshots of a recording (smaller images are still
/// snapshotted this rarely, which bounds the recording's cost per scan).
pub const RECORD_MIN_INTERVAL: u64 = 64;

/// The most scans between two snapshots: showing a recorded scan replays at most this
/// many. A larger image keeps a shorter history instead.
pub const RECORD_MAX_INTERVAL: u64 = 1024;

/// Longest STRING the checker accepts, in characters.
pub const MAX_STRING_LEN: i64 = 65_535;

/// Most elements the checker accepts in one array (sizes are computed in checked
/// arithmetic; a larger or overflowing size is E0170).
pub const MAX_ARRAY_ELEMENTS: u64 = 1 << 22;

/// The largest memory image the compiler produces, in 8-byte cells (128 MiB).
pub const MAX_CELLS: u64 = 16 * 1024 * 1024;

/// The default watchdog budget: work units one scan may use (an instruction is one unit;
/// array copies and string instructions are charged by size, see below).
pub const DEFAULT_WATCHDOG: u64 = 10_000_000;

/// The deepest nesting of calls the VM allows (deeper is a FAULT, not a stack overflow:
/// calls do not recurse on the native stack).
pub const MAX_CALL_DEPTH: usize = 64;

/// The largest project a share link may expand to, in bytes (a decompression bomb is
/// refused as it inflates).
pub const MAX_PROJECT_BYTES: usize = 4 << 20;

/// The markings `plc petri analyze` explores by default.
pub const PETRI_DEFAULT_BUDGET: usize = 100_000;

/// The markings the analysis run when a net is compiled explores at most (for warnings).
pub const PETRI_COMPILE_BUDGET: usize = 10_000;

/// The markings the web app's analysis panel explores at most.
pub const PETRI_PANEL_BUDGET: usize = 20_000;

/// At most this many marking entries (markings × places) are kept by the compile-time
/// analysis and the web panel: a 10,000-place net explores 500 markings, not 10,000 (which
/// would take 800 MB).
pub const PETRI_MARKING_CELLS: usize = 5_000_000;

/// More rows than this in the semiflow table and its computation stops (the count of
/// minimal semiflows can grow exponentially with the net).
pub const SEMIFLOW_ROW_LIMIT: usize = 20_000;

/// The most situations (sets of active steps) explored per SFC chart by the structure
/// check.
pub const SFC_MAX_SITUATIONS: usize = 20_000;

/// The most scans one exercise scenario may ask for, all its random runs together (a file
/// asking for more, `duration = "1000h"`, is refused rather than left to run for hours).
pub const EXERCISE_MAX_SCANS: i64 = 20_000_000;
