//! What a student starts from, in each language an exercise allows, and which PROGRAM is
//! graded.
//!
//! An exercise lists its languages (`st`, `ld`, `petri`, `sfc`); the student chooses one
//! (`Start in` on the page) and gets that language's starter: the file the exercise names
//! for it (`starter` for the first language, `starter_ld` … for the others), or one made
//! here from the interface — an ST PROGRAM, a ladder PROGRAM with one empty rung, a Petri
//! net PROGRAM with its initial place only, or an SFC skeleton with its initial step — always with the interface
//! declared (its meanings as comments). Every starter names its PROGRAM in the project's
//! settings, which is what the grader grades ([`graded_program`]).

use crate::ladder::{LadderPou, LadderPouKind, Rung, DEFAULT_COLUMNS, DEFAULT_ROWS};
use crate::petri::{GenerationOptions, Net, PetriPou, Place, Position};
use crate::project::{PouLanguage, ProgramPou, Project};

use super::format::{Exercise, ExerciseError};

/// A language an exercise may be solved in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Language {
    /// Structured Text.
    St,
    /// A ladder diagram.
    Ld,
    /// A Petri net.
    Petri,
    /// A textual sequential function chart.
    Sfc,
}

impl Language {
    /// Every language, in the order the exercise format lists them.
    pub const ALL: [Language; 4] = [Language::St, Language::Ld, Language::Petri, Language::Sfc];

    /// The language of a code of the exercise file (`st`, `ld`, `petri`, `sfc`).
    pub fn from_code(code: &str) -> Option<Language> {
        Language::ALL.into_iter().find(|l| l.code().eq_ignore_ascii_case(code.trim()))
    }

    /// Its code in the exercise file.
    pub fn code(self) -> &'static str {
        super::format::LANGUAGE_CODES[self as usize]
    }

    /// Its name for people (the options of `Start in`).
    pub fn name(self) -> &'static str {
        match self {
            Language::St => "Structured Text",
            Language::Ld => "Ladder",
            Language::Petri => "Petri net",
            Language::Sfc => "SFC",
        }
    }

    /// The language a PROGRAM written in `language` is an attempt in (IL counts as ST; a
    /// network imported from another tool is none of them).
    pub fn of_program(language: PouLanguage) -> Option<Language> {
        match language {
            PouLanguage::St | PouLanguage::Il => Some(Language::St),
            PouLanguage::Sfc => Some(Language::Sfc),
            PouLanguage::Ladder => Some(Language::Ld),
            PouLanguage::PetriNet => Some(Language::Petri),
            PouLanguage::Network => None,
        }
    }
}

/// The PROGRAM of `project` a grader grades: the one the project's settings choose (the
/// student's choice, under `Program to check` or `Program`), else `preferred` (the one the
/// exercise names), else the first one; never the exercise's plant.
pub fn graded_program(
    project: &Project,
    preferred: Option<&str>,
    plant: Option<&str>,
) -> Option<ProgramPou> {
    let candidates: Vec<ProgramPou> = project
        .programs()
        .into_iter()
        .filter(|p| plant.is_none_or(|plant| !p.name.eq_ignore_ascii_case(plant)))
        .collect();
    let find = |name: &str| candidates.iter().find(|p| p.name.eq_ignore_ascii_case(name)).cloned();
    project
        .settings
        .program
        .as_deref()
        .and_then(find)
        .or_else(|| preferred.and_then(find))
        .or_else(|| candidates.first().cloned())
}

impl Exercise {
    /// The languages a student may start in, in the exercise's order (ST when it names
    /// none).
    pub fn start_languages(&self) -> Vec<Language> {
        let mut out: Vec<Language> = Vec::new();
        for l in self.languages.iter().filter_map(|c| Language::from_code(c)) {
            if !out.contains(&l) {
                out.push(l);
            }
        }
        if out.is_empty() {
            out.push(Language::St);
        }
        out
    }

    /// The file the exercise gives as its starter in `language`: `starter_<code>`, or
    /// `starter` for its first language.
    pub fn starter_file(&self, language: Language) -> Option<&str> {
        let own = match language {
            Language::St => &self.starter_st,
            Language::Ld => &self.starter_ld,
            Language::Petri => &self.starter_petri,
            Language::Sfc => &self.starter_sfc,
        };
        own.as_deref().or_else(|| {
            (self.start_languages().first() == Some(&language))
                .then_some(self.starter.as_deref())
                .flatten()
        })
    }

    /// Every starter file the exercise names, once each.
    pub fn starter_files(&self) -> Vec<&str> {
        let mut out: Vec<&str> = Vec::new();
        let named = [&self.starter, &self.starter_st, &self.starter_ld, &self.starter_petri];
        for f in named.into_iter().chain([&self.starter_sfc]).filter_map(|f| f.as_deref()) {
            if !out.contains(&f) {
                out.push(f);
            }
        }
        out
    }

    /// Every reference solution the exercise names: (`reference`, `reference_ld` …, the
    /// file).
    pub fn reference_files(&self) -> Vec<(&'static str, &str)> {
        [
            ("reference", &self.reference),
            ("reference_st", &self.reference_st),
            ("reference_ld", &self.reference_ld),
            ("reference_petri", &self.reference_petri),
            ("reference_sfc", &self.reference_sfc),
        ]
        .into_iter()
        .filter_map(|(key, file)| file.as_deref().map(|f| (key, f)))
        .collect()
    }

    /// The interface as declaration blocks (`VAR_INPUT … END_VAR`, `VAR_OUTPUT … END_VAR`),
    /// each variable with its meaning as a comment.
    pub fn interface_declarations(&self) -> String {
        super::interface_declarations(&self.interface)
    }

    /// A starter in `language` made from the interface, its PROGRAM named `program`.
    pub fn generated_starter(&self, language: Language, program: &str) -> Project {
        let mut project = Project::new(&self.title);
        project.source = String::new();
        let declarations = self.interface_declarations();
        match language {
            Language::St => {
                project.source = format!(
                    "PROGRAM {program}\n{declarations}\n(* your program *)\n\nEND_PROGRAM\n"
                );
            }
            Language::Sfc => {
                // The initial step's name must not be an interface variable's.
                let taken = |n: &str| self.interface.iter().any(|v| v.name.eq_ignore_ascii_case(n));
                let step = ["Idle", "Init", "Step0"]
                    .into_iter()
                    .find(|n| !taken(n))
                    .unwrap_or("InitialStep");
                project.source = format!(
                    "PROGRAM {program}\n{declarations}\n\
                     (* your chart: add STEP … END_STEP, TRANSITION FROM … TO … := …; END_TRANSITION\n   \
                     and ACTION … END_ACTION after the initial step *)\n\
                     INITIAL_STEP {step} :\nEND_STEP\n\nEND_PROGRAM\n"
                );
            }
            Language::Ld => project.ladder.push(LadderPou {
                name: program.to_string(),
                kind: LadderPouKind::Program,
                declarations: format!("{declarations}VAR\nEND_VAR\n"),
                rungs: vec![Rung::new(DEFAULT_ROWS, DEFAULT_COLUMNS)],
            }),
            Language::Petri => project.petri.push(PetriPou {
                name: program.to_string(),
                declarations,
                prologue: String::new(),
                epilogue: String::new(),
                // One place holding the token: a net must have one to build, and the
                // student draws the rest from it (as the shipped net starters do).
                net: Net {
                    places: vec![Place {
                        id: "P1".into(),
                        name: "P1".into(),
                        label: 1,
                        tokens: 1,
                        capacity: None,
                        actions: String::new(),
                        position: Some(Position { x: 60.0, y: 60.0 }),
                        comment: "initial state".into(),
                    }],
                    ..Net::default()
                },
                options: GenerationOptions::default(),
            }),
        }
        project.settings.program = Some(program.to_string());
        project.settings.traced = self.interface.iter().map(|v| v.name.clone()).collect();
        project
    }

    /// The PROGRAM the exercise grades when the student chose none: `program`, else
    /// `fallback` (what its starter declares), else `Main`.
    pub fn program_name(&self, fallback: Option<&str>) -> String {
        self.program.as_deref().or(fallback).unwrap_or("Main").to_string()
    }

    /// The starter in each of [`Exercise::start_languages`], in that order: the file the
    /// exercise gives for it (read by `open`), else one made from the interface named after
    /// the given starters' PROGRAM (or `program`, or `Main`). Each names its PROGRAM in its
    /// settings and carries the exercise's plant.
    pub fn starters(
        &self,
        open: impl FnMut(&str) -> Result<Project, String>,
    ) -> Result<Vec<(Language, Project)>, ExerciseError> {
        self.starters_by(open, &crate::build::Lowerings::ALL)
    }

    /// [`Exercise::starters`] with the given passes for the starters' diagram POUs (the
    /// exercise worker of the web app loads those its starters need: see
    /// [`crate::build::Lowerings`]).
    pub fn starters_by(
        &self,
        mut open: impl FnMut(&str) -> Result<Project, String>,
        lowerings: &crate::build::Lowerings,
    ) -> Result<Vec<(Language, Project)>, ExerciseError> {
        let languages = self.start_languages();
        let plant = self.plant.as_ref().map(|p| p.name.as_str());
        let mut given: Vec<(Language, Project)> = Vec::new();
        for &l in &languages {
            if let Some(file) = self.starter_file(l) {
                let project = open(file).map_err(|e| ExerciseError {
                    message: format!("the starter {file} cannot be opened: {e}"),
                })?;
                given.push((l, project));
            }
        }
        let declared = given
            .iter()
            .find_map(|(_, p)| graded_program(p, self.program.as_deref(), plant).map(|p| p.name));
        let name = self.program_name(declared.as_deref());
        Ok(languages
            .into_iter()
            .map(|l| {
                let mut project = match given.iter().find(|(g, _)| *g == l) {
                    Some((_, p)) => p.clone(),
                    None => self.generated_starter(l, &name),
                };
                if let Some(p) = graded_program(&project, Some(&name), plant) {
                    project.settings.program = Some(p.name);
                }
                (l, self.with_plant_by(&project, lowerings))
            })
            .collect())
    }

    /// The PROGRAM of `project` the grader grades (see [`graded_program`]).
    pub fn graded_program(&self, project: &Project) -> Option<ProgramPou> {
        graded_program(
            project,
            self.program.as_deref(),
            self.plant.as_ref().map(|p| p.name.as_str()),
        )
    }
}
