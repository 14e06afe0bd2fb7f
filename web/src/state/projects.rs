//! The stored projects: opening, saving, adding and deleting them through the core's
//! [`ProjectStore`], so that no failure of the browser's storage loses a project.
//!
//! - A project that could not be stored stays open *unsaved* (`project_id` is `None`)
//!   with an Export button; it is never saved over the project open before it, and the
//!   next save tries to store it again as a new project.
//! - Saves name the revision they started from: a change made in another tab is never
//!   overwritten; the user chooses (another tab's change is also noticed at once through
//!   the `storage` event).
//! - Damaged projects are listed, never opened or overwritten, and can be downloaded or
//!   deleted. A damaged index is rebuilt from the projects found.
//! - A mark is kept in storage while a project or share link is being opened: a page that
//!   stopped while opening one does not open it again on reload.

use leptos::prelude::*;
use plc_core::project::{Project, ProjectError, ProjectStore, StoreError};
use wasm_bindgen::closure::Closure;
use wasm_bindgen::JsCast;

use super::{AppState, Notice, NoticeAction};
use crate::download::download;
use crate::i18n::{said_text, t, tf, K};
use crate::storage::LocalStorage;

/// How long a project must have been open before its opening counts as finished.
const OPENING_SETTLES: std::time::Duration = std::time::Duration::from_secs(3);

/// Set by the panic hook: the page stopped, so leaving it must not count as a clean exit.
static PANICKED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Whether the page stopped: a panic the hook saw, or a trap of the wasm module (the release
/// build's panics trap without a hook; web/boot.js marks `plcStopped`).
fn stopped() -> bool {
    PANICKED.load(std::sync::atomic::Ordering::SeqCst)
        || js_sys::Reflect::get(&js_sys::global(), &"plcStopped".into())
            .is_ok_and(|v| v.is_truthy())
}

/// Notes that the app panicked (called from the panic hook before the instance stops).
pub fn note_panic() {
    PANICKED.store(true, std::sync::atomic::Ordering::SeqCst);
}

fn now_ms() -> u64 {
    js_sys::Date::now() as u64
}

fn store() -> ProjectStore<LocalStorage> {
    ProjectStore::with_reader(LocalStorage::open(), crate::lazy::project_reader())
}

/// A file name for a project: its name without characters file systems refuse.
pub fn project_file_name(name: &str) -> String {
    let clean: String = name
        .trim()
        .chars()
        .map(|c| if c.is_control() || "/\\:*?\"<>|".contains(c) { '_' } else { c })
        .collect();
    let clean = if clean.is_empty() { "project".to_string() } else { clean };
    format!("{clean}.plcproj.json")
}

/// The mark left while a share link is being opened: `share:` and a digest of the link.
fn share_mark(fragment: &str) -> String {
    // FNV-1a: stable across builds and enough to tell links apart.
    let hash = fragment
        .bytes()
        .fold(0xcbf2_9ce4_8422_2325_u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3));
    format!("share:{hash:016x}")
}

impl AppState {
    /// Shows a problem with buttons for what the user can do about it.
    pub fn error_with(&self, text: impl Into<String>, actions: Vec<NoticeAction>) {
        self.notice.set(Some(Notice { error: true, text: text.into(), site: None, actions }));
    }

    pub(super) fn refresh_list(&self) {
        let store = store();
        match store.list() {
            Ok(list) => self.projects.set(list),
            Err(e) => self.error(said_text(e.said())),
        }
        let mut damaged = std::collections::BTreeMap::new();
        for (id, reason) in store.damaged_said().unwrap_or_default() {
            damaged.insert(id, said_text(reason));
        }
        self.damaged.set(damaged);
    }

    /// Opens what the page starts with: a share link in the URL fragment (as a new
    /// project), else the most recent project that opens, else a new one.
    pub(super) fn open_initial_project(&self) {
        let mut store = store();
        let interrupted = store.interrupted_opening().ok().flatten();
        let _ = store.clear_opening();
        let hash = web_sys::window().and_then(|w| w.location().hash().ok()).unwrap_or_default();
        if hash.starts_with("#p=") {
            if interrupted.as_deref() == Some(share_mark(&hash).as_str()) {
                clear_fragment();
                self.error_with(t(K::state_shared_stopped), vec![NoticeAction::OpenShared(hash)]);
            } else {
                // The link's reader (base64 and DEFLATE) is a chunk fetched only for links.
                let state = *self;
                state.opening_shared.set(true);
                leptos::task::spawn_local(async move {
                    if !state.open_shared(&hash).await {
                        state.open_most_recent(interrupted);
                    }
                    state.opening_shared.set(false);
                    state.scan_wished();
                });
                return;
            }
        }
        self.open_most_recent(interrupted);
    }

    /// Opens the most recent project that opens (not the one whose opening stopped the
    /// page last time, `interrupted`), else a new one.
    fn open_most_recent(&self, interrupted: Option<String>) {
        let store = store();
        self.refresh_list();
        let damage = store.index_damage_said().ok().flatten().map(said_text);
        let damaged = self.damaged.get_untracked();
        let projects = self.projects.get_untracked();
        let first = projects.iter().find(|p| {
            !damaged.contains_key(&p.id) && interrupted.as_deref() != Some(p.id.as_str())
        });
        match first.map(|p| p.id.clone()) {
            Some(id) => self.open(&id),
            None => {
                self.add_and_open(Project::new(t(K::state_first_project)));
            }
        }
        // Say why the most recent project is not the one open.
        if let Some(skipped) = projects.first().filter(|p| first.is_none_or(|f| f.id != p.id)) {
            if let Some(reason) = damaged.get(&skipped.id) {
                self.error_with(
                    tf(K::state_cannot_open_kept, &[("name", &skipped.name), ("reason", reason)]),
                    vec![
                        NoticeAction::DownloadDamaged(skipped.id.clone()),
                        NoticeAction::DeleteDamaged(skipped.id.clone()),
                    ],
                );
            } else if interrupted.as_deref() == Some(skipped.id.as_str()) {
                self.error(tf(K::state_stopped_page, &[("name", &skipped.name)]));
            }
        }
        if let Some(message) = damage {
            self.error(message);
        }
    }

    /// Opens the shared project in `fragment` as a new project; false when the link is
    /// unusable (the most recent project opens instead).
    async fn open_shared(&self, fragment: &str) -> bool {
        let decoded = match crate::lazy::read_share(fragment.to_string()).await {
            Ok(decoded) => decoded,
            Err(e) => {
                self.error(tf(K::state_shared_failed, &[("error", &e.to_string())]));
                return false;
            }
        };
        let project = match decoded {
            Ok(project) => project,
            Err(e) => {
                clear_fragment();
                self.error(tf(K::state_shared_unusable, &[("error", &said_text(e.said()))]));
                return false;
            }
        };
        let mut store = store();
        let _ = store.mark_opening(&share_mark(fragment));
        let name = project.name.clone();
        match self.open_as_new(project) {
            Ok(()) => {
                clear_fragment();
                self.info(tf(K::state_shared_opened, &[("name", &name)]));
            }
            // Not stored: the link stays in the address bar so that nothing is lost.
            Err(e) => self.error_with(
                tf(K::state_shared_not_saved, &[("name", &name), ("error", &said_text(e.said()))]),
                vec![NoticeAction::Export],
            ),
        }
        self.settle_opening();
        true
    }

    /// Removes the opening mark once the page has kept running for a while after the
    /// project was checked (the check waits for the engine's chunk, which on a slow network
    /// may come later than that while).
    fn settle_opening(&self) {
        let state = *self;
        set_timeout(
            move || match state.engine_ready.try_get_untracked() {
                _ if stopped() => {}
                Some(false) => state.settle_opening(),
                _ => {
                    let _ = store().clear_opening();
                }
            },
            OPENING_SETTLES,
        );
    }

    /// Opens `project` and stores it as a new project (checked before it is stored, so a
    /// project that stops the page is never stored; before the engine is here it is
    /// stored first and checked when the engine comes). Returns whether it was stored; when
    /// not, it stays open unsaved and the banner says why, with an Export button.
    pub fn add_and_open(&self, project: Project) -> bool {
        let name = project.name.clone();
        match self.open_as_new(project) {
            Ok(()) => true,
            Err(e) => {
                self.error_with(
                    tf(
                        K::state_open_not_saved,
                        &[("name", &name), ("error", &said_text(e.said()))],
                    ),
                    vec![NoticeAction::Export],
                );
                false
            }
        }
    }

    /// An imported file or an example starts opening as a new project (its code, and an
    /// example's file, are fetched first): called in the gesture's handler, and
    /// [`AppState::opened_new_project`] when it is open or could not be. Meanwhile the
    /// editor says `Opening the project…` and a Run or Step pressed waits for it.
    pub fn opening_new_project(&self) {
        self.opening_new.update(|n| *n += 1);
    }

    /// An opening begun by [`AppState::opening_new_project`] is over: when it was the last,
    /// a Run or Step pressed meanwhile is done on the project now open.
    pub fn opened_new_project(&self) {
        self.opening_new.update(|n| *n = n.saturating_sub(1));
        if self.opening_new.get_untracked() == 0 {
            self.scan_wished();
        }
    }

    /// Opens `project`, checks it, then stores it as a new project. When storing fails
    /// it stays open with no id, so no later save can write it over another project.
    fn open_as_new(&self, project: Project) -> Result<(), StoreError> {
        self.opening_stored.set(None);
        self.project.set(project.clone());
        self.project_id.set(None);
        self.project_rev.set_value(None);
        self.forget_run();
        self.check_now();
        self.show_main_view();
        let stored = store().add(&project, now_ms());
        if let Ok((id, rev)) = &stored {
            self.project_id.set(Some(id.clone()));
            self.project_rev.set_value(Some(*rev));
        }
        self.refresh_list();
        stored.map(|_| ())
    }

    /// Opens a stored project; a damaged one is not opened and the banner offers to
    /// download or delete it.
    pub fn open(&self, id: &str) {
        let mut store = store();
        match store.open(id) {
            Ok(opened) => {
                let _ = store.mark_opening(id);
                // A stored project still waiting for its readers does not open over this.
                self.opening_stored.set(None);
                self.project.set(opened.project);
                self.project_id.set(Some(id.to_string()));
                self.project_rev.set_value(Some(opened.rev));
                self.forget_run();
                self.check_now();
                self.show_main_view();
                self.settle_opening();
            }
            // Its diagram POUs' readers are a chunk, fetched the first time: the editor
            // says `Opening the project…` until then.
            Err(StoreError::Damaged(ProjectError::NeedsDiagramReaders)) => {
                let (state, id) = (*self, id.to_string());
                self.opening_stored.set(Some(id.clone()));
                // The engine comes meanwhile (nothing is checked until the project opens).
                leptos::task::spawn_local(async move {
                    if !state.engine_arrived().await {
                        state.error(t(K::lazy_failed_checker));
                    }
                });
                leptos::task::spawn_local(async move {
                    let loaded = crate::lazy::load_project_reader().await;
                    if state.opening_stored.get_untracked().as_deref() != Some(id.as_str()) {
                        // Another project was opened meanwhile: it stays.
                        return;
                    }
                    state.opening_stored.set(None);
                    if loaded.is_ok() {
                        // Projects with diagram POUs are looked at for damage now too.
                        state.refresh_list();
                        state.open(&id);
                    } else {
                        let name = state.name_of(&id);
                        let reason = said_text(ProjectError::NeedsDiagramReaders.said());
                        state.error_with(
                            tf(K::state_cannot_open_kept, &[("name", &name), ("reason", &reason)]),
                            vec![NoticeAction::OpenStored(id)],
                        );
                    }
                });
            }
            Err(StoreError::Damaged(e)) => {
                let name = self.name_of(id);
                self.error_with(
                    tf(
                        K::state_cannot_open_kept,
                        &[("name", &name), ("reason", &said_text(e.said()))],
                    ),
                    vec![
                        NoticeAction::DownloadDamaged(id.to_string()),
                        NoticeAction::DeleteDamaged(id.to_string()),
                    ],
                );
                // The list still shows the project that is open.
                self.project_id.update(|_| {});
            }
            Err(e) => self.error(said_text(e.said())),
        }
    }

    fn name_of(&self, id: &str) -> String {
        self.projects.with_untracked(|ps| {
            ps.iter().find(|p| p.id == id).map_or_else(|| id.to_string(), |p| p.name.clone())
        })
    }

    /// Saves the open project now: over the revision it was opened at, or as a new
    /// project when it is not stored yet.
    pub fn save(&self) {
        let project = self.project.get_untracked();
        let Some(id) = self.project_id.get_untracked() else {
            match store().add(&project, now_ms()) {
                Ok((id, rev)) => {
                    self.project_id.set(Some(id));
                    self.project_rev.set_value(Some(rev));
                    self.refresh_list();
                    self.info(tf(K::state_saved_now, &[("name", &project.name)]));
                }
                Err(e) => self.error_with(
                    tf(K::state_not_saved, &[("error", &said_text(e.said()))]),
                    vec![NoticeAction::Export],
                ),
            }
            return;
        };
        let base = self.project_rev.get_value();
        match store().save(&id, &project, base, now_ms()) {
            Ok(rev) => {
                self.project_rev.set_value(Some(rev));
                self.refresh_list();
            }
            Err(StoreError::Conflict { stored, .. }) => self.show_conflict(stored.is_some()),
            Err(e) => self.error_with(
                tf(K::state_not_saved, &[("error", &said_text(e.said()))]),
                vec![NoticeAction::Export],
            ),
        }
    }

    /// Tells the user that another tab changed (or deleted) the open project and offers
    /// the choices.
    fn show_conflict(&self, still_stored: bool) {
        let name = self.project.with_untracked(|p| p.name.clone());
        if still_stored {
            self.error_with(
                tf(K::state_changed_elsewhere, &[("name", &name)]),
                vec![NoticeAction::LoadTheirs, NoticeAction::KeepMine, NoticeAction::SaveAsNew],
            );
        } else {
            self.error_with(
                tf(K::state_deleted_elsewhere, &[("name", &name)]),
                vec![NoticeAction::SaveAsNew, NoticeAction::Export],
            );
        }
    }

    /// Called on the window's `storage` event: another tab changed the store.
    fn storage_changed(&self) {
        self.refresh_list();
        let Some(id) = self.project_id.get_untracked() else { return };
        let Ok(stored) = store().current_rev(&id) else { return };
        if stored != self.project_rev.get_value() {
            self.show_conflict(stored.is_some());
        }
    }

    /// Listens for changes other tabs make to the store.
    pub(super) fn watch_other_tabs(&self) {
        let Some(window) = web_sys::window() else { return };
        let state = *self;
        let listener =
            Closure::<dyn Fn(web_sys::StorageEvent)>::new(move |ev: web_sys::StorageEvent| {
                let ours = ev.key().is_none_or(|k| ProjectStore::<LocalStorage>::is_store_key(&k));
                if ours && state.project.try_get_untracked().is_some() {
                    state.storage_changed();
                }
            });
        let _ =
            window.add_event_listener_with_callback("storage", listener.as_ref().unchecked_ref());
        // The listener lives as long as the page (the app is never unmounted).
        listener.forget();
        // Leaving the page normally (reload, close) is not a page that stopped.
        let leaving = Closure::<dyn Fn()>::new(|| {
            if !stopped() {
                let _ = store().clear_opening();
            }
        });
        let _ =
            window.add_event_listener_with_callback("pagehide", leaving.as_ref().unchecked_ref());
        leaving.forget();
    }

    /// Does what a banner button offers.
    pub fn act(&self, action: &NoticeAction) {
        self.notice.set(None);
        match action {
            NoticeAction::Export => self.export_project(),
            NoticeAction::RunLastBuilt => self.run_last_built(),
            NoticeAction::LoadTheirs => {
                if let Some(id) = self.project_id.get_untracked() {
                    self.open(&id);
                    self.info(t(K::state_loaded_theirs));
                }
            }
            NoticeAction::KeepMine => {
                let Some(id) = self.project_id.get_untracked() else { return };
                match store().current_rev(&id) {
                    Ok(rev) => {
                        self.project_rev.set_value(rev);
                        self.save();
                    }
                    Err(e) => self.error(said_text(e.said())),
                }
            }
            NoticeAction::SaveAsNew => {
                let mut project = self.project.get_untracked();
                project.name = tf(K::state_this_tab, &[("name", &project.name)]);
                let name = project.name.clone();
                if self.add_and_open(project) {
                    self.info(tf(K::state_saved_as, &[("name", &name)]));
                }
            }
            NoticeAction::DownloadDamaged(id) => match store().raw(id) {
                Ok(text) => {
                    let file = tf(K::state_damaged_file, &[("name", &self.name_of(id))]);
                    if let Err(e) = download(&project_file_name(&file), "text/plain", &text) {
                        self.error(e);
                    }
                }
                Err(e) => self.error(said_text(e.said())),
            },
            NoticeAction::DeleteDamaged(id) => {
                let name = self.name_of(id);
                match store().delete(id) {
                    Ok(()) => {
                        self.refresh_list();
                        self.info(tf(K::state_deleted_damaged, &[("name", &name)]));
                    }
                    Err(e) => self.error(said_text(e.said())),
                }
            }
            NoticeAction::OpenShared(fragment) => {
                let (state, fragment) = (*self, fragment.clone());
                leptos::task::spawn_local(async move {
                    state.open_shared(&fragment).await;
                });
            }
            NoticeAction::OpenStored(id) => {
                self.notice.set(None);
                self.open(id);
            }
        }
    }

    /// Offers the open project as a project file download.
    pub fn export_project(&self) {
        let (name, text) = self.project.with_untracked(|p| (p.name.clone(), p.to_file()));
        if let Err(e) = download(&project_file_name(&name), "application/json", &text) {
            self.error(tf(K::state_export_failed, &[("error", &e)]));
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
        p.name = tf(K::state_copy_name, &[("name", &p.name)]);
        self.add_and_open(p);
    }

    /// Deletes the open project and opens another (or a new one).
    pub fn delete_current(&self) {
        if let Some(id) = self.project_id.get_untracked() {
            if let Err(e) = store().delete(&id) {
                self.error(said_text(e.said()));
                return;
            }
        }
        self.project_id.set(None);
        self.project_rev.set_value(None);
        self.refresh_list();
        let damaged = self.damaged.get_untracked();
        let next = self.projects.with_untracked(|ps| {
            ps.iter().find(|p| !damaged.contains_key(&p.id)).map(|p| p.id.clone())
        });
        match next {
            Some(id) => self.open(&id),
            None => {
                self.add_and_open(Project::new(t(K::state_first_project)));
            }
        }
    }

    /// Replaces the open project's contents by `project`; its name and its place in
    /// storage stay (an exercise's `Reset to starter`).
    pub fn replace_contents(&self, mut project: Project) {
        project.name = self.project.with_untracked(|p| p.name.clone());
        self.project.set(project);
        self.forget_run();
        self.check_now();
        self.show_main_view();
        self.save();
    }

    /// The share link of the open project (its writer is a chunk, `lazy::share_fragment`).
    pub async fn share_link(&self) -> Result<String, crate::lazy::LoadFailed> {
        let fragment = crate::lazy::share_fragment(self.project.get_untracked()).await?;
        let base = web_sys::window()
            .and_then(|w| w.location().href().ok())
            .map(|h| h.split('#').next().unwrap_or_default().to_string())
            .unwrap_or_default();
        Ok(format!("{base}#{fragment}"))
    }
}

/// Removes the fragment from the address bar (what it held is open and kept).
pub fn clear_fragment() {
    if let Some(w) = web_sys::window() {
        let url = w.location().href().unwrap_or_default();
        let base = url.split('#').next().unwrap_or_default().to_string();
        if let Ok(history) = w.history() {
            let _ = history.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&base));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_and_share_marks() {
        assert_eq!(project_file_name("a/b: c"), "a_b_ c.plcproj.json");
        assert_eq!(project_file_name("  "), "project.plcproj.json");
        assert_eq!(share_mark("#p=abc"), share_mark("#p=abc"));
        assert_ne!(share_mark("#p=abc"), share_mark("#p=abd"));
    }
}
