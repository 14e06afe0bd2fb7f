//! The virtual machine: the bytecode interpreter, built-in functions, and values at its
//! boundary (reading/writing variables, JSON rendering). It runs a
//! [`crate::program::Executable`]: the instruction set and the memory image's cell format
//! are in `crate::program`, the value rules (wrap, round, convert, compare) and faults in
//! `crate::values`.
//!
//! Map: `machine` (the outer dispatch loop, calls, faults, watchdog) · `fast` (the inner
//! loop of the simple instructions; it trusts the regions `program::verify` accepted) ·
//! `builtins` and `strings` (less frequent instructions) · `text` (values as IEC text) ·
//! `value` (the boundary `Value`) · `json` (rendering).
//!
//! The VM must not allocate during a scan except for string temporaries (in reusable
//! scratch buffers), must not panic (every memory and code index is checked; a bad one is
//! `Fault::Internal`), and never reads a wall clock: time comes in [`SysState`].

mod builtins;
pub(crate) mod fast;
mod json;
mod machine;
mod strings;
#[cfg(test)]
mod tests;
mod text;
pub(crate) mod trace;
mod value;

pub use crate::program::Memory;
pub use crate::values::Fault;
pub use json::{decode_bytes, to_json};
pub use machine::{Machine, RuntimeError, SysState, MAX_CALL_DEPTH};
pub use text::{
    civil_from_days, days_from_civil, format_date, format_dt, format_real, format_time, format_tod,
    parse_text, parse_time,
};
pub use trace::{Cause, TraceEvent};
pub use value::{read, write, write_init, Value, WriteError};
