//! Exercises that grade themselves (issue 15): the exercise file format (TOML, see
//! `docs/exercises.md`) and the grader, which runs a submission's scenarios on the one VM
//! with virtual time.

mod format;
mod grade;
mod random;

pub use format::{
    parse_duration, scenarios_from_toml, time_text, Direction, Exercise, ExerciseError, Expect,
    Expectation, InterfaceVar, Random, RandomInput, Scenario, Step,
};
pub use grade::{grade, Failure, Report, Sample, ScenarioReport};

#[cfg(test)]
mod tests;
