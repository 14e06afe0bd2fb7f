//! Opening any file a user may hand the trainer as a project: a project file (JSON), a
//! PLCopen XML project, a PNML net, or plain ST text. The `plc` command line and the web
//! app's Import both go through [`open_text`], so they recognise files the same way.

use std::fmt;

use crate::project::{Project, ProjectError};

/// What kind of file a text was read as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// A project file (`*.plcproj.json`).
    Project,
    /// A PLCopen XML (TC6 0201) project.
    Plcopen,
    /// A PNML place/transition net.
    Pnml,
    /// Structured Text.
    St,
}

impl FileKind {
    /// What the file was read as, for a message (“Imported … from x.xml (PLCopen XML)”).
    pub fn description(self) -> &'static str {
        match self {
            FileKind::Project => "the project file",
            FileKind::Plcopen => "PLCopen XML",
            FileKind::Pnml => "PNML",
            FileKind::St => "Structured Text",
        }
    }
}

/// A file opened as a project.
#[derive(Debug, Clone, PartialEq)]
pub struct Opened {
    /// The project.
    pub project: Project,
    /// What the file was read as.
    pub kind: FileKind,
    /// Notes on what an import skipped or changed (PLCopen FBD/SFC bodies, …), each with
    /// its place in the file.
    pub warnings: Vec<crate::plcopen::ImportNote>,
    /// The POUs of the file that were left out, and why.
    pub skipped: Vec<crate::plcopen::SkippedPou>,
    /// Where each imported ladder cell and ST line came from in the file.
    pub file_map: crate::build::FileMap,
}

/// Why a file could not be opened as a project.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum OpenError {
    /// A project file that could not be read.
    Project(ProjectError),
    /// A PLCopen XML file that could not be imported.
    Plcopen(crate::plcopen::ImportError),
    /// A PNML file that could not be imported.
    Pnml(crate::pnml::PnmlError),
}

impl fmt::Display for OpenError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OpenError::Project(e) => e.fmt(f),
            OpenError::Plcopen(e) => e.fmt(f),
            OpenError::Pnml(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for OpenError {}

impl OpenError {
    /// The error as one message, to be shown in any language (its English text is the
    /// error's `Display`).
    pub fn said(&self) -> crate::diagnostics::Said {
        match self {
            OpenError::Plcopen(e) => e.said(),
            OpenError::Pnml(e) => e.said(),
            OpenError::Project(e) => e.said(),
        }
    }

    /// The 1-based line and column in `text` (the file that gave this error) of what the
    /// error is about, when known.
    pub fn location_in(&self, text: &str) -> Option<(u32, u32)> {
        match self {
            OpenError::Plcopen(e) => e.location_in(text),
            _ => None,
        }
    }
}

/// What `text` looks like: JSON → a project file, `<pnml>` → PNML, other XML → PLCopen,
/// anything else → ST.
pub fn file_kind(text: &str) -> FileKind {
    let trimmed = text.trim_start_matches('\u{feff}').trim_start();
    if trimmed.starts_with('{') {
        FileKind::Project
    } else if crate::pnml::is_pnml(text) {
        FileKind::Pnml
    } else if trimmed.starts_with("<?xml") || trimmed.starts_with("<project") {
        FileKind::Plcopen
    } else {
        FileKind::St
    }
}

/// Opens a project file or ST text without the XML importers, so that a program that links
/// only this (the web page) stays small; `Ok(None)` for PLCopen XML and PNML, which need
/// [`open_text`] (the web page runs it in a worker, loaded when a file needs it).
pub fn open_plain(name: &str, text: &str) -> Result<Option<Opened>, OpenError> {
    open_plain_by(name, text, Project::from_file)
}

/// [`open_plain`] reading a project file with `read` (the web page reads without the
/// diagram models' readers until a file needs them:
/// [`Project::from_file_without_diagrams`]).
pub fn open_plain_by(
    name: &str,
    text: &str,
    read: crate::project::ProjectReader,
) -> Result<Option<Opened>, OpenError> {
    let kind = file_kind(text);
    let project = match kind {
        FileKind::Project => read(text).map_err(OpenError::Project)?,
        FileKind::St => {
            let mut project = Project::new(name);
            project.source = text.to_string();
            project
        }
        FileKind::Plcopen | FileKind::Pnml => return Ok(None),
    };
    Ok(Some(Opened {
        project,
        kind,
        warnings: Vec::new(),
        skipped: Vec::new(),
        file_map: Default::default(),
    }))
}

/// Opens `text` as a project. `name` names the project when the file has no name of its
/// own (ST text: usually the file name without its extension).
pub fn open_text(name: &str, text: &str) -> Result<Opened, OpenError> {
    open_text_by(name, text, Project::from_file)
}

/// [`open_text`] reading a project file with `read` (see [`open_plain_by`]).
pub fn open_text_by(
    name: &str,
    text: &str,
    read: crate::project::ProjectReader,
) -> Result<Opened, OpenError> {
    if let Some(opened) = open_plain_by(name, text, read)? {
        return Ok(opened);
    }
    if file_kind(text) == FileKind::Pnml {
        let pou = crate::pnml::import(text).map_err(OpenError::Pnml)?;
        let mut project = Project::new(pou.name.clone());
        project.source.clear();
        project.petri.push(pou);
        return Ok(Opened {
            project,
            kind: FileKind::Pnml,
            warnings: Vec::new(),
            skipped: Vec::new(),
            file_map: Default::default(),
        });
    }
    let import = crate::plcopen::import(text).map_err(OpenError::Plcopen)?;
    Ok(Opened {
        project: import.project,
        kind: FileKind::Plcopen,
        warnings: import.warnings,
        skipped: import.skipped,
        file_map: import.file_map,
    })
}

#[cfg(test)]
mod tests;
