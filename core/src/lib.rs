//! `plc-core`: the engines of the PLC trainer.
//!
//! The pipeline (see `core/README.md` for the map):
//! source text → [`syntax`] (tokens, AST, syntax diagnostics) → [`semantic`] (names, types,
//! checked IR) → [`compile`] (bytecode, memory layout, debug map) → [`vm`] (executes one
//! scan) → [`sim`] (scan cycle, virtual clock, inputs, forcing, breakpoints, trace).
//! The core never reads a wall clock, never touches the DOM and never panics on user input.

#![deny(missing_docs)]
#![deny(clippy::unwrap_used)]

pub mod bench;
pub mod build;
pub mod compile;
pub mod diagnostics;
pub mod export;
pub mod ladder;
pub mod open;
pub mod petri;
pub mod plcopen;
pub mod pnml;
pub mod program;
pub mod project;
pub mod run;
pub mod semantic;
pub mod sfc;
pub mod sim;
pub mod syntax;
pub mod values;
pub mod vm;
