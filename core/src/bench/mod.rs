//! The benchmark suite behind `plc bench` (see BENCHMARKS.md): each figure runs the real
//! pipeline (check, compile, simulate) and, where the issue asks for it, the same work
//! hand-written in Rust in the same run, so the ratio VM/native is measured on the same
//! machine at the same moment.
//!
//! The programs and the work are built for every target (the browser harness runs them in
//! wasm); the timing reads the wall clock, so it exists only in native builds. No test
//! asserts anything about a timing.

pub mod ladder;
pub mod programs;
#[cfg(test)]
mod tests;
#[cfg(not(target_arch = "wasm32"))]
mod timing;
pub mod workload;

#[cfg(not(target_arch = "wasm32"))]
pub use timing::{
    b1, b2, b3, b4, b5, b6, b8, report_text, run_all, run_selected, Effort, Paired, FIGURES,
};
pub use workload::{load, BenchError};
