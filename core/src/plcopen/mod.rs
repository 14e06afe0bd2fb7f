//! PLCopen XML (IEC 61131-10, TC6 XML 0201) import and export.
//!
//! [`import`] reads a PLCopen project as OpenPLC Editor, Beremiz or CODESYS write it: data
//! types become a `TYPE … END_TYPE` block, configuration and resource globals a top-level
//! `VAR_GLOBAL` block, ST POUs full POU texts in [`Project::source`], and LD POUs
//! [`LadderPou`](crate::ladder::LadderPou)s whose networks (elements at free positions wired
//! by `refLocalId`) are laid out onto the rung grid. FBD, SFC and IL bodies are skipped with
//! a warning. [`export`] writes a TC6 0201 document back; `import(&export(p))` gives the same
//! program (ST text equal up to whitespace, ladder grids equal when they were laid out by
//! [`import`]).
//!
//! XML is read with quick-xml's event reader into a small element tree; nothing here panics
//! on malformed input: every problem is an [`ImportError`] naming the element.

mod decl_xml;
mod export;
mod import;
mod ld_export;
mod ld_import;
mod union_find;
mod xml;

use crate::project::Project;
use std::fmt;

pub use export::export;
pub use import::import;

/// The result of a successful import: the project and what was skipped or changed.
#[derive(Debug, Clone, PartialEq)]
pub struct Import {
    /// The imported project.
    pub project: Project,
    /// Human-readable notes on things that were skipped (FBD/SFC POUs, dangling elements, …).
    pub warnings: Vec<String>,
}

/// Why a PLCopen XML document could not be imported.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ImportError {
    /// The text is not well-formed XML.
    Xml(String),
    /// Well-formed XML, but not a PLCopen `<project>`.
    NotPlcopen(String),
    /// A data type could not be read.
    DataType {
        /// The type's name.
        name: String,
        /// What is wrong.
        message: String,
    },
    /// A POU (its interface or body) could not be read.
    Pou {
        /// The POU's name.
        pou: String,
        /// What is wrong.
        message: String,
    },
    /// A graphical element of a POU body could not be read or laid out.
    Element {
        /// The POU's name.
        pou: String,
        /// The element's `localId`.
        local_id: String,
        /// What is wrong.
        message: String,
    },
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImportError::Xml(m) => write!(f, "not well-formed XML: {m}"),
            ImportError::NotPlcopen(m) => write!(f, "not a PLCopen XML project: {m}"),
            ImportError::DataType { name, message } => {
                write!(f, "data type {name}: {message}")
            }
            ImportError::Pou { pou, message } => write!(f, "POU {pou}: {message}"),
            ImportError::Element { pou, local_id, message } => {
                write!(f, "POU {pou}, element localId {local_id}: {message}")
            }
        }
    }
}

impl std::error::Error for ImportError {}

/// Why [`load`] failed.
#[derive(Debug)]
#[non_exhaustive]
pub enum LoadError {
    /// The file could not be read.
    Io(std::io::Error),
    /// The file is not an importable PLCopen project.
    Import(ImportError),
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Io(e) => write!(f, "cannot read the file: {e}"),
            LoadError::Import(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for LoadError {}

/// Reads the PLCopen XML file at `path` and imports it (for the CLI's `.xml` inputs).
pub fn load(path: &str) -> Result<Import, LoadError> {
    let text = std::fs::read_to_string(path).map_err(LoadError::Io)?;
    import(&text).map_err(LoadError::Import)
}

/// Whether `path` names a PLCopen XML file (by its `.xml` extension, any case).
pub fn is_plcopen_path(path: &str) -> bool {
    std::path::Path::new(path)
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}
