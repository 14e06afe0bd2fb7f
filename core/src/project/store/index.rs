//! The index: which projects exist and which revision of each is current, in every
//! storage layout the trainer has written.
//!
//! - Layout 1 (the first release): a JSON array of `{id, name, modified_ms}`; each project
//!   under `plc-trainer/v1/project/<id>`.
//! - Layout 2: `{"layout": 2, "projects": [{id, name, modified_ms, rev}]}`; revision `rev`
//!   of a project under `plc-trainer/v1/project/<id>@<rev>`, revision 0 being the layout-1
//!   key. Reading layout 1 is the migration: its projects are revision 0, and the first
//!   save of each moves it to revision 1.

use serde::{Deserialize, Serialize};

use super::{ProjectSummary, StorageBackend, StoreError, PREFIX};
use crate::project::Project;

/// The storage layout this build writes.
pub const STORE_LAYOUT: u32 = 2;

/// The index's contents.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct Index {
    /// Every project, in no particular order.
    pub projects: Vec<ProjectSummary>,
}

/// The index as written (layout 2).
#[derive(Serialize, Deserialize)]
struct IndexFile {
    layout: u32,
    projects: Vec<ProjectSummary>,
}

impl Index {
    /// The index as stored text (the current layout).
    pub fn to_text(&self) -> String {
        let file = IndexFile { layout: STORE_LAYOUT, projects: self.projects.clone() };
        serde_json::to_string(&file).unwrap_or_default()
    }
}

/// The index as read, with what was wrong with it.
#[derive(Debug, Clone, Default)]
pub(super) struct ReadIndex {
    /// The projects (rebuilt from the project keys when the stored index was unusable).
    pub index: Index,
    /// The stored index's text when it could not be read (rebuilt from the keys).
    pub damaged_text: Option<String>,
    /// The layout of an index written by a newer trainer.
    pub too_new: Option<u32>,
}

/// The key of revision `rev` of project `id`.
pub(super) fn project_key(id: &str, rev: u64) -> String {
    if rev == 0 {
        format!("{PREFIX}project/{id}")
    } else {
        format!("{PREFIX}project/{id}@{rev}")
    }
}

/// The project id and revision a storage key holds, if it is a project key.
fn parse_project_key(key: &str) -> Option<(&str, u64)> {
    let rest = key.strip_prefix(PREFIX)?.strip_prefix("project/")?;
    match rest.rsplit_once('@') {
        Some((id, rev)) => Some((id, rev.parse().ok()?)),
        None => Some((rest, 0)),
    }
}

/// Reads the index at `key`, rebuilding it from the project keys when it is unreadable.
pub(super) fn read<B: StorageBackend + ?Sized>(
    backend: &B,
    key: &str,
) -> Result<ReadIndex, StoreError> {
    let Some(text) = backend.get(key)? else {
        return Ok(ReadIndex::default());
    };
    match parse(&text) {
        Ok((projects, layout)) if layout > STORE_LAYOUT => {
            Ok(ReadIndex { index: Index { projects }, damaged_text: None, too_new: Some(layout) })
        }
        Ok((projects, _)) => Ok(ReadIndex { index: Index { projects }, ..ReadIndex::default() }),
        Err(()) => {
            Ok(ReadIndex { index: rebuild(backend)?, damaged_text: Some(text), too_new: None })
        }
    }
}

/// The projects and the layout of an index's text (read straight from the text, as
/// `Project::from_file` does, for the same reason).
fn parse(text: &str) -> Result<(Vec<ProjectSummary>, u32), ()> {
    let (mut projects, layout) = if text.trim_start().starts_with('[') {
        (serde_json::from_str::<Vec<ProjectSummary>>(text).map_err(|_| ())?, 1)
    } else {
        let file: IndexFile = serde_json::from_str(text).map_err(|_| ())?;
        (file.projects, file.layout)
    };
    let mut seen = std::collections::BTreeSet::new();
    projects.retain(|p| seen.insert(p.id.clone()));
    Ok((projects, layout))
}

/// An index of every project key in storage: the highest revision of each id, named as
/// the project says (or by its id when its text is damaged).
fn rebuild<B: StorageBackend + ?Sized>(backend: &B) -> Result<Index, StoreError> {
    let mut latest: std::collections::BTreeMap<String, (u64, String)> = Default::default();
    for key in backend.keys()? {
        if let Some((id, rev)) = parse_project_key(&key) {
            let entry = latest.entry(id.to_string()).or_insert((rev, key.clone()));
            if rev >= entry.0 {
                *entry = (rev, key.clone());
            }
        }
    }
    let mut projects = Vec::new();
    for (id, (rev, key)) in latest {
        let text = backend.get(&key)?.unwrap_or_default();
        let name = Project::name_in_file(&text).unwrap_or_else(|| id.clone());
        let modified_ms =
            id.strip_prefix('p').and_then(|h| u64::from_str_radix(h, 16).ok()).unwrap_or(0);
        projects.push(ProjectSummary { id, name, modified_ms, rev });
    }
    Ok(Index { projects })
}
