//! PNML (ISO/IEC 15909-2) for place/transition nets: import and export.
//!
//! The standard part carries the net: places (name, initial marking, position),
//! transitions (name, position) and arcs (inscription = weight), on one or more pages
//! (flattened on import, with reference places and transitions resolved). What P/T PNML
//! has no room for — guards, actions, CASE labels, priorities, comments, macro-places,
//! processes, the emergency, declarations and generation options — goes into
//! `<toolspecific tool="plc-trainer" version="1">` elements, which other tools ignore.
//! A file from another tool imports as a net whose guards are all TRUE, with labels taken
//! from the numbers ending the place names (P1, P20…) when they are all different, else
//! 1, 2, 3… in document order. `import(&export(pou))` gives back `pou`.

mod read;
mod tree;
mod write;

pub use read::import;
pub use write::export;

use std::fmt;

use crate::diagnostics::{LineIndex, Said};

/// The `tool` attribute of our `<toolspecific>` elements.
pub const TOOL: &str = "plc-trainer";

/// Why a PNML file could not be imported, with where (1-based line and column).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PnmlError {
    /// What is wrong (English: `said.english`).
    pub message: String,
    /// What is wrong, as data to be shown in any language (without the place; the whole
    /// error is [`PnmlError::said`]).
    pub said: Said,
    /// 1-based line.
    pub line: u32,
    /// 1-based column.
    pub column: u32,
}

impl PnmlError {
    fn at(index: &LineIndex<'_>, offset: usize, said: Said) -> Self {
        let loc = index.location(offset as u32);
        PnmlError { message: said.english.clone(), said, line: loc.line, column: loc.column }
    }

    /// The whole error with its place, as data; its English text is what the error
    /// displays as (`line 3, column 7: malformed XML: … [E0516]`).
    pub fn said(&self) -> Said {
        crate::msg!(PnmlErrorAt, line = self.line, column = self.column, problem = self.said)
    }
}

impl fmt::Display for PnmlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for PnmlError {}

/// Whether `text` looks like a PNML document (its root element is `<pnml>`).
pub fn is_pnml(text: &str) -> bool {
    let mut rest = text.trim_start_matches('\u{feff}').trim_start();
    loop {
        if let Some(r) = rest.strip_prefix("<?") {
            rest = r.split_once("?>").map_or("", |(_, after)| after).trim_start();
        } else if let Some(r) = rest.strip_prefix("<!--") {
            rest = r.split_once("-->").map_or("", |(_, after)| after).trim_start();
        } else {
            break;
        }
    }
    rest.strip_prefix('<').is_some_and(|r| {
        let name: String =
            r.chars().take_while(|c| !c.is_whitespace() && *c != '>' && *c != '/').collect();
        name == "pnml" || name.ends_with(":pnml")
    })
}

#[cfg(test)]
mod tests;
