//! The messages between the page and the exercise worker (`src/workers/exercise.rs`),
//! which reads exercise files, renders their statements and grades attempts off the
//! page's own module (the TOML reader, the Markdown renderer and the grader are not in the
//! first load). Both sides send one JSON text per message.

use plc_core::exercise::{ExerciseLink, ExerciseView};
use serde::{Deserialize, Serialize};

/// What the page asks.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Request {
    /// Open a shipped exercise, by id.
    Shipped(String),
    /// Open an exercise file (with its starter when the page fetched it); `base` is the
    /// file's address, for the statement's relative links.
    File {
        /// The exercise file and its starter.
        link: ExerciseLink,
        /// Where the file came from.
        base: Option<String>,
    },
    /// Open the exercise a `#x=…` fragment carries.
    Link(String),
    /// Grade a project file against an exercise file.
    Grade {
        /// The exercise file (TOML).
        exercise: String,
        /// The project file of the attempt.
        project: String,
    },
    /// Pack the exercise (its file and starter) with the site's files into a SCORM 1.2
    /// package; the worker answers with the ZIP's bytes (a `Uint8Array`) or an `Error`.
    Scorm {
        /// The exercise and its starter.
        link: ExerciseLink,
        /// The site's root URL (the page's folder, ending in `/`): its `site-files.txt`
        /// lists the files to pack.
        site: String,
    },
}

/// What the worker answers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Reply {
    /// An exercise opened.
    Opened(Box<Opened>),
    /// An attempt graded: its report as JSON text, read by the page with the report's
    /// view (`lazy::read_report`, a chunk fetched at the first check), so that opening an
    /// exercise does not bring the report's decoder.
    Graded(String),
    /// Why the request could not be done (worded by the page, in the language shown).
    Error(Failure),
}

/// Why the worker could not do a request: what failed, worded by the page in the language
/// shown (the worker has only English), with the engine's located message or the file
/// it is about.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Failure {
    /// The engine's message alone.
    Plain(String),
    /// The exercise a link carries does not read.
    LinkUnusable(String),
    /// The exercise file does not read.
    FileUnusable(String),
    /// The attempt's project file does not read.
    ProjectUnreadable(String),
    /// The grader stopped.
    CannotGrade(String),
    /// A starter file does not open.
    StarterBroken(String),
    /// There is no shipped exercise with this id.
    NoExercise(String),
    /// The shipped exercise (id) does not read (why).
    ExerciseUnreadable(String, String),
    /// The shipped exercise (id) could not be fetched.
    ExerciseOffline(String),
    /// The shipped exercise (id) could not be fetched (HTTP status).
    ExerciseHttp(String, u16),
    /// A file of the site (its address) could not be fetched.
    UrlUnreadable(String),
    /// A file of the site (its address) could not be fetched (HTTP status).
    UrlHttp(String, u16),
    /// The site lists no files to pack.
    NoFileList(String),
    /// A SCORM request sent as text.
    NotText,
    /// The request does not read.
    BadRequest(String),
    /// The answer could not be written.
    Unwritable,
}

impl Failure {
    /// The failure in the language shown.
    pub fn text(&self) -> String {
        use crate::i18n::{t, tf, K};
        let one = |key, name, value: &str| tf(key, &[(name, value)]);
        match self {
            Failure::Plain(e) => e.clone(),
            Failure::LinkUnusable(e) => one(K::exercise_link_unusable, "error", e),
            Failure::FileUnusable(e) => one(K::exercise_file_unusable, "error", e),
            Failure::ProjectUnreadable(e) => one(K::exercise_project_unreadable, "error", e),
            Failure::CannotGrade(e) => one(K::exercise_cannot_grade, "error", e),
            Failure::StarterBroken(e) => one(K::exercise_starter_unusable, "error", e),
            Failure::NoExercise(id) => one(K::exercise_no_exercise, "id", id),
            Failure::ExerciseUnreadable(id, e) => {
                tf(K::exercise_exercise_unreadable, &[("id", id), ("error", e)])
            }
            Failure::ExerciseOffline(id) => one(K::exercise_exercise_offline, "id", id),
            Failure::ExerciseHttp(id, status) => {
                tf(K::exercise_exercise_http, &[("id", id), ("status", &status.to_string())])
            }
            Failure::UrlUnreadable(url) => one(K::exercise_url_unreadable, "url", url),
            Failure::UrlHttp(url, status) => format!("{url}: HTTP {status}"),
            Failure::NoFileList(list) => one(K::exercise_no_file_list, "list", list),
            Failure::NotText => t(K::exercise_not_text_answer).to_string(),
            Failure::BadRequest(e) => one(K::exercise_bad_request, "error", e),
            Failure::Unwritable => t(K::exercise_unwritable).to_string(),
        }
    }
}

/// An exercise ready to show.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Opened {
    /// What the page shows.
    pub view: ExerciseView,
    /// The exercise file and its starter as given: what a link carries and what the
    /// browser keeps to reopen it.
    pub link: ExerciseLink,
    /// Where the file came from (`?exercise=URL`), if anywhere.
    pub base: Option<String>,
    /// The starter in each language the student may start in, in the exercise's order:
    /// the file it names opened, or one made from the interface. Empty while `missing`
    /// is not.
    pub starters: Vec<StarterFile>,
    /// The starter files the exercise names that were not given (the page fetches them
    /// next to the file and asks again).
    pub missing: Vec<String>,
}

/// The starter in one language.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StarterFile {
    /// The language's code (`st`, `ld`, `petri`, `sfc`).
    pub language: String,
    /// The starter as a project file; its settings name the PROGRAM graded.
    pub project: String,
}
