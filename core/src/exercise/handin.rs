//! Hand-ins: a student's attempt as a file the instructor's batch grader recognises by
//! student and exercise. A `.plcsub` file is a project file (it opens as a project
//! anywhere a project does) with one more key first, `hand_in`, an object of three:
//! `exercise` (the exercise's id), `name` (the student's name as typed) and `handed_in`
//! (when, as the browser's clock said it, ISO 8601). They sit in their own object because
//! the project has a `name` of its own. It holds no score: `plc grade` grades it again.

use serde::Deserialize;

use super::format::ExerciseError;
use crate::project::Project;

/// The extension of a hand-in file.
pub const HAND_IN_EXTENSION: &str = "plcsub";

/// A hand-in read back.
#[derive(Debug, Clone, PartialEq)]
pub struct HandIn {
    /// The exercise's id.
    pub exercise: String,
    /// The student's name.
    pub name: String,
    /// When it was handed in (ISO 8601, as written).
    pub handed_in: String,
    /// The attempt.
    pub project: Project,
}

/// The `hand_in` object of a file.
#[derive(Deserialize)]
struct Keys {
    exercise: Option<String>,
    name: Option<String>,
    handed_in: Option<String>,
}

/// A file's `hand_in` key (every other key is the project's).
#[derive(Deserialize)]
struct Header {
    hand_in: Option<Keys>,
}

impl HandIn {
    /// The hand-in file of an attempt: `project_file` (a project file, as
    /// [`Project::to_file`] writes it) with the `hand_in` key first.
    pub fn file_text(project_file: &str, exercise: &str, name: &str, handed_in: &str) -> String {
        let quote = |s: &str| serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into());
        let rest = project_file.trim_start().strip_prefix('{').unwrap_or(project_file);
        format!(
            "{{\n  \"hand_in\": {{\n    \"exercise\": {},\n    \"name\": {},\n    \"handed_in\": {}\n  }},{rest}",
            quote(exercise),
            quote(name.trim()),
            quote(handed_in)
        )
    }

    /// Whether `text` is a hand-in (a JSON object with a `hand_in` key) rather than a
    /// plain project file.
    pub fn is_hand_in(text: &str) -> bool {
        serde_json::from_str::<Header>(text).is_ok_and(|h| h.hand_in.is_some())
    }

    /// Reads a hand-in file; a file without its keys, or whose project does not read, is
    /// refused with the reason.
    pub fn from_file(text: &str) -> Result<HandIn, ExerciseError> {
        let fail = |m: String| ExerciseError { message: m };
        let header: Header = serde_json::from_str(text)
            .map_err(|e| fail(format!("this is not a hand-in file (not JSON: {e})")))?;
        let missing = |key: &str| fail(format!("this hand-in file has no `{key}`"));
        let keys = header.hand_in.ok_or_else(|| missing("hand_in"))?;
        let exercise = keys.exercise.ok_or_else(|| missing("exercise"))?;
        let name = keys.name.ok_or_else(|| missing("name"))?;
        let handed_in = keys.handed_in.ok_or_else(|| missing("handed_in"))?;
        let project = Project::from_file(text).map_err(|e| fail(e.to_string()))?;
        Ok(HandIn { exercise, name, handed_in, project })
    }

    /// The file name a hand-in is downloaded as: `EXERCISE-ID--NAME.plcsub`, the name
    /// reduced to letters, digits, `_` and `.` with single dashes between its words (so
    /// `--` only ever separates the id from the name).
    pub fn file_name(exercise: &str, name: &str) -> String {
        let mut clean = String::new();
        for c in name.chars() {
            if c.is_alphanumeric() || c == '_' || c == '.' {
                clean.push(c);
            } else if !clean.is_empty() && !clean.ends_with('-') {
                clean.push('-');
            }
        }
        let clean = clean.trim_matches(['-', '.']);
        let clean = if clean.is_empty() { "student" } else { clean };
        format!("{exercise}--{clean}.{HAND_IN_EXTENSION}")
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn a_hand_in_is_a_project_file_with_its_exercise_name_and_time() {
        let mut project = Project::new("Exercise: Latch");
        project.source = "PROGRAM Main END_PROGRAM".into();
        let text = HandIn::file_text(
            &project.to_file(),
            "latch",
            " Ada \"A\" Lovelace ",
            "2025-01-02T03:04:05.000Z",
        );
        let head = "{\n  \"hand_in\": {\n    \"exercise\": \"latch\",\n    \"name\": \"Ada \\\"A\\\" Lovelace\",\n";
        assert!(text.starts_with(head), "{text}");
        assert!(serde_json::from_str::<serde_json::Value>(&text).is_ok(), "{text}");
        assert!(HandIn::is_hand_in(&text));
        let back = HandIn::from_file(&text).unwrap();
        assert_eq!(
            (back.exercise.as_str(), back.name.as_str(), back.handed_in.as_str()),
            ("latch", "Ada \"A\" Lovelace", "2025-01-02T03:04:05.000Z")
        );
        assert_eq!(back.project, project);
        // It opens as a project wherever a project does.
        assert_eq!(Project::from_file(&text).unwrap(), project);
        assert!(!HandIn::is_hand_in(&project.to_file()));
    }

    #[test]
    fn damaged_hand_ins_are_refused_with_the_reason() {
        let e = |t: &str| HandIn::from_file(t).unwrap_err().message;
        assert!(e("nonsense").starts_with("this is not a hand-in file (not JSON"));
        assert_eq!(e(r#"{"schema": 1}"#), "this hand-in file has no `hand_in`");
        assert_eq!(
            e(r#"{"hand_in": {"exercise": "latch", "handed_in": "x"}}"#),
            "this hand-in file has no `name`"
        );
        let no_project = r#"{"hand_in": {"exercise": "latch", "name": "A", "handed_in": "x"}}"#;
        assert_eq!(e(no_project), "this JSON file is not a PLC trainer project");
    }

    #[test]
    fn the_file_name_carries_the_exercise_and_a_clean_name() {
        assert_eq!(HandIn::file_name("latch", "Ada Lovelace"), "latch--Ada-Lovelace.plcsub");
        assert_eq!(
            HandIn::file_name("two-hand", "  Zoë   O'Neil / B2 "),
            "two-hand--Zoë-O-Neil-B2.plcsub"
        );
        assert_eq!(HandIn::file_name("latch", "../.."), "latch--student.plcsub");
        assert_eq!(HandIn::file_name("latch", "a--b"), "latch--a-b.plcsub");
    }
}
