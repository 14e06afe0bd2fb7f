//! The virtual machine: memory image, the bytecode interpreter, built-in functions, and
//! values at its boundary (reading/writing variables, JSON rendering).
//!
//! Map: `op` (instruction set) · `memory` (cells, strings in cells) · `machine` (the
//! outer dispatch loop, calls, faults, watchdog) · `fast` (the inner loop of the simple
//! instructions, and the verification that lets checked-once code skip operand checks) · `builtins` and `strings` (less frequent
//! instructions) · `text` (values as IEC text) · `value` (the boundary `Value`) · `json`
//! (rendering) · `arith` (the one definition of cell arithmetic) · `fault` (runtime
//! faults).
//!
//! The VM must not allocate during a scan except for string temporaries (in reusable
//! scratch buffers), must not panic (every memory and code index is checked; a bad one is
//! `Fault::Internal`), and never reads a wall clock: time comes in [`SysState`].

pub mod arith;
mod builtins;
pub(crate) mod fast;
pub mod fault;
mod json;
mod machine;
pub mod memory;
pub mod op;
mod strings;
mod tables;
#[cfg(test)]
mod tests;
mod text;
mod value;

pub use fault::Fault;
pub use json::{decode_bytes, to_json};
pub use machine::{Machine, RuntimeError, SysState, MAX_CALL_DEPTH};
pub use memory::Memory;
pub use text::{
    civil_from_days, days_from_civil, format_date, format_dt, format_real, format_time, format_tod,
    parse_text, parse_time,
};
pub use value::{read, write, write_init, Value, WriteError};
