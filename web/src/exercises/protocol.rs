//! The messages between the page and the exercise worker (`src/workers/exercise.rs`),
//! which reads exercise files, renders their statements and grades attempts off the
//! page's own module (the TOML reader, the Markdown renderer and the grader are not in the
//! first load). Both sides send one JSON text per message.

use plc_core::exercise::{ExerciseLink, ExerciseView, Report};
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
    /// An attempt graded.
    Graded(Report),
    /// Why the request could not be done (a located message for the user).
    Error(String),
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
    /// The fragment of a link that carries it (`x=…`, without `#`).
    pub fragment: String,
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
