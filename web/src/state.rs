//! The app's shared state (provided as context) and the operations every panel uses:
//! checking the source, the simulator and its run loop, projects and notices.
//!
//! The run loop is sliced per animation frame: each frame runs as many scans as the speed
//! asks for (real time, ×10) or as fit in a small wall-time budget (as fast as possible),
//! so the page stays responsive at any speed. The core keeps the virtual clock.

use std::collections::BTreeMap;

use leptos::prelude::*;
use plc_core::diagnostics::{LineIndex, Severity};
use plc_core::project::{decode_share, encode_share, Project, ProjectStore, ProjectSummary};
use plc_core::semantic;
use plc_core::sim::{BreakpointId, ScanOutcome, SimState, Simulator};

use crate::storage::LocalStorage;

/// One diagnostic, located for the editor.
#[derive(Debug, Clone, PartialEq)]
pub struct DiagView {
    /// Error or warning.
    pub error: bool,
    /// Stable code (`E0100`).
    pub code: String,
    /// The message.
    pub message: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column.
    pub column: u32,
    /// Byte span in the source.
    pub start: u32,
    /// End of the byte span.
    pub end: u32,
}

/// How many samples the timeline keeps (the oldest are dropped).
pub const TRACE_CAPACITY: usize = 20_000;

/// Whether the PLC is scanning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunMode {
    /// Not scanning (after Reset, or no program).
    Stopped,
    /// Scanning every animation frame.
    Running,
    /// Paused by the user or a breakpoint.
    Paused,
}

/// How fast virtual time runs against wall time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Speed {
    /// One virtual millisecond per wall millisecond.
    RealTime,
    /// Ten virtual milliseconds per wall millisecond.
    Times10,
    /// As many scans as fit in each frame.
    Max,
}

/// A message for the user in the banner.
#[derive(Debug, Clone, PartialEq)]
pub struct Notice {
    /// True for problems, false for information.
    pub error: bool,
    /// The text.
    pub text: String,
    /// A source line the message is about (the banner links to it).
    pub line: Option<u32>,
}

/// The state shared by every component.
#[derive(Clone, Copy)]
pub struct AppState {
    /// The open project.
    pub project: RwSignal<Project>,
    /// Its id in storage.
    pub project_id: RwSignal<Option<String>>,
    /// Every stored project.
    pub projects: RwSignal<Vec<ProjectSummary>>,
    /// The diagnostics of the last check.
    pub diagnostics: RwSignal<Vec<DiagView>>,
    /// The simulator of the last program that checked clean.
    pub sim: StoredValue<Option<Simulator>>,
    /// Bumped whenever the simulator's state changes; panels re-read on it.
    pub sim_version: RwSignal<u64>,
    /// Scanning or not.
    pub run_mode: RwSignal<RunMode>,
    /// Run speed.
    pub speed: RwSignal<Speed>,
    /// Inputs held at values by the I/O panel (name → IEC literal), kept over recompiles.
    pub held: RwSignal<BTreeMap<String, String>>,
    /// The banner message.
    pub notice: RwSignal<Option<Notice>>,
    /// A request to move the editor's cursor to (line, column).
    pub jump_to: RwSignal<Option<(u32, u32)>>,
    /// The line of the active statement to mark in the editor (a fault, the last CASE branch).
    pub marked_line: RwSignal<Option<u32>>,
    /// The breakpoints (condition text, and its id when it compiled against the current
    /// program); the texts are kept in the project's settings.
    pub breakpoints: RwSignal<Vec<(String, Option<BreakpointId>)>>,
    /// Lines of the active CASE branches of the last scan (marked in the editor).
    pub active_lines: RwSignal<Vec<u32>>,
    /// Virtual nanoseconds owed to the run loop but not yet scanned (less than one cycle).
    pending_ns: StoredValue<f64>,
}

fn now_ms() -> u64 {
    js_sys::Date::now() as u64
}

fn perf_now() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

impl AppState {
    /// Creates the state: opens a shared project from the URL fragment if there is one
    /// (as a new project), else the most recent project, else a new one.
    pub fn new() -> Self {
        let state = AppState {
            project: RwSignal::new(Project::new("My first project")),
            project_id: RwSignal::new(None),
            projects: RwSignal::new(Vec::new()),
            diagnostics: RwSignal::new(Vec::new()),
            sim: StoredValue::new(None),
            sim_version: RwSignal::new(0),
            run_mode: RwSignal::new(RunMode::Stopped),
            speed: RwSignal::new(Speed::RealTime),
            held: RwSignal::new(BTreeMap::new()),
            notice: RwSignal::new(None),
            jump_to: RwSignal::new(None),
            marked_line: RwSignal::new(None),
            breakpoints: RwSignal::new(Vec::new()),
            active_lines: RwSignal::new(Vec::new()),
            pending_ns: StoredValue::new(0.0),
        };
        state.open_initial_project();
        state.check_now();
        state
    }

    fn store(&self) -> ProjectStore<LocalStorage> {
        ProjectStore::new(LocalStorage::open())
    }

    /// Shows an error in the banner.
    pub fn error(&self, text: impl Into<String>) {
        self.notice.set(Some(Notice { error: true, text: text.into(), line: None }));
    }

    /// Shows information in the banner.
    pub fn info(&self, text: impl Into<String>) {
        self.notice.set(Some(Notice { error: false, text: text.into(), line: None }));
    }

    fn refresh_list(&self) {
        match self.store().list() {
            Ok(list) => self.projects.set(list),
            Err(e) => self.error(e.to_string()),
        }
    }

    fn open_initial_project(&self) {
        let hash = web_sys::window().and_then(|w| w.location().hash().ok()).unwrap_or_default();
        if hash.starts_with("#p=") {
            match decode_share(&hash) {
                Ok(project) => {
                    let name = project.name.clone();
                    self.add_and_open(project);
                    self.info(format!("Opened the shared project “{name}” as a new project."));
                }
                Err(e) => self.error(format!("{e}. Your own projects are unchanged.")),
            }
            clear_fragment();
            if self.project_id.get_untracked().is_some() {
                return;
            }
        }
        self.refresh_list();
        let first = self.projects.get_untracked().first().map(|p| p.id.clone());
        match first {
            Some(id) => self.open(&id),
            None => self.add_and_open(Project::new("My first project")),
        }
    }

    /// Stores `project` as a new project and opens it.
    pub fn add_and_open(&self, project: Project) {
        let result = self.store().add(&project, now_ms());
        match result {
            Ok(id) => self.project_id.set(Some(id)),
            Err(e) => self.error(format!("{e} (the project is open but not saved)")),
        }
        self.project.set(project);
        self.refresh_list();
        self.held.set(BTreeMap::new());
        self.check_now();
    }

    /// Opens a stored project.
    pub fn open(&self, id: &str) {
        match self.store().load(id) {
            Ok(project) => {
                self.project.set(project);
                self.project_id.set(Some(id.to_string()));
                self.held.set(BTreeMap::new());
                self.run_mode.set(RunMode::Stopped);
                self.check_now();
            }
            Err(e) => self.error(e.to_string()),
        }
    }

    /// Saves the open project now.
    pub fn save(&self) {
        let Some(id) = self.project_id.get_untracked() else { return };
        let project = self.project.get_untracked();
        match self.store().save(&id, &project, now_ms()) {
            Ok(()) => self.refresh_list(),
            Err(e) => self.error(format!("Not saved: {e}")),
        }
    }

    /// Renames the open project.
    pub fn rename(&self, name: &str) {
        let name = name.trim();
        if name.is_empty() {
            return;
        }
        self.project.update(|p| p.name = name.to_string());
        self.save();
    }

    /// Copies the open project and opens the copy.
    pub fn duplicate(&self) {
        let mut p = self.project.get_untracked();
        p.name = format!("{} (copy)", p.name);
        self.add_and_open(p);
    }

    /// Deletes the open project and opens another (or a new one).
    pub fn delete_current(&self) {
        if let Some(id) = self.project_id.get_untracked() {
            if let Err(e) = self.store().delete(&id) {
                self.error(e.to_string());
                return;
            }
        }
        self.project_id.set(None);
        self.refresh_list();
        match self.projects.get_untracked().first().map(|p| p.id.clone()) {
            Some(id) => self.open(&id),
            None => self.add_and_open(Project::new("My first project")),
        }
    }

    /// The share link of the open project.
    pub fn share_link(&self) -> String {
        let fragment = encode_share(&self.project.get_untracked());
        let base = web_sys::window()
            .and_then(|w| w.location().href().ok())
            .map(|h| h.split('#').next().unwrap_or_default().to_string())
            .unwrap_or_default();
        format!("{base}#{fragment}")
    }

    /// Replaces the source text (from the editor). The caller debounces checks and saves.
    pub fn set_source(&self, text: String) {
        self.project.update(|p| p.source = text);
    }

    /// Checks the source; when it is clean, builds a fresh simulator (held inputs are
    /// re-applied; a running PLC keeps running with the new program).
    pub fn check_now(&self) {
        let source = self.project.with_untracked(|p| p.source.clone());
        let analysis = semantic::analyze(&source);
        let index = LineIndex::new(&source);
        let views = analysis
            .diagnostics
            .iter()
            .map(|d| {
                let loc = index.location(d.span.start);
                DiagView {
                    error: d.severity == Severity::Error,
                    code: d.code.as_str().to_string(),
                    message: d.message.clone(),
                    line: loc.line,
                    column: loc.column,
                    start: d.span.start,
                    end: d.span.end,
                }
            })
            .collect();
        self.diagnostics.set(views);
        let Some(program) = analysis.program else { return };
        let Some(main) = program.programs().find(|&p| !program.pou(p).library) else {
            self.sim.set_value(None);
            self.bump();
            return;
        };
        match Simulator::new(program, main) {
            Ok(mut sim) => {
                let cycle = self.project.with_untracked(|p| p.settings.cycle_ms).max(1);
                sim.set_cycle_ns(cycle as i64 * 1_000_000);
                for (name, value) in self.held.get_untracked() {
                    let _ = sim.hold(&name, &value);
                }
                self.restore_sim_settings(&mut sim);
                self.sim.set_value(Some(sim));
                self.marked_line.set(None);
            }
            Err(e) => self.error(e.to_string()),
        }
        self.bump();
    }

    /// Re-adds the project's breakpoints and timeline variables to a fresh simulator
    /// (conditions or paths that no longer fit the program are kept but inactive).
    fn restore_sim_settings(&self, sim: &mut Simulator) {
        let (conditions, traced) = self
            .project
            .with_untracked(|p| (p.settings.breakpoints.clone(), p.settings.traced.clone()));
        let list = conditions
            .into_iter()
            .map(|c| {
                let id = sim.add_breakpoint(&c).ok();
                (c, id)
            })
            .collect();
        self.breakpoints.set(list);
        let paths: Vec<&str> = traced
            .iter()
            .map(String::as_str)
            .filter(|p| sim.executable().locate(p).is_some())
            .collect();
        let _ = sim.set_trace(&paths, TRACE_CAPACITY);
    }

    /// Adds a breakpoint on an ST condition (kept in the project).
    pub fn add_breakpoint(&self, condition: &str) -> Result<(), String> {
        let condition = condition.trim();
        if condition.is_empty() {
            return Err("Type a condition, e.g. Level > 50".to_string());
        }
        let id = match self.with_sim_mut(|s| s.add_breakpoint(condition)) {
            None => return Err("The program has errors: fix them to add breakpoints.".to_string()),
            Some(Err(e)) => return Err(e.to_string()),
            Some(Ok(id)) => id,
        };
        self.breakpoints.update(|b| b.push((condition.to_string(), Some(id))));
        self.project.update(|p| p.settings.breakpoints.push(condition.to_string()));
        self.save();
        Ok(())
    }

    /// Removes the breakpoint at `index` of [`AppState::breakpoints`].
    pub fn remove_breakpoint(&self, index: usize) {
        let Some((text, id)) = self.breakpoints.with_untracked(|b| b.get(index).cloned()) else {
            return;
        };
        if let Some(id) = id {
            self.with_sim_mut(|s| s.remove_breakpoint(id));
        }
        self.breakpoints.update(|b| {
            b.remove(index);
        });
        self.project.update(|p| {
            if let Some(k) = p.settings.breakpoints.iter().position(|c| *c == text) {
                p.settings.breakpoints.remove(k);
            }
        });
        self.save();
    }

    /// Sets the variables recorded for the timeline (kept in the project); recording
    /// restarts.
    pub fn set_traced(&self, paths: Vec<String>) {
        self.project.update(|p| p.settings.traced = paths.clone());
        self.save();
        self.with_sim_mut(|s| {
            let valid: Vec<&str> = paths
                .iter()
                .map(String::as_str)
                .filter(|p| s.executable().locate(p).is_some())
                .collect();
            let _ = s.set_trace(&valid, TRACE_CAPACITY);
        });
    }

    /// Tells the panels the simulator changed.
    pub fn bump(&self) {
        self.sim_version.update(|v| *v += 1);
        let spans = self
            .sim
            .with_value(|s| s.as_ref().map(Simulator::active_case_branches))
            .unwrap_or_default();
        let lines: Vec<u32> = if spans.is_empty() {
            Vec::new()
        } else {
            self.project.with_untracked(|p| {
                let index = LineIndex::new(&p.source);
                spans.iter().map(|s| index.location(s.start).line).collect()
            })
        };
        if self.active_lines.with_untracked(|l| *l != lines) {
            self.active_lines.set(lines);
        }
    }

    /// Reads from the simulator (tracks `sim_version`, so views update).
    pub fn with_sim<R>(&self, f: impl FnOnce(&Simulator) -> R) -> Option<R> {
        self.sim_version.track();
        self.sim.with_value(|s| s.as_ref().map(f))
    }

    /// Changes the simulator and tells the panels.
    pub fn with_sim_mut<R>(&self, f: impl FnOnce(&mut Simulator) -> R) -> Option<R> {
        let r = self.sim.try_update_value(|s| s.as_mut().map(f)).flatten();
        self.bump();
        r
    }

    /// Holds an input at a value (an IEC literal) until changed.
    pub fn hold_input(&self, name: &str, literal: &str) {
        self.held.update(|h| {
            h.insert(name.to_string(), literal.to_string());
        });
        if let Some(Err(e)) = self.with_sim_mut(|s| s.hold(name, literal)) {
            self.error(e.to_string());
        }
    }

    fn after_outcome(&self, outcome: ScanOutcome) {
        match outcome {
            ScanOutcome::Completed => {}
            ScanOutcome::Breakpoint(id) => {
                self.run_mode.set(RunMode::Paused);
                let cond =
                    self.with_sim(|s| s.breakpoint_condition(id).map(str::to_string)).flatten();
                self.info(format!("Paused at breakpoint: {}", cond.unwrap_or_default()));
            }
            ScanOutcome::Fault(info) => {
                self.run_mode.set(RunMode::Stopped);
                let source = self.project.with_untracked(|p| p.source.clone());
                let loc = LineIndex::new(&source).location(info.span.start);
                self.marked_line.set(Some(loc.line));
                self.notice.set(Some(Notice {
                    error: true,
                    text: format!(
                        "FAULT on scan {}: {} (line {})",
                        info.scan, info.fault, loc.line
                    ),
                    line: Some(loc.line),
                }));
            }
        }
    }

    /// Runs `n` scans now (Step, Step N).
    pub fn step(&self, n: u64) {
        if self.run_mode.get_untracked() == RunMode::Running {
            self.run_mode.set(RunMode::Paused);
        }
        if let Some(outcome) = self.with_sim_mut(|s| s.run_scans(n)) {
            if self.run_mode.get_untracked() == RunMode::Stopped
                && !matches!(outcome, ScanOutcome::Fault(_))
            {
                self.run_mode.set(RunMode::Paused);
            }
            self.after_outcome(outcome);
        }
    }

    /// Starts scanning every animation frame.
    pub fn run(&self) {
        if self.sim.with_value(|s| s.is_none()) {
            self.error("The program has errors: fix them to run it.");
            return;
        }
        let faulted = self.with_sim(|s| matches!(s.state(), SimState::Faulted(_))).unwrap_or(false);
        if faulted {
            self.error("The PLC is in FAULT: press Reset to restart it.");
            return;
        }
        if self.run_mode.get_untracked() == RunMode::Running {
            return;
        }
        self.run_mode.set(RunMode::Running);
        let state = *self;
        let start = perf_now();
        request_animation_frame(move || state.frame(start));
    }

    /// Stops scanning (the state is kept).
    pub fn pause(&self) {
        if self.run_mode.get_untracked() == RunMode::Running {
            self.run_mode.set(RunMode::Paused);
        }
    }

    /// Cold restart.
    pub fn reset(&self) {
        self.run_mode.set(RunMode::Stopped);
        self.with_sim_mut(Simulator::cold_restart);
        self.marked_line.set(None);
        self.notice.set(None);
    }

    /// Warm restart (RETAIN kept).
    pub fn warm_restart(&self) {
        self.run_mode.set(RunMode::Stopped);
        self.with_sim_mut(Simulator::warm_restart);
        self.marked_line.set(None);
        self.notice.set(None);
    }

    /// Sets the cycle time in milliseconds (kept in the project).
    pub fn set_cycle_ms(&self, ms: u64) {
        let ms = ms.clamp(1, 60_000);
        self.project.update(|p| p.settings.cycle_ms = ms);
        self.with_sim_mut(|s| s.set_cycle_ns(ms as i64 * 1_000_000));
        self.save();
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
            Some(match speed {
                Speed::RealTime | Speed::Times10 => {
                    let factor = if speed == Speed::Times10 { 10.0 } else { 1.0 };
                    let owed = self.pending_ns.get_value() + wall_ms * factor * 1e6;
                    let cycle = sim.cycle_ns().max(1) as f64;
                    let scans = (owed / cycle).floor();
                    self.pending_ns.set_value(owed - scans * cycle);
                    let mut outcome = ScanOutcome::Completed;
                    let mut left = scans as u64;
                    // Never more than a frame's worth of work, even after a long pause.
                    let budget_end = perf_now() + 12.0;
                    while left > 0 && perf_now() < budget_end {
                        let n = left.min(64);
                        outcome = sim.run_scans(n);
                        left -= n;
                        if outcome != ScanOutcome::Completed {
                            break;
                        }
                    }
                    outcome
                }
                Speed::Max => {
                    let budget_end = perf_now() + 12.0;
                    let mut outcome = ScanOutcome::Completed;
                    while perf_now() < budget_end {
                        outcome = sim.run_scans(256);
                        if outcome != ScanOutcome::Completed {
                            break;
                        }
                    }
                    outcome
                }
            })
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

fn clear_fragment() {
    if let Some(w) = web_sys::window() {
        let url = w.location().href().unwrap_or_default();
        let base = url.split('#').next().unwrap_or_default().to_string();
        if let Ok(history) = w.history() {
            let _ = history.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&base));
        }
    }
}
