//! Adding, renaming and deleting the ladder POUs of a project: the project-level edits of
//! the POU navigator. Each is checked (a valid, unused name) and applies whole or not at
//! all, so an editor can keep whole projects in a [`History`](super::History).

use std::fmt;

use super::Project;
use crate::ladder::{LadderPou, LadderPouKind, Rung, DEFAULT_COLUMNS, DEFAULT_ROWS};
use crate::syntax::{self, Item};

/// Why a POU edit cannot be made.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum PouError {
    /// The name is not an IEC identifier.
    NotAName(String),
    /// Another POU (ST, ladder or Petri net) already has the name.
    Taken(String),
    /// No ladder POU has that name.
    NoSuchPou(String),
}

impl fmt::Display for PouError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PouError::NotAName(n) => write!(
                f,
                "“{n}” is not a name: use letters, digits and single underscores, starting with a letter"
            ),
            PouError::Taken(n) => write!(f, "the project already has a POU named {n}"),
            PouError::NoSuchPou(n) => write!(f, "the project has no ladder POU named {n}"),
        }
    }
}

impl std::error::Error for PouError {}

impl Project {
    /// Every POU name of the project: its ST POUs, ladder and Petri net POUs.
    pub fn pou_names(&self) -> Vec<String> {
        let (file, _) = syntax::parse(&self.source);
        let st = file.items.into_iter().filter_map(|item| match item {
            Item::Pou(p) => Some(p.name.name),
            _ => None,
        });
        st.chain(self.ladder.iter().map(|l| l.name.clone()))
            .chain(self.petri.iter().map(|p| p.name.clone()))
            .collect()
    }

    fn check_new_name(&self, name: &str, except: Option<&str>) -> Result<(), PouError> {
        if !syntax::is_identifier(name) {
            return Err(PouError::NotAName(name.to_string()));
        }
        let taken = self.pou_names().iter().any(|n| {
            n.eq_ignore_ascii_case(name) && except.is_none_or(|e| !e.eq_ignore_ascii_case(n))
        });
        if taken {
            return Err(PouError::Taken(name.to_string()));
        }
        Ok(())
    }

    /// Adds a ladder POU named `name` with one empty rung of the default grid (8 × 10) and
    /// an empty declaration block.
    pub fn add_ladder_pou(&mut self, name: &str, kind: LadderPouKind) -> Result<(), PouError> {
        let name = name.trim();
        self.check_new_name(name, None)?;
        let declarations = "VAR_INPUT\nEND_VAR\nVAR_OUTPUT\nEND_VAR\nVAR\nEND_VAR\n";
        self.ladder.push(LadderPou {
            name: name.to_string(),
            kind,
            declarations: declarations.to_string(),
            rungs: vec![Rung::new(DEFAULT_ROWS, DEFAULT_COLUMNS)],
        });
        Ok(())
    }

    /// Renames a ladder POU (the program chosen to run follows it).
    pub fn rename_ladder_pou(&mut self, old: &str, new: &str) -> Result<(), PouError> {
        let new = new.trim();
        let index = self.ladder_index(old)?;
        self.check_new_name(new, Some(old))?;
        if self.settings.program.as_deref().is_some_and(|p| p.eq_ignore_ascii_case(old)) {
            self.settings.program = Some(new.to_string());
        }
        self.ladder[index].name = new.to_string();
        Ok(())
    }

    /// Deletes a ladder POU.
    pub fn delete_ladder_pou(&mut self, name: &str) -> Result<(), PouError> {
        let index = self.ladder_index(name)?;
        self.ladder.remove(index);
        if self.settings.program.as_deref().is_some_and(|p| p.eq_ignore_ascii_case(name)) {
            self.settings.program = None;
        }
        Ok(())
    }

    fn ladder_index(&self, name: &str) -> Result<usize, PouError> {
        self.ladder
            .iter()
            .position(|l| l.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| PouError::NoSuchPou(name.to_string()))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn ladder_pous_are_added_renamed_and_deleted_with_checked_names() {
        let mut p = Project::new("p");
        p.source.clear();
        p.add_ladder_pou("Main", LadderPouKind::Program).unwrap();
        assert_eq!(p.ladder[0].rungs.len(), 1);
        assert_eq!((p.ladder[0].rungs[0].rows(), p.ladder[0].rungs[0].columns()), (8, 10));
        let build = crate::build::build_project(&p);
        assert!(!build.has_errors(), "{:?}", build.diagnostics);
        assert_eq!(build.program_names(), ["Main"], "a new PROGRAM can be chosen to run");
        assert_eq!(
            p.add_ladder_pou("main", LadderPouKind::Program),
            Err(PouError::Taken("main".into()))
        );
        assert_eq!(
            p.add_ladder_pou("2nd", LadderPouKind::Program),
            Err(PouError::NotAName("2nd".into()))
        );
        p.source = "FUNCTION_BLOCK Valve END_FUNCTION_BLOCK".into();
        assert_eq!(
            p.add_ladder_pou("VALVE", LadderPouKind::FunctionBlock),
            Err(PouError::Taken("VALVE".into()))
        );
        p.settings.program = Some("Main".into());
        p.rename_ladder_pou("main", "Line1").unwrap();
        assert_eq!(
            (p.ladder[0].name.as_str(), p.settings.program.as_deref()),
            ("Line1", Some("Line1"))
        );
        p.rename_ladder_pou("Line1", "LINE1").unwrap();
        assert_eq!(p.rename_ladder_pou("Line1", "Valve"), Err(PouError::Taken("Valve".into())));
        p.delete_ladder_pou("line1").unwrap();
        assert!(p.ladder.is_empty() && p.settings.program.is_none());
        assert_eq!(p.delete_ladder_pou("x"), Err(PouError::NoSuchPou("x".into())));
    }
}
