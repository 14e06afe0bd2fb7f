//! Exercises in the page: the catalogue of shipped exercises, opening one (shipped, from an
//! address `?exercise=URL`, or from a `#x=…` link) with the attempt the student saved or
//! the starter, checking an attempt, and the report. The exercise worker
//! (`src/workers/exercise.rs`) reads the files and grades; the page keeps what it shows.

mod catalogue;
mod handin;
mod panel;
pub mod protocol;
pub mod report;
pub(crate) mod scorm;
mod store;

use std::collections::BTreeSet;

use leptos::prelude::*;
use plc_core::exercise::{graded_program, next_to, ExerciseLink, Language, LinkedFile, Report};
use plc_core::project::Project;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_futures::JsFuture;

use crate::i18n::{t, tf, K};
use crate::lazy::LoadFailed;
use crate::state::{clear_fragment, AppState};
pub use catalogue::Catalogue;
use handin::HandInActions;
pub use panel::ExercisePanel;
use protocol::{Opened, Reply, Request};

mod list {
    include!(concat!(env!("OUT_DIR"), "/exercises.rs"));
}

/// The exercise worker's name (`src/workers/mod.rs`).
const WORKER: &str = "exercise";

/// What the page's main area shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Screen {
    /// The editors and the simulator.
    Workspace,
    /// The exercise catalogue.
    Catalogue,
}

/// One shipped exercise of the catalogue.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// Its id.
    pub id: &'static str,
    /// Its title.
    pub title: &'static str,
    /// 1 … 5.
    pub level: u8,
    /// `st`, `ld`, `petri`, `sfc`.
    pub languages: &'static [&'static str],
}

/// The shipped exercises, easiest first.
pub fn catalogue() -> Vec<Entry> {
    list::CATALOGUE
        .iter()
        .map(|&(id, title, level, languages)| Entry { id, title, level, languages })
        .collect()
}

/// A language's name for people.
pub fn language_name(code: &str) -> &str {
    match code {
        "st" => "ST",
        "ld" => t(K::exercise_lang_ladder),
        "petri" => t(K::exercise_lang_petri),
        "sfc" => "SFC",
        other => other,
    }
}

/// A starter's language for people (`Start in`; empty when unknown).
pub fn starter_language_name(code: &str) -> &'static str {
    match code {
        "st" => t(K::exercise_lang_st),
        "ld" => t(K::exercise_lang_ladder),
        "petri" => t(K::exercise_lang_petri),
        "sfc" => "SFC",
        _ => "",
    }
}

/// The exercise open in the page.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenExercise {
    /// What the worker gave.
    pub opened: Opened,
}

/// The exercises' state, shared by the header, the catalogue and the exercise panel.
#[derive(Clone, Copy)]
pub struct Exercises {
    /// What the main area shows.
    pub screen: RwSignal<Screen>,
    /// The exercise whose attempt is the open project.
    pub open: RwSignal<Option<OpenExercise>>,
    /// The last check's report (for the open exercise).
    pub report: RwSignal<Option<Report>>,
    /// A check is running.
    pub checking: RwSignal<bool>,
    /// The ids of the exercises passed (the catalogue's ticks, read when it is shown).
    pub passed: RwSignal<BTreeSet<String>>,
    /// The link of the open exercise, once `Share exercise` made it.
    pub share_link: RwSignal<Option<String>>,
}

impl Exercises {
    /// The state; opens the exercise of the address (`?exercise=URL` or `#x=…`) if any,
    /// and follows the open project: an attempt shows its exercise.
    pub fn new(state: AppState) -> Self {
        let ex = Exercises {
            screen: RwSignal::new(Screen::Workspace),
            open: RwSignal::new(None),
            report: RwSignal::new(None),
            checking: RwSignal::new(false),
            passed: RwSignal::new(BTreeSet::new()),
            share_link: RwSignal::new(None),
        };
        let location = web_sys::window().map(|w| w.location());
        let hash = location.as_ref().and_then(|l| l.hash().ok()).unwrap_or_default();
        let search = location.as_ref().and_then(|l| l.search().ok()).unwrap_or_default();
        if let Some(fragment) = hash.strip_prefix('#').filter(|h| h.starts_with("x=")) {
            let fragment = fragment.to_string();
            clear_fragment();
            leptos::task::spawn_local(async move {
                ex.open_lazily(state, OpenHow::Link(fragment)).await;
            });
        } else if let Some(url) = query_param(&search, "exercise") {
            // Launched by an LMS (a SCORM package): report to it (the SCORM runtime is a
            // chunk of its own, fetched only then).
            let scorm = query_param(&search, "scorm").as_deref() == Some("1");
            leptos::task::spawn_local(async move {
                let lms = scorm && crate::lazy::scorm_launch(ex, state).await.unwrap_or(false);
                ex.open_lazily(state, OpenHow::Url(url)).await;
                if lms {
                    let _ = crate::lazy::scorm_resume(ex, state).await;
                }
            });
        }
        // The open project decides which exercise the panel shows.
        Effect::new(move |_| {
            let project_id = state.project_id.get();
            let exercise = project_id.as_deref().and_then(store::exercise_of);
            let shown = ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.id.clone()));
            if exercise == shown {
                return;
            }
            ex.report.set(None);
            ex.share_link.set(None);
            match exercise {
                None => ex.open.set(None),
                // Asking the worker again is code of the exercise chunk, fetched only for a
                // project that is an attempt.
                Some(id) => leptos::task::spawn_local(async move {
                    ex.open_lazily(state, OpenHow::Reattach(id)).await
                }),
            }
        });
        ex
    }

    /// Opens a shipped exercise (from the catalogue).
    pub fn open_shipped(self, state: AppState, id: &str) {
        let id = id.to_string();
        leptos::task::spawn_local(async move {
            self.open_lazily(state, OpenHow::Shipped(id)).await;
        });
    }

    /// Opens an exercise with the code that does it, a chunk fetched the first time
    /// (`lazy::open_exercise`): the first screen does not carry it.
    async fn open_lazily(self, state: AppState, how: OpenHow) {
        match crate::lazy::open_exercise(self, state, how).await {
            Ok(opening) => opening.await,
            Err(_) => state.error(t(K::lazy_failed_exercise)),
        }
    }

    /// Opens the exercise `how` names (in the `exercise_ui` chunk).
    pub(crate) async fn open_how(self, state: AppState, how: OpenHow) {
        match how {
            OpenHow::Shipped(id) => self.open_with(state, Request::Shipped(id), None).await,
            OpenHow::Link(fragment) => self.open_with(state, Request::Link(fragment), None).await,
            OpenHow::Url(url) => self.open_url(state, &url).await,
            OpenHow::Reattach(id) => self.reattach(state, &id).await,
        }
    }

    /// Fetches the exercise file at `url` (and its starter next to it) and opens it.
    async fn open_url(self, state: AppState, url: &str) {
        let text = match fetch_text(url).await {
            Ok(t) => t,
            Err(e) => {
                state.error(tf(K::exercise_load_failed, &[("url", url), ("error", &e)]));
                return;
            }
        };
        let link = ExerciseLink { exercise: text, starter: None, starters: Vec::new() };
        self.open_with(state, Request::File { link, base: Some(url.to_string()) }, Some(url)).await;
    }

    /// Asks the worker to open an exercise, fetching its starter next to `base` when it
    /// names one, then opens the student's attempt at it (or a new one from the starter).
    async fn open_with(self, state: AppState, request: Request, base: Option<&str>) {
        let mut opened = match ask(&request).await {
            Ok(Reply::Opened(o)) => *o,
            Err(e) => {
                state.error(tf(K::exercise_open_failed, &[("error", &e)]));
                return;
            }
            Ok(_) => return,
        };
        if let (false, Some(base)) = (opened.missing.is_empty(), base) {
            let mut files = Vec::new();
            for name in opened.missing.clone() {
                let url = next_to(base, &name);
                match fetch_text(&url).await {
                    Ok(text) => files.push(LinkedFile { name, text }),
                    Err(e) => {
                        state.error(tf(
                            K::exercise_starter_load_failed,
                            &[("url", &url), ("error", &e)],
                        ));
                        return;
                    }
                }
            }
            let mut link = opened.link.clone();
            link.starters.extend(files);
            opened = match ask(&Request::File { link, base: Some(base.to_string()) }).await {
                Ok(Reply::Opened(o)) => *o,
                Err(e) => {
                    state.error(tf(K::exercise_open_failed, &[("error", &e)]));
                    return;
                }
                Ok(_) => return,
            };
        }
        // A starter with diagram POUs is read with their models' readers (a chunk).
        for starter in &opened.starters {
            if let Err(e) = crate::lazy::readers_for(&starter.project).await {
                state.error(tf(K::exercise_open_failed, &[("error", &e.to_string())]));
                return;
            }
        }
        let shipped = matches!(request, Request::Shipped(_));
        self.attach(state, opened, shipped);
    }

    /// Opens the attempt at `opened` (the stored one, else a new project from the starter)
    /// and shows the exercise beside it.
    fn attach(self, state: AppState, opened: Opened, shipped: bool) {
        let id = opened.view.id.clone();
        let title = opened.view.title_in(crate::i18n::shown_lang()).to_string();
        if !shipped {
            store::keep_source(
                &id,
                &store::KeptSource { link: opened.link.clone(), base: opened.base.clone() },
            );
        }
        let existing = store::attempts()
            .get(&id)
            .cloned()
            .filter(|pid| state.projects.with_untracked(|ps| ps.iter().any(|p| &p.id == pid)));
        self.open.set(Some(OpenExercise { opened: opened.clone() }));
        self.report.set(None);
        self.share_link.set(None);
        self.screen.set(Screen::Workspace);
        match existing {
            Some(pid) => {
                if state.project_id.get_untracked().as_deref() != Some(pid.as_str()) {
                    state.open(&pid);
                }
                state.info(tf(K::exercise_attempt_open, &[("title", &title)]));
            }
            None => {
                let Some(project) = starter_project(&opened, None) else {
                    state.error(t(K::exercise_starter_broken));
                    return;
                };
                state.add_and_open(project);
                if let Some(pid) = state.project_id.get_untracked() {
                    store::set_attempt(&id, &pid);
                }
                state.info(tf(K::exercise_attempt_new, &[("title", &title)]));
            }
        }
    }

    /// Shows the exercise of an attempt opened from the project menu (or at start).
    async fn reattach(self, state: AppState, id: &str) {
        let request = match store::kept_source(id) {
            Some(kept) => Request::File { link: kept.link, base: kept.base },
            None => Request::Shipped(id.to_string()),
        };
        let reply = ask(&request).await;
        // Another project may have been opened meanwhile.
        let current = state.project_id.get_untracked().as_deref().and_then(store::exercise_of);
        if current.as_deref() != Some(id) {
            return;
        }
        match reply {
            Ok(Reply::Opened(o)) => self.open.set(Some(OpenExercise { opened: *o })),
            _ => self.open.set(None),
        }
    }

    /// Grades the open project against the open exercise; a pass ticks it in the
    /// catalogue.
    pub fn check(self, state: AppState) {
        let Some(open) = self.open.get_untracked() else { return };
        if self.checking.get_untracked() {
            return;
        }
        self.checking.set(true);
        let project = state.project.with_untracked(Project::to_file);
        let request = Request::Grade { exercise: open.opened.link.exercise.clone(), project };
        leptos::task::spawn_local(async move {
            let reply = ask(&request).await;
            self.checking.set(false);
            match reply {
                Ok(Reply::Graded(text)) => {
                    let read = crate::lazy::read_report(text).await;
                    let report = match read.map_err(|e| e.to_string()).and_then(|r| r) {
                        Ok(report) => report,
                        Err(e) => {
                            return state.error(tf(K::exercise_check_failed, &[("error", &e)]))
                        }
                    };
                    if report.error.is_none() && report.score == report.total {
                        self.passed.set(store::mark_passed(&open.opened.view.id));
                    }
                    if scorm::in_session() {
                        // The SCORM chunk is here already: the session's launch fetched it.
                        let (id, graded) = (open.opened.view.id.clone(), report.clone());
                        if let Err(e) = crate::lazy::scorm_report(state, id, graded).await {
                            state.error(e.to_string());
                        }
                    }
                    self.report.set(Some(report));
                }
                Err(e) => state.error(tf(K::exercise_check_failed, &[("error", &e)])),
                Ok(_) => {}
            }
        });
    }

    /// Replaces the attempt by the starter in the language it is written in (after
    /// asking).
    pub fn reset_to_starter(self, state: AppState) {
        let Some(open) = self.open.get_untracked() else { return };
        let question = tf(
            K::exercise_reset_confirm,
            &[("title", open.opened.view.title_in(crate::i18n::shown_lang()))],
        );
        if !confirm(&question) {
            return;
        }
        let language = self.attempt_language(state);
        match starter_project(&open.opened, language.as_deref()) {
            Some(project) => {
                state.replace_contents(project);
                self.report.set(None);
                state.info(t(K::exercise_reset_done));
            }
            None => state.error(t(K::exercise_starter_broken)),
        }
    }

    /// The language the attempt is written in: that of the PROGRAM it checks, when the
    /// exercise offers a starter in it.
    pub fn attempt_language(self, state: AppState) -> Option<String> {
        self.open.with(|open| {
            let opened = &open.as_ref()?.opened;
            let (preferred, plant) = (opened.view.program.as_deref(), opened.view.plant.as_deref());
            let program = state.project.with(|p| graded_program(p, preferred, plant))?;
            let code = Language::of_program(program.language)?.code();
            opened.starters.iter().any(|s| s.language == code).then(|| code.to_string())
        })
    }

    /// Starts the attempt again in another language (`Start in`): its starter replaces
    /// the attempt, at once when the attempt is still a starter, else after asking. False
    /// when the student kept their work.
    pub fn start_in(self, state: AppState, code: &str) -> bool {
        let Some(open) = self.open.get_untracked() else { return false };
        let Some(project) = starter_project(&open.opened, Some(code)) else {
            state.error(t(K::exercise_starter_broken));
            return false;
        };
        let name = match starter_language_name(code) {
            "" => code.to_string(),
            known => known.to_string(),
        };

        // The work in a project: its POUs, whatever its name and settings.
        let work = |p: &Project| {
            let mut p = p.clone();
            p.name.clear();
            p.settings = Default::default();
            p.source = p.source.trim().to_string();
            p.to_file()
        };
        let current = state.project.with_untracked(work);
        let untouched = open
            .opened
            .starters
            .iter()
            .filter_map(|s| crate::lazy::project_reader()(&s.project).ok())
            .any(|s| work(&s) == current);
        if !untouched {
            let question = tf(
                K::exercise_start_in_confirm,
                &[
                    ("title", open.opened.view.title_in(crate::i18n::shown_lang())),
                    ("language", &name),
                ],
            );
            if !confirm(&question) {
                return false;
            }
        }
        state.replace_contents(project);
        self.report.set(None);
        state.info(tf(K::exercise_started_in, &[("language", &name)]));
        true
    }

    /// The link that carries the open exercise (its DEFLATE writer is a chunk, fetched
    /// now: `Err` when it cannot be).
    pub async fn link(self) -> Option<Result<String, LoadFailed>> {
        let open = self.open.get_untracked()?;
        let base = web_sys::window()
            .and_then(|w| w.location().href().ok())
            .map(|h| h.split('#').next().unwrap_or_default().to_string())
            .unwrap_or_default();
        // The `?exercise=` query would open the file at that address instead.
        let base = base.split('?').next().unwrap_or_default().to_string();
        let fragment = crate::lazy::exercise_fragment(open.opened.link).await;
        Some(fragment.map(|fragment| format!("{base}#{fragment}")))
    }
}

/// The starter of an opened exercise in `language` (its first language by default) as a
/// new project named after it.
fn starter_project(opened: &Opened, language: Option<&str>) -> Option<Project> {
    let starter = match language {
        Some(code) => opened.starters.iter().find(|s| s.language == code)?,
        None => opened.starters.first()?,
    };
    let mut project = crate::lazy::project_reader()(&starter.project).ok()?;
    project.name =
        tf(K::exercise_project_name, &[("title", opened.view.title_in(crate::i18n::shown_lang()))]);
    Some(project)
}

/// Asks the student (a browser dialog); false when they decline or it cannot be shown.
fn confirm(question: &str) -> bool {
    web_sys::window().and_then(|w| w.confirm_with_message(question).ok()).unwrap_or(false)
}

/// Sends one request to a fresh exercise worker; its `Error` worded in the language shown.
async fn ask(request: &Request) -> Result<Reply, String> {
    let text = serde_json::to_string(request).map_err(|e| e.to_string())?;
    let answer = crate::import::ask_worker_at(WORKER, &JsValue::from_str(&text)).await?;
    match crate::lazy::read_exercise_reply(answer).await.map_err(|e| e.to_string())? {
        Some(Reply::Error(failure)) => Err(failure.text()),
        Some(reply) => Ok(reply),
        None => Err(t(K::exercise_worker_no_answer).to_string()),
    }
}

/// Which exercise to open.
pub enum OpenHow {
    /// A shipped exercise, by its id.
    Shipped(String),
    /// The exercise a share link's fragment (`x=…`) carries.
    Link(String),
    /// The exercise file at an address (`?exercise=URL`).
    Url(String),
    /// The exercise of the project opened (an attempt), by its id: shown again without
    /// opening a new attempt.
    Reattach(String),
}

/// The text at `url` (a CORS fetch).
pub(crate) async fn fetch_text(url: &str) -> Result<String, String> {
    let window = web_sys::window().ok_or("no window")?;
    let failed = |_| t(K::exercise_unreachable).to_string();
    let response: web_sys::Response = JsFuture::from(window.fetch_with_str(url))
        .await
        .map_err(failed)?
        .dyn_into()
        .map_err(|_| t(K::exercise_no_response).to_string())?;
    if !response.ok() {
        return Err(format!("HTTP {}", response.status()));
    }
    let text = JsFuture::from(response.text().map_err(failed)?).await.map_err(failed)?;
    text.as_string().ok_or_else(|| t(K::exercise_not_text).to_string())
}

/// A query parameter's decoded value (`?exercise=https%3A%2F%2F…`).
pub(crate) fn query_param(search: &str, name: &str) -> Option<String> {
    let query = search.strip_prefix('?').unwrap_or(search);
    query.split('&').find_map(|pair| {
        let (key, value) = pair.split_once('=')?;
        (key == name).then(|| {
            js_sys::decode_uri_component(&value.replace('+', " ")).ok().map(String::from)
        })?
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses_next_to_the_file() {
        assert_eq!(
            next_to("https://h.example/c/latch.toml?v=1", "starter.st"),
            "https://h.example/c/starter.st"
        );
        assert_eq!(next_to("latch.toml", "starter.st"), "starter.st");
    }

    #[test]
    fn the_catalogue_lists_the_shipped_exercises_easiest_first() {
        let all = catalogue();
        assert!(all.iter().any(|e| e.id == "latch"));
        assert!(all.windows(2).all(|w| w[0].level <= w[1].level));
        // Level 1 in the order it teaches (`order` in each file), not by title.
        let first: Vec<&str> = all.iter().take(5).map(|e| e.id).collect();
        assert_eq!(first, ["lamp", "two-switches", "nc-stop", "latch", "ton-delay"]);
    }
}
