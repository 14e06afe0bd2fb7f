//! `plc-core`: the engines of the PLC trainer.
//!
//! The pipeline (see `core/README.md` for the map and the floors):
//! source text → `syntax` (tokens, AST, syntax diagnostics) → `semantic` (names, types,
//! checked IR) → `compile` (bytecode, memory layout, debug map: a [`program::Executable`])
//! → [`vm`] (executes one scan) → [`sim`] (scan cycle, virtual clock, inputs, forcing,
//! breakpoints, trace). Ladder and Petri net POUs lower to the same IR ([`build`]).
//! The core never reads a wall clock, never touches the DOM and never panics on user input.
//!
//! # The surface
//!
//! What the `plc` command line, the web app and the test suites use:
//! - a project and its files: [`project`] (model, store, share links, undo history),
//!   [`open`] (any file as a project), [`plcopen`] and [`pnml`] (import and export);
//! - building and running: [`build`] (one checked program from a whole project, with
//!   located diagnostics), [`run`] (one-shot runs and their JSON report), [`sim`] (the
//!   simulator), [`export`] (values as text, CSV, VCD);
//! - the models the editors show: [`ladder`] (rung grid, validation, ST view), [`petri`]
//!   (nets, analysis, generated code);
//! - what those return: [`diagnostics`] (spans, codes), [`syntax`] (the AST and editor
//!   tokens), [`semantic`] (the typed IR and the checker), [`program`] (the compiled
//!   program), [`vm`] (values at the VM's boundary).
//!
//! The compiler, the value rules and the SFC lowering are internal (`compile`, `values`,
//! `sfc`): reach them through the modules above.

#![deny(missing_docs)]
// The site's wasm is built for size (opt-level z); the scan loop's few functions are
// compiled for speed there (`#[cfg_attr(plc_speed, optimize(speed))]`). The attribute is
// unstable: only that build, which already runs the compiler with RUSTC_BOOTSTRAP for
// build-std, sets `--cfg plc_speed` (scripts/wasm-build.sh). BENCHMARKS.md, "The scan
// loop compiled for speed", says what it costs and gives.
#![cfg_attr(plc_speed, feature(optimize_attribute))]
#![deny(clippy::unwrap_used)]

#[cfg(feature = "bench")]
#[doc(hidden)]
pub mod bench;
pub mod build;
pub(crate) mod compile;
pub mod diagnostics;
pub mod exercise;
pub mod export;
pub mod i18n;
pub mod il;
pub mod ladder;
pub mod limits;
pub mod network;
pub mod open;
pub mod order;
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
pub(crate) mod values;
pub mod vm;
pub mod why;
