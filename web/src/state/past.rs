//! Going back in time (issue 36): the simulator records its recent history, and the page
//! can show any recorded scan instead of the present. While a past scan is shown every
//! panel reads the recorded [`ScanView`] through [`AppState::read`] or
//! [`AppState::with_readout`]; changing an input or pressing Run there makes that scan the
//! present (`rewind_to`), dropping the later ones. `Why?` buttons ask about a variable or
//! a Petri net place at the shown scan ([`WhyQuery`]); the explanation itself is a lazy
//! chunk (`lazy::explanation_view`).

use leptos::prelude::*;
use plc_core::sim::{Readout, ScanView, Simulator};
use plc_core::vm::Value;

use super::{AppState, RunMode};
use crate::i18n::{tf, K};

/// What a `Why?` button asks about.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum WhyTarget {
    /// A variable, by path (`Motor`, `T1.Q`).
    Var(String),
    /// A Petri net place, by id (`P3`).
    Place(String),
}

/// The question the `Explanation` region answers: a variable or place, at a scan.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WhyQuery {
    /// What is asked about.
    pub target: WhyTarget,
    /// The scan the question was asked at (while paused, the explanation follows the
    /// scan shown instead).
    pub scan: u64,
}

/// The words of the stepping controls and the banner.
pub mod words {
    use crate::i18n::{tf, K};

    /// The banner while a past scan is shown.
    pub fn showing(scan: u64, last: u64) -> String {
        tf(K::state_showing_scan, &[("scan", &scan.to_string()), ("last", &last.to_string())])
    }
    /// The banner's button.
    pub const RETURN_TO_NOW: &str = "Return to now";
    /// The notice after a new future started from a past scan.
    pub fn dropped(scan: u64, last: u64) -> String {
        let many = last > scan + 1;
        let (scan, from, last) = (scan.to_string(), (scan + 1).to_string(), last.to_string());
        if many {
            tf(K::state_dropped_many, &[("scan", &scan), ("from", &from), ("last", &last)])
        } else {
            tf(K::state_dropped_one, &[("scan", &scan), ("last", &last)])
        }
    }
}

/// `Cannot show scan N: why.` (`key` says what could not be done).
fn cannot(key: K, scan: u64, e: &dyn std::fmt::Display) -> String {
    tf(key, &[("scan", &scan.to_string()), ("error", &e.to_string())])
}

impl AppState {
    /// The first and last recorded scans (`None` without a program or a recording).
    pub fn recorded_range(&self) -> Option<(u64, u64)> {
        self.with_sim(Simulator::recorded_range).flatten()
    }

    /// The scan the page shows: the recorded one, or the present.
    pub fn displayed_scan(&self) -> u64 {
        match self.shown.get() {
            Some(n) => n,
            None => self.with_sim(Simulator::scan_count).unwrap_or(0),
        }
    }

    /// Reads a variable as the page shows it: at the recorded scan shown, or now.
    pub fn read(&self, path: &str) -> Option<Value> {
        self.with_readout(|r| r.read(path).ok()).flatten()
    }

    /// Reads the state the page shows (a recorded scan or the present) through the trait
    /// both implement. Tracks the simulator and the scan shown.
    pub fn with_readout<R>(&self, f: impl FnOnce(&dyn Readout) -> R) -> Option<R> {
        self.sim_version.track();
        if self.shown.get().is_some() {
            if let Some(r) =
                self.shown_view.with_value(|v| v.as_ref().map(|v| f(v as &dyn Readout)))
            {
                return Some(r);
            }
            return None;
        }
        self.sim.with_value(|s| s.as_ref().map(|s| f(s as &dyn Readout)))
    }

    /// Reads the recorded scan shown, if one is.
    pub fn with_shown_view<R>(&self, f: impl FnOnce(&ScanView) -> R) -> Option<R> {
        self.sim_version.track();
        self.shown.track();
        self.shown_view.with_value(|v| v.as_ref().map(f))
    }

    /// Shows recorded scan `scan` (the present when it is the last one). Pauses a run.
    /// The replay that rebuilds it is a chunk of its own (`lazy::show_scan`), fetched the
    /// first time the page goes back.
    pub fn show_scan(&self, scan: u64) {
        let Some((first, last)) = self.sim.with_value(|s| s.as_ref()?.recorded_range()) else {
            return;
        };
        if self.run_mode.get_untracked() == RunMode::Running {
            self.run_mode.set(RunMode::Paused);
        }
        let scan = scan.clamp(first, last);
        self.going_to.set_value(Some(scan));
        if scan == last {
            self.going_to.set_value(None);
            self.return_to_now();
            return;
        }
        let state = *self;
        leptos::task::spawn_local(async move {
            if let Err(e) = crate::lazy::show_scan(state, scan).await {
                state.going_to.set_value(None);
                state.error(cannot(K::state_cannot_show, scan, &e));
            }
        });
    }

    /// The scan `scan` shown, once the replay is here (`lazy::show_scan`), unless a later
    /// request (another click) came meanwhile.
    pub(crate) fn show_scan_now(self, scan: u64) {
        if self.going_to.try_get_value() != Some(Some(scan)) {
            return;
        }
        self.going_to.set_value(None);
        match self.sim.with_value(|s| s.as_ref().map(|s| s.view_at(scan))) {
            Some(Ok(view)) => {
                self.shown_view.set_value(Some(view));
                self.shown.set(Some(scan));
                self.bump();
            }
            Some(Err(e)) => self.error(cannot(K::state_cannot_show, scan, &e)),
            None => {}
        }
    }

    /// Shows the present again.
    pub fn return_to_now(&self) {
        self.going_to.set_value(None);
        if self.shown.get_untracked().is_some() {
            self.shown.set(None);
            self.shown_view.set_value(None);
            self.bump();
        }
    }

    /// The scan shown, or the one on its way (several quick clicks add up).
    fn target_scan(&self) -> Option<u64> {
        self.going_to.get_value().or(self.shown.get_untracked())
    }

    /// Moves `n` recorded scans forward from the scan shown (`Step` in the past).
    pub fn step_forward(&self, n: u64) {
        if let Some(at) = self.target_scan() {
            self.show_scan(at.saturating_add(n));
        }
    }

    /// Whether the page shows (or is going to) a past scan.
    pub fn in_past(&self) -> bool {
        self.target_scan().is_some()
    }

    /// Shows the scan before the one shown (`Step back`).
    pub fn step_back(&self) {
        let Some((first, last)) = self.sim.with_value(|s| s.as_ref()?.recorded_range()) else {
            return;
        };
        let now = self.target_scan().unwrap_or(last);
        if now > first {
            self.show_scan(now - 1);
        }
    }

    /// Whether `Step back` can go back.
    pub fn can_step_back(&self) -> bool {
        match self.recorded_range() {
            Some((first, last)) => self.shown.get().unwrap_or(last) > first,
            None => false,
        }
    }

    /// Runs `then` after a change from the user (an input, a value, Run). While a past scan
    /// is shown, that scan first becomes the present (the scans after it are dropped, and
    /// the banner says so).
    pub fn leave_past_then(&self, then: impl FnOnce() + 'static) {
        // One copy of the code for every caller.
        self.leave_past_boxed(Box::new(then));
    }

    fn leave_past_boxed(&self, then: Box<dyn FnOnce()>) {
        let Some(scan) = self.target_scan() else {
            then();
            return;
        };
        let last = self.sim.with_value(|s| s.as_ref().map(Simulator::scan_count)).unwrap_or(scan);
        self.going_to.set_value(None);
        let state = *self;
        leptos::task::spawn_local(async move {
            if let Err(e) = crate::lazy::rewind(state, scan, last).await {
                state.shown.set(None);
                state.shown_view.set_value(None);
                state.bump();
                state.error(cannot(K::state_cannot_continue, scan, &e));
            }
            then();
        });
    }

    /// Recorded scan `scan` made the present (`lazy::rewind`), the banner saying which
    /// scans up to `last` were dropped.
    pub(crate) fn rewind_now(self, scan: u64, last: u64) {
        let rewound =
            self.sim.try_update_value(|s| s.as_mut().map(|s| s.rewind_to(scan))).flatten();
        self.shown.set(None);
        self.shown_view.set_value(None);
        self.bump();
        match rewound {
            Some(Ok(())) => self.info(words::dropped(scan, last)),
            Some(Err(e)) => self.error(cannot(K::state_cannot_continue, scan, &e)),
            None => {}
        }
    }

    /// Forgets the scan shown (a new simulator, a restart).
    pub(super) fn forget_past(&self) {
        self.going_to.set_value(None);
        self.shown.set(None);
        self.shown_view.set_value(None);
    }

    /// Asks why a variable has the value it has at the scan shown.
    pub fn ask_why(&self, path: &str) {
        let scan = self.displayed_scan_untracked();
        self.why.set(Some(WhyQuery { target: WhyTarget::Var(path.to_string()), scan }));
    }

    /// Asks why a Petri net place holds (or does not hold) a token at the scan shown.
    pub fn ask_why_place(&self, place: &str) {
        let scan = self.displayed_scan_untracked();
        self.why.set(Some(WhyQuery { target: WhyTarget::Place(place.to_string()), scan }));
    }

    fn displayed_scan_untracked(&self) -> u64 {
        self.shown.get_untracked().unwrap_or_else(|| {
            self.sim.with_value(|s| s.as_ref().map(Simulator::scan_count)).unwrap_or(0)
        })
    }
}
