//! Building a whole project — its ST source, ladder POUs and Petri net POUs — into one
//! checked program, with every diagnostic located where the user wrote the problem: an ST
//! line and column, a ladder cell, or a Petri net element.
//!
//! This is the one pipeline behind `plc check`, `plc run` ([`crate::run::run_project`]),
//! [`crate::run::project_simulator`] and the web app: Petri net errors stop the build first,
//! then ladder errors (from [`project_source`]), then the ST checker runs on
//! the combined text. Nothing here runs a scan.

use crate::diagnostics::{Code, LineIndex, Said, Severity, Span};
use crate::petri::{NetElement, TextPosition};
use crate::project::Project;
use crate::semantic::{self, PouId, Program};
use crate::sim::Simulator;
use crate::syntax::PouKind;

mod source;

pub use source::{
    compile_project, compile_project_by, project_diagnostics, project_source, project_source_by,
    project_source_with, LadderLowering, Lowerings, NetworkPass, NetworkSegment, Origin, PetriPass,
    PetriSegment, ProjectNets, ProjectSource, Segment, SourceMap,
};

/// Where a problem (or a runtime fault, or a running statement) is in a project.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Site {
    /// The project as a whole (no place to show).
    Project,
    /// The project's ST source.
    St {
        /// 1-based line.
        line: u32,
        /// 1-based column (characters).
        column: u32,
        /// Byte span in [`Project::source`].
        span: Span,
    },
    /// A ladder POU, and the 0-based `(rung, row, column)` of the cell when known.
    Ladder {
        /// The POU's name.
        pou: String,
        /// The cell.
        cell: Option<(usize, usize, usize)>,
    },
    /// The declarations of a ladder POU: 1-based line and column inside its text.
    Declarations {
        /// The POU's name.
        pou: String,
        /// 1-based line.
        line: u32,
        /// 1-based column (characters).
        column: u32,
    },
    /// A network POU, and the `localId` of the element when known.
    Network {
        /// The POU's name.
        pou: String,
        /// The element's `localId`.
        element: Option<String>,
    },
    /// A Petri net POU, and the element (with the position inside its text) when known.
    Petri {
        /// The POU's name.
        pou: String,
        /// The place, transition, arc… the problem belongs to.
        element: Option<NetElement>,
        /// Where inside the element's guard or actions.
        at: Option<TextPosition>,
    },
}

impl Site {
    /// The words a message gets in front when it is not about the ST source:
    /// `POU Latch, rung 1, row 2, column 3` or `POU Weighing, transition T5 (guard line 1,
    /// column 4)`; `None` for the ST source and the project as a whole.
    pub fn describe(&self) -> Option<String> {
        match self {
            Site::Project | Site::St { .. } => None,
            Site::Ladder { pou, cell: Some((r, row, c)) } => {
                Some(format!("POU {pou}, rung {}, row {}, column {}", r + 1, row + 1, c + 1))
            }
            Site::Ladder { pou, cell: None }
            | Site::Petri { pou, element: None, .. }
            | Site::Network { pou, element: None } => Some(format!("POU {pou}")),
            Site::Network { pou, element: Some(id) } => {
                Some(format!("POU {pou}, element localId {id}"))
            }
            Site::Declarations { pou, line, column } => {
                Some(format!("POU {pou}, declarations line {line}, column {column}"))
            }
            Site::Petri { pou, element: Some(e), at } => {
                Some(crate::petri::describe(pou, e, at.as_ref()))
            }
        }
    }

    /// [`Site::describe`] as data, shown in any language (`POU {pou}, {place}`).
    pub fn message(&self) -> Option<Said> {
        let pou = self.pou()?;
        Some(match self.detail() {
            Some(place) => crate::msg!(PlaceInPou, pou = pou, place = place),
            None => crate::msg!(PlacePou, pou = pou),
        })
    }

    /// Where inside its POU the site is, as data (`rung 1, row 1, column 2`, `transition
    /// T1 (guard line 1, column 2)`); `None` for a POU as a whole or outside a POU.
    pub fn detail(&self) -> Option<Said> {
        match self {
            Site::Project | Site::St { .. } => None,
            Site::Ladder { cell: Some((r, row, c)), .. } => {
                Some(crate::msg!(PlaceRung, rung = r + 1, row = row + 1, column = c + 1))
            }
            Site::Ladder { cell: None, .. }
            | Site::Petri { element: None, .. }
            | Site::Network { element: None, .. } => None,
            Site::Network { element: Some(id), .. } => Some(crate::msg!(PlaceElement, id = id)),
            Site::Declarations { line, column, .. } => {
                Some(crate::msg!(PlaceDeclarations, line = line, column = column))
            }
            Site::Petri { element: Some(e), at, .. } => Some(match at {
                Some(at) => crate::msg!(PlaceElementAt, element = e.said(), at = at.said()),
                None => e.said(),
            }),
        }
    }

    /// The POU a site belongs to (ladder and Petri net sites).
    pub fn pou(&self) -> Option<&str> {
        match self {
            Site::Ladder { pou, .. }
            | Site::Declarations { pou, .. }
            | Site::Petri { pou, .. }
            | Site::Network { pou, .. } => Some(pou),
            Site::Project | Site::St { .. } => None,
        }
    }
}

/// Where a part of a project came from in a file it was imported from: the site (a ladder
/// cell) and the 1-based line and column of its element in the file, so problems found in
/// the project are reported at the element the file's author drew.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FilePlace {
    /// The part of the project.
    pub site: Site,
    /// 1-based line of the element in the file.
    pub line: u32,
    /// 1-based column.
    pub column: u32,
}

/// How the ST source of a project imported from a file maps back to that file, line by line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SourceLine {
    /// 1-based line in the file.
    pub line: u32,
    /// 1-based column in the file.
    pub column: u32,
    /// The source line is the file's own text starting at `column` (an ST body): a column
    /// on it moves by as much in the file. Otherwise the line was written from the element
    /// at `line`, `column` (declarations, a lowered FBD statement) and every column on it
    /// is reported there.
    pub verbatim: bool,
}

/// Where a project imported from a file came from in it: ladder cells by element, and the
/// lines of its ST source; problems found in the project are reported at the element or
/// text the file's author wrote. Empty for projects not imported.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FileMap {
    /// Ladder cells and the elements they came from.
    pub places: Vec<FilePlace>,
    /// Entry `k` is where line `k + 1` of the project's ST source came from (`None`: a line
    /// the import wrote with no element behind it).
    pub lines: Vec<Option<SourceLine>>,
    /// The same for the declarations of each ladder and network POU, by POU name.
    pub declarations: Vec<(String, Vec<Option<SourceLine>>)>,
}

impl FileMap {
    /// The 1-based line and column in the file of `site`, when the map knows it.
    pub fn locate(&self, site: &Site) -> Option<(u32, u32)> {
        let in_lines = |lines: &[Option<SourceLine>], line: u32, column: u32| {
            let at = (line as usize).checked_sub(1).and_then(|k| lines.get(k).copied())??;
            Some(if at.verbatim {
                (at.line, at.column + column.saturating_sub(1))
            } else {
                (at.line, at.column)
            })
        };
        match site {
            Site::St { line, column, .. } => return in_lines(&self.lines, *line, *column),
            Site::Declarations { pou, line, column } => {
                let (_, lines) = self.declarations.iter().find(|(p, _)| p == pou)?;
                return in_lines(lines, *line, *column);
            }
            _ => {}
        }
        self.places.iter().find(|p| p.site == *site).map(|p| (p.line, p.column))
    }
}

/// One problem of a project, located at its [`Site`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProjectDiagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// The stable problem code.
    pub code: Code,
    /// The message, without its location (English).
    pub message: String,
    /// The message as data, to be shown in any language ([`ProjectDiagnostic::render`]);
    /// `None` while the stage that found the problem words it in English only.
    pub msg: Option<Box<crate::diagnostics::Message>>,
    /// Where the problem is.
    pub site: Site,
    /// For an unknown name: the declared name it probably misspells and the type its use
    /// implies, for the editors' quick fixes (see [`NameHint`]); boxed, as most problems
    /// have none.
    pub hint: Option<Box<NameHint>>,
}

/// What the editors' quick fixes of an unknown name need (see
/// [`crate::diagnostics::Diagnostic::suggestion`] and
/// [`crate::diagnostics::Diagnostic::implied_type`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NameHint {
    /// The declared name the unknown one probably misspells (the message ends with `did
    /// you mean NAME?`): `Replace with NAME`.
    pub suggestion: Option<String>,
    /// The type the use of an undeclared name implies, when the checker knows it:
    /// `Declare NAME`.
    pub implied_type: Option<String>,
}

impl NameHint {
    /// The hint of a diagnostic that has one.
    fn of(suggestion: Option<String>, implied_type: Option<String>) -> Option<Box<NameHint>> {
        (suggestion.is_some() || implied_type.is_some())
            .then(|| Box::new(NameHint { suggestion, implied_type }))
    }
}

impl ProjectDiagnostic {
    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// The declared name an unknown one probably misspells (`Replace with NAME`).
    pub fn suggestion(&self) -> Option<&str> {
        self.hint.as_ref()?.suggestion.as_deref()
    }

    /// The type the use of an undeclared name implies, when known (`Declare NAME`).
    pub fn implied_type(&self) -> Option<&str> {
        self.hint.as_ref()?.implied_type.as_deref()
    }

    /// The message (without its location) in `lang`, with its `did you mean NAME?`; the
    /// English [`ProjectDiagnostic::message`] when it is not data yet.
    pub fn render(&self, lang: crate::i18n::Lang) -> String {
        match &self.msg {
            Some(m) => crate::diagnostics::render_with_hint(m, self.suggestion(), lang),
            None => self.message.clone(),
        }
    }

    /// The message with the site in front when the site is not in the ST source, as
    /// `plc check` prints it (`POU Latch, rung 1, row 1, column 2: …`).
    pub fn located_message(&self) -> String {
        match self.site.describe() {
            Some(place) => format!("{place}: {}", self.message),
            None => self.message.clone(),
        }
    }
}

/// The result of building a project: its diagnostics and, when it has no errors, the
/// checked program.
#[derive(Debug, Clone)]
pub struct ProjectBuild {
    /// Every diagnostic, errors and warnings: ladder warnings and Petri net diagnostics
    /// first, then those of the ST checker.
    pub diagnostics: Vec<ProjectDiagnostic>,
    /// The combined source and where its lines come from (`None` when a ladder or Petri
    /// net POU has errors, so the ST checker did not run).
    pub source: Option<ProjectSource>,
    /// The checked program (`None` when anything has errors).
    pub program: Option<Program>,
}

/// Powers a simulator on for PROGRAM `name` of a checked program (or the first one), with
/// PROGRAM `plant` run after it on every scan (none when the plant is the one chosen); the
/// error is the code and message `plc run` reports.
pub fn simulator_for(
    program: Program,
    name: Option<&str>,
    plant: Option<&str>,
) -> Result<Simulator, (Code, Said)> {
    let main = find_program(&program, name)?;
    let plant = match plant {
        Some(p) => find_program(&program, Some(p)).map_err(|(code, message)| {
            (code, crate::msg!(PlantNamedInSettings, detail = message))
        })?,
        None => main,
    };
    if plant == main {
        Simulator::new(program, main).map_err(|e| (Code::ProgramTooLarge, e.said()))
    } else {
        Simulator::with_plant(program, main, plant).map_err(|e| (Code::PlantMismatch, e.said()))
    }
}

/// Finds PROGRAM `name` (or, without a name, the CONFIGURATION when there is one, else the
/// first PROGRAM of the user) in a checked
/// program; the error is the code and message `plc run` reports.
pub fn find_program(program: &Program, name: Option<&str>) -> Result<PouId, (Code, Said)> {
    match name {
        Some(name) => program
            .find_pou(name)
            .filter(|&p| program.pou(p).kind == PouKind::Program)
            .ok_or_else(|| (Code::UnknownProgram, crate::msg!(NoProgramNamed, name = name))),
        None => program
            .config
            .as_ref()
            .map(|c| c.pou)
            .into_iter()
            .chain(program.programs())
            .find(|&p| !program.pou(p).library)
            .ok_or_else(|| (Code::NoProgram, crate::msg!(SourceHoldsNoProgram))),
    }
}

impl ProjectBuild {
    /// Whether any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(ProjectDiagnostic::is_error)
    }

    /// The names of the user's PROGRAMs, in source order (ST first, then ladder, then
    /// Petri net POUs), after the CONFIGURATION's name when there is one (it runs every
    /// program instance under its task); empty when the project did not build.
    pub fn program_names(&self) -> Vec<String> {
        let Some(program) = &self.program else { return Vec::new() };
        let config = program.config.as_ref().map(|c| c.pou);
        config
            .into_iter()
            .chain(program.programs().filter(|&p| Some(p) != config))
            .filter(|&p| !program.pou(p).library)
            .map(|p| program.pou(p).name.clone())
            .collect()
    }

    /// Powers a simulator on for PROGRAM `name` (or the first one).
    pub fn simulator(&self, name: Option<&str>) -> Result<Simulator, ProjectDiagnostic> {
        self.simulator_with_plant(name, None)
    }

    /// [`ProjectBuild::simulator`] with PROGRAM `plant` (the project's settings name it)
    /// run after the chosen one on every scan; no plant runs when the plant is itself the
    /// PROGRAM chosen.
    pub fn simulator_with_plant(
        &self,
        name: Option<&str>,
        plant: Option<&str>,
    ) -> Result<Simulator, ProjectDiagnostic> {
        let error = |code, said: Said| ProjectDiagnostic {
            severity: Severity::Error,
            msg: Some(Box::new(said.message)),
            code,
            message: said.english,
            site: Site::Project,
            hint: None,
        };
        let Some(program) = &self.program else {
            return Err(error(Code::NoProgram, crate::msg!(ProjectHasErrors)));
        };
        simulator_for(program.clone(), name, plant).map_err(|(code, message)| error(code, message))
    }

    /// The PROGRAM the project's `settings` choose to run, when the build still has it.
    pub fn chosen_program<'s>(&self, settings: &'s crate::project::Settings) -> Option<&'s str> {
        settings.program.as_deref().filter(|name| {
            self.program.as_ref().is_some_and(|p| find_program(p, Some(name)).is_ok())
        })
    }

    /// The site of a byte span of the combined source (a fault, a running statement).
    pub fn site_of(&self, span: Span) -> Site {
        match &self.source {
            Some(source) => site_in(source, &LineIndex::new(&source.text), span),
            None => Site::Project,
        }
    }
}

/// The site of `span` in a combined project source indexed by `index`.
fn site_in(source: &ProjectSource, index: &LineIndex<'_>, span: Span) -> Site {
    let loc = index.location(span.start);
    match source.map.origin_at(loc.line, loc.column) {
        Origin::St(line) => Site::St { line, column: loc.column, span },
        Origin::Ladder(pou, cell) => Site::Ladder { pou, cell },
        Origin::Declarations(pou, line) => Site::Declarations { pou, line, column: loc.column },
        Origin::Network(pou, element) => Site::Network { pou, element },
        Origin::Petri(pou, None) => Site::Petri { pou, element: None, at: None },
        Origin::Petri(pou, Some((element, at))) => Site::Petri { pou, element: Some(element), at },
    }
}

/// Builds a project as `plc check` and `plc run` do (see the module comment).
pub fn build_project(project: &Project) -> ProjectBuild {
    build_project_by(project, &Lowerings::ALL)
}

/// [`build_project`] with the given passes for the diagram POUs. The diagram POUs of a kind
/// `lowerings` lacks are left out of the program (the web app loads the pass first: see
/// [`Lowerings::lacks`]).
pub fn build_project_by(project: &Project, lowerings: &Lowerings) -> ProjectBuild {
    let nets = compile_project_by(project, lowerings);
    let petri_diags: Vec<ProjectDiagnostic> = nets
        .diagnostics
        .iter()
        .cloned()
        .map(|(pou, d)| ProjectDiagnostic {
            severity: d.severity,
            msg: Some(Box::new(d.msg)),
            code: d.code,
            message: d.message,
            site: Site::Petri { pou, element: Some(d.element), at: d.at },
            hint: None,
        })
        .collect();
    if petri_diags.iter().any(ProjectDiagnostic::is_error) {
        return ProjectBuild { diagnostics: petri_diags, source: None, program: None };
    }
    let ladder_diag = |(pou, d): (String, crate::ladder::LadderDiagnostic)| ProjectDiagnostic {
        severity: d.severity,
        msg: Some(Box::new(d.msg)),
        code: d.code,
        message: d.message,
        site: Site::Ladder { pou, cell: Some((d.rung, d.row, d.column)) },
        hint: NameHint::of(d.suggestion, None),
    };
    let source = match project_source_by(project, &nets, lowerings) {
        Ok(source) => source,
        Err(diags) => {
            let diagnostics = diags.into_iter().map(ladder_diag).collect();
            return ProjectBuild { diagnostics, source: None, program: None };
        }
    };
    if !source.network_errors.is_empty() {
        let diagnostics = source
            .network_errors
            .iter()
            .map(|(pou, e)| ProjectDiagnostic {
                severity: Severity::Error,
                msg: Some(Box::new(e.msg.clone())),
                code: Code::NetworkNotRunnable,
                message: e.message.clone(),
                site: Site::Network { pou: pou.clone(), element: Some(e.element.clone()) },
                hint: None,
            })
            .collect();
        return ProjectBuild { diagnostics, source: None, program: None };
    }
    let mut diagnostics: Vec<ProjectDiagnostic> =
        source.warnings.iter().cloned().map(ladder_diag).collect();
    diagnostics.extend(petri_diags);
    let analysis = semantic::analyze_by(&source.text, &lowerings.text);
    let index = LineIndex::new(&source.text);
    diagnostics.extend(analysis.diagnostics.into_iter().map(|d| ProjectDiagnostic {
        severity: d.severity,
        code: d.code,
        message: d.message,
        msg: Some(Box::new(d.msg)),
        site: site_in(&source, &index, d.span),
        hint: NameHint::of(d.suggestion, d.implied_type),
    }));
    if let (Some(scene), Some(program)) = (&project.scene, &analysis.program) {
        diagnostics.extend(scene_diagnostics(scene, &project.settings, program));
    }
    ProjectBuild { diagnostics, source: Some(source), program: analysis.program }
}

/// W0033 for each binding of the scene that names a variable neither the PROGRAM that
/// runs (its variables, the globals) nor the plant (`Plant.Name`) has. Only the first
/// one or two parts of a path are checked (`T1.Q`, `Arr[2]` are taken as their variable).
fn scene_diagnostics(
    scene: &crate::project::Scene,
    settings: &crate::project::Settings,
    program: &semantic::Program,
) -> Vec<ProjectDiagnostic> {
    let find = |name: Option<&str>| find_program(program, name).ok();
    let Some(main) = find(settings.program.as_deref()).or_else(|| find(None)) else {
        return Vec::new();
    };
    let plant = settings.plant.as_deref().and_then(|n| find(Some(n))).filter(|&p| p != main);
    let head = |part: &str| part.split('[').next().unwrap_or_default().trim().to_string();
    let known = |path: &str| {
        let mut parts = path.split('.');
        let first = head(parts.next().unwrap_or_default());
        if program.pou(main).find_var(&first).is_some()
            || program.globals.iter().any(|g| g.name.eq_ignore_ascii_case(&first))
        {
            return true;
        }
        match (plant, parts.next()) {
            (Some(q), Some(second)) if program.pou(q).name.eq_ignore_ascii_case(&first) => {
                program.pou(q).find_var(&head(second)).is_some()
            }
            _ => false,
        }
    };
    scene
        .bindings()
        .into_iter()
        .filter(|(_, path)| !known(path))
        .map(|(label, path)| crate::msg!(SceneWidgetUnknownVariable, label = label, path = path))
        .map(|said| ProjectDiagnostic {
            severity: Severity::Warning,
            msg: Some(Box::new(said.message)),
            code: Code::SceneUnknownVariable,
            message: said.english,
            site: Site::Project,
            hint: None,
        })
        .collect()
}

/// Whether `name` is a hidden variable that a front-end generated (ladder power flow and
/// edge memories `LdPow_…`, network edge detectors `LdEdge…`, Petri-net scan copies `PnScan_…`, SFC bookkeeping `SFC__…`):
/// reports and variable lists leave these out, the views still read them by name.
pub fn is_hidden_variable(name: &str) -> bool {
    crate::ladder::is_hidden_name(name)
        || crate::network::lower::is_hidden_name(name)
        || crate::petri::is_hidden_name(name)
        || crate::sfc::is_hidden_name(name)
        || crate::il::is_hidden_name(name)
        || crate::semantic::is_image_name(name)
}

#[cfg(test)]
mod tests;
