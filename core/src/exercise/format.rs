//! The exercise file: one TOML file per exercise (`docs/exercises.md` describes it with a
//! complete example). Read with the `toml` crate into these types, then checked: every
//! duration reads, every expectation says exactly one thing. Errors name the line and
//! column in the file, or the scenario and expectation they are about.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;

/// An exercise as its file gives it.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// A short identifier (`latch`).
    pub id: String,
    /// The title.
    pub title: String,
    /// 1 (beginner) … 5 (advanced).
    pub level: u8,
    /// Its place among the exercises of its level in the catalogue (those without one
    /// come after, by title).
    #[serde(default)]
    pub order: Option<u32>,
    /// The languages a solution may use: `st`, `ld`, `petri`, `sfc`.
    #[serde(default)]
    pub languages: Vec<String>,
    /// The task, in Markdown.
    #[serde(default)]
    pub statement: String,
    /// The PROGRAM the exercise grades (`Main`) when the student has not chosen another;
    /// by default the one the starter declares.
    #[serde(default)]
    pub program: Option<String>,
    /// The starter project in the first of `languages`: a file next to the exercise
    /// (project, ST or PLCopen XML).
    #[serde(default)]
    pub starter: Option<String>,
    /// The starter in Structured Text, when it is not `starter` (else made from the
    /// interface).
    #[serde(default)]
    pub starter_st: Option<String>,
    /// The starter in ladder (a project file with a ladder PROGRAM).
    #[serde(default)]
    pub starter_ld: Option<String>,
    /// The starter as a Petri net (a project file with a Petri net PROGRAM).
    #[serde(default)]
    pub starter_petri: Option<String>,
    /// The starter as a textual SFC (an ST file).
    #[serde(default)]
    pub starter_sfc: Option<String>,
    /// The reference solution: a file next to the exercise.
    #[serde(default)]
    pub reference: Option<String>,
    /// A reference solution in Structured Text, besides `reference`.
    #[serde(default)]
    pub reference_st: Option<String>,
    /// A reference solution in ladder, besides `reference`.
    #[serde(default)]
    pub reference_ld: Option<String>,
    /// A reference solution as a Petri net, besides `reference`.
    #[serde(default)]
    pub reference_petri: Option<String>,
    /// A reference solution as a textual SFC, besides `reference`.
    #[serde(default)]
    pub reference_sfc: Option<String>,
    /// The variables the solution must declare.
    #[serde(default)]
    pub interface: Vec<InterfaceVar>,
    /// The scenarios that grade it.
    #[serde(default, rename = "scenario")]
    pub scenarios: Vec<Scenario>,
    /// The plant the solution drives (`docs/plants.md`): the exercise's own, always — the
    /// grader replaces any copy a submission carries.
    #[serde(default)]
    pub plant: Option<ExercisePlant>,
    /// The exercise in other languages (`[lang.pl]`, `[lang.cs]`): whatever a translation
    /// leaves out is shown in English, the top-level fields (see
    /// [`Exercise::localised`]).
    #[serde(default)]
    pub lang: BTreeMap<String, super::translation::Translation>,
}

/// A plant an exercise ships: its PROGRAM, run after the solution on every scan, and the
/// scene the exercise page draws beside the editor. Written inline in the exercise file,
/// so a link carries it.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExercisePlant {
    /// The plant PROGRAM's name (`TankPlant`).
    pub name: String,
    /// Its ST source: the PROGRAM, and any POU it needs.
    pub source: String,
    /// The scene drawn beside the editor.
    #[serde(default)]
    pub scene: Option<crate::project::Scene>,
}

/// One variable of the interface.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InterfaceVar {
    /// Its name.
    pub name: String,
    /// Its IEC type (`BOOL`, `INT`).
    #[serde(rename = "type")]
    pub ty: String,
    /// `input` (VAR_INPUT) or `output` (VAR_OUTPUT).
    pub direction: Direction,
    /// What it means, in one line.
    #[serde(default)]
    pub meaning: String,
}

/// Whether an interface variable is an input or an output of the solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Direction {
    /// Set by the scenario (VAR_INPUT).
    Input,
    /// Checked by the scenario (VAR_OUTPUT).
    Output,
}

/// A scenario: inputs set at times, expectations on the outputs.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Its name, shown in the report.
    pub name: String,
    /// The PLC cycle (`10ms`, the default).
    #[serde(default)]
    pub cycle: Option<String>,
    /// How long it runs (default: one cycle past the last time it mentions).
    #[serde(default)]
    pub duration: Option<String>,
    /// Its share of the score (default 1).
    #[serde(default = "one")]
    pub weight: u32,
    /// Shown when it fails.
    #[serde(default)]
    pub hint: Option<String>,
    /// Inputs set at times.
    #[serde(default, rename = "step")]
    pub steps: Vec<Step>,
    /// What must hold.
    #[serde(default, rename = "expect")]
    pub expectations: Vec<Expect>,
    /// Run this many times with input events drawn at random (`never` and `always`
    /// expectations only): safety rules checked against many input histories.
    #[serde(default)]
    pub random: Option<Random>,
    /// The inputs a random scenario drives, and how.
    #[serde(default, rename = "input")]
    pub inputs: Vec<RandomInput>,
}

/// How many random runs, from which seed (run `k` uses seed `seed + k`, so a failing run
/// is replayed with `runs = 1` and its seed).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Random {
    /// How many runs.
    pub runs: u32,
    /// The first run's seed.
    pub seed: u64,
}

/// An input a random scenario drives: BOOL `pulse`s of a random length at random times, or
/// a random `walk` of a number between two bounds.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomInput {
    /// The input.
    pub name: String,
    /// Pulse lengths (and the gaps between pulses) between these two durations.
    #[serde(default)]
    pub pulse: Option<[String; 2]>,
    /// The walk stays between these two values.
    #[serde(default)]
    pub walk: Option<[f64; 2]>,
    /// The walk's largest step (default: a tenth of its range).
    #[serde(default)]
    pub step: Option<f64>,
    /// How often the walk moves (default 100 ms).
    #[serde(default)]
    pub every: Option<String>,
}

fn one() -> u32 {
    1
}

/// Inputs set from a time on, or a restart of the PLC at that time.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    /// When (`1.5s`, `200ms`, `T#2s`).
    pub at: String,
    /// Input → value (a TOML boolean or number, or an IEC literal as a string).
    #[serde(default)]
    pub set: BTreeMap<String, SetValue>,
    /// A power cycle at `at`, before the inputs are set: `warm` (RETAIN variables keep
    /// their values) or `cold` (everything back to its initial value). Held inputs stay.
    #[serde(default)]
    pub restart: Option<Restart>,
}

/// The value a step sets an input to: a boolean, an integer or a float as TOML writes
/// them, or an IEC literal as a string (`T#2s`, `16#FF`). Read by hand rather than as a
/// `toml::Value`, so that the exercise's built form (JSON) reads without the TOML crate,
/// and an array, a table or a date is refused where the file gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum SetValue {
    /// `true` / `false`.
    Bool(bool),
    /// A whole number.
    Int(i64),
    /// A number with a fraction or an exponent.
    Float(f64),
    /// An IEC literal, as written.
    Literal(String),
}

impl SetValue {
    /// The IEC literal the simulator takes.
    pub fn literal(&self) -> String {
        match self {
            SetValue::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
            SetValue::Int(i) => i.to_string(),
            SetValue::Float(f) => format!("{f:?}"),
            SetValue::Literal(s) => s.clone(),
        }
    }
}

impl<'de> Deserialize<'de> for SetValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = SetValue;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a boolean, a number or an IEC literal in quotes")
            }
            fn visit_bool<E: serde::de::Error>(self, v: bool) -> Result<SetValue, E> {
                Ok(SetValue::Bool(v))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<SetValue, E> {
                Ok(SetValue::Int(v))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<SetValue, E> {
                i64::try_from(v).map(SetValue::Int).map_err(|_| {
                    E::invalid_value(serde::de::Unexpected::Unsigned(v), &"a 64-bit integer")
                })
            }
            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<SetValue, E> {
                Ok(SetValue::Float(v))
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<SetValue, E> {
                Ok(SetValue::Literal(v.to_string()))
            }
        }
        d.deserialize_any(Visitor)
    }
}

/// The kind of a restart a step asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Restart {
    /// RETAIN variables keep their values.
    Warm,
    /// Every variable back to its initial value.
    Cold,
}

/// One expectation as written: exactly one of `that` (with `at`), `becomes`, `holds` (both
/// with `from` and `to`), `never` and `always`, each a BOOL ST expression over the interface.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expect {
    /// TRUE at time `at`.
    pub that: Option<String>,
    /// The time of `that`.
    pub at: Option<String>,
    /// Becomes TRUE (FALSE on one scan, TRUE on the next) between `from` and `to`, not
    /// before.
    pub becomes: Option<String>,
    /// TRUE throughout `from` … `to`.
    pub holds: Option<String>,
    /// Never TRUE.
    pub never: Option<String>,
    /// Always TRUE.
    pub always: Option<String>,
    /// Start of the window of `becomes` and `holds`.
    pub from: Option<String>,
    /// End of the window.
    pub to: Option<String>,
}

/// A checked expectation, times in nanoseconds.
#[derive(Debug, Clone, PartialEq)]
pub enum Expectation {
    /// `condition` is TRUE at `at`.
    At {
        /// The condition.
        condition: String,
        /// When.
        at: i64,
    },
    /// `condition` rises (FALSE on one scan, TRUE on the next) at a time in `from ..= to`,
    /// and not before.
    Becomes {
        /// The condition.
        condition: String,
        /// Window start.
        from: i64,
        /// Window end.
        to: i64,
    },
    /// `condition` is TRUE at every scan in `from ..= to`.
    Holds {
        /// The condition.
        condition: String,
        /// Window start.
        from: i64,
        /// Window end.
        to: i64,
    },
    /// `condition` is TRUE at no scan.
    Never {
        /// The condition.
        condition: String,
    },
    /// `condition` is TRUE at every scan.
    Always {
        /// The condition.
        condition: String,
    },
}

impl Expectation {
    /// The condition it is about.
    pub fn condition(&self) -> &str {
        match self {
            Expectation::At { condition, .. }
            | Expectation::Becomes { condition, .. }
            | Expectation::Holds { condition, .. }
            | Expectation::Never { condition }
            | Expectation::Always { condition } => condition,
        }
    }

    /// What the condition should be on the scan that ends at `t` (ns) with cycle `cycle`:
    /// `None` where any value is right. `that` is checked on the first scan ending at or
    /// after its time; `becomes` is FALSE before its window and TRUE after it.
    pub fn expected_at(&self, t: i64, cycle: i64) -> Option<bool> {
        match self {
            Expectation::At { at, .. } => {
                (t >= *at && t < at.saturating_add(cycle)).then_some(true)
            }
            Expectation::Becomes { from, to, .. } => {
                if t < *from {
                    Some(false)
                } else if t > *to {
                    Some(true)
                } else {
                    None
                }
            }
            Expectation::Holds { from, to, .. } => (t >= *from && t <= *to).then_some(true),
            Expectation::Never { .. } => Some(false),
            Expectation::Always { .. } => Some(true),
        }
    }

    /// How a report says it (`Lamp becomes TRUE between 1.9 s and 2.1 s`).
    pub fn describe(&self) -> String {
        self.said().english
    }

    /// [`Expectation::describe`] as a message (the report's `expected`, translated).
    pub fn said(&self) -> crate::diagnostics::Said {
        let t = |ns: &i64| time_text(*ns);
        match self {
            Expectation::At { condition, at } => {
                crate::msg!(GradeExpectAt, condition = condition, at = t(at))
            }
            Expectation::Becomes { condition, from, to } => {
                crate::msg!(GradeExpectBecomes, condition = condition, from = t(from), to = t(to))
            }
            Expectation::Holds { condition, from, to } => {
                crate::msg!(GradeExpectHolds, condition = condition, from = t(from), to = t(to))
            }
            Expectation::Never { condition } => {
                crate::msg!(GradeExpectNever, condition = condition)
            }
            Expectation::Always { condition } => {
                crate::msg!(GradeExpectAlways, condition = condition)
            }
        }
    }
}

/// Why an exercise file cannot be used.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExerciseError {
    /// The message, with its place (`line 4, column 7: …`, `scenario "Start": …`).
    pub message: String,
}

impl fmt::Display for ExerciseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ExerciseError {}

/// Reads a duration: `1.5s`, `200ms`, `2min`, `1h`, or an IEC TIME literal (`T#1s500ms`).
pub fn parse_duration(text: &str) -> Result<i64, String> {
    let t = text.trim();
    let iec = t.strip_prefix("T#").or_else(|| t.strip_prefix("t#"));
    let iec = iec.or_else(|| t.strip_prefix("TIME#")).or_else(|| t.strip_prefix("time#"));
    if let Some(rest) = iec {
        let lit = crate::syntax::parse_expression(&format!("T#{rest}"))
            .map_err(|_| format!("“{text}” is not a TIME literal"))?;
        if let crate::syntax::ExprKind::Literal(l) = &lit.kind {
            if let crate::syntax::ast::LiteralValue::Time(ns) = l.value {
                return Ok(ns);
            }
        }
        return Err(format!("“{text}” is not a TIME literal"));
    }
    let split = t.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(t.len());
    let (number, unit) = t.split_at(split);
    let value: f64 =
        number.parse().map_err(|_| format!("“{text}” is not a duration (e.g. 1.5s, 200ms)"))?;
    let scale = match unit.trim() {
        "ns" => 1.0,
        "us" | "µs" => 1e3,
        "ms" => 1e6,
        "s" => 1e9,
        "min" | "m" => 60e9,
        "h" => 3600e9,
        _ => return Err(format!("“{text}” has no unit: write ms, s, min or h")),
    };
    let ns = value * scale;
    if !ns.is_finite() || ns > i64::MAX as f64 / 2.0 {
        return Err(format!("“{text}” is too long"));
    }
    Ok(ns.round() as i64)
}

/// A time for a report: seconds without trailing zeros (`1.9 s`, `2 s`, `0.05 s`).
pub fn time_text(ns: i64) -> String {
    let s = format!("{:.6}", ns as f64 / 1e9);
    format!("{} s", s.trim_end_matches('0').trim_end_matches('.'))
}

/// 1-based line and column of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The codes of the languages an exercise can be written in (`languages = […]`), in the
/// order of `starter::Language::ALL` (which reads its codes from here).
pub(super) const LANGUAGE_CODES: [&str; 4] = ["st", "ld", "petri", "sfc"];

impl Exercise {
    /// Reads an exercise file (TOML).
    pub fn from_toml(text: &str) -> Result<Exercise, ExerciseError> {
        let exercise: Exercise = toml::from_str(text).map_err(|e| {
            let place = e.span().map(|s| line_column(text, s.start));
            let message = e.message().to_string();
            ExerciseError {
                message: match place {
                    Some((l, c)) => format!("line {l}, column {c}: {message}"),
                    None => message,
                },
            }
        })?;
        if let Some(key) =
            exercise.lang.iter().find(|(_, t)| t.statement_html.is_some()).map(|(k, _)| k)
        {
            return Err(ExerciseError {
                message: format!(
                    "lang.{key}: `statement_html` is the built form's; write the Markdown as `statement`"
                ),
            });
        }
        exercise.checked()
    }

    /// Reads an exercise in the built form (`built_form.rs`): the exercise, whose
    /// `statement` is empty, and its statement as HTML. Checked as a TOML file is.
    pub fn from_built(text: &str) -> Result<(Exercise, String), ExerciseError> {
        #[derive(Deserialize)]
        #[serde(deny_unknown_fields)]
        struct Built {
            #[allow(dead_code)]
            plc_exercise: u32,
            statement_html: String,
            exercise: Exercise,
        }
        let built: Built = serde_json::from_str(text).map_err(|e| ExerciseError {
            message: format!("the built exercise cannot be read: {e}"),
        })?;
        Ok((built.exercise.checked()?, built.statement_html))
    }

    /// Reads an exercise file, TOML or the built form.
    pub fn from_text(text: &str) -> Result<Exercise, ExerciseError> {
        if super::built_form::is_built(text) {
            Ok(Exercise::from_built(text)?.0)
        } else {
            Exercise::from_toml(text)
        }
    }

    /// The exercise, if everything it says can be used.
    fn checked(self) -> Result<Exercise, ExerciseError> {
        let exercise = self;
        if !(1..=5).contains(&exercise.level) {
            return Err(ExerciseError { message: "level is 1 (beginner) to 5 (advanced)".into() });
        }
        if let Some(code) = exercise
            .languages
            .iter()
            .find(|code| !LANGUAGE_CODES.iter().any(|c| c.eq_ignore_ascii_case(code.trim())))
        {
            return Err(ExerciseError {
                message: format!("languages: “{code}” is not one of st, ld, petri, sfc"),
            });
        }
        if let Some(name) = exercise.program.as_deref() {
            if !crate::syntax::is_identifier(name) {
                return Err(ExerciseError {
                    message: format!("program: “{name}” is not a PROGRAM name"),
                });
            }
        }
        for s in &exercise.scenarios {
            s.check()?;
        }
        for key in exercise.lang.keys() {
            if !super::translation::TRANSLATED.iter().any(|l| l.tag() == key) {
                return Err(ExerciseError {
                    message: format!(
                        "lang.{key}: the translations are [lang.pl] and [lang.cs] (English is the top-level fields)"
                    ),
                });
            }
        }
        if let Some(plant) = &exercise.plant {
            let (file, _) = crate::syntax::parse(&plant.source);
            let named = file.items.iter().any(|item| {
                matches!(item, crate::syntax::ast::Item::Pou(p)
                    if p.kind == crate::syntax::ast::PouKind::Program
                        && p.name.name.eq_ignore_ascii_case(&plant.name))
            });
            if !named {
                return Err(ExerciseError {
                    message: format!("the plant's source has no PROGRAM {}", plant.name),
                });
            }
        }
        Ok(exercise)
    }

    /// `project` as the exercise runs it: with the exercise's plant (when it has one) in
    /// place of any POU of the plant's name, named as the plant in the settings, and its
    /// scene. The student's own PROGRAM stays the one that runs.
    pub fn with_plant(&self, project: &crate::project::Project) -> crate::project::Project {
        self.with_plant_by(project, &crate::build::Lowerings::ALL)
    }

    /// [`Exercise::with_plant`], building the project with the given passes for its
    /// diagram POUs (to find the PROGRAM that runs).
    pub fn with_plant_by(
        &self,
        project: &crate::project::Project,
        lowerings: &crate::build::Lowerings,
    ) -> crate::project::Project {
        let mut project = project.clone();
        let Some(plant) = &self.plant else { return project };
        let (file, _) = crate::syntax::parse(&project.source);
        let mut spans: Vec<(usize, usize)> = file
            .items
            .iter()
            .filter_map(|item| match item {
                crate::syntax::ast::Item::Pou(p)
                    if p.name.name.eq_ignore_ascii_case(&plant.name) =>
                {
                    Some((p.span.start as usize, p.span.end as usize))
                }
                _ => None,
            })
            .collect();
        spans.sort_unstable();
        for (start, end) in spans.into_iter().rev() {
            if start <= end && end <= project.source.len() {
                project.source.replace_range(start..end, "");
            }
        }
        if project.settings.program.is_none() {
            // The PROGRAM that ran before the plant joined (the first one) keeps running.
            let names = crate::build::build_project_by(&project, lowerings).program_names();
            project.settings.program = names.into_iter().next();
        }
        let source = project.source.trim_end();
        project.source = if source.is_empty() {
            format!("{}\n", plant.source.trim_end())
        } else {
            format!("{source}\n\n{}\n", plant.source.trim_end())
        };
        project.settings.plant = Some(plant.name.clone());
        if plant.scene.is_some() {
            project.scene = plant.scene.clone();
        }
        project
    }
}

/// The scenarios of a second file of the same form (the hidden scenarios an instructor
/// keeps): its `[[scenario]]` tables; whatever else it says is not read.
pub fn scenarios_from_toml(text: &str) -> Result<Vec<Scenario>, ExerciseError> {
    #[derive(Deserialize)]
    struct Only {
        #[serde(default, rename = "scenario")]
        scenarios: Vec<Scenario>,
    }
    let only: Only = toml::from_str(text).map_err(|e| {
        let place = e.span().map(|s| line_column(text, s.start));
        ExerciseError {
            message: match place {
                Some((l, c)) => format!("line {l}, column {c}: {}", e.message()),
                None => e.message().to_string(),
            },
        }
    })?;
    for s in &only.scenarios {
        s.check()?;
    }
    Ok(only.scenarios)
}

impl Scenario {
    /// Checks everything a scenario says can be used.
    fn check(&self) -> Result<(), ExerciseError> {
        let expectations = self.expectations()?;
        self.cycle_ns()?;
        let fail =
            |m: String| ExerciseError { message: format!("scenario “{}”: {m}", self.name) };
        for step in &self.steps {
            self.time(&step.at, "step")?;
            if step.set.is_empty() && step.restart.is_none() {
                return Err(fail(format!(
                    "the step at {} neither sets inputs (set = {{ … }}) nor restarts (restart = \"warm\" or \"cold\")",
                    step.at
                )));
            }
        }
        let runs = i64::from(self.random.map_or(1, |r| r.runs.max(1)));
        let scans = (self.duration_ns()? / self.cycle_ns()?).saturating_add(1).saturating_mul(runs);
        if scans > crate::limits::EXERCISE_MAX_SCANS {
            return Err(fail(format!(
                "it asks for {scans} scans, more than {} (shorten it, lengthen the cycle or make fewer runs)",
                crate::limits::EXERCISE_MAX_SCANS
            )));
        }
        if self.random.is_some() {
            if self.duration.is_none() {
                return Err(fail("a random scenario says how long it runs (`duration`)".into()));
            }
            let safety = expectations
                .iter()
                .all(|e| matches!(e, Expectation::Never { .. } | Expectation::Always { .. }));
            if !safety {
                return Err(fail("a random scenario checks only `never` and `always`".into()));
            }
            for i in &self.inputs {
                match (&i.pulse, &i.walk) {
                    (Some([a, b]), None) => {
                        let (a, b) = (self.time(a, "pulse")?, self.time(b, "pulse")?);
                        if a <= 0 || b < a {
                            return Err(fail(format!(
                                "input {}: the pulse range is wrong",
                                i.name
                            )));
                        }
                    }
                    (None, Some([lo, hi])) if lo <= hi => {
                        if let Some(e) = &i.every {
                            self.time(e, "every")?;
                        }
                    }
                    _ => {
                        return Err(fail(format!(
                            "input {}: give `pulse = [\"MIN\", \"MAX\"]` or `walk = [LOW, HIGH]`",
                            i.name
                        )))
                    }
                }
            }
        } else if !self.inputs.is_empty() {
            return Err(fail("`input` drives random scenarios only: add `random`".into()));
        }
        Ok(())
    }

    pub(super) fn time(&self, text: &str, what: &str) -> Result<i64, ExerciseError> {
        parse_duration(text).map_err(|m| ExerciseError {
            message: format!("scenario “{}”, {what}: {m}", self.name),
        })
    }

    /// The cycle time in nanoseconds (10 ms unless given).
    pub fn cycle_ns(&self) -> Result<i64, ExerciseError> {
        match &self.cycle {
            None => Ok(10_000_000),
            Some(c) => {
                let ns = self.time(c, "cycle")?;
                if ns <= 0 {
                    return Err(ExerciseError {
                        message: format!("scenario “{}”: the cycle is longer than 0", self.name),
                    });
                }
                Ok(ns)
            }
        }
    }

    /// The checked expectations, in order.
    pub fn expectations(&self) -> Result<Vec<Expectation>, ExerciseError> {
        self.expectations
            .iter()
            .enumerate()
            .map(|(i, e)| {
                let fail = |m: &str| ExerciseError {
                    message: format!("scenario “{}”, expectation {}: {m}", self.name, i + 1),
                };
                let time = |t: &Option<String>, what: &str| -> Result<i64, ExerciseError> {
                    let t = t.as_deref().ok_or_else(|| fail(&format!("give `{what}`")))?;
                    parse_duration(t).map_err(|m| fail(&m))
                };
                let given = [&e.that, &e.becomes, &e.holds, &e.never, &e.always]
                    .iter()
                    .filter(|x| x.is_some())
                    .count();
                if given != 1 {
                    return Err(fail(
                        "give exactly one of `that` (with `at`), `becomes`, `holds` (with `from` and `to`), `never`, `always`",
                    ));
                }
                Ok(if let Some(c) = &e.that {
                    Expectation::At { condition: c.clone(), at: time(&e.at, "at")? }
                } else if let Some(c) = &e.becomes {
                    let (from, to) = (time(&e.from, "from")?, time(&e.to, "to")?);
                    Expectation::Becomes { condition: c.clone(), from, to }
                } else if let Some(c) = &e.holds {
                    let (from, to) = (time(&e.from, "from")?, time(&e.to, "to")?);
                    Expectation::Holds { condition: c.clone(), from, to }
                } else if let Some(c) = &e.never {
                    Expectation::Never { condition: c.clone() }
                } else {
                    Expectation::Always { condition: e.always.clone().unwrap_or_default() }
                })
            })
            .collect()
    }

    /// How long it runs: `duration`, or one cycle past the last time it mentions.
    pub fn duration_ns(&self) -> Result<i64, ExerciseError> {
        if let Some(d) = &self.duration {
            return self.time(d, "duration");
        }
        let mut last = 0;
        for s in &self.steps {
            last = last.max(self.time(&s.at, "step")?);
        }
        for e in self.expectations()? {
            last = last.max(match e {
                Expectation::At { at, .. } => at,
                Expectation::Becomes { to, .. } | Expectation::Holds { to, .. } => to,
                Expectation::Never { .. } | Expectation::Always { .. } => 0,
            });
        }
        Ok(last + self.cycle_ns()?)
    }
}
