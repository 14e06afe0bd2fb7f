//! The app's shared state (provided as context) and the operations every panel uses:
//! projects and notices here, building the project in `check.rs`, the simulator's run loop
//! in `run.rs`.

mod check;
mod gate;
mod past;
mod projects;
mod run;

use std::collections::BTreeMap;

use leptos::prelude::*;
use plc_core::build::{ProjectBuild, Site};
use plc_core::petri::PlaceMap;
use plc_core::project::{Project, ProjectSummary};
use plc_core::sim::{BreakpointId, ScanView, Simulator};

use crate::i18n::{t, tf, K};

pub use check::DiagView;
pub use gate::version_text;
pub use past::{words as past_words, WhyQuery, WhyTarget};
pub use projects::{clear_fragment, note_panic, project_file_name};
pub use run::marking_of;

pub use crate::i18n::plural;

/// How long after the last edit of a diagram the project is checked and saved.
const CHECK_DELAY: std::time::Duration = std::time::Duration::from_millis(300);

/// How many samples the timeline keeps (the oldest are dropped).
pub const TRACE_CAPACITY: usize = 20_000;

/// Whether the PLC is scanning.
/// A scan the user asked for before the engine was loaded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScanWish {
    /// Run.
    Run,
    /// Step or Step N: this many scans.
    Step(u64),
}

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

/// Which POU the editor pane shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PouView {
    /// The project's ST source in the text editor.
    St,
    /// A ladder POU, by name.
    Ladder(String),
    /// A Petri net POU, by name.
    Petri(String),
    /// The chart of a POU of the ST source written as a textual SFC, by name.
    Sfc(String),
    /// A network POU (LD or FBD as an imported file drew it), by name.
    Network(String),
}

/// A message for the user in the banner.
#[derive(Debug, Clone, PartialEq)]
pub struct Notice {
    /// True for problems, false for information.
    pub error: bool,
    /// The text.
    pub text: String,
    /// The place the message is about (the banner links to it).
    pub site: Option<Site>,
    /// What the user can do about it (buttons in the banner).
    pub actions: Vec<NoticeAction>,
}

/// A button in the banner: something the user can do about the message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NoticeAction {
    /// Download the open project as a project file.
    Export,
    /// Replace the open project by the version another tab saved.
    LoadTheirs,
    /// Save this tab's version over the one another tab saved.
    KeepMine,
    /// Save this tab's version as a new project.
    SaveAsNew,
    /// Download the stored text of a damaged project (by id).
    DownloadDamaged(String),
    /// Delete a damaged project (by id).
    DeleteDamaged(String),
    /// Open a share link (the URL fragment) held back after it stopped the page.
    OpenShared(String),
    /// Open a stored project again (by id) whose diagram POUs' readers could not be
    /// fetched.
    OpenStored(String),
    /// Run the build the simulator holds although the project has errors since.
    RunLastBuilt,
}

impl NoticeAction {
    /// The button's text (its accessible name).
    pub fn label(&self) -> &'static str {
        match self {
            NoticeAction::Export => t(K::state_export_project),
            NoticeAction::LoadTheirs => t(K::state_load_theirs),
            NoticeAction::KeepMine => t(K::state_keep_mine),
            NoticeAction::SaveAsNew => t(K::state_save_as_new),
            NoticeAction::DownloadDamaged(_) => t(K::state_download_damaged),
            NoticeAction::DeleteDamaged(_) => t(K::state_delete_damaged),
            NoticeAction::OpenShared(_) => t(K::state_open_shared),
            NoticeAction::OpenStored(_) => t(K::lazy_retry),
            NoticeAction::RunLastBuilt => t(K::state_run_last_built),
        }
    }
}

/// The state shared by every component.
#[derive(Clone, Copy)]
pub struct AppState {
    /// The open project.
    pub project: RwSignal<Project>,
    /// Its id in storage (`None`: open but not stored, e.g. the storage is full).
    pub project_id: RwSignal<Option<String>>,
    /// The revision of it that was opened or last saved (saves name it, so another tab's
    /// change is never overwritten).
    project_rev: StoredValue<Option<u64>>,
    /// Stored projects that cannot be opened: id → why.
    pub damaged: RwSignal<BTreeMap<String, String>>,
    /// Every stored project.
    pub projects: RwSignal<Vec<ProjectSummary>>,
    /// The diagnostics of the last build.
    pub diagnostics: RwSignal<Vec<DiagView>>,
    /// The PROGRAMs of the last build that succeeded.
    pub programs: RwSignal<Vec<String>>,
    /// The POUs of the ST source written as a textual SFC (as of the last check).
    pub sfc_charts: RwSignal<Vec<String>>,
    /// The PROGRAM the simulator runs.
    pub running: RwSignal<Option<String>>,
    /// The simulator of the last project that built clean.
    pub sim: StoredValue<Option<Simulator>>,
    /// The simulator holds an older build than the project on the screen (which has errors
    /// since): the controls say so.
    pub stale: RwSignal<bool>,
    /// The user chose `Run the last version that built` (until the project builds again).
    pub run_old: RwSignal<bool>,
    /// The project changed since its last check (the editors check a moment after an
    /// edit; Run checks first when that moment has not come yet).
    check_pending: StoredValue<bool>,
    /// Bumped by every Step and Step N that scanned (the guided tour waits for one).
    pub steps_taken: RwSignal<u64>,
    /// The engine's checker and compiler are loaded (a chunk the page fetches as it starts:
    /// `crate::lazy::load_engine`); until then the panels say so.
    pub engine_ready: RwSignal<bool>,
    /// The page was opened by a share link whose project is being read (its reader is a
    /// chunk): the editor waits for it rather than show another project meanwhile.
    pub opening_shared: RwSignal<bool>,
    /// The stored project with diagram POUs being opened (by id): their models' readers
    /// are a chunk, and the editor waits for them. Another project opened meanwhile
    /// takes its place.
    pub opening_stored: RwSignal<Option<String>>,
    /// How many imported files and examples are being opened as new projects (each
    /// fetches its code, and an example its file, first): the editor says so, and a Run
    /// or Step pressed meanwhile is done on the project once it is open
    /// ([`AppState::opening_new_project`]).
    pub opening_new: RwSignal<u32>,
    /// Run or Step pressed while the engine was loading or a project opening: done once
    /// it is here.
    scan_when_ready: StoredValue<Option<ScanWish>>,
    /// The build the simulator comes from (to map its code back to ST lines, ladder cells
    /// and Petri net elements).
    pub sim_build: StoredValue<Option<ProjectBuild>>,
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
    /// The POU shown in the editor pane.
    pub view: RwSignal<PouView>,
    /// Declarations asked for from outside a ladder POU's view (the problem list's
    /// `Declare NAME`): (POU, section, name, type), queued; the view of that POU adds each
    /// to the declarations it has then, through its editor, so each is one undo step.
    pub ladder_declare: RwSignal<Vec<(String, &'static str, String, String)>>,
    /// Edits asked for from the problem list for a ladder POU (`Replace with NAME`):
    /// (POU, edit), queued; the view of that POU applies each through its editor, so each
    /// is one undo step.
    pub ladder_fix: RwSignal<Vec<(String, plc_core::ladder::LadderEdit)>>,
    /// A request to move the ST editor's cursor to (line, column).
    pub jump_to: RwSignal<Option<(u32, u32)>>,
    /// A quick fix of the ST source asked for from the problem list (`Replace with NAME`,
    /// `Declare NAME`): the new source and the byte offset for the caret, applied by the ST
    /// editor as one undo step.
    pub st_fix: RwSignal<Option<(String, usize)>>,
    /// A ladder cell or net element to point out in its view (a clicked problem).
    pub focus: RwSignal<Option<Site>>,
    /// The ST line of a runtime fault (marked in the editor).
    pub marked_line: RwSignal<Option<u32>>,
    /// Where a runtime fault happened (marked in the ladder and Petri net views).
    pub fault_site: RwSignal<Option<Site>>,
    /// The breakpoints (condition text, and its id when it compiled against the current
    /// program); the texts are kept in the project's settings.
    pub breakpoints: RwSignal<Vec<(String, Option<BreakpointId>)>>,
    /// ST lines of the active CASE branches of the last scan (marked in the editor).
    pub active_lines: RwSignal<Vec<u32>>,
    /// Active CASE branches in generated Petri net code: (POU, 1-based line of its code).
    pub active_generated: RwSignal<Vec<(String, u32)>>,
    /// The place map of the running PROGRAM when it is a Petri net POU.
    running_places: StoredValue<Option<PlaceMap>>,
    /// The scan count before the last scan and the marking then (Petri net POUs).
    pub marking_before_last: StoredValue<Option<(u64, Vec<u32>)>>,
    /// Virtual nanoseconds owed to the run loop but not yet scanned (less than one cycle).
    pending_ns: StoredValue<f64>,
    /// How many scans the run loop runs between clock readings (adapted to scan time).
    batch: StoredValue<u64>,
    /// Generation of the pending debounced check (see [`AppState::check_soon`]).
    check_generation: StoredValue<u64>,
    /// The recorded scan the page shows (`None`: the present).
    pub shown: RwSignal<Option<u64>>,
    /// That scan, rebuilt from the recording.
    shown_view: StoredValue<Option<ScanView>>,
    /// The recorded scan asked for and still being rebuilt.
    going_to: StoredValue<Option<u64>>,
    /// What the `Explanation` region explains (`None`: closed).
    pub why: RwSignal<Option<WhyQuery>>,
}

impl AppState {
    /// Creates the state: opens a shared project from the URL fragment if there is one
    /// (as a new project), else the most recent project, else a new one.
    pub fn new() -> Self {
        let state = AppState {
            project: RwSignal::new(Project::new(t(K::state_first_project))),
            project_id: RwSignal::new(None),
            project_rev: StoredValue::new(None),
            damaged: RwSignal::new(BTreeMap::new()),
            projects: RwSignal::new(Vec::new()),
            diagnostics: RwSignal::new(Vec::new()),
            programs: RwSignal::new(Vec::new()),
            sfc_charts: RwSignal::new(Vec::new()),
            running: RwSignal::new(None),
            sim: StoredValue::new(None),
            stale: RwSignal::new(false),
            run_old: RwSignal::new(false),
            check_pending: StoredValue::new(false),
            steps_taken: RwSignal::new(0),
            engine_ready: RwSignal::new(crate::lazy::engine().is_some()),
            opening_shared: RwSignal::new(false),
            opening_stored: RwSignal::new(None),
            opening_new: RwSignal::new(0),
            scan_when_ready: StoredValue::new(None),
            sim_build: StoredValue::new(None),
            sim_version: RwSignal::new(0),
            run_mode: RwSignal::new(RunMode::Stopped),
            speed: RwSignal::new(Speed::RealTime),
            held: RwSignal::new(BTreeMap::new()),
            notice: RwSignal::new(None),
            view: RwSignal::new(PouView::St),
            ladder_declare: RwSignal::new(Vec::new()),
            ladder_fix: RwSignal::new(Vec::new()),
            jump_to: RwSignal::new(None),
            st_fix: RwSignal::new(None),
            focus: RwSignal::new(None),
            marked_line: RwSignal::new(None),
            fault_site: RwSignal::new(None),
            breakpoints: RwSignal::new(Vec::new()),
            active_lines: RwSignal::new(Vec::new()),
            active_generated: RwSignal::new(Vec::new()),
            running_places: StoredValue::new(None),
            marking_before_last: StoredValue::new(None),
            pending_ns: StoredValue::new(0.0),
            batch: StoredValue::new(1),
            check_generation: StoredValue::new(0),
            shown: RwSignal::new(None),
            shown_view: StoredValue::new(None),
            going_to: StoredValue::new(None),
            why: RwSignal::new(None),
        };
        state.open_initial_project();
        state.watch_other_tabs();
        state
    }

    /// Checks and saves the project a moment after the last call (the diagram editors call
    /// it after every edit, as the ST editor checks after a pause in typing).
    pub fn check_soon(&self) {
        self.check_pending.set_value(true);
        self.check_generation.update_value(|g| *g += 1);
        let generation = self.check_generation.get_value();
        let state = *self;
        set_timeout(
            move || {
                if state.check_generation.try_get_value() == Some(generation) {
                    // Run may have checked the edit already (a check restarts the PLC).
                    state.check_if_pending();
                    state.save();
                }
            },
            CHECK_DELAY,
        );
    }

    /// Shows an error in the banner.
    pub fn error(&self, text: impl Into<String>) {
        self.notice.set(Some(Notice {
            error: true,
            text: text.into(),
            site: None,
            actions: vec![],
        }));
    }

    /// Shows information in the banner.
    pub fn info(&self, text: impl Into<String>) {
        self.notice.set(Some(Notice {
            error: false,
            text: text.into(),
            site: None,
            actions: vec![],
        }));
    }

    /// Everything that belongs to the previous project is forgotten.
    fn forget_run(&self) {
        self.held.set(BTreeMap::new());
        self.run_mode.set(RunMode::Stopped);
        self.sim.set_value(None);
        self.stale.set(false);
        self.run_old.set(false);
        self.sim_build.set_value(None);
        self.forget_past();
        self.why.set(None);
        self.running_places.set_value(None);
        self.running.set(None);
        self.programs.set(Vec::new());
        self.marked_line.set(None);
        self.fault_site.set(None);
        self.focus.set(None);
        self.bump();
    }

    /// Replaces the source text (from the editor). The caller debounces checks and saves.
    pub fn set_source(&self, text: String) {
        self.check_pending.set_value(true);
        self.project.update(|p| p.source = text);
    }

    /// Shows the place a diagnostic, fault or notice is about: the ST line in the editor,
    /// the ladder cell or the net element in its view.
    pub fn reveal(&self, site: &Site) {
        match site {
            Site::Project => {}
            Site::St { line, column, .. } => {
                self.view.set(PouView::St);
                self.jump_to.set(Some((*line, *column)));
            }
            Site::Network { pou, .. } => {
                self.view.set(PouView::Network(pou.clone()));
                self.focus.set(Some(site.clone()));
            }
            Site::Declarations { pou, .. }
                if self.project.with_untracked(|p| p.networks.iter().any(|n| &n.name == pou)) =>
            {
                self.view.set(PouView::Network(pou.clone()));
                self.focus.set(Some(site.clone()));
            }
            Site::Ladder { pou, .. } | Site::Declarations { pou, .. } => {
                self.view.set(PouView::Ladder(pou.clone()));
                self.focus.set(Some(site.clone()));
            }
            Site::Petri { pou, .. } => {
                self.view.set(PouView::Petri(pou.clone()));
                self.focus.set(Some(site.clone()));
            }
        }
    }

    /// Adds a breakpoint on an ST condition (kept in the project).
    pub fn add_breakpoint(&self, condition: &str) -> Result<(), String> {
        let condition = condition.trim();
        if condition.is_empty() {
            return Err(t(K::state_breakpoint_empty).to_string());
        }
        let id = match self
            .with_sim_mut(|s| crate::lazy::engine().map(|e| (e.add_breakpoint)(s, condition)))
        {
            None | Some(None) => return Err(t(K::state_breakpoint_errors).to_string()),
            Some(Some(Err(e))) => return Err(e.to_string()),
            Some(Some(Ok(id))) => id,
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
        self.with_sim_mut(|s| check::trace_paths(s, &paths));
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
        let (state, name, literal) = (*self, name.to_string(), literal.to_string());
        self.leave_past_then(move || {
            if let Some(Err(e)) = state.with_sim_mut(|s| {
                crate::lazy::engine().map_or(Ok(()), |e| (e.hold)(s, &name, &literal))
            }) {
                state.error(e.to_string());
            }
        });
    }

    /// Sets the cycle time in milliseconds (kept in the project).
    pub fn set_cycle_ms(&self, ms: u64) {
        match plc_core::limits::cycle_ns(ms) {
            Ok(ns) => {
                self.project.update(|p| p.settings.cycle_ms = ms);
                self.with_sim_mut(|s| s.set_cycle_ns(ns));
                self.save();
            }
            Err(said) => {
                let message = crate::i18n::message_text(&said.message, None, &said.english);
                self.error(tf(K::state_cycle_unchanged, &[("message", &message)]))
            }
        }
    }
}
