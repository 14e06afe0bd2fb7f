//! Ladder diagrams (LD): the rung grid model, validation with located diagnostics,
//! lowering to ST (so ladder runs on the one ST compiler and VM), the readable ST view,
//! and the glue that turns a project's ST, LD and Petri net POUs into one source text.

mod blocks;
pub mod catalog;
pub mod lower;
pub mod model;
mod network;
pub mod st_view;
pub mod validate;

pub use catalog::Catalog;
pub use lower::{is_hidden_name, lower, power_map, power_var, LineMap, LoweredPou};
pub use model::*;
pub use st_view::{st_view, st_view_pou};
pub use validate::{validate, validate_with, LadderDiagnostic};

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
    /// The generated Petri net POUs, in order (after the ladder ones).
    pub petri: Vec<crate::petri::PetriSegment>,
}

/// Where a line of the combined source comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Origin {
    /// A line of the ST source (1-based).
    St(u32),
    /// A ladder POU: its name and the 0-based `(rung, row, column)` when the line comes
    /// from a cell (`None` for declarations and generated framing).
    Ladder(String, Option<(usize, usize, usize)>),
    /// A Petri net POU: its name, and the net element (with the position inside its guard
    /// or actions) when the line comes from one.
    Petri(String, Option<(crate::petri::NetElement, Option<crate::petri::TextPosition>)>),
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
        match self.segments.iter().rev().find(|s| s.first_line <= line) {
            Some(s) => {
                Origin::Ladder(s.pou.clone(), s.lowered.cell_of_line(line + 1 - s.first_line))
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
            Origin::Petri(pou, Some((element, at))) => (
                None,
                format!("{}: {message}", crate::petri::describe(&pou, &element, at.as_ref())),
            ),
            Origin::Petri(pou, None) => (None, format!("POU {pou}: {message}")),
            Origin::St(l) => (Some(l), message.to_string()),
            Origin::Ladder(pou, Some((r, row, c))) => (
                None,
                format!("POU {pou}, rung {}, row {}, column {}: {message}", r + 1, row + 1, c + 1),
            ),
            Origin::Ladder(pou, None) => (None, format!("POU {pou}: {message}")),
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
}

/// Validates every ladder POU of a project and combines them with the ST source and the
/// generated Petri net POUs. Fails with every ladder diagnostic (errors and warnings) when
/// any ladder POU has errors.
pub fn project_source(project: &Project) -> Result<ProjectSource, Vec<(String, LadderDiagnostic)>> {
    project_source_with(project, &crate::petri::compile_project(project))
}

/// [`project_source`] with the project's Petri net POUs already compiled.
pub fn project_source_with(
    project: &Project,
    nets: &crate::petri::ProjectNets,
) -> Result<ProjectSource, Vec<(String, LadderDiagnostic)>> {
    let mut diags = Vec::new();
    let catalog = Catalog::of_project(project);
    for pou in &project.ladder {
        diags.extend(validate_with(pou, &catalog).into_iter().map(|d| (pou.name.clone(), d)));
    }
    if diags.iter().any(|(_, d)| d.is_error()) {
        return Err(diags);
    }
    let mut text = project.source.clone();
    if !text.is_empty() && !text.ends_with('\n') {
        text.push('\n');
    }
    let st_lines = text.lines().count() as u32;
    let mut map = SourceMap { st_lines, segments: Vec::new(), petri: Vec::new() };
    let mut line = st_lines + 1;
    for pou in &project.ladder {
        let lowered = lower(pou);
        let n = lowered.st.lines().count() as u32;
        text.push_str(&lowered.st);
        map.segments.push(Segment { pou: pou.name.clone(), first_line: line, lowered });
        line += n;
    }
    crate::petri::append_to_source(nets, &mut text, &mut map.petri, line);
    Ok(ProjectSource { text, map, warnings: diags })
}

#[cfg(test)]
mod tests;
