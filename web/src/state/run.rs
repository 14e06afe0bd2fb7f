//! The simulator's run loop and controls: run, pause, step, restarts.
//!
//! The run loop is sliced per animation frame: each frame runs as many scans as the speed
//! asks for (real time, ×10) or as fit in a small wall-time budget (as fast as possible),
//! so the page stays responsive at any speed. The core keeps the virtual clock. Before the
//! last scan of every batch the marking of a running Petri net is noted, so the net view
//! can show which transitions fired on the last scan.

use leptos::prelude::*;
use plc_core::export::value_number;
use plc_core::petri::PlaceMap;
use plc_core::sim::{Readout, ScanOutcome, SimState, Simulator};

use super::{AppState, Notice, RunMode, ScanWish, Speed};
use crate::i18n::{t, tf, K};

/// The wall time one batch of scans aims at, in milliseconds.
const BATCH_MS: f64 = 1.0;

/// The most scans in one batch.
const MAX_BATCH: u64 = 4096;

fn perf_now() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

/// The marking of a net read from the simulator's step variables.
pub fn marking_of(sim: &dyn Readout, places: &PlaceMap) -> Vec<u32> {
    places.marking(|var| sim.read(var).ok().as_ref().and_then(value_number).map(|x| x as i64))
}

impl AppState {
    /// Runs `n` scans, noting the marking before the last one.
    fn scan_batch(&self, sim: &mut Simulator, n: u64) -> ScanOutcome {
        // A simulator is made by the engine, so the engine is here.
        let Some(engine) = crate::lazy::engine().filter(|_| n > 0) else {
            return ScanOutcome::Completed;
        };
        let outcome = (engine.run_scans)(sim, n - 1);
        if outcome != ScanOutcome::Completed {
            return outcome;
        }
        let before = self
            .running_places
            .with_value(|p| p.as_ref().map(|p| (sim.scan_count(), marking_of(sim, p))));
        self.marking_before_last.set_value(before);
        (engine.run_scans)(sim, 1)
    }

    /// Runs a batch of `n` scans and sizes the next batch from how long it took, so that a
    /// batch stays near [`BATCH_MS`] of wall time: many cheap scans per clock reading, and
    /// one scan at a time when scans are slow (the frame's budget is checked between
    /// batches, so a slow program cannot hold the page for more than about one scan).
    fn timed_batch(&self, sim: &mut Simulator, n: u64) -> ScanOutcome {
        let start = perf_now();
        let outcome = self.scan_batch(sim, n);
        let took = perf_now() - start;
        let next = if took > 2.0 * BATCH_MS {
            n / 2
        } else if took < BATCH_MS / 2.0 {
            n * 2
        } else {
            n
        };
        self.batch.set_value(next.clamp(1, MAX_BATCH));
        outcome
    }

    fn after_outcome(&self, outcome: ScanOutcome) {
        match outcome {
            ScanOutcome::Completed => {}
            ScanOutcome::Breakpoint(id) => {
                self.run_mode.set(RunMode::Paused);
                let cond =
                    self.with_sim(|s| s.breakpoint_condition(id).map(str::to_string)).flatten();
                self.info(tf(K::state_paused_at, &[("condition", &cond.unwrap_or_default())]));
            }
            ScanOutcome::Fault(info) => {
                self.run_mode.set(RunMode::Stopped);
                let site = self
                    .sim_build
                    .with_value(|b| b.as_ref().map(|b| b.site_of(info.span)))
                    .unwrap_or(plc_core::build::Site::Project);
                let place = match &site {
                    plc_core::build::Site::St { line, .. } => {
                        self.marked_line.set(Some(*line));
                        tf(K::state_fault_line, &[("line", &line.to_string())])
                    }
                    other => other
                        .message()
                        .map(|p| crate::i18n::message_text(&p.message, None, &p.english))
                        .unwrap_or_default(),
                };
                self.fault_site.set(Some(site.clone()));
                self.notice.set(Some(Notice {
                    error: true,
                    text: tf(
                        K::state_fault,
                        &[
                            ("scan", &info.scan.to_string()),
                            (
                                "fault",
                                &crate::i18n::message_text(
                                    &info.fault.message(),
                                    None,
                                    &info.fault.to_string(),
                                ),
                            ),
                            ("place", &place),
                        ],
                    ),
                    site: Some(site),
                    actions: Vec::new(),
                }));
            }
        }
    }

    /// True when the engine is still loading, or a project is being opened in place of
    /// the one shown (an imported file, an example, a share link): the scan `wish` is done
    /// once the engine is here (and the project checked) and the project open, on that
    /// project and never on the one about to go; the banner says what it waits for.
    fn wait_until_ready(&self, wish: ScanWish) -> bool {
        let engine_ready = self.engine_ready.get_untracked();
        let opening = self.opening_new.get_untracked() > 0 || self.opening_shared.get_untracked();
        if engine_ready && !opening {
            return false;
        }
        self.scan_when_ready.set_value(Some(wish));
        self.info(t(if opening {
            K::state_opening_project
        } else {
            K::lazy_loading_run_when_ready
        }));
        if !engine_ready {
            self.check_now();
        }
        true
    }

    /// Does the Run or Step pressed while the engine was loading or a project opening.
    pub(super) fn scan_wished(&self) {
        let Some(wish) = self.scan_when_ready.try_update_value(Option::take).flatten() else {
            return;
        };
        let waiting = self.notice.with_untracked(|n| {
            n.as_ref().is_some_and(|n| {
                n.text == t(K::lazy_loading_run_when_ready) || n.text == t(K::state_opening_project)
            })
        });
        if waiting {
            self.notice.set(None);
        }
        match wish {
            ScanWish::Run => self.run(),
            ScanWish::Step(n) => self.step(n),
        }
    }

    /// Runs `n` scans now (Step, Step N).
    pub fn step(&self, n: u64) {
        // In the past, Step moves through the recording.
        if self.in_past() {
            self.step_forward(n);
            return;
        }
        if self.wait_until_ready(ScanWish::Step(n)) || !self.may_scan() {
            return;
        }
        if self.run_mode.get_untracked() == RunMode::Running {
            self.run_mode.set(RunMode::Paused);
        }
        let state = *self;
        if let Some(outcome) = self.with_sim_mut(|s| state.scan_batch(s, n)) {
            if self.run_mode.get_untracked() == RunMode::Stopped
                && !matches!(outcome, ScanOutcome::Fault(_))
            {
                self.run_mode.set(RunMode::Paused);
            }
            self.after_outcome(outcome);
            self.steps_taken.update(|s| *s += 1);
        }
    }

    /// Starts scanning every animation frame (not an older build than the text on the
    /// screen unless the user chose it: see `gate.rs`).
    pub fn run(&self) {
        if self.wait_until_ready(ScanWish::Run) || !self.may_scan() {
            return;
        }
        let faulted = self.with_sim(|s| matches!(s.state(), SimState::Faulted(_))).unwrap_or(false);
        if faulted {
            self.error(t(K::state_in_fault));

            return;
        }
        if self.run_mode.get_untracked() == RunMode::Running {
            return;
        }
        let state = *self;
        self.leave_past_then(move || {
            state.run_mode.set(RunMode::Running);
            let start = perf_now();
            request_animation_frame(move || state.frame(start));
        });
    }

    /// Stops scanning (the state is kept).
    pub fn pause(&self) {
        if self.run_mode.get_untracked() == RunMode::Running {
            self.run_mode.set(RunMode::Paused);
        }
    }

    fn after_restart(&self) {
        self.forget_past();
        self.marked_line.set(None);
        self.fault_site.set(None);
        self.marking_before_last.set_value(None);
        self.notice.set(None);
    }

    /// Cold restart.
    pub fn reset(&self) {
        self.run_mode.set(RunMode::Stopped);
        if let Some(engine) = crate::lazy::engine() {
            self.with_sim_mut(engine.cold_restart);
        }
        self.after_restart();
    }

    /// Warm restart (RETAIN kept).
    pub fn warm_restart(&self) {
        self.run_mode.set(RunMode::Stopped);
        if let Some(engine) = crate::lazy::engine() {
            self.with_sim_mut(engine.warm_restart);
        }
        self.after_restart();
    }

    /// One animation frame of the run loop.
    fn frame(self, last: f64) {
        if self.run_mode.try_get_untracked() != Some(RunMode::Running) {
            return;
        }
        let now = perf_now();
        let wall_ms = (now - last).clamp(0.0, 100.0);
        let speed = self.speed.get_untracked();
        let outcome = self.sim.try_update_value(|sim| {
            let sim = sim.as_mut()?;
            // Never more than a frame's worth of work, even after a long pause.
            let budget_end = perf_now() + 12.0;
            let mut outcome = ScanOutcome::Completed;
            match speed {
                Speed::RealTime | Speed::Times10 => {
                    let factor = if speed == Speed::Times10 { 10.0 } else { 1.0 };
                    let owed = self.pending_ns.get_value() + wall_ms * factor * 1e6;
                    let cycle = sim.cycle_ns().max(1) as f64;
                    let scans = (owed / cycle).floor();
                    self.pending_ns.set_value(owed - scans * cycle);
                    let mut left = scans as u64;
                    while left > 0 && perf_now() < budget_end {
                        let n = left.min(self.batch.get_value());
                        outcome = self.timed_batch(sim, n);
                        left -= n;
                        if outcome != ScanOutcome::Completed {
                            break;
                        }
                    }
                }
                Speed::Max => {
                    while perf_now() < budget_end {
                        outcome = self.timed_batch(sim, self.batch.get_value());
                        if outcome != ScanOutcome::Completed {
                            break;
                        }
                    }
                }
            }
            Some(outcome)
        });
        self.bump();
        if let Some(Some(outcome)) = outcome {
            self.after_outcome(outcome);
        }
        if self.run_mode.get_untracked() == RunMode::Running {
            request_animation_frame(move || self.frame(now));
        }
    }
}
