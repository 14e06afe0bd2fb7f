//! Building the open project with the core's one pipeline (`build::build_project`, as
//! `plc check` and `plc run` do), turning its diagnostics into what the panels show, and
//! mapping the running program's active CASE branches back to ST lines and Petri net code.

use leptos::prelude::*;
use plc_core::build::{ProjectBuild, ProjectDiagnostic, Site};
use plc_core::diagnostics::Severity;
use plc_core::sim::Simulator;

use super::{AppState, PouView, TRACE_CAPACITY};
use crate::i18n::{t, tf, K};

/// One diagnostic, located for the problem list, the ST editor and the POU views.
#[derive(Debug, Clone, PartialEq)]
pub struct DiagView {
    /// Error or warning.
    pub error: bool,
    /// Stable code (`E0100`).
    pub code: String,
    /// The message in English (without its location): [`DiagView::message`] shows it in
    /// the page's language.
    pub english: String,
    /// The message as data, when the stage that found it has made it so.
    pub msg: Option<Box<plc_core::diagnostics::Message>>,
    /// Where the problem is.
    pub site: Site,
    /// The declared name an unknown one probably misspells (`Replace with NAME`).
    pub suggestion: Option<String>,
    /// For an undeclared name, the type its use implies when the checker knows it.
    pub implied_type: Option<String>,
}

impl DiagView {
    fn new(d: &ProjectDiagnostic) -> Self {
        DiagView {
            error: d.severity == Severity::Error,
            code: d.code.as_str().to_string(),
            english: d.message.clone(),
            msg: d.msg.clone(),
            site: d.site.clone(),
            suggestion: d.suggestion().map(str::to_string),
            implied_type: d.implied_type().map(str::to_string),
        }
    }

    /// The message in the language shown (English where it is not data yet).
    pub fn message(&self) -> String {
        match &self.msg {
            Some(m) => crate::i18n::message_text(m, self.suggestion.as_deref(), &self.english),
            None => self.english.clone(),
        }
    }

    /// `(line, column, start, end)` when the problem is in the ST source.
    pub fn st(&self) -> Option<(u32, u32, u32, u32)> {
        match self.site {
            Site::St { line, column, span } => Some((line, column, span.start, span.end)),
            _ => None,
        }
    }

    /// Where the problem is, as the problem list shows it in the language shown (`12:5`,
    /// `Latch, rung 1, row 1, column 2`, `Weighing, transition T5 (guard line 1, column 3)`):
    /// the POU's name, then its place inside the POU ([`Site::detail`]).
    pub fn place_label(&self) -> String {
        match &self.site {
            Site::Project => t(K::state_place_project).to_string(),
            Site::St { line, column, .. } => format!("{line}:{column}"),
            site => match (site.pou(), site.detail()) {
                (Some(pou), Some(d)) => {
                    format!("{pou}, {}", crate::i18n::message_text(&d.message, None, &d.english))
                }
                (Some(pou), None) => pou.to_string(),
                (None, _) => String::new(),
            },
        }
    }
}

thread_local! {
    /// `show_main_view` waits for the engine and the build that loads the project's
    /// passes: the view shown when it was asked for (a view the user picks meanwhile is
    /// kept).
    static MAIN_VIEW_PENDING: std::cell::RefCell<Option<PouView>> =
        const { std::cell::RefCell::new(None) };
}

impl AppState {
    /// Fetches the engine's chunk (once for the page: a second caller waits for the same
    /// fetch) and, the first time it comes, checks the project, shows the main view and
    /// does a Run or Step pressed meanwhile. False when it could not be fetched.
    pub(super) async fn engine_arrived(&self) -> bool {
        if crate::lazy::load_engine().await.is_err() {
            return false;
        }
        if !self.engine_ready.get_untracked() {
            self.engine_ready.set(true);
            self.check_now();
            self.show_pending_main_view();
            self.scan_wished();
        }
        true
    }

    /// Shows the main view asked for before the engine or the passes were here, unless the
    /// user has picked another view since.
    fn show_pending_main_view(&self) {
        let Some(asked_in) = MAIN_VIEW_PENDING.with(|p| p.borrow_mut().take()) else { return };
        if self.view.get_untracked() == asked_in {
            self.show_main_view();
        }
    }
}

/// The 1-based line of byte `offset` in `text`.
fn line_of(text: &str, offset: usize) -> u32 {
    let end = offset.min(text.len());
    text.as_bytes()[..end].iter().filter(|&&b| b == b'\n').count() as u32 + 1
}

/// Records `paths` on the timeline (those the program does not have, and arrays or
/// structures, which the timeline cannot draw, are left out).
pub(super) fn trace_paths(sim: &mut Simulator, paths: &[String]) {
    let valid: Vec<&str> =
        paths.iter().map(String::as_str).filter(|p| sim.trace_cost(p).is_ok()).collect();
    let _ = sim.set_trace(&valid, TRACE_CAPACITY);
}

impl AppState {
    /// Builds the project; when it is clean, powers a fresh simulator on for the chosen
    /// PROGRAM (held inputs are re-applied; a running PLC keeps running with the new
    /// program). With errors the previous program keeps running, marked stale (the
    /// controls say so, and Run does not start it unless the user chooses to).
    ///
    /// A project with diagram POUs is built only once the passes for them are loaded (a
    /// chunk each, fetched the first time: `crate::lazy::load_lowerings`); until then the
    /// panels keep what they show.
    pub fn check_now(&self) {
        if self.opening_stored.with_untracked(Option::is_some) {
            // The project shown is not the one being opened: it is checked once open.
            self.check_pending.set_value(true);
            return;
        }
        let project = self.project.get_untracked();
        let lowerings = crate::lazy::lowerings();
        let Some(engine) = crate::lazy::engine() else {
            // The checker and compiler come in a chunk the page fetches as it starts: the
            // check (and a Run or Step pressed meanwhile) is done when it is here.
            self.check_pending.set_value(true);
            if crate::lazy::engine_loading() {
                return;
            }
            let state = *self;
            leptos::task::spawn_local(async move {
                if !state.engine_arrived().await {
                    state.error(t(K::lazy_failed_checker));
                }
            });
            return;
        };
        let lacks = (engine.lacks)(&lowerings, &project);
        if !lacks.is_empty() {
            let state = *self;
            leptos::task::spawn_local(async move {
                match crate::lazy::load_lowerings(&lacks).await {
                    Ok(()) => {
                        state.check_now();
                        state.show_pending_main_view();
                    }
                    Err(e) => state.error(tf(K::state_check_failed, &[("error", &e.to_string())])),
                }
            });
            return;
        }
        self.check_pending.set_value(false);
        let build = (engine.build)(&project, &lowerings);
        self.diagnostics.set(build.diagnostics.iter().map(DiagView::new).collect());
        let charts = (engine.charts)(&project.source);
        if self.sfc_charts.with_untracked(|c| *c != charts) {
            self.sfc_charts.set(charts);
        }
        if build.has_errors() {
            self.set_stale(self.sim.with_value(Option::is_some));
            return;
        }
        self.set_stale(false);
        let names = build.program_names();
        let chosen = project
            .settings
            .program
            .as_deref()
            .and_then(|p| names.iter().find(|n| n.eq_ignore_ascii_case(p)))
            .or(names.first())
            .cloned();
        self.programs.set(names);
        let Some(chosen) = chosen else {
            self.sim.set_value(None);
            self.sim_build.set_value(None);
            self.running.set(None);
            self.bump();
            return;
        };
        match (engine.simulator)(&build, Some(&chosen), project.settings.plant.as_deref()) {
            Ok(mut sim) => {
                sim.set_cycle_ns(
                    plc_core::limits::cycle_ns(project.settings.cycle_ms).unwrap_or(10_000_000),
                );
                for (name, value) in self.held.get_untracked() {
                    let _ = (engine.hold)(&mut sim, &name, &value);
                }
                self.restore_sim_settings(&mut sim, engine);
                // The history the page can go back through (issue 36); a program too
                // large for the recording's budget runs without it.
                let _ = sim.set_recording(true);
                // A network PROGRAM's function outputs have no variables: the simulator
                // watches their expressions so the network view can show them.
                // (The code that finds them comes with the network pass.)
                let net = project.networks.iter().find(|n| n.name.eq_ignore_ascii_case(&chosen));
                if let (Some(net), Some(watches)) = (net, crate::lazy::network_watches()) {
                    for (_, text) in watches(net) {
                        let _ = (engine.add_watch)(&mut sim, &text);
                    }
                }
                let places = build.source.as_ref().and_then(|s| {
                    s.map.petri.iter().find(|seg| seg.pou.eq_ignore_ascii_case(&chosen))
                });
                self.running_places.set_value(places.map(|seg| seg.generated.place_map.clone()));
                self.marking_before_last.set_value(None);
                self.forget_past();
                self.sim.set_value(Some(sim));
                self.sim_build.set_value(Some(build));
                self.running.set(Some(chosen));
                self.marked_line.set(None);
                self.fault_site.set(None);
            }
            Err(e) => {
                self.set_stale(self.sim.with_value(Option::is_some));
                self.error(e.located_message());
            }
        }
        self.bump();
    }

    /// Notes whether the simulator holds an older build than the text on the screen; the
    /// choice to run that one ends when the project builds again.
    fn set_stale(&self, stale: bool) {
        if self.stale.get_untracked() != stale {
            self.stale.set(stale);
        }
        if !stale {
            if self.run_old.get_untracked() {
                self.run_old.set(false);
            }
            self.clear_refusal();
        }
    }

    /// Chooses the PROGRAM to run (kept in the project's settings) and restarts on it.
    pub fn set_program(&self, name: &str) {
        self.project.update(|p| p.settings.program = Some(name.to_string()));
        self.save();
        self.check_now();
    }

    /// Shows the running PROGRAM's POU (or the first ladder or Petri net POU of a project
    /// without ST text), else the ST editor.
    pub fn show_main_view(&self) {
        // Which PROGRAM runs is known once the project is built (see `check_now`).
        let lacks = |engine: crate::lazy::Engine| {
            self.project
                .with_untracked(|p| !(engine.lacks)(&crate::lazy::lowerings(), p).is_empty())
        };
        let ready = self.engine_ready.get_untracked().then(crate::lazy::engine).flatten();
        if ready.is_none_or(lacks) {
            let shown = self.view.get_untracked();
            MAIN_VIEW_PENDING.with(|p| *p.borrow_mut() = Some(shown));
            return;
        }
        let running = self.running.get_untracked();
        let view = self.project.with_untracked(|p| {
            let is = |name: &str| running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(name));
            if let Some(l) = p.ladder.iter().find(|l| is(&l.name)) {
                return PouView::Ladder(l.name.clone());
            }
            if let Some(n) = p.petri.iter().find(|n| is(&n.name)) {
                return PouView::Petri(n.name.clone());
            }
            if let Some(n) = p.networks.iter().find(|n| is(&n.name)) {
                return PouView::Network(n.name.clone());
            }
            if p.source.trim().is_empty() {
                if let Some(l) = p.ladder.first() {
                    return PouView::Ladder(l.name.clone());
                }
                if let Some(n) = p.petri.first() {
                    return PouView::Petri(n.name.clone());
                }
            }
            PouView::St
        });
        self.view.set(view);
    }

    /// Re-adds the project's breakpoints and timeline variables to a fresh simulator
    /// (conditions or paths that no longer fit the program are kept but inactive).
    fn restore_sim_settings(&self, sim: &mut Simulator, engine: crate::lazy::Engine) {
        let (conditions, traced) = self
            .project
            .with_untracked(|p| (p.settings.breakpoints.clone(), p.settings.traced.clone()));
        let list = conditions
            .into_iter()
            .map(|c| {
                let id = (engine.add_breakpoint)(sim, &c).ok();
                (c, id)
            })
            .collect();
        self.breakpoints.set(list);
        trace_paths(sim, &traced);
    }

    /// Tells the panels the simulator changed, and finds the lines of the CASE branches
    /// taken on the last scan: ST lines for the editor, generated lines for Petri nets.
    pub fn bump(&self) {
        self.sim_version.update(|v| *v += 1);
        let spans =
            match self.shown_view.with_value(|v| v.as_ref().map(|v| v.active_case_branches())) {
                Some(spans) => spans,
                None => self
                    .sim
                    .with_value(|s| s.as_ref().map(Simulator::active_case_branches))
                    .unwrap_or_default(),
            };
        let mut st_lines = Vec::new();
        let mut generated = Vec::new();
        if !spans.is_empty() {
            self.sim_build.with_value(|b| {
                let Some(source) = b.as_ref().and_then(|b: &ProjectBuild| b.source.as_ref()) else {
                    return;
                };
                for span in &spans {
                    let line = line_of(&source.text, span.start as usize);
                    if line <= source.map.st_lines {
                        st_lines.push(line);
                    } else if let Some(seg) =
                        source.map.petri.iter().rev().find(|s| s.first_line <= line)
                    {
                        generated.push((seg.pou.clone(), line + 1 - seg.first_line));
                    }
                }
            });
        }
        if self.active_lines.with_untracked(|l| *l != st_lines) {
            self.active_lines.set(st_lines);
        }
        if self.active_generated.with_untracked(|l| *l != generated) {
            self.active_generated.set(generated);
        }
    }
}
