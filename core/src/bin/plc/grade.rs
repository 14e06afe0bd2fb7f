//! `plc grade EXERCISE SUBMISSION...`: grades submissions (project files, ST files, PLCopen
//! XML, hand-ins, or folders of them) against an exercise, in parallel, one row per
//! submission; a submission that cannot be read, or a hand-in of another exercise, gets
//! its own row with the reason and never stops the batch.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use plc_core::exercise::{
    grade, scenarios_from_toml, scorm_package, time_text, Exercise, ExerciseLink, HandIn,
    LinkedFile, Report, ScormVersion, HAND_IN_EXTENSION,
};

/// How the grades are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A line per submission, and the first wrong expectation of each failed scenario.
    Text,
    /// One JSON array.
    Json,
    /// A CSV table with a header row.
    Csv,
    /// A class report: one self-contained HTML page (rows, pass rates, a histogram of
    /// scores, the most common first failures).
    Html,
}

/// One submission's outcome: its report, or why it could not be graded.
pub(crate) struct Row {
    /// The file, as given.
    pub name: String,
    /// The student's name, for a hand-in.
    pub student: Option<String>,
    /// When it was handed in, for a hand-in.
    pub handed_in: Option<String>,
    /// The report, or why there is none.
    pub result: Result<Report, String>,
}

/// Grades one file: a hand-in (checked to be of this exercise), or any file `plc` opens.
fn grade_file(ex: &Exercise, file: &Path) -> Row {
    let name = file.display().to_string();
    let graded = |project: Result<plc_core::project::Project, String>| {
        project.and_then(|p| grade(ex, &p).map_err(|e| format!("plc: the exercise: {e}")))
    };
    let text = super::read_source(file);
    let is_hand_in = file.extension().is_some_and(|e| e == HAND_IN_EXTENSION)
        || text.as_deref().is_ok_and(HandIn::is_hand_in);
    let Ok(text) = text.as_deref().map(|t| t.trim_start_matches('\u{feff}')) else {
        return Row {
            name,
            student: None,
            handed_in: None,
            result: graded(super::load_project(file)),
        };
    };
    if !is_hand_in {
        return Row {
            name,
            student: None,
            handed_in: None,
            result: graded(super::load_project(file)),
        };
    }
    match HandIn::from_file(text) {
        Err(e) => Row { name, student: None, handed_in: None, result: Err(e.to_string()) },
        Ok(h) => {
            let result = if h.exercise == ex.id {
                graded(Ok(h.project))
            } else {
                Err(format!(
                    "this is a hand-in of exercise “{}”, not of “{}”: grade it with its own exercise",
                    h.exercise, ex.id
                ))
            };
            Row { name, student: Some(h.name), handed_in: Some(h.handed_in), result }
        }
    }
}

/// The files to grade: each path, or the files of each folder (sorted by name).
fn expand(paths: &[PathBuf]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for p in paths {
        match std::fs::read_dir(p) {
            Ok(entries) => {
                let mut files: Vec<PathBuf> =
                    entries.flatten().map(|e| e.path()).filter(|f| f.is_file()).collect();
                plc_core::order::sort(&mut files);
                out.extend(files);
            }
            Err(_) => out.push(p.clone()),
        }
    }
    out
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("plc: {}: {e}", path.display()))
}

/// Runs `plc grade`.
pub fn run(
    exercise: &Path,
    submissions: &[PathBuf],
    hidden: Option<&Path>,
    format: Format,
    jobs: Option<usize>,
    lang: plc_core::i18n::Lang,
) -> ExitCode {
    let mut ex = match read(exercise).and_then(|t| {
        Exercise::from_toml(&t).map_err(|e| format!("plc: {}: {e}", exercise.display()))
    }) {
        Ok(ex) => ex,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    if let Some(h) = hidden {
        match read(h)
            .and_then(|t| scenarios_from_toml(&t).map_err(|e| format!("plc: {}: {e}", h.display())))
        {
            Ok(more) => ex.scenarios.extend(more),
            Err(e) => {
                eprintln!("{e}");
                return ExitCode::from(2);
            }
        }
    }
    // The scenarios' names and hints as the exercise translates them (text only).
    if format == Format::Text {
        ex = ex.localised(lang);
    }
    let files = expand(submissions);
    let jobs = jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .clamp(1, 64);
    // Each worker takes the next submission not yet taken, so slow ones (a right answer
    // runs every random run) spread over the workers whatever their order.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let rows: std::sync::Mutex<Vec<Option<Row>>> =
        std::sync::Mutex::new((0..files.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..jobs.min(files.len().max(1)) {
            let (ex, files, next, rows) = (&ex, &files, &next, &rows);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(file) = files.get(i) else { break };
                let row = grade_file(ex, file);
                if let Some(slot) = rows.lock().ok().as_mut().and_then(|r| r.get_mut(i)) {
                    *slot = Some(row);
                }
            });
        }
    });
    let rows = rows.into_inner().unwrap_or_default();
    let rows: Vec<Row> = rows.into_iter().flatten().collect();
    match format {
        Format::Text => print_text(&rows, lang),
        Format::Json => println!("{}", json(&rows)),
        Format::Csv => print!("{}", csv(&rows)),
        Format::Html => print!("{}", super::class_report::html(&ex, &rows)),
    }
    ExitCode::SUCCESS
}

impl Row {
    /// The file, and the student's name when it is a hand-in: `a.plcsub (Ada Lovelace)`.
    fn label(&self) -> String {
        match &self.student {
            Some(student) => format!("{} ({student})", self.name),
            None => self.name.clone(),
        }
    }
}

fn print_text(rows: &[Row], lang: plc_core::i18n::Lang) {
    for row in rows {
        match &row.result {
            Err(e) => println!("{}: cannot be graded: {e}", row.label()),
            Ok(r) => {
                match r.checked().map(|s| s.message.render(lang)) {
                    Some(line) => {
                        let mut chars = line.chars();
                        let first = chars.next().map(|c| c.to_lowercase().to_string());
                        println!(
                            "{}: {}/{} — {}{}",
                            row.label(),
                            r.score,
                            r.total,
                            first.unwrap_or_default(),
                            chars.as_str()
                        )
                    }
                    None => println!("{}: {}/{}", row.label(), r.score, r.total),
                }
                if let Some(e) = r.error_in(lang) {
                    println!("  {e}");
                }
                for s in r.scenarios.iter().filter(|s| !s.passed()) {
                    if let Some(line) = s.fail_line(lang) {
                        println!("  {line}");
                    }
                    if let Some(line) = s.hint_line(lang) {
                        println!("    {line}");
                    }
                }
            }
        }
    }
}

fn json(rows: &[Row]) -> serde_json::Value {
    let rows: Vec<serde_json::Value> = rows
        .iter()
        .map(|row| match &row.result {
            Err(e) => serde_json::json!({
                "submission": row.name,
                "name": row.student,
                "handed_in": row.handed_in,
                "error": e,
            }),
            Ok(r) => serde_json::json!({
                "submission": row.name,
                "name": row.student,
                "handed_in": row.handed_in,
                "program": r.program,
                "language": r.language,
                "score": r.score,
                "total": r.total,
                "error": r.error,
                "scenarios": r.scenarios.iter().map(|s| serde_json::json!({
                    "name": s.name,
                    "weight": s.weight,
                    "passed": s.passed(),
                    "expected": s.failure.as_ref().map(|f| &f.expected),
                    "actual": s.failure.as_ref().map(|f| &f.actual),
                    "time": s.failure.as_ref().map(|f| time_text(f.time_ns)),
                    "scan": s.failure.as_ref().map(|f| f.scan),
                    "hint": s.hint,
                })).collect::<Vec<_>>(),
            }),
        })
        .collect();
    serde_json::Value::Array(rows)
}

/// A CSV field, quoted when it must be.
fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

fn csv(rows: &[Row]) -> String {
    let mut out = String::from(
        "submission,score,total,passed,failed,error,first_failure,program,name,handed_in\n",
    );
    for row in rows {
        let line = match &row.result {
            Err(e) => format!("{},,,,,{},,", field(&row.name), field(e)),
            Ok(r) => {
                let passed = r.scenarios.iter().filter(|s| s.passed()).count();
                let failed = r.scenarios.len() - passed;
                let first = r
                    .scenarios
                    .iter()
                    .find_map(|s| s.failure.as_ref().map(|f| format!("{}: {}", s.name, f.actual)))
                    .unwrap_or_default();
                format!(
                    "{},{},{},{passed},{failed},{},{},{}",
                    field(&row.name),
                    r.score,
                    r.total,
                    field(r.error.as_deref().unwrap_or_default()),
                    field(&first),
                    field(r.program.as_deref().unwrap_or_default())
                )
            }
        };
        out.push_str(&line);
        for extra in [&row.student, &row.handed_in] {
            out.push(',');
            out.push_str(&field(extra.as_deref().unwrap_or_default()));
        }
        out.push('\n');
    }
    out
}

/// `plc exercise …`.
#[derive(clap::Subcommand)]
pub enum ExerciseCommand {
    /// Check an exercise: its reference passes every scenario (the hidden ones too when
    /// given), its starter fails at least one, and every mutant in its folder's `mutants/`
    /// fails at least one, with the first wrong output and its time.
    Validate {
        /// The exercise file (TOML).
        exercise: PathBuf,
        /// A file of hidden scenarios to add.
        #[arg(long, value_name = "HIDDEN.toml")]
        scenarios: Option<PathBuf>,
    },
    /// Write the skeleton of a new exercise in the folder ID (exercise file, starter,
    /// reference, a mutant).
    New {
        /// The exercise's id (also its folder).
        id: String,
    },
    /// Print a link that carries the whole exercise (its file and its starter, never the
    /// hidden scenarios nor the reference) in its fragment: `#x=…`.
    Link {
        /// The exercise file (TOML).
        exercise: PathBuf,
        /// The trainer's address to put before the fragment (`https://host/plc/`).
        #[arg(long, value_name = "URL", default_value = "")]
        base: String,
    },
    /// Write a SCORM package an LMS (Moodle, Canvas, Blackboard, ILIAS) imports as an
    /// activity: the built site, the exercise and its starter (never the hidden scenarios
    /// nor the reference) and imsmanifest.xml; the page reports each Check's score to the
    /// LMS's gradebook.
    Scorm {
        /// The exercise file (TOML).
        exercise: PathBuf,
        /// The package to write (default: ID-scorm.zip).
        #[arg(long, value_name = "FILE.zip")]
        out: Option<PathBuf>,
        /// The built site (`bash scripts/build-web.sh` writes it to dist/).
        #[arg(long, value_name = "DIR", default_value = "dist")]
        site: PathBuf,
        /// The SCORM edition the manifest declares: 1.2, or 2004 (4th edition).
        #[arg(long = "scorm", value_name = "VERSION", default_value = "1.2",
              value_parser = ["1.2", "2004"])]
        version: String,
    },
}

/// Runs `plc exercise …`.
pub fn exercise(command: ExerciseCommand) -> ExitCode {
    match command {
        ExerciseCommand::Validate { exercise, scenarios } => {
            validate(&exercise, scenarios.as_deref())
        }
        ExerciseCommand::New { id } => new(&id),
        ExerciseCommand::Link { exercise, base } => link(&exercise, &base),
        ExerciseCommand::Scorm { exercise, out, site, version } => {
            let version =
                if version == "2004" { ScormVersion::Scorm2004 } else { ScormVersion::Scorm12 };
            scorm(&exercise, out.as_deref(), &site, version)
        }
    }
}

/// The files under `dir` as `(path with /, contents)`, sorted by path.
fn site_files(dir: &Path) -> Result<Vec<(String, Vec<u8>)>, String> {
    let mut files = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        let entries =
            std::fs::read_dir(&folder).map_err(|e| format!("plc: {}: {e}", folder.display()))?;
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            let rel = path.strip_prefix(dir).unwrap_or(&path);
            let name: Vec<String> =
                rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
            let bytes =
                std::fs::read(&path).map_err(|e| format!("plc: {}: {e}", path.display()))?;
            files.push((name.join("/"), bytes));
        }
    }
    files.sort_by(|a, b| a.0.cmp(&b.0));
    Ok(files)
}

/// `plc exercise scorm`: the exercise's SCORM package.
fn scorm(path: &Path, out: Option<&Path>, site: &Path, version: ScormVersion) -> ExitCode {
    let made = (|| -> Result<(PathBuf, usize), String> {
        let text = read(path)?;
        let exercise =
            Exercise::from_toml(&text).map_err(|e| format!("plc: {}: {e}", path.display()))?;
        let mut starters = Vec::new();
        for name in exercise.starter_files() {
            let file = path.parent().unwrap_or(Path::new(".")).join(name);
            starters.push(LinkedFile { name: name.to_string(), text: read(&file)? });
        }
        if !site.join("index.html").is_file() {
            return Err(format!(
                "plc: {}: no built site there (build it with `bash scripts/build-web.sh`, or give --site DIR)",
                site.display()
            ));
        }
        let files = site_files(site)?;
        let zip = scorm_package(&text, &starters, files, version)
            .map_err(|e| format!("plc: {}: {e}", path.display()))?;
        let out = out
            .map_or_else(|| PathBuf::from(format!("{}-scorm.zip", exercise.id)), Path::to_path_buf);
        std::fs::write(&out, &zip).map_err(|e| format!("plc: {}: {e}", out.display()))?;
        Ok((out, zip.len()))
    })();
    match made {
        Ok((out, size)) => {
            println!("wrote {} ({} KB)", out.display(), size.div_ceil(1024));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(2)
        }
    }
}

/// `plc exercise link`: the exercise and its starter, packed into a URL fragment.
fn link(path: &Path, base: &str) -> ExitCode {
    let made = (|| -> Result<String, String> {
        let text = read(path)?;
        let exercise =
            Exercise::from_toml(&text).map_err(|e| format!("plc: {}: {e}", path.display()))?;
        let dir = path.parent().unwrap_or(Path::new("."));
        let mut files = Vec::new();
        for name in exercise.starter_files() {
            files.push(LinkedFile { name: name.to_string(), text: read(&dir.join(name))? });
        }
        let fragment = ExerciseLink { exercise: text, starter: None, starters: files }
            .arranged(&exercise)
            .encode()
            .map_err(|e| format!("plc: {}: {e}", path.display()))?;
        Ok(format!("{base}#{fragment}"))
    })();
    match made {
        Ok(url) => {
            println!("{url}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(2)
        }
    }
}

/// The first failed scenario of a report, as a line (`“Start”: Motor was FALSE at …`).
fn first_failure(r: &Report) -> Option<String> {
    if let Some(e) = &r.error {
        return Some(e.clone());
    }
    r.scenarios.iter().find_map(|s| {
        s.failure.as_ref().map(|f| format!("“{}”: expected {}; {}", s.name, f.expected, f.actual))
    })
}

fn validate(path: &Path, hidden: Option<&Path>) -> ExitCode {
    let load = || -> Result<Exercise, String> {
        let mut ex = Exercise::from_toml(&read(path)?)
            .map_err(|e| format!("plc: {}: {e}", path.display()))?;
        if let Some(h) = hidden {
            let more =
                scenarios_from_toml(&read(h)?).map_err(|e| format!("plc: {}: {e}", h.display()))?;
            ex.scenarios.extend(more);
        }
        Ok(ex)
    };
    let ex = match load() {
        Ok(ex) => ex,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    let problems = std::cell::Cell::new(0u32);
    let graded = |label: &str, file: &Path| -> Option<Report> {
        match super::load_project(file).and_then(|p| grade(&ex, &p).map_err(|e| e.to_string())) {
            Ok(r) => Some(r),
            Err(e) => {
                println!("{label}: cannot be graded: {e}");
                problems.set(problems.get() + 1);
                None
            }
        }
    };
    // The translations keep the English names and program text; what they leave out is
    // shown in English (a note, not a problem).
    for problem in ex.translation_problems() {
        println!("{}: {problem}", path.display());
        problems.set(problems.get() + 1);
    }
    for lang in plc_core::exercise::TRANSLATED {
        let missing = ex.untranslated(lang);
        if !missing.is_empty() {
            println!("lang.{lang}: shown in English: {}", missing.join(", "));
        }
    }
    if ex.reference.is_none() {
        println!("reference: missing (give `reference = \"FILE\"`)");
        problems.set(problems.get() + 1);
    }
    for (key, file) in ex.reference_files() {
        if let Some(r) = graded(key, &dir.join(file)) {
            let program = r
                .checked_line()
                .map(|l| format!(" — {}", l.replacen("Checked", "checked", 1)))
                .unwrap_or_default();
            match first_failure(&r) {
                None => println!("{key}: passes all {} scenarios{program}", r.scenarios.len()),
                Some(f) => {
                    println!("{key}: FAILS {f}");
                    problems.set(problems.get() + 1);
                }
            }
        }
    }
    // The starter in every language the student may start in, given or made.
    match ex.starters(|file| super::load_project(&dir.join(file))) {
        Err(e) => {
            println!("starter: cannot be opened: {e}");
            problems.set(problems.get() + 1);
        }
        Ok(starters) => {
            for (language, project) in starters {
                let label = format!("starter ({})", language.name());
                match grade(&ex, &project).map(|r| first_failure(&r)) {
                    Ok(Some(f)) => println!("{label}: fails, as it should: {f}"),
                    Ok(None) => {
                        println!("{label}: PASSES every scenario (it should leave work to do)");
                        problems.set(problems.get() + 1);
                    }
                    Err(e) => {
                        println!("{label}: cannot be graded: {e}");
                        problems.set(problems.get() + 1);
                    }
                }
            }
        }
    }
    for mutant in expand(&[dir.join("mutants")]).iter().filter(|m| m.is_file()) {
        let name = format!(
            "mutant {}",
            mutant.file_name().map_or(String::new(), |n| n.to_string_lossy().into_owned())
        );
        if let Some(r) = graded(&name, mutant) {
            match first_failure(&r) {
                Some(f) => println!("{name}: caught: {f}"),
                None => {
                    println!("{name}: NOT CAUGHT: it passes every scenario");
                    problems.set(problems.get() + 1);
                }
            }
        }
    }
    if problems.get() == 0 {
        ExitCode::SUCCESS
    } else {
        println!("{} problem(s)", problems.get());
        ExitCode::FAILURE
    }
}

fn new(id: &str) -> ExitCode {
    if !plc_core::syntax::is_identifier(id) {
        eprintln!("plc: “{id}” is not an id: use letters, digits and underscores");
        return ExitCode::from(2);
    }
    let dir = Path::new(id);
    if dir.exists() {
        eprintln!("plc: {id} exists already: nothing written");
        return ExitCode::from(2);
    }
    let program = |body: &str| {
        format!(
            "PROGRAM Main\nVAR_INPUT\n    Start : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\n{body}\nEND_PROGRAM\n"
        )
    };
    let exercise = format!(
        r#"id = "{id}"
title = "The title"
level = 1
languages = ["st", "ld"]
statement = """
What the student builds, in Markdown.
"""
starter = "starter.st"
reference = "reference.st"

[[interface]]
name = "Start"
type = "BOOL"
direction = "input"
meaning = "a push button"

[[interface]]
name = "Lamp"
type = "BOOL"
direction = "output"
meaning = "a lamp"

[[scenario]]
name = "The lamp follows the button"
hint = "Is Lamp written from Start?"
step = [ {{ at = "0s", set = {{ Start = false }} }}, {{ at = "100ms", set = {{ Start = true }} }} ]
expect = [ {{ holds = "NOT Lamp", from = "0s", to = "90ms" }}, {{ that = "Lamp", at = "120ms" }} ]
"#
    );
    let files = [
        (dir.join(format!("{id}.toml")), exercise),
        (dir.join("starter.st"), program("Lamp := FALSE;")),
        (dir.join("reference.st"), program("Lamp := Start;")),
        (dir.join("mutants").join("inverted.st"), program("Lamp := NOT Start;")),
    ];
    for (path, text) in &files {
        if let Err(e) = path
            .parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| std::fs::write(path, text))
        {
            eprintln!("plc: {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
        println!("wrote {}", path.display());
    }
    ExitCode::SUCCESS
}
