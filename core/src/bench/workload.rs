//! The work each benchmark times, without the timing: loading a program into a simulator,
//! scanning it, the weighing plant of B5 and the check + compile of B6. Built for every
//! target, so that the browser harness (`core/examples/bench_wasm.rs`) runs exactly what
//! `plc bench` runs natively and only the clock differs.

use std::fmt;

use crate::semantic;
use crate::sim::{ScanOutcome, Simulator};
use crate::vm::Value;

use super::programs;

/// Why a benchmark could not run (a bug in a benchmark program, reported, never a panic).
#[derive(Debug, Clone, PartialEq)]
pub struct BenchError(pub String);

impl fmt::Display for BenchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "benchmark failed: {}", self.0)
    }
}

impl std::error::Error for BenchError {}

pub(crate) fn err(e: impl fmt::Display) -> BenchError {
    BenchError(e.to_string())
}

/// Checks and compiles `source` into a simulator for its first user PROGRAM, with the
/// watchdog out of the way (the benchmarks loop on purpose).
pub fn load(source: &str) -> Result<Simulator, BenchError> {
    let analysis = semantic::analyze(source);
    let program = analysis.program.ok_or_else(|| {
        let first = analysis.diagnostics.first().map_or(String::new(), |d| d.message.clone());
        BenchError(format!("program does not check: {first}"))
    })?;
    let main = program
        .programs()
        .find(|&p| !program.pou(p).library)
        .ok_or_else(|| BenchError("no PROGRAM".into()))?;
    let mut sim = Simulator::new(program, main).map_err(err)?;
    sim.set_watchdog(u64::MAX / 2);
    Ok(sim)
}

/// Runs one scan; a fault is an error.
pub fn scan(sim: &mut Simulator) -> Result<(), BenchError> {
    match sim.scan() {
        ScanOutcome::Fault(f) => Err(BenchError(f.fault.to_string())),
        _ => Ok(()),
    }
}

/// The weighing plant of B5: the load cell reads what is in the hopper, which fills while
/// the feed valve is open and empties while the discharge valve is open.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WeighingPlant {
    /// Grams × 10 in the hopper (0..=1000, the load cell's range).
    pub weight: i128,
    /// Batches discharged so far (the discharge valve closing).
    pub batches: u64,
    discharging: bool,
}

impl WeighingPlant {
    /// Grams × 10 per 10 ms scan while filling.
    pub const FILL: i128 = 4;
    /// Grams × 10 per 10 ms scan while discharging.
    pub const DRAIN: i128 = 8;

    /// Reads the valves the last scan set and puts the new weight on the input.
    ///
    /// Never inlined into [`run_weighing`]'s loop: V8 keeps running a wasm function in the
    /// code it was entered with (it has no on-stack replacement for wasm), so work inlined
    /// into a loop that runs the whole hour in one call would stay in the baseline code all
    /// hour, where a function called once per scan is optimised after a few thousand scans.
    #[inline(never)]
    pub fn step(&mut self, sim: &mut Simulator) -> Result<(), BenchError> {
        let on = |sim: &Simulator, name: &str| -> Result<bool, BenchError> {
            Ok(matches!(sim.read(name).map_err(err)?, Value::Bool(true)))
        };
        if on(sim, "FeedValve")? {
            self.weight += Self::FILL;
        }
        let discharging = on(sim, "DischargeValve")?;
        if discharging {
            self.weight -= Self::DRAIN;
        } else if self.discharging {
            self.batches += 1;
        }
        self.discharging = discharging;
        self.weight = self.weight.clamp(0, 1000);
        sim.hold_value("Weight", Value::Int(self.weight, semantic::Elem::Int)).map_err(err)
    }
}

/// B5's simulator: the Petri net POU of `examples/weighing-sequential.plcproj.json`, built
/// as the product builds a project (net → CASE OF code → checker → VM), with Start held
/// and the setpoint at 500.
pub fn weighing() -> Result<Simulator, BenchError> {
    let project = crate::project::Project::from_file(programs::WEIGHING).map_err(err)?;
    let mut sim = crate::run::project_simulator(&project, None).map_err(|d| {
        BenchError(
            d.first().map_or("the weighing project does not build".into(), |d| d.message.clone()),
        )
    })?;
    sim.set_watchdog(u64::MAX / 2);
    sim.hold("Start", "TRUE").map_err(err)?;
    sim.hold("Setpoint", "500").map_err(err)?;
    Ok(sim)
}

/// Runs `scans` scans of the weighing program against its plant; returns how many
/// batches were discharged (the number of times the process went back to P1 from P33),
/// so that a caller can see the run did real work.
pub fn run_weighing(sim: &mut Simulator, scans: u64) -> Result<u64, BenchError> {
    let mut plant = WeighingPlant::default();
    for _ in 0..scans {
        plant.step(sim)?;
        scan(sim)?;
    }
    Ok(plant.batches)
}

/// B6's work: check and compile `source`; returns the number of instructions.
pub fn check_and_compile(source: &str) -> Result<usize, BenchError> {
    Ok(load(source)?.executable().code_len())
}
