//! Projects: the file format (serde, versioned), the share-link codec, the storage
//! abstraction the web app implements over the browser's local storage, and the undo/redo
//! history every editor shares.
//!
//! Nothing here touches the DOM or a real storage: `ProjectStore` is a trait with an
//! in-memory implementation for tests, as Ruffle's `StorageBackend` does.

mod codec;
mod history;
mod pous;
mod programs;
mod scene;
mod store;

pub use codec::{decode_share, encode_share, pack, unpack, ShareError, SHARE_PREFIX};
pub use history::{History, DEFAULT_HISTORY_LIMIT};
pub use pous::PouError;
pub use programs::{PouLanguage, ProgramPou};
pub use scene::{Scene, Widget, WidgetKind};
pub use store::{
    MemoryBackend, Opened, ProjectReader, ProjectStore, ProjectSummary, StorageBackend, StoreError,
    STORE_LAYOUT,
};

use crate::diagnostics::Said;
use serde::{Deserialize, Serialize};
use std::fmt;

/// The schema version written by this build. Older versions are migrated on load.
pub const SCHEMA_VERSION: u32 = 1;

/// A student's project: its program text and simulation settings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Project {
    /// Schema version of this file.
    pub schema: u32,
    /// The project's name as shown in the project list.
    pub name: String,
    /// The Structured Text source (every POU and type of the project).
    pub source: String,
    /// Simulation settings.
    #[serde(default)]
    pub settings: Settings,
    /// The ladder (LD) POUs of the project.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ladder: Vec<crate::ladder::LadderPou>,
    /// The Petri net POUs of the project (generated into ST by the CASE OF method).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub petri: Vec<crate::petri::PetriPou>,
    /// The network POUs (LD and FBD as PLCopen files hold them, drawn at their own
    /// positions and lowered by power flow and execution order).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub networks: Vec<crate::network::NetworkPou>,
    /// The scene that draws the plant (`docs/plants.md`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene: Option<Scene>,
}

/// Simulation settings kept with a project.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    /// Cycle time in milliseconds.
    pub cycle_ms: u64,
    /// Variables shown on the timeline chart.
    pub traced: Vec<String>,
    /// Breakpoint conditions.
    pub breakpoints: Vec<String>,
    /// The PROGRAM the web app runs when the project has several (`None`: the first one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub program: Option<String>,
    /// The PROGRAM that models the plant (`docs/plants.md`): run after the controller on
    /// every scan, its inputs and outputs linked to the controller's variables by name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plant: Option<String>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            cycle_ms: 10,
            traced: Vec::new(),
            breakpoints: Vec::new(),
            program: None,
            plant: None,
        }
    }
}

/// The program a new project starts with.
pub const NEW_PROJECT_SOURCE: &str = "PROGRAM Main
VAR_INPUT
    Start : BOOL; (* start button *)
    Stop : BOOL;  (* stop button *)
END_VAR
VAR_OUTPUT
    Motor : BOOL; (* motor contactor *)
END_VAR

Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
";

impl Project {
    /// The block types and operand types the project's ladder POUs can use: the standard
    /// FBs, the ST POUs, types and globals, and the ladder FBs.
    pub fn catalog(&self) -> crate::ladder::Catalog {
        let mut catalog = crate::ladder::Catalog::of_parts(&self.source, &self.ladder);
        for net in &self.networks {
            if net.kind != crate::network::NetworkPouKind::Program {
                catalog.add_source(&net.signature());
            }
        }
        catalog
    }

    /// A new project named `name` with the starter program.
    pub fn new(name: impl Into<String>) -> Self {
        Project {
            schema: SCHEMA_VERSION,
            name: name.into(),
            source: NEW_PROJECT_SOURCE.to_string(),
            settings: Settings::default(),
            ladder: Vec::new(),
            petri: Vec::new(),
            networks: Vec::new(),
            scene: None,
        }
    }

    /// The project as a project file (pretty JSON, as `serde_json::to_string_pretty`
    /// writes it). Written compact and then indented: share links write it compact too,
    /// so the web app carries one copy of the writer instead of two.
    pub fn to_file(&self) -> String {
        indent_json(&serde_json::to_string(self).unwrap_or_default())
    }

    /// Reads a project file, migrating older schemas.
    ///
    /// The text is read twice, first for its schema version alone and then as a whole, both
    /// straight from the text: a detour through `serde_json::Value` would compile every
    /// model type's reader a second time (about 12 KB of the web app's download).
    pub fn from_file(text: &str) -> Result<Project, ProjectError> {
        read_file(text, |text| serde_json::from_str::<Project>(text).map(Some))
    }

    /// Reads a project file as [`Project::from_file`] does, without the readers of the
    /// diagram POUs' models (the web app's first screen is drawn without them): a file
    /// with ladder, network or Petri net POUs is [`ProjectError::NeedsDiagramReaders`],
    /// to be read with [`Project::from_file`] once they are loaded (unless the rest of it
    /// is damaged: that is said at once). A file without diagram POUs reads as
    /// `from_file` reads it, to the same project or the same error.
    pub fn from_file_without_diagrams(text: &str) -> Result<Project, ProjectError> {
        read_file(text, |text| serde_json::from_str::<NoDiagrams>(text).map(NoDiagrams::project))
    }

    /// The name a project file gives, read without the rest of it.
    pub fn name_in_file(text: &str) -> Option<String> {
        /// Only the name (every other field is skipped).
        #[derive(Deserialize)]
        struct Named {
            name: String,
        }
        serde_json::from_str::<Named>(text).ok().map(|n| n.name)
    }
}

/// Reads a project file with `read` (`None`: a diagram POU it cannot read), checking the
/// schema version first and the settings after.
fn read_file(
    text: &str,
    read: impl FnOnce(&str) -> Result<Option<Project>, serde_json::Error>,
) -> Result<Project, ProjectError> {
    /// Only the schema version (every other field is skipped).
    #[derive(Deserialize)]
    struct Header {
        schema: Option<u64>,
    }
    let header: Header = serde_json::from_str(text).map_err(|e| match e.classify() {
        serde_json::error::Category::Data => ProjectError::NotAProject,
        _ => ProjectError::NotJson(e.to_string()),
    })?;
    let schema = header.schema.ok_or(ProjectError::NotAProject)?;
    if schema > SCHEMA_VERSION as u64 {
        return Err(ProjectError::TooNew(schema));
    }
    // serde_json's own words (English, naming the field) are shown as they are.
    let mut project = read(text)
        .map_err(|e| ProjectError::Invalid(Said::from(e.to_string())))?
        .ok_or(ProjectError::NeedsDiagramReaders)?;
    crate::limits::cycle_ns(project.settings.cycle_ms).map_err(|e| {
        ProjectError::Invalid(crate::msg!(
            ProjectFieldProblem,
            field = "settings.cycle_ms",
            problem = e
        ))
    })?;
    project.schema = SCHEMA_VERSION;
    Ok(project)
}

/// A project file read as [`Project`] is, its diagram POUs only counted: its field list
/// and attributes are `Project`'s (the conversion in [`NoDiagrams::project`] names every
/// field of `Project`, so a field added there does not compile until it is added here).
#[derive(Deserialize)]
struct NoDiagrams {
    schema: u32,
    name: String,
    source: String,
    #[serde(default)]
    settings: Settings,
    #[serde(default)]
    ladder: Vec<serde::de::IgnoredAny>,
    #[serde(default)]
    petri: Vec<serde::de::IgnoredAny>,
    #[serde(default)]
    networks: Vec<serde::de::IgnoredAny>,
    #[serde(default)]
    scene: Option<Scene>,
}

impl NoDiagrams {
    /// The project, or `None` when the file has diagram POUs.
    fn project(self) -> Option<Project> {
        let NoDiagrams { schema, name, source, settings, ladder, petri, networks, scene } = self;
        if !(ladder.is_empty() && petri.is_empty() && networks.is_empty()) {
            return None;
        }
        Some(Project {
            schema,
            name,
            source,
            settings,
            ladder: Vec::new(),
            petri: Vec::new(),
            networks: Vec::new(),
            scene,
        })
    }
}

/// Indents compact JSON text the way `serde_json::to_string_pretty` does: two spaces per
/// level, `": "` after keys, one element per line, `[]` and `{}` when empty.
fn indent_json(compact: &str) -> String {
    let mut out = String::with_capacity(compact.len() * 2);
    let mut depth = 0usize;
    let mut in_string = false;
    let mut escaped = false;
    let mut chars = compact.chars().peekable();
    let newline = |out: &mut String, depth: usize| {
        out.push('\n');
        out.extend(std::iter::repeat_n("  ", depth));
    };
    while let Some(c) = chars.next() {
        if in_string {
            out.push(c);
            match c {
                _ if escaped => escaped = false,
                '\\' => escaped = true,
                '"' => in_string = false,
                _ => {}
            }
            continue;
        }
        match c {
            '"' => {
                in_string = true;
                out.push(c);
            }
            '{' | '[' => {
                out.push(c);
                let close = if c == '{' { '}' } else { ']' };
                if chars.peek() == Some(&close) {
                    out.push(close);
                    chars.next();
                } else {
                    depth += 1;
                    newline(&mut out, depth);
                }
            }
            '}' | ']' => {
                depth = depth.saturating_sub(1);
                newline(&mut out, depth);
                out.push(c);
            }
            ',' => {
                out.push(c);
                newline(&mut out, depth);
            }
            ':' => out.push_str(": "),
            _ => out.push(c),
        }
    }
    out
}

/// Why a project file could not be read.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ProjectError {
    /// The text is not JSON.
    NotJson(String),
    /// JSON, but not a project (no schema version).
    NotAProject,
    /// Written by a newer version of the trainer.
    TooNew(u64),
    /// A project with missing or malformed fields: why, as a message (serde_json's own
    /// words are an untranslated text, [`Said::from`]).
    Invalid(Said),
    /// A project with diagram POUs read by [`Project::from_file_without_diagrams`]: not
    /// damaged, to be read again once the diagram models' readers are loaded.
    NeedsDiagramReaders,
}

impl ProjectError {
    /// The error as a message, with its English text (what it displays as).
    pub fn said(&self) -> Said {
        match self {
            ProjectError::NotJson(e) => crate::msg!(ProjectNotJson, error = e),
            ProjectError::NotAProject => crate::msg!(ProjectNotAProject),
            ProjectError::TooNew(v) => crate::msg!(ProjectTooNew, schema = v),
            ProjectError::Invalid(reason) => crate::msg!(ProjectDamaged, reason = reason),
            ProjectError::NeedsDiagramReaders => crate::msg!(ProjectNeedsDiagramReaders),
        }
    }
}

impl fmt::Display for ProjectError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for ProjectError {}

#[cfg(test)]
mod tests;
