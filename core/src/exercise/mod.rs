//! Exercises that grade themselves (issue 15): the exercise file format (TOML, see
//! `docs/exercises.md`) and the grader, which runs a submission's scenarios on the one VM
//! with virtual time.

mod built_form;
mod format;
mod grade;
mod handin;
mod interface;
mod link;
mod localise;
mod random;
mod scorm;
mod sentence;
mod starter;
mod statement;
mod translation;
mod view;

pub use built_form::{built_form, is_built, BUILT_PREFIX};
pub use format::{
    parse_duration, scenarios_from_toml, time_text, Direction, Exercise, ExerciseError, Expect,
    Expectation, InterfaceVar, Random, RandomInput, Restart, Scenario, SetValue, Step,
};
pub use grade::{
    grade, grade_by, grade_with, Failure, GradeOptions, Report, Sample, ScenarioReport,
};
pub use handin::{HandIn, HAND_IN_EXTENSION};
pub use interface::interface_declarations;
pub use link::{ExerciseLink, LinkedFile, EXERCISE_LINK_PREFIX};
pub use scorm::{
    scorm_files, scorm_launch, scorm_manifest, scorm_package, PackageFile, ScormVersion,
    SCORM_12_SUSPEND_LIMIT, SCORM_EXERCISE_DIR, SITE_FILE_LIST,
};
pub use sentence::Sentence;
pub use starter::{graded_program, Language};
pub use statement::{next_to, statement_html};
pub use translation::{ScenarioTranslation, Translation, TRANSLATED};
pub use view::{ExerciseView, ScenarioView};

#[cfg(test)]
mod tests;
