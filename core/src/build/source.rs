//! The source assembly of a project: its ST source, its lowered ladder POUs and its
//! generated Petri net POUs as one text for the checker, and the map from every line of
//! that text back to where it came from (an ST line, a ladder cell, a net element).

use crate::ladder::{lower, validate_with, Catalog, LadderDiagnostic, LadderPou, LoweredPou};
use crate::network::{NetError, NetworkPou, NetworkText};
use crate::petri::{self, NetElement, PetriPou, TextPosition};
use crate::project::Project;

/// One lowered ladder POU inside a combined project source.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    /// The POU's name.
    pub pou: String,
    /// 1-based line of the combined text where the lowered POU starts.
    pub first_line: u32,
    /// The lowered POU.
    pub lowered: LoweredPou,
}

/// Where the lines of a combined project source come from.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SourceMap {
    /// Lines `1..=st_lines` are the project's ST source, unchanged.
    pub st_lines: u32,
    /// The lowered ladder POUs, in order.
    pub segments: Vec<Segment>,
    /// The network POUs, in order (after the ladder ones).
    pub networks: Vec<NetworkSegment>,
    /// The generated Petri net POUs, in order (after the network ones).
    pub petri: Vec<PetriSegment>,
}

/// One network POU inside a combined project source.
#[derive(Debug, Clone, PartialEq)]
pub struct NetworkSegment {
    /// The POU's name.
    pub pou: String,
    /// 1-based line of the combined text where the POU starts.
    pub first_line: u32,
    /// The POU as ST.
    pub text: crate::network::NetworkText,
}

/// Where a line of the combined source comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Origin {
    /// A line of the ST source (1-based).
    St(u32),
    /// A ladder POU: its name and the 0-based `(rung, row, column)` when the line comes
    /// from a cell (`None` for generated framing).
    Ladder(String, Option<(usize, usize, usize)>),
    /// The declarations of a ladder POU: its name and the 1-based line inside them.
    Declarations(String, u32),
    /// A Petri net POU: its name, and the net element (with the position inside its guard
    /// or actions) when the line comes from one.
    Petri(String, Option<(NetElement, Option<TextPosition>)>),
    /// A network POU: its name, and the `localId` of the element the line was written
    /// from (`None` for its header and framing).
    Network(String, Option<String>),
}

impl SourceMap {
    /// The origin of a 1-based line of the combined source.
    pub fn origin(&self, line: u32) -> Origin {
        self.origin_at(line, 1)
    }

    /// The origin of a 1-based line and column of the combined source.
    pub fn origin_at(&self, line: u32, column: u32) -> Origin {
        if line <= self.st_lines {
            return Origin::St(line);
        }
        if let Some(s) = self.petri.iter().rev().find(|s| s.first_line <= line) {
            return Origin::Petri(s.pou.clone(), s.locate(line, column));
        }
        if let Some(s) = self.networks.iter().rev().find(|s| s.first_line <= line) {
            let inside = line + 1 - s.first_line;
            if s.text.declaration_lines.contains(&inside) {
                return Origin::Declarations(
                    s.pou.clone(),
                    inside + 1 - s.text.declaration_lines.start,
                );
            }
            let element = s.text.lines.get(inside as usize - 1).cloned().flatten();
            return Origin::Network(s.pou.clone(), element);
        }
        match self.segments.iter().rev().find(|s| s.first_line <= line) {
            Some(s) => {
                let inside = line + 1 - s.first_line;
                let decls = &s.lowered.declaration_lines;
                if decls.contains(&inside) {
                    return Origin::Declarations(s.pou.clone(), inside + 1 - decls.start);
                }
                Origin::Ladder(s.pou.clone(), s.lowered.cell_of_line(inside))
            }
            None => Origin::St(line),
        }
    }

    /// Rewrites a message for a line of the combined source: ladder lines get
    /// `POU Name, rung R, row r, column c: ` (1-based) in front.
    pub fn locate_message(&self, line: u32, message: &str) -> (Option<u32>, String) {
        self.locate_message_at(line, 1, message)
    }

    /// As [`SourceMap::locate_message`], for a line and column: Petri net lines get
    /// `POU Name, transition T2 (guard line 1, column 5): ` in front.
    pub fn locate_message_at(
        &self,
        line: u32,
        column: u32,
        message: &str,
    ) -> (Option<u32>, String) {
        match self.origin_at(line, column) {
            Origin::Petri(pou, Some((element, at))) => {
                (None, format!("{}: {message}", petri::describe(&pou, &element, at.as_ref())))
            }
            Origin::Petri(pou, None) => (None, format!("POU {pou}: {message}")),
            Origin::St(l) => (Some(l), message.to_string()),
            Origin::Ladder(pou, Some((r, row, c))) => (
                None,
                format!("POU {pou}, rung {}, row {}, column {}: {message}", r + 1, row + 1, c + 1),
            ),
            Origin::Ladder(pou, None) => (None, format!("POU {pou}: {message}")),
            Origin::Declarations(pou, l) => {
                (None, format!("POU {pou}, declarations line {l}: {message}"))
            }
            Origin::Network(pou, Some(id)) => {
                (None, format!("POU {pou}, element localId {id}: {message}"))
            }
            Origin::Network(pou, None) => (None, format!("POU {pou}: {message}")),
        }
    }
}

/// A project's ST source and lowered ladder POUs as one text for `semantic::analyze`.
#[derive(Debug, Clone, PartialEq)]
pub struct ProjectSource {
    /// The combined text: the ST source first (so its lines keep their numbers).
    pub text: String,
    /// Where each line comes from.
    pub map: SourceMap,
    /// Ladder warnings, with the POU they belong to.
    pub warnings: Vec<(String, LadderDiagnostic)>,
    /// The network POUs that could not be lowered (left out of `text`), with the POU.
    pub network_errors: Vec<(String, crate::network::NetError)>,
}

/// Validates every ladder POU of a project and combines them with the ST source and the
/// generated Petri net POUs. Fails with every ladder diagnostic (errors and warnings) when
/// any ladder POU has errors.
pub fn project_source(project: &Project) -> Result<ProjectSource, Vec<(String, LadderDiagnostic)>> {
    project_source_with(project, &compile_project(project))
}

/// [`project_source`] with the project's Petri net POUs already compiled.
pub fn project_source_with(
    project: &Project,
    nets: &ProjectNets,
) -> Result<ProjectSource, Vec<(String, LadderDiagnostic)>> {
    project_source_by(project, nets, &Lowerings::ALL)
}

/// [`project_source_with`] with the given passes for the diagram POUs: a kind of POU the
/// project has and `lowerings` lacks is left out (see [`Lowerings::lacks`]).
pub fn project_source_by(
    project: &Project,
    nets: &ProjectNets,
    lowerings: &Lowerings,
) -> Result<ProjectSource, Vec<(String, LadderDiagnostic)>> {
    let mut diags = Vec::new();
    let catalog = project.catalog();
    if let Some(ladder) = &lowerings.ladder {
        for pou in &project.ladder {
            diags.extend(
                (ladder.validate)(pou, &catalog).into_iter().map(|d| (pou.name.clone(), d)),
            );
        }
    }
    if diags.iter().any(|(_, d)| d.is_error()) {
        return Err(diags);
    }
    let mut text = project.source.clone();
    if !text.is_empty() && !text.ends_with('\n') {
        text.push('\n');
    }
    let st_lines = text.lines().count() as u32;
    let mut map =
        SourceMap { st_lines, segments: Vec::new(), networks: Vec::new(), petri: Vec::new() };
    let mut line = st_lines + 1;
    if let Some(ladder) = &lowerings.ladder {
        for pou in &project.ladder {
            let lowered = (ladder.lower)(pou);
            let n = lowered.st.lines().count() as u32;
            text.push_str(&lowered.st);
            map.segments.push(Segment { pou: pou.name.clone(), first_line: line, lowered });
            line += n;
        }
    }
    let mut network_errors = Vec::new();
    if let Some(to_st) = lowerings.network {
        for pou in &project.networks {
            match to_st(pou) {
                Ok(net) => {
                    let n = net.st.lines().count() as u32;
                    text.push_str(&net.st);
                    map.networks.push(NetworkSegment {
                        pou: pou.name.clone(),
                        first_line: line,
                        text: net,
                    });
                    line += n;
                }
                Err(e) => network_errors.push((pou.name.clone(), e)),
            }
        }
    }
    append_to_source(nets, &mut text, &mut map.petri, line);
    Ok(ProjectSource { text, map, warnings: diags, network_errors })
}

/// The passes that turn a project's diagram POUs into ST. [`Lowerings::ALL`] has every
/// one, and every build of the engine uses it, except the web app's page: it loads each
/// pass as a chunk of its wasm the first time a project needs it, and builds with those it
/// has ([`crate::build::build_project_by`]), so an ST-only project never downloads them.
#[derive(Debug, Clone, Copy)]
pub struct Lowerings {
    /// Ladder POUs: validation against the block catalogue, then lowering.
    pub ladder: Option<LadderLowering>,
    /// Network POUs (LD and FBD as drawn, and SFC charts): their ST.
    pub network: Option<NetworkPass>,
    /// Petri net POUs: the generated CASE OF program with its analysis.
    pub petri: Option<PetriPass>,
}

/// The network pass of [`Lowerings`]: a network POU's ST.
pub type NetworkPass = fn(&NetworkPou) -> Result<NetworkText, NetError>;

/// The Petri net pass of [`Lowerings`]: a net POU's generated program and analysis.
pub type PetriPass = fn(&PetriPou) -> Result<petri::Compiled, Vec<petri::PetriDiagnostic>>;

/// The ladder passes of [`Lowerings`].
#[derive(Debug, Clone, Copy)]
pub struct LadderLowering {
    /// Validates a ladder POU against the project's catalogue of blocks.
    pub validate: fn(&LadderPou, &Catalog) -> Vec<LadderDiagnostic>,
    /// Lowers a valid ladder POU to ST.
    pub lower: fn(&LadderPou) -> LoweredPou,
}

impl Lowerings {
    /// Every pass.
    pub const ALL: Lowerings = Lowerings {
        ladder: Some(LadderLowering { validate: validate_with, lower }),
        network: Some(NetworkPou::to_st),
        petri: Some(petri::compile),
    };

    /// No pass (an ST-only project needs none).
    pub const NONE: Lowerings = Lowerings { ladder: None, network: None, petri: None };

    /// The kinds of diagram POU the project has that these passes cannot build, by name
    /// (`"ladder"`, `"network"`, `"petri"`).
    pub fn lacks(&self, project: &Project) -> Vec<&'static str> {
        let mut out = Vec::new();
        if self.ladder.is_none() && !project.ladder.is_empty() {
            out.push("ladder");
        }
        if self.network.is_none() && !project.networks.is_empty() {
            out.push("network");
        }
        if self.petri.is_none() && !project.petri.is_empty() {
            out.push("petri");
        }
        out
    }
}

/// A project's Petri net POUs compiled once, for its diagnostics and its combined source.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ProjectNets {
    /// The POUs that compiled, by name, in project order.
    pub compiled: Vec<(String, petri::Compiled)>,
    /// Every diagnostic (errors and warnings), with the POU name.
    pub diagnostics: Vec<(String, petri::PetriDiagnostic)>,
}

impl ProjectNets {
    /// Whether some POU has an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(|(_, d)| d.is_error())
    }
}

/// Compiles every Petri net POU of a project.
pub fn compile_project(project: &Project) -> ProjectNets {
    compile_project_by(project, &Lowerings::ALL)
}

/// [`compile_project`] with the given passes (none without the Petri net pass).
pub fn compile_project_by(project: &Project, lowerings: &Lowerings) -> ProjectNets {
    let mut out = ProjectNets::default();
    let Some(compile) = lowerings.petri else { return out };
    for pou in &project.petri {
        match compile(pou) {
            Ok(c) => {
                out.diagnostics.extend(c.warnings.iter().map(|d| (pou.name.clone(), d.clone())));
                out.compiled.push((pou.name.clone(), c));
            }
            Err(d) => out.diagnostics.extend(d.into_iter().map(|d| (pou.name.clone(), d))),
        }
    }
    out
}

/// Every diagnostic (errors and warnings) of a project's Petri net POUs, with the POU name.
pub fn project_diagnostics(project: &Project) -> Vec<(String, petri::PetriDiagnostic)> {
    compile_project(project).diagnostics
}

/// One generated Petri net POU inside a combined project source.
#[derive(Debug, Clone, PartialEq)]
pub struct PetriSegment {
    /// The POU's name.
    pub pou: String,
    /// 1-based line of the combined text where the generated POU starts.
    pub first_line: u32,
    /// The generated POU.
    pub generated: petri::Generated,
}

impl PetriSegment {
    /// The element (and position in its text) behind a 1-based line and column of the
    /// combined source.
    pub fn locate(&self, line: u32, column: u32) -> Option<(NetElement, Option<TextPosition>)> {
        self.generated.locate(line + 1 - self.first_line, column)
    }
}

/// Appends the generated PROGRAM of every compiled Petri net POU to `text`, whose next
/// line is `first_line`; POUs with errors are not among `nets.compiled` (report them from
/// `nets.diagnostics`).
pub fn append_to_source(
    nets: &ProjectNets,
    text: &mut String,
    segments: &mut Vec<PetriSegment>,
    first_line: u32,
) {
    let mut line = first_line;
    for (pou, c) in &nets.compiled {
        let n = c.generated.st.lines().count() as u32;
        text.push_str(&c.generated.st);
        segments.push(PetriSegment {
            pou: pou.clone(),
            first_line: line,
            generated: c.generated.clone(),
        });
        line += n;
    }
}
