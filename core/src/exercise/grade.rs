//! The grader: runs each scenario of an exercise on a submission (a project), on the one
//! VM and its virtual clock, and reports per scenario whether it passed — for a failure
//! the first wrong expectation (the condition, what it was and should have been, at what
//! time and scan) and the interface's values on the scans around it — and a score out of
//! the weights. Deterministic: the same submission gives the same report.

use crate::build::{build_project, Site};
use crate::export::value_text;
use crate::project::Project;
use crate::sim::{ProbeId, ScanOutcome, Simulator};

use super::format::{time_text, Direction, Exercise, ExerciseError, Expectation, Scenario};

/// Scans shown before and after the first wrong one.
const WINDOW: usize = 5;

/// The interface's values after one scan.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// The scan (1-based).
    pub scan: u64,
    /// The virtual time at its end, in nanoseconds.
    pub time_ns: i64,
    /// `(variable, value)` for every interface variable, in interface order.
    pub values: Vec<(String, String)>,
}

/// The first wrong expectation of a scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
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
}

/// One scenario's result.
#[derive(Debug, Clone, PartialEq)]
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
}

/// A submission's grade.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Why nothing could run (the project does not build, has no PROGRAM …), located.
    pub error: Option<String>,
    /// Per scenario.
    pub scenarios: Vec<ScenarioReport>,
    /// The weights of the passed scenarios.
    pub score: u32,
    /// All the weights.
    pub total: u32,
}

/// Where a site is, for a report.
fn place(site: &Site) -> String {
    match site {
        Site::St { line, column, .. } => format!("line {line}, column {column}"),
        other => other.describe().unwrap_or_else(|| "the project".into()),
    }
}

/// Grades `project` against `exercise`: every scenario on a fresh PLC.
pub fn grade(exercise: &Exercise, project: &Project) -> Result<Report, ExerciseError> {
    let total = exercise.scenarios.iter().map(|s| s.weight).sum();
    let build = build_project(project);
    let not_run =
        |message: String| Report { error: Some(message), scenarios: Vec::new(), score: 0, total };
    if let Some(d) = build.diagnostics.iter().find(|d| d.is_error()) {
        return Ok(not_run(format!(
            "the program does not build: {}: {} [{}]",
            place(&d.site),
            d.message,
            d.code.as_str()
        )));
    }
    let chosen = project.settings.program.clone();
    let sim = match build.simulator(chosen.as_deref()) {
        Ok(sim) => sim,
        Err(d) => return Ok(not_run(format!("the program cannot run: {}", d.message))),
    };
    for v in &exercise.interface {
        if sim.read(&v.name).is_err() {
            let what = match v.direction {
                Direction::Input => "VAR_INPUT",
                Direction::Output => "VAR_OUTPUT",
            };
            return Ok(not_run(format!(
                "the program does not declare {} ({what} {} : {})",
                v.name, v.name, v.ty
            )));
        }
    }
    let mut scenarios = Vec::new();
    for s in &exercise.scenarios {
        let failure = run(exercise, s, sim.clone(), &build)?;
        scenarios.push(ScenarioReport {
            name: s.name.clone(),
            weight: s.weight,
            hint: failure.as_ref().and(s.hint.clone()),
            failure,
        });
    }
    let score = scenarios.iter().filter(|s| s.passed()).map(|s| s.weight).sum();
    Ok(Report { error: None, scenarios, score, total })
}

use super::random::Event;

/// Runs one scenario; the first wrong expectation, if any. A random scenario runs its
/// runs until one fails, then shrinks that run's events to a shortest failing list.
fn run(
    exercise: &Exercise,
    s: &Scenario,
    sim: Simulator,
    build: &crate::build::ProjectBuild,
) -> Result<Option<Failure>, ExerciseError> {
    let Some(random) = s.random else {
        return run_events(exercise, s, &super::random::step_events(s), sim, build);
    };
    for k in 0..random.runs {
        let seed = random.seed.wrapping_add(u64::from(k));
        let events = super::random::events(s, seed)?;
        let Some(_) = run_events(exercise, s, &events, sim.clone(), build)? else { continue };
        let shortest = super::random::shrink(events, |e| {
            matches!(run_events(exercise, s, e, sim.clone(), build), Ok(Some(_)))
        });
        let Some(mut failure) = run_events(exercise, s, &shortest, sim.clone(), build)? else {
            continue;
        };
        let list: Vec<String> = shortest
            .iter()
            .map(|(t, name, value)| format!("{} {name} := {value}", time_text(*t)))
            .collect();
        failure.actual = format!(
            "{} — random run with seed {seed} (replay: random = {{ runs = 1, seed = {seed} }}); shortest failing events: {}",
            failure.actual,
            if list.is_empty() { "none".to_string() } else { list.join(", ") }
        );
        return Ok(Some(failure));
    }
    Ok(None)
}

/// Runs a scenario's expectations against a list of input events.
fn run_events(
    exercise: &Exercise,
    s: &Scenario,
    events: &[Event],
    mut sim: Simulator,
    build: &crate::build::ProjectBuild,
) -> Result<Option<Failure>, ExerciseError> {
    let expectations = s.expectations()?;
    let cycle = s.cycle_ns()?;
    let end = s.duration_ns()?;
    sim.set_cycle_ns(cycle);
    let mut probes: Vec<ProbeId> = Vec::new();
    for e in &expectations {
        match sim.add_probe(e.condition()) {
            Ok(p) => probes.push(p),
            Err(err) => {
                return Ok(Some(Failure {
                    expected: e.describe(),
                    actual: format!("the condition does not check against the program: {err}"),
                    scan: 0,
                    time_ns: 0,
                    window: Vec::new(),
                }))
            }
        }
    }
    // Per expectation: decided already (an `At` checked, a `Becomes` seen or missed).
    let mut done = vec![false; expectations.len()];
    // Per expectation: its value on the scan before (for `becomes`).
    let mut prev: Vec<Option<bool>> = vec![None; expectations.len()];
    let mut samples: Vec<Sample> = Vec::new();
    let mut next_step = 0;
    let mut failure: Option<(usize, Failure)> = None;
    let sample = |sim: &Simulator| Sample {
        scan: sim.scan_count(),
        time_ns: sim.time_ns(),
        values: exercise
            .interface
            .iter()
            .map(|v| {
                (v.name.clone(), sim.read(&v.name).map(|x| value_text(&x)).unwrap_or_default())
            })
            .collect(),
    };
    while sim.time_ns() < end && failure.is_none() {
        while next_step < events.len() && events[next_step].0 <= sim.time_ns() {
            let (_, name, value) = &events[next_step];
            sim.hold(name, value).map_err(|e| ExerciseError {
                message: format!("scenario “{}”: {name} cannot be set: {e}", s.name),
            })?;
            next_step += 1;
        }
        if let ScanOutcome::Fault(info) = sim.scan() {
            let at = place(&build.site_of(info.span));
            let actual = format!(
                "the program stopped with a FAULT at {at} on scan {} ({}): {}",
                info.scan,
                time_text(info.time_ns),
                info.fault
            );
            failure = Some((
                samples.len(),
                Failure {
                    expected: "no FAULT".into(),
                    actual,
                    scan: info.scan,
                    time_ns: info.time_ns,
                    window: Vec::new(),
                },
            ));
            break;
        }
        let now = sim.time_ns();
        samples.push(sample(&sim));
        for (i, e) in expectations.iter().enumerate() {
            let value = sim.probe(probes[i]);
            let wrong = match e {
                // Checked once, on the first scan that ends at or after `at`.
                Expectation::At { at, .. } if !done[i] && now >= *at => {
                    done[i] = true;
                    !value
                }
                Expectation::At { .. } => false,
                // A rising edge (FALSE on the scan before, TRUE now): wrong before `from`,
                // right up to `to`; none by `to` is wrong too.
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
                let actual = format!(
                    "{} was {} at {} (scan {})",
                    e.condition(),
                    if value { "TRUE" } else { "FALSE" },
                    time_text(now),
                    sim.scan_count()
                );
                failure = Some((
                    samples.len() - 1,
                    Failure {
                        expected: e.describe(),
                        actual,
                        scan: sim.scan_count(),
                        time_ns: now,
                        window: Vec::new(),
                    },
                ));
                break;
            }
        }
    }
    let Some((at, mut failure)) = failure else { return Ok(None) };
    // The scans after the first wrong one, then the window around it.
    for _ in 0..WINDOW {
        if !matches!(sim.scan(), ScanOutcome::Completed | ScanOutcome::Breakpoint(_)) {
            break;
        }
        samples.push(sample(&sim));
    }
    let start = at.saturating_sub(WINDOW);
    failure.window = samples.get(start..).map(<[Sample]>::to_vec).unwrap_or_default();
    Ok(Some(failure))
}
