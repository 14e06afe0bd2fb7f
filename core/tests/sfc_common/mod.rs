//! A scan-by-scan harness for the SFC tests: one PROGRAM on the `Simulator`, a 10 ms
//! virtual cycle (scan k runs at SYS_CLOCK = (k - 1) * 10 ms), BOOL inputs held per scan.

#![allow(dead_code, clippy::unwrap_used)]

use plc_core::diagnostics::Diagnostic;
use plc_core::semantic;
use plc_core::sim::{ScanOutcome, Simulator};
use plc_core::vm::Value;

/// The cycle time of every test, in milliseconds.
pub const CYCLE_MS: i64 = 10;

/// A running chart and the BOOL inputs it is driven with.
pub struct Run {
    /// The simulator.
    pub sim: Simulator,
    inputs: Vec<&'static str>,
}

/// Errors and warnings of `src`.
pub fn diagnostics(src: &str) -> Vec<Diagnostic> {
    semantic::analyze(src).diagnostics
}

impl Run {
    /// Compiles `src` (which must have no error) with BOOL inputs `inputs`.
    pub fn new(src: &str, inputs: &[&'static str]) -> Run {
        let analysis = semantic::analyze(src);
        let errors: Vec<_> = analysis.diagnostics.iter().filter(|d| d.is_error()).collect();
        assert!(errors.is_empty(), "{errors:#?}");
        let program = analysis.program.unwrap();
        let main = program.programs().find(|&p| !program.pou(p).library).unwrap();
        let mut sim = Simulator::new(program, main).unwrap();
        sim.set_cycle_ns(CYCLE_MS * 1_000_000);
        Run { sim, inputs: inputs.to_vec() }
    }

    /// Runs one scan with exactly the inputs in `on` TRUE (the others FALSE).
    pub fn scan(&mut self, on: &[&str]) {
        for name in &self.inputs {
            let value =
                if on.iter().any(|o| o.eq_ignore_ascii_case(name)) { "TRUE" } else { "FALSE" };
            self.sim.hold(name, value).unwrap();
        }
        assert_eq!(self.sim.scan(), ScanOutcome::Completed);
    }

    /// Runs `n` scans with no input TRUE.
    pub fn idle(&mut self, n: usize) {
        for _ in 0..n {
            self.scan(&[]);
        }
    }

    /// A BOOL at `path` (`Step.X`, `Act.Q`, a variable).
    pub fn bool(&self, path: &str) -> bool {
        match self.sim.read(path).unwrap() {
            Value::Bool(b) => b,
            other => panic!("{path} is {other:?}"),
        }
    }

    /// A TIME at `path`, in milliseconds.
    pub fn ms(&self, path: &str) -> i64 {
        match self.sim.read(path).unwrap() {
            Value::Time(ns) => ns / 1_000_000,
            other => panic!("{path} is {other:?}"),
        }
    }

    /// An integer at `path`.
    pub fn int(&self, path: &str) -> i128 {
        match self.sim.read(path).unwrap() {
            Value::Int(v, _) => v,
            other => panic!("{path} is {other:?}"),
        }
    }

    /// The names of the active steps among `steps`.
    pub fn active(&self, steps: &[&str]) -> Vec<String> {
        steps.iter().filter(|s| self.bool(&format!("{s}.X"))).map(|s| s.to_string()).collect()
    }
}
