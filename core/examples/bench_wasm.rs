//! The browser side of B5, B6, B7 and B8: the same work `plc bench` times natively
//! (`plc_core::bench::workload`), exported to JavaScript so that a page in headless
//! Chromium can time it with `performance.now()` (the core never reads a clock).
//! Built and driven by `scripts/bench-browser.sh`; see BENCHMARKS.md.
#![cfg(target_arch = "wasm32")]

use plc_core::bench::{programs, workload};
use plc_core::sim::Simulator;
use wasm_bindgen::prelude::*;

fn js(e: workload::BenchError) -> JsValue {
    JsValue::from_str(&e.to_string())
}

/// B5: the weighing program, loaded and ready, with its plant.
#[wasm_bindgen]
pub struct Weighing {
    sim: Simulator,
}

#[wasm_bindgen]
impl Weighing {
    /// Checks and compiles `examples/weighing.st` with Start held and the setpoint at 500.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<Weighing, JsValue> {
        Ok(Weighing { sim: workload::weighing().map_err(js)? })
    }

    /// Runs `scans` scans of 10 ms against the plant; returns the batches discharged.
    pub fn run(&mut self, scans: u32) -> Result<u32, JsValue> {
        let batches = workload::run_weighing(&mut self.sim, u64::from(scans)).map_err(js)?;
        Ok(batches as u32)
    }
}

/// B7: the weighing controller (the Petri net of `examples/weighing-plant.plcproj.json`)
/// with its plant PROGRAM run after it on every scan, or alone, Start held.
#[wasm_bindgen]
pub struct WeighingPlant {
    sim: Simulator,
}

#[wasm_bindgen]
impl WeighingPlant {
    /// Builds the project, with its plant or (`with_plant` false) the controller alone.
    #[wasm_bindgen(constructor)]
    pub fn new(with_plant: bool) -> Result<WeighingPlant, JsValue> {
        let mut project = plc_core::project::Project::from_file(programs::WEIGHING_PLANT)
            .map_err(|e| JsValue::from_str(&e.to_string()))?;
        if !with_plant {
            project.settings.plant = None;
        }
        let mut sim = plc_core::run::project_simulator(&project, None).map_err(|d| {
            JsValue::from_str(&d.first().map_or("B7 does not build".into(), |d| d.message.clone()))
        })?;
        sim.set_watchdog(u64::MAX / 2);
        sim.hold("Start", "TRUE").map_err(|e| JsValue::from_str(&e.to_string()))?;
        Ok(WeighingPlant { sim })
    }

    /// B8: keeps the history from now on (`Simulator::set_recording`).
    pub fn record(&mut self) -> Result<(), JsValue> {
        self.sim.set_recording(true).map_err(|e| JsValue::from_str(&e.to_string()))
    }

    /// B8: the bytes the recording takes.
    pub fn recorded_bytes(&self) -> f64 {
        self.sim.recording().map_or(0.0, |r| r.bytes as f64)
    }

    /// B8: shows recorded scan `scan` again (`Simulator::view_at`); returns the scan
    /// shown. The longest replays are one interval minus one past a snapshot.
    pub fn view(&self, scan: u32) -> Result<u32, JsValue> {
        let view =
            self.sim.view_at(u64::from(scan)).map_err(|e| JsValue::from_str(&e.to_string()))?;
        Ok(view.scan() as u32)
    }

    /// B8: the snapshot interval.
    pub fn interval(&self) -> u32 {
        self.sim.recording().map_or(0, |r| r.interval as u32)
    }

    /// Runs `scans` scans of 10 ms; returns the batches the plant counted (0 alone).
    pub fn run(&mut self, scans: u32) -> Result<u32, JsValue> {
        for _ in 0..scans {
            workload::scan(&mut self.sim).map_err(js)?;
        }
        Ok(match self.sim.read("WeighingPlant.Batches") {
            Ok(plc_core::vm::Value::Int(n, _)) => n as u32,
            _ => 0,
        })
    }
}

/// B6's program: generated ST of about `lines` lines.
#[wasm_bindgen]
pub fn b6_source(lines: u32) -> String {
    programs::b6(lines as usize)
}

/// B6's work: check and compile `source`; returns the number of instructions.
#[wasm_bindgen]
pub fn check_and_compile(source: &str) -> Result<u32, JsValue> {
    Ok(workload::check_and_compile(source).map_err(js)? as u32)
}
