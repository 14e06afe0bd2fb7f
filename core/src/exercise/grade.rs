//! The grader: runs each scenario of an exercise on a submission (a project), on the one
//! VM and its virtual clock, and reports per scenario whether it passed — for a failure
//! the first wrong expectation (the condition, what it was and should have been, at what
//! time and scan) and the interface's values on the scans around it — and a score out of
//! the weights. Deterministic: the same submission gives the same report.

use std::collections::VecDeque;

use serde::{Deserialize, Serialize};

use crate::build::{build_project_by, Lowerings, Site};
use crate::export::value_text;
use crate::program::Slot;
use crate::project::Project;
use crate::sim::{ProbeId, ScanOutcome, Simulator};
use crate::syntax::VarSection;
use crate::vm::Value;

use super::format::{time_text, Direction, Exercise, ExerciseError, Expectation, Scenario};
use super::random::RESTART;
use super::sentence::Sentence;
use crate::diagnostics::{Arg, Said};

/// How much a report tells.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GradeOptions {
    /// Scans shown before and after the first wrong one (5 for the command line; the
    /// page's timeline shows more).
    pub window: usize,
}

impl Default for GradeOptions {
    fn default() -> Self {
        GradeOptions { window: 5 }
    }
}

/// The interface's values after one scan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// The scan (1-based, counted across restarts).
    pub scan: u64,
    /// The virtual time at its end, in nanoseconds (from the scenario's start).
    pub time_ns: i64,
    /// `(variable, value)` for every interface variable, in interface order.
    pub values: Vec<(String, String)>,
    /// The failing expectation's condition on this scan (`None` for a FAULT).
    pub actual: Option<bool>,
    /// What it should have been (`None`: any value is right).
    pub expected: Option<bool>,
}

/// The first wrong expectation of a scenario.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Failure {
    /// The condition that was wrong (`Motor`), or `None` for a FAULT.
    pub condition: Option<String>,
    /// What was expected (`Motor is TRUE at 0.2 s`).
    pub expected: String,
    /// What happened (`Motor was FALSE at 0.2 s (scan 20)`).
    pub actual: String,
    /// The scan it was seen on (0: before the first, or the program did not run).
    pub scan: u64,
    /// Its time in nanoseconds.
    pub time_ns: i64,
    /// The interface around it.
    pub window: Vec<Sample>,
    /// `expected` as data, to be shown in another language.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expected_msg: Option<Sentence>,
    /// `actual` as data.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub actual_msg: Option<Sentence>,
}

/// One scenario's result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ScenarioReport {
    /// Its name.
    pub name: String,
    /// Its weight.
    pub weight: u32,
    /// Why it failed (`None`: passed).
    pub failure: Option<Failure>,
    /// The exercise's hint, for a failure.
    pub hint: Option<String>,
}

impl ScenarioReport {
    /// Whether it passed.
    pub fn passed(&self) -> bool {
        self.failure.is_none()
    }

    /// A failed scenario as `plc grade` prints it, in `lang`: `FAIL Start: expected Motor
    /// is TRUE at 0.2 s; Motor was FALSE at 0.2 s (scan 20)`.
    pub fn fail_line(&self, lang: crate::i18n::Lang) -> Option<String> {
        let f = self.failure.as_ref()?;
        let text =
            |s: &Option<Sentence>, en: &String| s.as_ref().map_or(en.clone(), |s| s.render(lang));
        let said = crate::msg!(
            GradeFailLine,
            name = self.name,
            expected = text(&f.expected_msg, &f.expected),
            actual = text(&f.actual_msg, &f.actual)
        );
        Some(said.message.render(lang))
    }

    /// Its hint as `plc grade` prints it, in `lang`: `hint: …`.
    pub fn hint_line(&self, lang: crate::i18n::Lang) -> Option<String> {
        let hint = self.hint.as_ref()?;
        Some(crate::msg!(GradeHintLine, hint = hint).message.render(lang))
    }
}

/// A submission's grade.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// The PROGRAM graded (`Latch`), when the submission has one.
    #[serde(default)]
    pub program: Option<String>,
    /// The language it is written in, as a report names it (`ST`, `ladder`, `Petri net`,
    /// `SFC`, `IL`, `network`).
    #[serde(default)]
    pub language: Option<String>,
    /// Why nothing could run (the project does not build, has no PROGRAM …), located.
    pub error: Option<String>,
    /// `error` as data, to be shown in another language.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error_msg: Option<Sentence>,
    /// Per scenario.
    pub scenarios: Vec<ScenarioReport>,
    /// The weights of the passed scenarios.
    pub score: u32,
    /// All the weights.
    pub total: u32,
}

impl Report {
    /// What was graded, the report's first line: `Checked PROGRAM Latch (ladder)`.
    pub fn checked_line(&self) -> Option<String> {
        self.checked().map(|s| s.english)
    }

    /// Why nothing could run, in `lang`.
    pub fn error_in(&self, lang: crate::i18n::Lang) -> Option<String> {
        self.error_msg.as_ref().map(|s| s.render(lang)).or_else(|| self.error.clone())
    }

    /// [`Report::checked_line`] as a message (the language's name translated).
    pub fn checked(&self) -> Option<Said> {
        let program = self.program.as_deref()?;
        Some(match self.language.as_deref() {
            Some(language) => {
                let language = match language {
                    "ladder" => Arg::Msg(crate::phrase!(GradeLanguageLadder)),
                    "Petri net" => Arg::Msg(crate::phrase!(GradeLanguagePetriNet)),
                    "network" => Arg::Msg(crate::phrase!(GradeLanguageNetwork)),
                    other => Arg::Text(other.to_string()),
                };
                crate::msg!(GradeCheckedIn, program = program, language = language)
            }
            None => crate::msg!(GradeChecked, program = program),
        })
    }

    /// The score, with the scenarios' weights when they explain it: `Score 1 of 3
    /// (scenario weights: 2 + 1)` when the weights differ, `Score 2 of 4 (4 scenarios, 1
    /// point each)` when they do not; just `Score 3 of 3` with every scenario passed or
    /// a single scenario.
    pub fn score_line(&self) -> String {
        self.score_said().english
    }

    /// [`Report::score_line`] as a message.
    pub fn score_said(&self) -> Said {
        let (score, total) = (self.score, self.total);
        let weights: Vec<u32> = self.scenarios.iter().map(|s| s.weight).collect();
        if score == total || weights.len() < 2 {
            return crate::msg!(GradeScore, score = score, total = total);
        }
        let count = weights.len();
        if weights.iter().all(|w| *w == weights[0]) {
            if weights[0] == 1 {
                crate::msg!(GradeScoreEachPoint, score = score, total = total, count = count)
            } else {
                crate::msg!(
                    GradeScoreEachPoints,
                    score = score,
                    total = total,
                    count = count,
                    points = weights[0]
                )
            }
        } else {
            let list: Vec<String> = weights.iter().map(u32::to_string).collect();
            crate::msg!(GradeScoreWeights, score = score, total = total, weights = list.join(" + "))
        }
    }
}

/// Where a site is, for a report.
fn place(site: &Site) -> Said {
    match site {
        Site::St { line, column, .. } => crate::msg!(GradeLineColumn, line = line, column = column),
        other => match other.describe() {
            Some(place) => Said::from(place),
            None => crate::msg!(GradeTheProject),
        },
    }
}

/// The direction a variable of the running PROGRAM has on a PLC: VAR_INPUT and VAR_OUTPUT
/// (RETAIN or not) by their section, and a local variable (VAR) by its location — at
/// `%I…` an input, at `%Q…` an output, as OpenPLC Editor and Beremiz declare a program's
/// I/O. Anything else is neither.
fn direction_of(var: &crate::semantic::ir::Var) -> Option<Direction> {
    use crate::syntax::AddressArea;
    match var.section {
        VarSection::Input => Some(Direction::Input),
        VarSection::Output => Some(Direction::Output),
        VarSection::Var => match var.location.as_ref().map(|l| l.area) {
            Some(AddressArea::Input) => Some(Direction::Input),
            Some(AddressArea::Output) => Some(Direction::Output),
            _ => None,
        },
        _ => None,
    }
}

/// Why the program's declarations do not match the exercise's interface: every interface
/// variable must be declared by the running PROGRAM with its direction (VAR_INPUT or a
/// VAR at `%I…` for an input, VAR_OUTPUT or a VAR at `%Q…` for an output) and its type.
fn interface_problem(exercise: &Exercise, sim: &Simulator) -> Option<Said> {
    let exe = sim.executable();
    exercise.interface.iter().find_map(|v| {
        let (keyword, area) = match v.direction {
            Direction::Input => ("VAR_INPUT", "%I"),
            Direction::Output => ("VAR_OUTPUT", "%Q"),
        };
        let asked = format!("{keyword} {} : {}", v.name, v.ty);
        let Some(entry) =
            exe.main_vars().iter().find(|e| !e.global && e.var.name.eq_ignore_ascii_case(&v.name))
        else {
            return Some(crate::msg!(GradeNotDeclared, name = v.name, asked = asked));
        };
        if direction_of(&entry.var) != Some(v.direction) {
            return Some(crate::msg!(
                GradeOtherSection,
                name = v.name,
                asked = asked,
                area = area,
                ty = v.ty
            ));
        }
        let ty = exe.type_table().display(entry.var.ty).to_string();
        (!ty.eq_ignore_ascii_case(v.ty.trim()))
            .then(|| crate::msg!(GradeDeclaredAs, name = v.name, ty = ty, asked = asked))
    })
}

/// Grades `project` against `exercise`: every scenario on a fresh PLC.
pub fn grade(exercise: &Exercise, project: &Project) -> Result<Report, ExerciseError> {
    grade_with(exercise, project, GradeOptions::default())
}

/// [`grade`] with a window of `options.window` scans around a failure.
pub fn grade_with(
    exercise: &Exercise,
    project: &Project,
    options: GradeOptions,
) -> Result<Report, ExerciseError> {
    grade_by(exercise, project, options, &Lowerings::ALL)
}

/// [`grade_with`], building the project with the given passes for its diagram POUs (the
/// exercise worker of the web app loads those a submission needs: see [`Lowerings`]).
pub fn grade_by(
    exercise: &Exercise,
    project: &Project,
    options: GradeOptions,
    lowerings: &Lowerings,
) -> Result<Report, ExerciseError> {
    let total = exercise.scenarios.iter().map(|s| s.weight).sum();
    // The PROGRAM the student chose (the project's settings), else the exercise's.
    let graded = exercise.graded_program(project);
    let mut project = project.clone();
    if let Some(g) = &graded {
        project.settings.program = Some(g.name.clone());
    }
    // The exercise's plant, never the submission's copy; without one, the scenarios
    // alone drive the inputs (a plant the submission names is not run).
    let project = &exercise.with_plant_by(&project, lowerings);
    let plant = exercise.plant.as_ref().map(|p| p.name.as_str());
    let build = build_project_by(project, lowerings);
    let program = graded.as_ref().map(|g| g.name.clone());
    let language = graded.as_ref().map(|g| g.language.label().to_string());
    let not_run = |said: Said, sentence: Sentence| Report {
        program: program.clone(),
        language: language.clone(),
        error: Some(said.english),
        error_msg: Some(sentence),
        scenarios: Vec::new(),
        score: 0,
        total,
    };
    if let Some(d) = build.diagnostics.iter().find(|d| d.is_error()) {
        let at = place(&d.site);
        let said = crate::msg!(
            GradeDoesNotBuild,
            place = at.english,
            message = d.message,
            code = d.code.as_str()
        );
        let mut sentence = Sentence::from(said.message.clone()).with("place", at);
        if let Some(m) = &d.msg {
            let part = match d.suggestion() {
                None => Sentence::from((**m).clone()),
                // `… ; did you mean NAME?`, both halves in the language asked.
                Some(name) => {
                    let hinted = crate::msg!(MessageDidYouMean, message = d.message, name = name);
                    Sentence::from(hinted.message).with("message", (**m).clone())
                }
            };
            sentence = sentence.with("message", part);
        }
        return Ok(not_run(said, sentence));
    }
    let chosen = project.settings.program.clone();
    let sim = match build.simulator_with_plant(chosen.as_deref(), plant) {
        Ok(sim) => sim,
        Err(d) => {
            let said = crate::msg!(GradeCannotRun, message = d.message);
            let mut sentence = Sentence::from(said.message.clone());
            if let Some(m) = &d.msg {
                sentence = sentence.with("message", (**m).clone());
            }
            return Ok(not_run(said, sentence));
        }
    };
    if let Some(problem) = interface_problem(exercise, &sim) {
        let sentence = Sentence::from(problem.message.clone());
        return Ok(not_run(problem, sentence));
    }
    let mut scenarios = Vec::new();
    for s in &exercise.scenarios {
        let run = Run { exercise, scenario: s, build: &build, window: options.window };
        let failure = run.failure(sim.clone())?;
        scenarios.push(ScenarioReport {
            name: s.name.clone(),
            weight: s.weight,
            hint: failure.as_ref().and(s.hint.clone()),
            failure,
        });
    }
    let score = scenarios.iter().filter(|s| s.passed()).map(|s| s.weight).sum();
    Ok(Report { program, language, error: None, error_msg: None, scenarios, score, total })
}

use super::random::Event;

/// A scan as the grader keeps it until a report needs it: the interface's values as the
/// VM holds them and every expectation's condition.
struct Raw {
    scan: u64,
    time_ns: i64,
    values: Vec<Option<Value>>,
    checks: Vec<bool>,
}

/// One scenario run on one submission.
struct Run<'a> {
    exercise: &'a Exercise,
    scenario: &'a Scenario,
    build: &'a crate::build::ProjectBuild,
    window: usize,
}

impl Run<'_> {
    /// The first wrong expectation, if any. A random scenario runs its runs until one
    /// fails, then shrinks that run's events to a shortest failing list.
    fn failure(&self, sim: Simulator) -> Result<Option<Failure>, ExerciseError> {
        let s = self.scenario;
        let Some(random) = s.random else {
            return self.events(&super::random::step_events(s), sim);
        };
        for k in 0..random.runs {
            let seed = random.seed.wrapping_add(u64::from(k));
            let events = super::random::events(s, seed)?;
            let Some(_) = self.events(&events, sim.clone())? else { continue };
            let shortest = super::random::shrink(events, |e| {
                matches!(self.events(e, sim.clone()), Ok(Some(_)))
            });
            let Some(mut failure) = self.events(&shortest, sim.clone())? else {
                continue;
            };
            let list: Vec<String> = shortest
                .iter()
                .map(|(t, name, value)| format!("{} {name} := {value}", time_text(*t)))
                .collect();
            let events = if list.is_empty() {
                Arg::Msg(crate::phrase!(GradeNoEvents))
            } else {
                Arg::Text(list.join(", "))
            };
            let said =
                crate::msg!(GradeRandomRun, actual = failure.actual, seed = seed, events = events);
            failure.actual = said.english;
            failure.actual_msg = failure
                .actual_msg
                .take()
                .map(|actual| Sentence::from(said.message).with("actual", actual));
            return Ok(Some(failure));
        }
        Ok(None)
    }

    /// Runs the scenario's expectations against a list of input events.
    fn events(
        &self,
        events: &[Event],
        mut sim: Simulator,
    ) -> Result<Option<Failure>, ExerciseError> {
        let (exercise, s) = (self.exercise, self.scenario);
        let expectations = s.expectations()?;
        let cycle = s.cycle_ns()?;
        let end = s.duration_ns()?;
        sim.set_cycle_ns(cycle);
        let mut probes: Vec<ProbeId> = Vec::new();
        for e in &expectations {
            match sim.add_probe(e.condition()) {
                Ok(p) => probes.push(p),
                Err(err) => {
                    let expected = e.said();
                    let actual = crate::msg!(GradeConditionDoesNotCheck, error = err.to_string());
                    return Ok(Some(Failure {
                        condition: Some(e.condition().to_string()),
                        expected: expected.english,
                        actual: actual.english,
                        scan: 0,
                        time_ns: 0,
                        window: Vec::new(),
                        expected_msg: Some(expected.message.into()),
                        actual_msg: Some(actual.message.into()),
                    }));
                }
            }
        }
        // Per expectation: decided already (an `At` checked, a `Becomes` seen or missed).
        let mut done = vec![false; expectations.len()];
        // Per expectation: its value on the scan before (for `becomes`).
        let mut prev: Vec<Option<bool>> = vec![None; expectations.len()];
        // The last scans (at most `window` before the one being checked), each with every
        // expectation's value on it.
        let mut recent: VecDeque<Raw> = VecDeque::new();
        let mut next_step = 0;
        // Time and scans before the last restart (a restart sets the PLC's clock to 0).
        let (mut base_ns, mut base_scans) = (0i64, 0u64);
        let mut failure: Option<(Option<usize>, Failure)> = None;
        // The interface's slots, looked up once; values are written out as text only for
        // the scans a report shows.
        let slots: Vec<Option<Slot>> =
            exercise.interface.iter().map(|v| sim.locate(&v.name).ok()).collect();
        let sample = |sim: &mut Simulator, base_ns: i64, base_scans: u64| Raw {
            scan: base_scans + sim.scan_count(),
            time_ns: base_ns + sim.time_ns(),
            values: slots.iter().map(|s| s.as_ref().map(|s| sim.read_slot(s))).collect(),
            checks: probes.iter().map(|p| sim.probe(*p)).collect(),
        };
        while base_ns + sim.time_ns() < end && failure.is_none() {
            let now = base_ns + sim.time_ns();
            while next_step < events.len() && events[next_step].0 <= now {
                let (_, name, value) = &events[next_step];
                next_step += 1;
                if name == RESTART {
                    base_ns += sim.time_ns();
                    base_scans += sim.scan_count();
                    if value == "cold" {
                        sim.cold_restart();
                    } else {
                        sim.warm_restart();
                    }
                    continue;
                }
                sim.hold(name, value).map_err(|e| ExerciseError {
                    message: format!("scenario “{}”: {name} cannot be set: {e}", s.name),
                })?;
            }
            if let ScanOutcome::Fault(info) = sim.scan() {
                let at = place(&self.build.site_of(info.span));
                let (scan, time_ns) = (base_scans + info.scan, base_ns + info.time_ns);
                let actual = crate::msg!(
                    GradeStoppedWithFault,
                    place = at.english,
                    scan = scan,
                    time = time_text(time_ns),
                    fault = info.fault.to_string()
                );
                let expected = crate::msg!(GradeExpectNoFault);
                let failure_here = Failure {
                    condition: None,
                    expected: expected.english,
                    actual: actual.english,
                    scan,
                    time_ns,
                    window: Vec::new(),
                    expected_msg: Some(expected.message.into()),
                    actual_msg: Some(
                        Sentence::from(actual.message)
                            .with("place", at)
                            .with("fault", info.fault.message()),
                    ),
                };
                failure = Some((None, failure_here));
                break;
            }
            let now = base_ns + sim.time_ns();
            let here = sample(&mut sim, base_ns, base_scans);
            for (i, e) in expectations.iter().enumerate() {
                let value = here.checks.get(i).copied().unwrap_or(false);
                let wrong = match e {
                    // Checked once, on the first scan that ends at or after `at`.
                    Expectation::At { at, .. } if !done[i] && now >= *at => {
                        done[i] = true;
                        !value
                    }
                    Expectation::At { .. } => false,
                    // A rising edge (FALSE on the scan before, TRUE now): wrong before
                    // `from`, right up to `to`; none by `to` is wrong too.
                    Expectation::Becomes { from, to, .. } if !done[i] => {
                        let rose = prev[i] == Some(false) && value;
                        if rose {
                            done[i] = true;
                            now < *from || now > *to
                        } else if now >= *to {
                            done[i] = true;
                            true
                        } else {
                            false
                        }
                    }
                    Expectation::Becomes { .. } => false,
                    Expectation::Holds { from, to, .. } => now >= *from && now <= *to && !value,
                    Expectation::Never { .. } => value,
                    Expectation::Always { .. } => !value,
                };
                prev[i] = Some(value);
                if wrong {
                    let actual = crate::msg!(
                        GradeWas,
                        condition = e.condition(),
                        value = if value { "TRUE" } else { "FALSE" },
                        time = time_text(now),
                        scan = here.scan
                    );
                    let expected = e.said();
                    let failure_here = Failure {
                        condition: Some(e.condition().to_string()),
                        expected: expected.english,
                        actual: actual.english,
                        scan: here.scan,
                        time_ns: now,
                        window: Vec::new(),
                        expected_msg: Some(expected.message.into()),
                        actual_msg: Some(actual.message.into()),
                    };
                    failure = Some((Some(i), failure_here));
                    break;
                }
            }
            recent.push_back(here);
            if recent.len() > self.window + 1 {
                recent.pop_front();
            }
        }
        let Some((which, mut failure)) = failure else { return Ok(None) };
        // The scans after the first wrong one.
        for _ in 0..self.window {
            if !matches!(sim.scan(), ScanOutcome::Completed | ScanOutcome::Breakpoint(_)) {
                break;
            }
            recent.push_back(sample(&mut sim, base_ns, base_scans));
        }
        let expectation = which.and_then(|i| expectations.get(i));
        failure.window = recent
            .into_iter()
            .map(|raw| Sample {
                scan: raw.scan,
                time_ns: raw.time_ns,
                values: exercise
                    .interface
                    .iter()
                    .zip(&raw.values)
                    .map(|(v, x)| (v.name.clone(), x.as_ref().map(value_text).unwrap_or_default()))
                    .collect(),
                actual: which.and_then(|i| raw.checks.get(i).copied()),
                expected: expectation.and_then(|e| e.expected_at(raw.time_ns, cycle)),
            })
            .collect();
        Ok(Some(failure))
    }
}
