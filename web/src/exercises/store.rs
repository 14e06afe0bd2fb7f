//! What the browser keeps about exercises, in local storage: which exercises were passed
//! (the catalogue's ticks), which stored project is the attempt at each exercise, and the
//! files of exercises opened from a link or an address (so the attempt reopens with its
//! exercise after a reload). Storage that is full or disabled loses only these notes.

use std::collections::{BTreeMap, BTreeSet};

use plc_core::exercise::ExerciseLink;
use plc_core::project::StorageBackend;
use serde::{Deserialize, Serialize};

use crate::storage::LocalStorage;

const PASSED: &str = "plc-exercises-passed";
const ATTEMPTS: &str = "plc-exercise-attempts";
const SOURCE_PREFIX: &str = "plc-exercise-source:";

/// An exercise file kept for its attempt: the file, its starter and where it came from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KeptSource {
    /// The exercise file and starter.
    pub link: ExerciseLink,
    /// Its address, when it was fetched.
    pub base: Option<String>,
}

/// The value kept under `key` (its default when there is none or it does not read).
fn read<T: for<'de> Deserialize<'de> + Default>(key: &str) -> T {
    read_opt(key).unwrap_or_default()
}

fn read_opt<T: for<'de> Deserialize<'de>>(key: &str) -> Option<T> {
    let text = LocalStorage::open().get(key).ok().flatten()?;
    serde_json::from_str(&text).ok()
}

fn write<T: Serialize>(key: &str, value: &T) {
    if let Ok(text) = serde_json::to_string(value) {
        let _ = LocalStorage::open().set(key, &text);
    }
}

/// The ids of the exercises passed.
pub fn passed() -> BTreeSet<String> {
    read(PASSED)
}

/// Notes that exercise `id` was passed.
pub fn mark_passed(id: &str) -> BTreeSet<String> {
    let mut all = passed();
    all.insert(id.to_string());
    write(PASSED, &all);
    all
}

/// Exercise id → the id of the stored project that is the attempt at it.
pub fn attempts() -> BTreeMap<String, String> {
    read(ATTEMPTS)
}

/// Notes that project `project_id` is the attempt at exercise `id`.
pub fn set_attempt(id: &str, project_id: &str) {
    let mut all = attempts();
    all.insert(id.to_string(), project_id.to_string());
    write(ATTEMPTS, &all);
}

/// The exercise whose attempt the project `project_id` is.
pub fn exercise_of(project_id: &str) -> Option<String> {
    attempts().into_iter().find(|(_, p)| p == project_id).map(|(id, _)| id)
}

/// Keeps the file of exercise `id` (opened from a link or an address).
pub fn keep_source(id: &str, source: &KeptSource) {
    write(&format!("{SOURCE_PREFIX}{id}"), source);
}

/// The kept file of exercise `id`.
pub fn kept_source(id: &str) -> Option<KeptSource> {
    read_opt(&format!("{SOURCE_PREFIX}{id}"))
}
