//! PLCopen XML (IEC 61131-10, TC6 XML 0201) import and export.
//!
//! [`import`] reads a PLCopen project as OpenPLC Editor, Beremiz or CODESYS write it: data
//! types become a `TYPE … END_TYPE` block, configuration and resource globals a top-level
//! `VAR_GLOBAL` block, ST POUs full POU texts in [`Project::source`], and LD POUs
//! [`LadderPou`](crate::ladder::LadderPou)s whose networks (elements at free positions wired
//! by `refLocalId`) are laid out onto the rung grid. Networks that do not fit the grid, LD
//! functions and FBD bodies are kept as [`NetworkPou`](crate::network::NetworkPou)s; SFC
//! bodies become textual SFC; IL bodies are kept as text, like ST (the parser recognises
//! IL, and export writes such a POU back as `<IL>`). Every line of the ST
//! written is mapped back to its place in the file ([`Import::file_map`]). [`export`] writes
//! a TC6 0201 document back; `import(&export(p))` gives the same program (ST text equal up
//! to whitespace, ladder grids equal when they were laid out by [`import`]).
//!
//! XML is read with quick-xml's event reader into a small element tree; nothing here panics
//! on malformed input: every problem is an [`ImportError`] naming the element.

mod decl_xml;
mod export;
mod import;
mod ld_export;
mod ld_import;
mod network_export;
mod sfc_read;
mod source_out;
mod tasks;
mod union_find;
mod xml;

pub(crate) use xml::reader_said;

use crate::diagnostics::Said;
use crate::project::Project;
use std::fmt;

pub use export::export;
pub use import::import;
pub use xml::XmlError;

/// The result of a successful import: the project and what was skipped or changed.
#[derive(Debug, Clone, PartialEq)]
pub struct Import {
    /// The imported project.
    pub project: Project,
    /// Notes on things that were skipped or changed (FBD/SFC POUs, dangling elements, …),
    /// each with its place in the file.
    pub warnings: Vec<ImportNote>,
    /// The POUs that were not imported, and why.
    pub skipped: Vec<SkippedPou>,
    /// Where each ladder cell and each line of the ST source came from in the file (for
    /// problems at the element).
    pub file_map: crate::build::FileMap,
}

/// A note on something an import skipped or changed, with the place in the file of the
/// element it is about (line 0 when it is about the file as a whole).
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct ImportNote {
    /// What was skipped or changed, and why (English: `said.english`).
    pub message: String,
    /// The note as data, to be shown in any language (`said.message.render(lang)`).
    #[serde(skip)]
    pub said: Said,
    /// 1-based line of the element in the file (0: the whole file).
    pub line: u32,
    /// 1-based column.
    pub column: u32,
}

impl ImportNote {
    /// A note about the element that starts at `line`, `column`.
    pub fn at(line: u32, column: u32, said: Said) -> Self {
        ImportNote { message: said.english.clone(), said, line, column }
    }

    /// A note about the element `node`.
    pub(crate) fn on(node: &xml::Node, said: Said) -> Self {
        ImportNote::at(node.line, node.column, said)
    }
}

impl fmt::Display for ImportNote {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "line {}, column {}: {}", self.line, self.column, self.message)
        } else {
            f.write_str(&self.message)
        }
    }
}

/// A POU of the file that the import left out.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct SkippedPou {
    /// Its name.
    pub name: String,
    /// `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION`.
    pub kind: String,
    /// Why (`FBD bodies are not supported yet`; English: `reason_said.english`).
    pub reason: String,
    /// Why, as data to be shown in any language.
    #[serde(skip)]
    pub reason_said: Said,
}

/// Why a PLCopen XML document could not be imported. Each message is data
/// ([`Said`]: its English text and its key with arguments); [`ImportError::said`] gives the
/// whole error as one message, whose English text is the error's `Display`.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ImportError {
    /// The text is not well-formed XML.
    Xml(xml::XmlError),
    /// Well-formed XML, but not a PLCopen `<project>`.
    NotPlcopen(Said),
    /// A data type could not be read.
    DataType {
        /// The type's name.
        name: String,
        /// What is wrong.
        message: Said,
    },
    /// A POU (its interface or body) could not be read.
    Pou {
        /// The POU's name (empty when the `<pou>` has none: shown as `(unnamed)`).
        pou: String,
        /// What is wrong.
        message: Said,
    },
    /// The global variables of a `<configuration>` or a `<resource>` could not be read.
    Globals {
        /// The element: `configuration` or `resource`.
        element: &'static str,
        /// The configuration's or resource's name.
        name: String,
        /// What is wrong.
        message: Said,
    },
    /// A graphical element of a POU body could not be read or laid out.
    Element {
        /// The POU's name.
        pou: String,
        /// The element's `localId`.
        local_id: String,
        /// What is wrong.
        message: Said,
    },
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for ImportError {}

impl ImportError {
    /// The whole error as one message (`not well-formed XML at line 1, column 2: …`, `POU
    /// Main: no <body>`), to be shown in any language; its English text is the error's
    /// `Display`.
    pub fn said(&self) -> Said {
        match self {
            ImportError::Xml(e) => crate::msg!(PlcopenNotWellFormed, error = e.said()),
            ImportError::NotPlcopen(m) => crate::msg!(PlcopenNotPlcopen, message = m),
            ImportError::DataType { name, message } => {
                crate::msg!(PlcopenDataTypeError, name = name, message = message)
            }
            ImportError::Pou { pou, message } if pou.is_empty() => {
                crate::msg!(PlcopenUnnamedPouError, message = message)
            }
            ImportError::Pou { pou, message } => {
                crate::msg!(PlcopenPouError, pou = pou, message = message)
            }
            ImportError::Globals { element: "configuration", name, message } => {
                crate::msg!(PlcopenConfigurationError, name = name, message = message)
            }
            ImportError::Globals { name, message, .. } => {
                crate::msg!(PlcopenResourceError, name = name, message = message)
            }
            ImportError::Element { pou, local_id, message } => {
                crate::msg!(PlcopenElementError, pou = pou, local_id = local_id, message = message)
            }
        }
    }

    /// The 1-based line and column in the file the error is about, when the error itself
    /// knows it (a well-formedness error); [`ImportError::location_in`] finds the others.
    pub fn location(&self) -> Option<(u32, u32)> {
        match self {
            ImportError::Xml(e) => Some((e.line, e.column)),
            _ => None,
        }
    }

    /// The 1-based line and column in `xml_text` (the file that gave this error) of the
    /// element the error is about: the data type, the POU, or the body element by its
    /// `localId`.
    pub fn location_in(&self, xml_text: &str) -> Option<(u32, u32)> {
        if let Some(at) = self.location() {
            return Some(at);
        }
        let root = xml::parse(xml_text).ok()?;
        let named = |kind: &'static str, name: &str| {
            find(&root, &|n: &xml::Node| n.name == kind && n.attr("name") == Some(name))
        };
        let node = match self {
            ImportError::DataType { name, .. } => named("dataType", name),
            ImportError::Pou { pou, .. } if !pou.is_empty() => named("pou", pou),
            ImportError::Element { pou, local_id, .. } => named("pou", pou).and_then(|p| {
                find(p, &|n: &xml::Node| n.attr("localId").map(str::trim) == Some(local_id))
            }),
            _ => None,
        }?;
        Some((node.line, node.column))
    }
}

/// The first element of `node`'s tree (itself included) that `is` accepts.
fn find<'a>(node: &'a xml::Node, is: &dyn Fn(&xml::Node) -> bool) -> Option<&'a xml::Node> {
    if is(node) {
        return Some(node);
    }
    node.children.iter().find_map(|c| find(c, is))
}

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
