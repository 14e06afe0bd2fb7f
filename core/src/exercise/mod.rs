//! Exercises that grade themselves (issue 15): the exercise file format (TOML, see
//! `docs/exercises.md`) and the grader, which runs a submission's scenarios on the one VM
//! with virtual time.

mod format;
mod grade;
mod interface;
mod link;
mod random;
mod starter;
mod statement;
mod view;

pub use format::{
    parse_duration, scenarios_from_toml, time_text, Direction, Exercise, ExerciseError, Expect,
    Expectation, InterfaceVar, Random, RandomInput, Restart, Scenario, Step,
};
pub use grade::{
    grade, grade_by, grade_with, Failure, GradeOptions, Report, Sample, ScenarioReport,
};
pub use interface::interface_declarations;
pub use link::{ExerciseLink, LinkedFile, EXERCISE_LINK_PREFIX};
pub use starter::{graded_program, Language};
pub use statement::{next_to, statement_html};
pub use view::{ExerciseView, ScenarioView};

#[cfg(test)]
mod tests;
