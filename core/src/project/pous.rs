//! Adding, renaming and deleting the ladder and Petri net POUs of a project (and renaming
//! and deleting its network POUs, which come from imported files): the project-level edits of
//! the POU navigator. Each is checked (a valid, unused name) and applies whole or not at
//! all, so an editor can keep whole projects in a [`History`](super::History).

use std::fmt;

use super::Project;
use crate::ladder::{LadderPou, LadderPouKind, Rung, DEFAULT_COLUMNS, DEFAULT_ROWS};
use crate::petri::{GenerationOptions, Net, PetriPou};
use crate::syntax::{self, Item};

/// Why a POU edit cannot be made.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum PouError {
    /// No name was given.
    Empty,
    /// The name is not an IEC identifier.
    NotAName(String),
    /// The name is reserved: a keyword, a type or a standard block (the name, and what it
    /// is).
    Reserved(String, &'static str),
    /// Another POU (ST, ladder or Petri net) already has the name.
    Taken(String),
    /// No ladder POU has that name.
    NoSuchPou(String),
    /// No Petri net POU has that name.
    NoSuchNet(String),
    /// No network POU (LD, FBD or SFC kept as drawn) has that name.
    NoSuchNetwork(String),
}

impl PouError {
    /// The error as data: the page shows it in its language; `Display` is its English.
    pub fn said(&self) -> crate::diagnostics::Said {
        use crate::msg;
        match self {
            PouError::Empty => msg!(PouNameEmpty),
            PouError::Reserved(n, what) => {
                msg!(PouNameReserved, name = n, what = reserved_phrase(what))
            }
            PouError::NotAName(n) => msg!(PouNotAName, name = n),
            PouError::Taken(n) => msg!(PouNameTaken, name = n),
            PouError::NoSuchPou(n) => msg!(PouNoLadder, name = n),
            PouError::NoSuchNet(n) => msg!(PouNoPetri, name = n),
            PouError::NoSuchNetwork(n) => msg!(PouNoNetwork, name = n),
        }
    }
}

/// What a reserved name is ([`reserved`]'s English) as a translated phrase.
fn reserved_phrase(what: &str) -> crate::diagnostics::Phrase {
    use crate::phrase;
    match what {
        "a keyword of ST" => phrase!(PouReservedKeyword),
        "the name of a data type" => phrase!(PouReservedType),
        "the name of a standard function block" => phrase!(PouReservedFb),
        _ => phrase!(PouReservedFunction),
    }
}

impl fmt::Display for PouError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for PouError {}

impl Project {
    /// Every POU name of the project: its ST POUs, ladder, Petri net and network POUs.
    pub fn pou_names(&self) -> Vec<String> {
        let (file, _) = syntax::parse(&self.source);
        let st = file.items.into_iter().filter_map(|item| match item {
            Item::Pou(p) => Some(p.name.name),
            _ => None,
        });
        st.chain(self.ladder.iter().map(|l| l.name.clone()))
            .chain(self.petri.iter().map(|p| p.name.clone()))
            .chain(self.networks.iter().map(|n| n.name.clone()))
            .collect()
    }

    /// Whether `name` (trimmed) can name a new POU: not empty, an IEC identifier, not a
    /// keyword, type or standard block, and not the name of another POU (any case). The
    /// error says why, for a message under the name field.
    pub fn check_pou_name(&self, name: &str) -> Result<(), PouError> {
        self.check_new_name(name.trim(), None)
    }

    /// The first of `base1`, `base2`, … that [`Project::check_pou_name`] accepts (`Ladder1`,
    /// `Net1`, `Latch2`); a `base` that cannot start a name becomes `Pou`.
    pub fn free_pou_name(&self, base: &str) -> String {
        let base = base.trim();
        let base = if syntax::is_identifier(base) { base } else { "Pou" };
        let taken = self.pou_names();
        (1u32..)
            .map(|n| format!("{base}{n}"))
            .find(|name| {
                !taken.iter().any(|t| t.eq_ignore_ascii_case(name))
                    && self.check_new_name(name, None).is_ok()
            })
            .unwrap_or_else(|| base.to_string())
    }

    fn check_new_name(&self, name: &str, except: Option<&str>) -> Result<(), PouError> {
        if name.is_empty() {
            return Err(PouError::Empty);
        }
        if !syntax::is_identifier(name) {
            return Err(PouError::NotAName(name.to_string()));
        }
        if let Some(what) = reserved(name) {
            return Err(PouError::Reserved(name.to_string(), what));
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
        self.add_ladder_pou_with(
            name,
            kind,
            "VAR_INPUT\nEND_VAR\nVAR_OUTPUT\nEND_VAR\nVAR\nEND_VAR\n",
        )
    }

    /// Adds a ladder POU named `name` with one empty rung of the default grid and the
    /// given declarations (an exercise's interface, declared for the student).
    pub fn add_ladder_pou_with(
        &mut self,
        name: &str,
        kind: LadderPouKind,
        declarations: &str,
    ) -> Result<(), PouError> {
        let name = name.trim();
        self.check_new_name(name, None)?;
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
        self.program_renamed(old, new);
        self.ladder[index].name = new.to_string();
        Ok(())
    }

    /// Deletes a ladder POU.
    pub fn delete_ladder_pou(&mut self, name: &str) -> Result<(), PouError> {
        let index = self.ladder_index(name)?;
        self.ladder.remove(index);
        self.program_deleted(name);
        Ok(())
    }

    /// Adds a Petri net PROGRAM named `name` with an empty net and empty input and output
    /// declarations.
    pub fn add_petri_pou(&mut self, name: &str) -> Result<(), PouError> {
        self.add_petri_pou_with(name, "VAR_INPUT\nEND_VAR\nVAR_OUTPUT\nEND_VAR\n")
    }

    /// Adds a Petri net PROGRAM named `name` with an empty net and the given declarations.
    pub fn add_petri_pou_with(&mut self, name: &str, declarations: &str) -> Result<(), PouError> {
        let name = name.trim();
        self.check_new_name(name, None)?;
        self.petri.push(PetriPou {
            name: name.to_string(),
            declarations: declarations.to_string(),
            prologue: String::new(),
            epilogue: String::new(),
            net: Net::default(),
            options: GenerationOptions::default(),
        });
        Ok(())
    }

    /// Renames a Petri net POU (the program chosen to run follows it).
    pub fn rename_petri_pou(&mut self, old: &str, new: &str) -> Result<(), PouError> {
        let new = new.trim();
        let index = self.petri_index(old)?;
        self.check_new_name(new, Some(old))?;
        self.program_renamed(old, new);
        self.petri[index].name = new.to_string();
        Ok(())
    }

    /// Deletes a Petri net POU.
    pub fn delete_petri_pou(&mut self, name: &str) -> Result<(), PouError> {
        let index = self.petri_index(name)?;
        self.petri.remove(index);
        self.program_deleted(name);
        Ok(())
    }

    /// Renames a network POU (the program chosen to run follows it; a FUNCTION's elements
    /// that write or read its result follow too).
    pub fn rename_network_pou(&mut self, old: &str, new: &str) -> Result<(), PouError> {
        let new = new.trim();
        let index = self.network_index(old)?;
        self.check_new_name(new, Some(old))?;
        self.program_renamed(old, new);
        let net = &mut self.networks[index];
        if net.kind == crate::network::NetworkPouKind::Function {
            use crate::network::NetKind;
            for e in &mut net.elements {
                match &mut e.kind {
                    NetKind::OutVar { expr }
                    | NetKind::InVar { expr }
                    | NetKind::InOutVar { expr }
                        if expr.trim().eq_ignore_ascii_case(old) =>
                    {
                        *expr = new.to_string();
                    }
                    NetKind::Coil { operand, .. } | NetKind::Contact { operand, .. }
                        if operand.trim().eq_ignore_ascii_case(old) =>
                    {
                        *operand = new.to_string();
                    }
                    _ => {}
                }
            }
        }
        net.name = new.to_string();
        Ok(())
    }

    /// Deletes a network POU.
    pub fn delete_network_pou(&mut self, name: &str) -> Result<(), PouError> {
        let index = self.network_index(name)?;
        self.networks.remove(index);
        self.program_deleted(name);
        Ok(())
    }

    fn network_index(&self, name: &str) -> Result<usize, PouError> {
        self.networks
            .iter()
            .position(|n| n.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| PouError::NoSuchNetwork(name.to_string()))
    }

    /// The program chosen to run follows a rename of its POU.
    fn program_renamed(&mut self, old: &str, new: &str) {
        if self.settings.program.as_deref().is_some_and(|p| p.eq_ignore_ascii_case(old)) {
            self.settings.program = Some(new.to_string());
        }
    }

    /// A deleted POU is no longer the program chosen to run.
    fn program_deleted(&mut self, name: &str) {
        if self.settings.program.as_deref().is_some_and(|p| p.eq_ignore_ascii_case(name)) {
            self.settings.program = None;
        }
    }

    fn petri_index(&self, name: &str) -> Result<usize, PouError> {
        self.petri
            .iter()
            .position(|l| l.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| PouError::NoSuchNet(name.to_string()))
    }

    fn ladder_index(&self, name: &str) -> Result<usize, PouError> {
        self.ladder
            .iter()
            .position(|l| l.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| PouError::NoSuchPou(name.to_string()))
    }
}

/// What `name` already is in the language when it cannot name a POU: a keyword, an
/// elementary type, a standard function block or a standard function.
fn reserved(name: &str) -> Option<&'static str> {
    let upper = name.to_ascii_uppercase();
    if syntax::is_keyword(name) {
        Some("a keyword of ST")
    } else if crate::semantic::Elem::from_name(&upper).is_some()
        || matches!(upper.as_str(), "STRING" | "WSTRING")
    {
        Some("the name of a data type")
    } else if crate::ladder::standard_fb_power(name).is_some() {
        Some("the name of a standard function block")
    } else if crate::ladder::blocks::is_standard_function(name) {
        Some("the name of a standard function")
    } else {
        None
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

    #[test]
    fn a_new_name_is_checked_with_a_message_that_says_why() {
        let p = Project::new("p"); // the ST source has PROGRAM Main
        let why = |name: &str| p.check_pou_name(name).map_err(|e| e.to_string());
        assert_eq!(why("  "), Err("type a name for the POU".into()));
        assert_eq!(why("Latch"), Ok(()));
        assert_eq!(why(" Latch "), Ok(()), "the name is trimmed, as adding trims it");
        assert_eq!(why("main"), Err("the project already has a POU named main".into()));
        assert_eq!(why("if"), Err("if is a keyword of ST: choose another name".into()));
        assert_eq!(why("Int"), Err("Int is the name of a data type: choose another name".into()));
        assert_eq!(
            why("TON"),
            Err("TON is the name of a standard function block: choose another name".into())
        );
        assert_eq!(
            why("sqrt"),
            Err("sqrt is the name of a standard function: choose another name".into())
        );
        assert!(why("1st").unwrap_err().contains("is not a name"));
        let mut q = Project::new("q");
        assert_eq!(
            q.add_ladder_pou("END_VAR", LadderPouKind::Program).unwrap_err(),
            PouError::Reserved("END_VAR".into(), "a keyword of ST")
        );
        assert_eq!(q.add_petri_pou("").unwrap_err(), PouError::Empty);
        // The same reasons in Polish and Czech, the name as typed.
        let said =
            |name: &str, lang| p.check_pou_name(name).unwrap_err().said().message.render(lang);
        use crate::i18n::Lang;
        assert_eq!(
            said("TON", Lang::Pl),
            "TON to nazwa standardowego bloku funkcyjnego: wybierz inną nazwę"
        );
        assert_eq!(said("if", Lang::Cs), "if je klíčové slovo ST: zvolte jiný název");
        assert_eq!(said("main", Lang::Pl), "projekt ma już POU o nazwie main");
    }

    #[test]
    fn a_free_name_is_suggested_from_a_base() {
        let mut p = Project::new("p");
        assert_eq!(p.free_pou_name("Ladder"), "Ladder1");
        p.add_ladder_pou("ladder1", LadderPouKind::Program).unwrap();
        p.add_petri_pou("Ladder2").unwrap();
        assert_eq!(p.free_pou_name("Ladder"), "Ladder3", "any kind of POU, any case");
        p.source.push_str("\nFUNCTION_BLOCK Net1\nEND_FUNCTION_BLOCK\n");
        assert_eq!(p.free_pou_name("Net"), "Net2", "ST POUs count too");
        assert_eq!(p.free_pou_name("9 lives"), "Pou1", "a base that is no name");
        assert_eq!(p.free_pou_name("CTU"), "CTU1", "a standard name with a number is free");
    }

    #[test]
    fn a_pou_can_start_with_declarations() {
        let mut p = Project::new("p");
        let decls = "VAR_INPUT\n    Start : BOOL;\nEND_VAR\n";
        p.add_ladder_pou_with("Latch1", LadderPouKind::Program, decls).unwrap();
        p.add_petri_pou_with("Net1", decls).unwrap();
        assert_eq!(
            (p.ladder[0].declarations.as_str(), p.petri[0].declarations.as_str()),
            (decls, decls)
        );
        assert_eq!(p.add_petri_pou_with("latch1", decls), Err(PouError::Taken("latch1".into())));
    }

    #[test]
    fn petri_net_pous_are_added_renamed_and_deleted_with_checked_names() {
        let mut p = Project::new("p");
        p.add_petri_pou("Cycle").unwrap();
        assert!(p.petri[0].net.places.is_empty());
        assert_eq!(p.add_petri_pou("cycle"), Err(PouError::Taken("cycle".into())));
        assert_eq!(p.add_petri_pou("Main"), Err(PouError::Taken("Main".into())), "the ST PROGRAM");
        p.settings.program = Some("Cycle".into());
        p.rename_petri_pou("CYCLE", "Loop").unwrap();
        assert_eq!(
            (p.petri[0].name.as_str(), p.settings.program.as_deref()),
            ("Loop", Some("Loop"))
        );
        assert_eq!(p.rename_petri_pou("Loop", "a b"), Err(PouError::NotAName("a b".into())));
        p.delete_petri_pou("loop").unwrap();
        assert!(p.petri.is_empty() && p.settings.program.is_none());
        assert_eq!(p.delete_petri_pou("Loop"), Err(PouError::NoSuchNet("Loop".into())));
    }
}
