//! Exercise links: a whole exercise — its file and its starter — compressed into a URL
//! fragment (`#x=…`), as project links carry a project, so an instructor publishes an
//! exercise with no account and no server. Only what is given travels: the hidden
//! scenarios are a second file that never goes into a link, and the reference solution is
//! not carried.

use serde::{Deserialize, Serialize};

use super::format::{Exercise, ExerciseError};
use crate::project::{pack, unpack};

/// The fragment prefix of an exercise link: `#x=<data>`.
pub const EXERCISE_LINK_PREFIX: &str = "x=";

/// What an exercise link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExerciseLink {
    /// The exercise file: TOML, or the built form the web app ships its exercises in
    /// (`built_form.rs`).
    pub exercise: String,
    /// The starter file, when the exercise names one.
    #[serde(default)]
    pub starter: Option<LinkedFile>,
    /// The starters in its other languages the exercise names (`starter_ld` …).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub starters: Vec<LinkedFile>,
}

/// A file carried by a link.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LinkedFile {
    /// Its name (`starter.st`): its extension says how to read it.
    pub name: String,
    /// Its text.
    pub text: String,
}

impl ExerciseLink {
    /// The link with every file in its place: the one `exercise` names as `starter` in
    /// `starter` (as links made before other languages' starters carry it), the others in
    /// `starters`.
    pub fn arranged(mut self, exercise: &Exercise) -> ExerciseLink {
        let mut files: Vec<LinkedFile> = self.starter.take().into_iter().collect();
        files.append(&mut self.starters);
        let main = exercise.starter.as_deref();
        self.starter =
            main.and_then(|n| files.iter().position(|f| f.name == n)).map(|i| files.remove(i));
        self.starters = files;
        self
    }

    /// The carried file named `name`.
    pub fn file(&self, name: &str) -> Option<&LinkedFile> {
        self.starter.iter().chain(&self.starters).find(|f| f.name == name)
    }

    /// The fragment (without `#`): `x=<base64url(deflate(json))>`. The exercise text is
    /// checked first, so a link never carries a file the page would refuse.
    pub fn encode(&self) -> Result<String, ExerciseError> {
        Exercise::from_text(&self.exercise)?;
        Ok(self.fragment())
    }

    /// The fragment of a link whose exercise was already read (see [`ExerciseLink::encode`]).
    pub fn fragment(&self) -> String {
        let json = serde_json::to_vec(self).unwrap_or_default();
        format!("{EXERCISE_LINK_PREFIX}{}", pack(&json))
    }

    /// Reads a fragment (with or without `#`) made by [`ExerciseLink::encode`]; the
    /// exercise it holds is checked as a file is.
    pub fn decode(fragment: &str) -> Result<(ExerciseLink, Exercise), ExerciseError> {
        let link = ExerciseLink::unpack(fragment)?;
        let exercise = Exercise::from_text(&link.exercise).map_err(|e| ExerciseError {
            message: format!("the exercise in this link cannot be used: {e}"),
        })?;
        Ok((link, exercise))
    }

    /// What a fragment carries, its exercise not read yet (see [`ExerciseLink::decode`]).
    pub fn unpack(fragment: &str) -> Result<ExerciseLink, ExerciseError> {
        let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
        let fail = |m: &str| ExerciseError { message: m.to_string() };
        let data = fragment
            .strip_prefix(EXERCISE_LINK_PREFIX)
            .ok_or_else(|| fail("this link does not hold an exercise"))?;
        let text = unpack(data)
            .map_err(|_| fail("this exercise link is damaged (was it copied completely?)"))?;
        serde_json::from_str(&text).map_err(|_| fail("this exercise link holds no exercise"))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    const FILE: &str = "id = \"t\"\ntitle = \"T\"\nlevel = 1\nstarter = \"starter.st\"\n";

    #[test]
    fn a_link_carries_the_exercise_and_its_starter() {
        let link = ExerciseLink {
            exercise: FILE.into(),
            starter: Some(LinkedFile {
                name: "starter.st".into(),
                text: "PROGRAM Main END_PROGRAM".into(),
            }),
            starters: Vec::new(),
        };
        let fragment = link.encode().unwrap();
        assert!(fragment.starts_with("x="));
        let (back, exercise) = ExerciseLink::decode(&format!("#{fragment}")).unwrap();
        assert_eq!((back, exercise.id.as_str()), (link, "t"));
    }

    #[test]
    fn damaged_and_foreign_links_are_refused_with_a_message() {
        let e = |f: &str| ExerciseLink::decode(f).unwrap_err().message;
        assert_eq!(e("#p=abc"), "this link does not hold an exercise");
        assert!(e("#x=!!!").contains("damaged"));
        let not_json = format!("x={}", pack(b"hello"));
        assert!(e(&not_json).contains("holds no exercise"));
        let bad = ExerciseLink { exercise: "id = 3".into(), starter: None, starters: Vec::new() };
        assert!(bad.encode().is_err());
        let json = serde_json::to_vec(&bad).unwrap();
        let message = e(&format!("x={}", pack(&json)));
        assert!(
            message.starts_with("the exercise in this link cannot be used: line 1"),
            "{message}"
        );
    }
}
