//! The project list kept in a key-value storage (the browser's local storage in the web
//! app, a map in tests), built so that no failure loses a project.
//!
//! - A save writes the project under a **new key** (`…/project/<id>@<rev>`) and switches the
//!   index to it only when that write is complete; the previous version is removed last.
//!   A full storage or a failed index write leaves the previous version and the index as
//!   they were.
//! - Every save names the revision it started from: a project changed meanwhile (in
//!   another tab) is refused with [`StoreError::Conflict`] instead of overwritten.
//! - A damaged index is never read as an empty list: the list is rebuilt from the project
//!   keys found, and the damaged text is kept under its own key before anything is written.
//! - A damaged project is listed by [`ProjectStore::damaged`], its stored text can be read
//!   with [`ProjectStore::raw`], and it is only ever removed by [`ProjectStore::delete`].
//! - The storage layout is versioned ([`STORE_LAYOUT`]); [`index`] reads every earlier one.
//! - [`ProjectStore::mark_opening`] leaves a mark while a project is being opened, so a
//!   page that stopped (crashed or hung) while opening one does not open it again blindly.

mod index;
mod memory;

use std::fmt;

pub use index::STORE_LAYOUT;
pub use memory::MemoryBackend;

use super::{Project, ProjectError};
use crate::diagnostics::Said;
use index::{project_key, Index, ReadIndex};

/// The prefix of every key the trainer writes.
const PREFIX: &str = "plc-trainer/v1/";
/// The index: the list of projects and their current revisions.
const INDEX_KEY: &str = "plc-trainer/v1/index";
/// Where a damaged index's text is kept before a new index replaces it.
const DAMAGED_INDEX_KEY: &str = "plc-trainer/v1/index.damaged";
/// What the page was opening when it last started to open something.
const OPENING_KEY: &str = "plc-trainer/v1/opening";

/// A key-value storage of strings.
pub trait StorageBackend {
    /// Reads a key.
    fn get(&self, key: &str) -> Result<Option<String>, StoreError>;
    /// Writes a key (fails with [`StoreError::QuotaExceeded`] when the storage is full).
    fn set(&mut self, key: &str, value: &str) -> Result<(), StoreError>;
    /// Removes a key.
    fn remove(&mut self, key: &str) -> Result<(), StoreError>;
    /// Every key in the storage (to rebuild a damaged index).
    fn keys(&self) -> Result<Vec<String>, StoreError>;
}

/// Why storage failed.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum StoreError {
    /// The storage is full.
    QuotaExceeded,
    /// The storage cannot be used (disabled, private mode).
    Unavailable(String),
    /// No project with that id.
    NotFound(String),
    /// A stored project is damaged.
    Damaged(ProjectError),
    /// The project was changed elsewhere (another tab) since it was opened.
    Conflict {
        /// The project's id.
        id: String,
        /// Its revision in storage now (`None`: it was deleted).
        stored: Option<u64>,
    },
    /// The storage was written by a newer trainer with this layout; it is not written to.
    TooNew(u32),
}

impl StoreError {
    /// The error as a message, with its English text (what it displays as). The browser's
    /// own words for an unusable storage ([`StoreError::Unavailable`]) stay as they are.
    pub fn said(&self) -> Said {
        match self {
            StoreError::QuotaExceeded => crate::msg!(StoreFull),
            StoreError::Unavailable(e) => crate::msg!(StoreUnavailable, error = e),
            StoreError::NotFound(id) => crate::msg!(StoreNotFound, id = id),
            StoreError::Damaged(e) => crate::msg!(StoreDamaged, error = e.said()),
            StoreError::Conflict { stored: Some(_), .. } => crate::msg!(StoreChangedElsewhere),
            StoreError::Conflict { stored: None, .. } => crate::msg!(StoreDeletedElsewhere),
            StoreError::TooNew(v) => crate::msg!(StoreTooNew, layout = v),
        }
    }
}

impl fmt::Display for StoreError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for StoreError {}

/// A project in the list.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct ProjectSummary {
    /// Stable id (key suffix).
    pub id: String,
    /// The name shown.
    pub name: String,
    /// Last change, milliseconds since the epoch (as the caller's clock says).
    pub modified_ms: u64,
    /// The revision stored (0: a project written by storage layout 1).
    #[serde(default)]
    pub rev: u64,
}

/// A project read from the store with the revision it was read at.
#[derive(Debug, Clone, PartialEq)]
pub struct Opened {
    /// The project.
    pub project: Project,
    /// Its revision: pass it to [`ProjectStore::save`].
    pub rev: u64,
}

/// How a store reads a project's text ([`Project::from_file`], or
/// [`Project::from_file_without_diagrams`] before the diagram models' readers are there).
pub type ProjectReader = fn(&str) -> Result<Project, ProjectError>;

/// The project list over a storage backend.
#[derive(Debug)]
pub struct ProjectStore<B: StorageBackend> {
    backend: B,
    read: ProjectReader,
}

impl<B: StorageBackend> ProjectStore<B> {
    /// A store over `backend`.
    pub fn new(backend: B) -> Self {
        Self::with_reader(backend, Project::from_file)
    }

    /// A store over `backend` that reads projects with `read`. With
    /// [`Project::from_file_without_diagrams`], a project with diagram POUs opens as
    /// [`StoreError::Damaged`]`(`[`ProjectError::NeedsDiagramReaders`]`)` and is not listed
    /// as damaged.
    pub fn with_reader(backend: B, read: ProjectReader) -> Self {
        ProjectStore { backend, read }
    }

    /// The backend (for tests).
    pub fn backend(&self) -> &B {
        &self.backend
    }

    fn read_index(&self) -> Result<ReadIndex, StoreError> {
        index::read(&self.backend, INDEX_KEY)
    }

    /// The projects, most recently changed first. A damaged index is rebuilt from the
    /// project keys in storage (see [`ProjectStore::index_damage`]).
    pub fn list(&self) -> Result<Vec<ProjectSummary>, StoreError> {
        let mut list = self.read_index()?.index.projects;
        crate::order::sort_by(&mut list, |a, b| {
            b.modified_ms.cmp(&a.modified_ms).then(a.name.cmp(&b.name))
        });
        Ok(list)
    }

    /// A message for the user when the index is damaged (the list was rebuilt from the
    /// projects found) or written by a newer trainer; `None` when it is sound. In English:
    /// [`ProjectStore::index_damage_said`] gives it in any language.
    pub fn index_damage(&self) -> Result<Option<String>, StoreError> {
        Ok(self.index_damage_said()?.map(|said| said.english))
    }

    /// [`ProjectStore::index_damage`] as a message, to be shown in any language.
    pub fn index_damage_said(&self) -> Result<Option<Said>, StoreError> {
        let read = self.read_index()?;
        Ok(if let Some(v) = read.too_new {
            Some(StoreError::TooNew(v).said())
        } else if read.damaged_text.is_some() {
            let count = read.index.projects.len();
            Some(crate::msg!(StoreIndexRebuilt, count = count, key = DAMAGED_INDEX_KEY))
        } else {
            None
        })
    }

    /// Writes `index`, first keeping a damaged index's text, and refusing to write over an
    /// index of a newer layout.
    fn write_index(&mut self, read: &ReadIndex, index: &Index) -> Result<(), StoreError> {
        if let Some(v) = read.too_new {
            return Err(StoreError::TooNew(v));
        }
        if let Some(text) = &read.damaged_text {
            if self.backend.get(DAMAGED_INDEX_KEY)?.as_deref() != Some(text.as_str()) {
                self.backend.set(DAMAGED_INDEX_KEY, text)?;
            }
        }
        self.backend.set(INDEX_KEY, &index.to_text())
    }

    /// Loads a project.
    pub fn load(&self, id: &str) -> Result<Project, StoreError> {
        self.open(id).map(|o| o.project)
    }

    /// Loads a project with its revision.
    pub fn open(&self, id: &str) -> Result<Opened, StoreError> {
        let rev = self.current_rev(id)?.ok_or_else(|| StoreError::NotFound(id.to_string()))?;
        let text = self.raw(id)?;
        let project = (self.read)(&text).map_err(StoreError::Damaged)?;
        Ok(Opened { project, rev })
    }

    /// The stored text of a project, damaged or not (to download a damaged one).
    pub fn raw(&self, id: &str) -> Result<String, StoreError> {
        let rev = self.current_rev(id)?.ok_or_else(|| StoreError::NotFound(id.to_string()))?;
        self.backend.get(&project_key(id, rev))?.ok_or_else(|| missing_text(id, rev))
    }

    /// The revision of project `id` in storage now (`None`: not in the list).
    pub fn current_rev(&self, id: &str) -> Result<Option<u64>, StoreError> {
        Ok(self.read_index()?.index.projects.iter().find(|p| p.id == id).map(|p| p.rev))
    }

    /// Every listed project that cannot be opened, with the reason (in English:
    /// [`ProjectStore::damaged_said`] gives it in any language).
    pub fn damaged(&self) -> Result<Vec<(String, String)>, StoreError> {
        Ok(self.damaged_said()?.into_iter().map(|(id, said)| (id, said.english)).collect())
    }

    /// Every listed project that cannot be opened, with the reason as a message.
    pub fn damaged_said(&self) -> Result<Vec<(String, Said)>, StoreError> {
        let mut out = Vec::new();
        for p in self.read_index()?.index.projects {
            let problem = match self.backend.get(&project_key(&p.id, p.rev))? {
                None => Some(missing_text(&p.id, p.rev)),
                Some(text) => match (self.read)(&text) {
                    // Not known yet: read again with the diagram models' readers.
                    Ok(_) | Err(ProjectError::NeedsDiagramReaders) => None,
                    Err(e) => Some(StoreError::Damaged(e)),
                },
            };
            if let Some(e) = problem {
                out.push((p.id, e.said()));
            }
        }
        Ok(out)
    }

    /// Saves a project under `id`, stamped `now_ms`, and returns its new revision.
    /// `base_rev` is the revision the caller opened (`None` for a project not stored yet):
    /// when storage holds another one the save is refused with [`StoreError::Conflict`].
    pub fn save(
        &mut self,
        id: &str,
        project: &Project,
        base_rev: Option<u64>,
        now_ms: u64,
    ) -> Result<u64, StoreError> {
        let read = self.read_index()?;
        let stored = read.index.projects.iter().find(|p| p.id == id).map(|p| p.rev);
        if stored != base_rev {
            return Err(StoreError::Conflict { id: id.to_string(), stored });
        }
        let rev = stored.map_or(1, |r| r + 1);
        let key = project_key(id, rev);
        self.backend.set(&key, &project.to_file())?;
        let mut index = read.index.clone();
        index.projects.retain(|p| p.id != id);
        index.projects.push(ProjectSummary {
            id: id.to_string(),
            name: project.name.clone(),
            modified_ms: now_ms,
            rev,
        });
        if let Err(e) = self.write_index(&read, &index) {
            // The index still names the previous version: drop the new one.
            let _ = self.backend.remove(&key);
            return Err(e);
        }
        if let Some(old) = stored {
            let _ = self.backend.remove(&project_key(id, old));
        }
        Ok(rev)
    }

    /// Adds a project under a fresh id derived from `now_ms` and returns the id and its
    /// revision. Never overwrites an existing project.
    pub fn add(&mut self, project: &Project, now_ms: u64) -> Result<(String, u64), StoreError> {
        let taken = self.read_index()?.index.projects;
        let keys = self.backend.keys()?;
        let mut n = now_ms;
        let id = loop {
            let id = format!("p{n:x}");
            let key = project_key(&id, 0);
            let in_use = taken.iter().any(|p| p.id == id)
                || keys.iter().any(|k| *k == key || k.starts_with(&format!("{key}@")));
            if !in_use {
                break id;
            }
            n += 1;
        };
        let rev = self.save(&id, project, None, now_ms)?;
        Ok((id, rev))
    }

    /// Renames a project.
    pub fn rename(&mut self, id: &str, name: &str, now_ms: u64) -> Result<u64, StoreError> {
        let Opened { mut project, rev } = self.open(id)?;
        project.name = name.to_string();
        self.save(id, &project, Some(rev), now_ms)
    }

    /// Copies a project under a new id, named "… (copy)".
    pub fn duplicate(&mut self, id: &str, now_ms: u64) -> Result<String, StoreError> {
        let mut project = self.load(id)?;
        project.name = format!("{} (copy)", project.name);
        self.add(&project, now_ms).map(|(id, _)| id)
    }

    /// Deletes a project (damaged or not): the list first, then its text.
    pub fn delete(&mut self, id: &str) -> Result<(), StoreError> {
        let read = self.read_index()?;
        let stored = read.index.projects.iter().find(|p| p.id == id).map(|p| p.rev);
        let mut index = read.index.clone();
        index.projects.retain(|p| p.id != id);
        self.write_index(&read, &index)?;
        if let Some(rev) = stored {
            self.backend.remove(&project_key(id, rev))?;
        }
        Ok(())
    }

    /// Notes that the page is about to open `what` (a project id, or a share link's
    /// digest); [`ProjectStore::clear_opening`] removes the note once it opened.
    pub fn mark_opening(&mut self, what: &str) -> Result<(), StoreError> {
        self.backend.set(OPENING_KEY, what)
    }

    /// Removes the note left by [`ProjectStore::mark_opening`].
    pub fn clear_opening(&mut self) -> Result<(), StoreError> {
        self.backend.remove(OPENING_KEY)
    }

    /// What the page was opening when it stopped last time, if it never finished.
    pub fn interrupted_opening(&self) -> Result<Option<String>, StoreError> {
        self.backend.get(OPENING_KEY)
    }

    /// Whether `key` (from a `storage` event) is one of the store's keys.
    pub fn is_store_key(key: &str) -> bool {
        key.starts_with(PREFIX)
    }
}

/// The error for a listed project whose text is not in storage.
fn missing_text(id: &str, rev: u64) -> StoreError {
    StoreError::Damaged(ProjectError::Invalid(crate::msg!(
        StoreTextMissing,
        key = project_key(id, rev)
    )))
}

#[cfg(test)]
mod tests;
