//! The PROGRAMs of a project and the language each is written in, read from the model
//! alone (the ST source is parsed, never checked): what the exercise panel lists under
//! `Program to check` and what a grading report names (`Checked PROGRAM Latch (ladder)`),
//! even while the project does not build.

use super::Project;
use crate::ladder::LadderPouKind;
use crate::network::NetworkPouKind;
use crate::syntax::{self, ast::PouKind, Item};

/// The language a POU is written in, as a report names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PouLanguage {
    /// Structured Text in the project's source.
    St,
    /// Instruction List in the project's source.
    Il,
    /// A textual sequential function chart in the project's source.
    Sfc,
    /// A ladder POU drawn in the ladder editor.
    Ladder,
    /// A Petri net POU.
    PetriNet,
    /// A network POU imported from another tool (LD, FBD or SFC as drawn there).
    Network,
}

impl PouLanguage {
    /// Its name in a report: `ST`, `IL`, `SFC`, `ladder`, `Petri net`, `network`.
    pub fn label(self) -> &'static str {
        match self {
            PouLanguage::St => "ST",
            PouLanguage::Il => "IL",
            PouLanguage::Sfc => "SFC",
            PouLanguage::Ladder => "ladder",
            PouLanguage::PetriNet => "Petri net",
            PouLanguage::Network => "network",
        }
    }
}

/// A PROGRAM of a project.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProgramPou {
    /// Its name.
    pub name: String,
    /// What it is written in.
    pub language: PouLanguage,
}

impl Project {
    /// The project's PROGRAMs in the order the build lists them (the ST source's, then the
    /// ladder, Petri net and network POUs'), each with its language.
    pub fn programs(&self) -> Vec<ProgramPou> {
        let (file, _) = syntax::parse(&self.source);
        let mut out: Vec<ProgramPou> = file
            .items
            .iter()
            .filter_map(|item| match item {
                Item::Pou(p) if p.kind == PouKind::Program => Some(ProgramPou {
                    name: p.name.name.clone(),
                    language: if p.sfc.is_some() {
                        PouLanguage::Sfc
                    } else if p.il.is_some() {
                        PouLanguage::Il
                    } else {
                        PouLanguage::St
                    },
                }),
                _ => None,
            })
            .collect();
        let program = |name: &str, language| ProgramPou { name: name.to_string(), language };
        out.extend(
            self.ladder
                .iter()
                .filter(|l| l.kind == LadderPouKind::Program)
                .map(|l| program(&l.name, PouLanguage::Ladder)),
        );
        out.extend(self.petri.iter().map(|p| program(&p.name, PouLanguage::PetriNet)));
        out.extend(
            self.networks
                .iter()
                .filter(|n| n.kind == NetworkPouKind::Program)
                .map(|n| program(&n.name, PouLanguage::Network)),
        );
        out
    }

    /// The PROGRAM named `name` (any case).
    pub fn program_named(&self, name: &str) -> Option<ProgramPou> {
        self.programs().into_iter().find(|p| p.name.eq_ignore_ascii_case(name))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn every_program_is_listed_with_its_language() {
        let mut p = Project::new("p");
        p.source = "PROGRAM Main\nVAR x : BOOL; END_VAR\nx := TRUE;\nEND_PROGRAM\n\
                    FUNCTION_BLOCK Fb\nEND_FUNCTION_BLOCK\n\
                    PROGRAM Seq\nINITIAL_STEP Idle :\nEND_STEP\nEND_PROGRAM\n\
                    PROGRAM Listed\nVAR a : BOOL; END_VAR\nLD a\nST a\nEND_PROGRAM\n"
            .into();
        p.add_ladder_pou("Latch", LadderPouKind::Program).unwrap();
        p.add_ladder_pou("Helper", LadderPouKind::FunctionBlock).unwrap();
        p.add_petri_pou("Net1").unwrap();
        let got: Vec<(String, &str)> =
            p.programs().into_iter().map(|p| (p.name, p.language.label())).collect();
        let want = [
            ("Main", "ST"),
            ("Seq", "SFC"),
            ("Listed", "IL"),
            ("Latch", "ladder"),
            ("Net1", "Petri net"),
        ];
        assert_eq!(got, want.map(|(n, l)| (n.to_string(), l)));
        assert_eq!(p.program_named("latch").unwrap().language, PouLanguage::Ladder);
        assert_eq!(p.program_named("Helper"), None);
    }
}
