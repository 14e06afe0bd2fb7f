//! The project list kept in a key-value storage (the browser's local storage in the web
//! app, a map in tests), under one versioned key space.
//!
//! Keys: `plc-trainer/v1/index` holds the list of projects; `plc-trainer/v1/project/<id>`
//! holds each project file. Writing a project never touches another one.

use std::collections::BTreeMap;
use std::fmt;

use serde::{Deserialize, Serialize};

use super::{Project, ProjectError};

const INDEX_KEY: &str = "plc-trainer/v1/index";
const PROJECT_KEY: &str = "plc-trainer/v1/project/";

/// A key-value storage of strings.
pub trait StorageBackend {
    /// Reads a key.
    fn get(&self, key: &str) -> Result<Option<String>, StoreError>;
    /// Writes a key (fails with [`StoreError::QuotaExceeded`] when the storage is full).
    fn set(&mut self, key: &str, value: &str) -> Result<(), StoreError>;
    /// Removes a key.
    fn remove(&mut self, key: &str) -> Result<(), StoreError>;
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
}

impl fmt::Display for StoreError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StoreError::QuotaExceeded => f.write_str(
                "the browser's storage is full: export your project to a file, then delete old projects",
            ),
            StoreError::Unavailable(e) => write!(f, "the browser's storage cannot be used: {e}"),
            StoreError::NotFound(id) => write!(f, "no project `{id}`"),
            StoreError::Damaged(e) => write!(f, "a stored project is damaged: {e}"),
        }
    }
}

impl std::error::Error for StoreError {}

/// A project in the list.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ProjectSummary {
    /// Stable id (key suffix).
    pub id: String,
    /// The name shown.
    pub name: String,
    /// Last change, milliseconds since the epoch (as the caller's clock says).
    pub modified_ms: u64,
}

/// The project list over a storage backend.
#[derive(Debug)]
pub struct ProjectStore<B: StorageBackend> {
    backend: B,
}

impl<B: StorageBackend> ProjectStore<B> {
    /// A store over `backend`.
    pub fn new(backend: B) -> Self {
        ProjectStore { backend }
    }

    /// The backend (for tests).
    pub fn backend(&self) -> &B {
        &self.backend
    }

    /// The projects, most recently changed first. A damaged index reads as empty (the
    /// projects themselves stay in storage).
    pub fn list(&self) -> Result<Vec<ProjectSummary>, StoreError> {
        let mut list: Vec<ProjectSummary> = match self.backend.get(INDEX_KEY)? {
            Some(text) => serde_json::from_str(&text).unwrap_or_default(),
            None => Vec::new(),
        };
        list.sort_by(|a, b| b.modified_ms.cmp(&a.modified_ms).then(a.name.cmp(&b.name)));
        Ok(list)
    }

    fn write_index(&mut self, list: &[ProjectSummary]) -> Result<(), StoreError> {
        let text = serde_json::to_string(list).unwrap_or_default();
        self.backend.set(INDEX_KEY, &text)
    }

    /// Loads a project.
    pub fn load(&self, id: &str) -> Result<Project, StoreError> {
        let text = self
            .backend
            .get(&format!("{PROJECT_KEY}{id}"))?
            .ok_or_else(|| StoreError::NotFound(id.to_string()))?;
        Project::from_file(&text).map_err(StoreError::Damaged)
    }

    /// Saves a project under `id` (creating or replacing it), stamped `now_ms`.
    pub fn save(&mut self, id: &str, project: &Project, now_ms: u64) -> Result<(), StoreError> {
        self.backend.set(&format!("{PROJECT_KEY}{id}"), &project.to_file())?;
        let mut list = self.list()?;
        list.retain(|p| p.id != id);
        list.push(ProjectSummary {
            id: id.to_string(),
            name: project.name.clone(),
            modified_ms: now_ms,
        });
        self.write_index(&list)
    }

    /// Adds a project under a fresh id derived from `now_ms` and returns the id. Never
    /// overwrites an existing project.
    pub fn add(&mut self, project: &Project, now_ms: u64) -> Result<String, StoreError> {
        let list = self.list()?;
        let mut n = now_ms;
        let id = loop {
            let id = format!("p{n:x}");
            if !list.iter().any(|p| p.id == id)
                && self.backend.get(&format!("{PROJECT_KEY}{id}"))?.is_none()
            {
                break id;
            }
            n += 1;
        };
        self.save(&id, project, now_ms)?;
        Ok(id)
    }

    /// Renames a project.
    pub fn rename(&mut self, id: &str, name: &str, now_ms: u64) -> Result<(), StoreError> {
        let mut project = self.load(id)?;
        project.name = name.to_string();
        self.save(id, &project, now_ms)
    }

    /// Copies a project under a new id, named "… (copy)".
    pub fn duplicate(&mut self, id: &str, now_ms: u64) -> Result<String, StoreError> {
        let mut project = self.load(id)?;
        project.name = format!("{} (copy)", project.name);
        self.add(&project, now_ms)
    }

    /// Deletes a project.
    pub fn delete(&mut self, id: &str) -> Result<(), StoreError> {
        self.backend.remove(&format!("{PROJECT_KEY}{id}"))?;
        let mut list = self.list()?;
        list.retain(|p| p.id != id);
        self.write_index(&list)
    }
}

/// An in-memory backend with an optional quota in bytes (for tests).
#[derive(Debug, Default, Clone)]
pub struct MemoryBackend {
    map: BTreeMap<String, String>,
    quota: Option<usize>,
}

impl MemoryBackend {
    /// An empty backend that holds at most `quota` bytes of keys and values.
    pub fn with_quota(quota: usize) -> Self {
        MemoryBackend { map: BTreeMap::new(), quota: Some(quota) }
    }

    fn used(&self) -> usize {
        self.map.iter().map(|(k, v)| k.len() + v.len()).sum()
    }
}

impl StorageBackend for MemoryBackend {
    fn get(&self, key: &str) -> Result<Option<String>, StoreError> {
        Ok(self.map.get(key).cloned())
    }

    fn set(&mut self, key: &str, value: &str) -> Result<(), StoreError> {
        if let Some(q) = self.quota {
            let old = self.map.get(key).map_or(0, |v| key.len() + v.len());
            if self.used() - old + key.len() + value.len() > q {
                return Err(StoreError::QuotaExceeded);
            }
        }
        self.map.insert(key.to_string(), value.to_string());
        Ok(())
    }

    fn remove(&mut self, key: &str) -> Result<(), StoreError> {
        self.map.remove(key);
        Ok(())
    }
}
