//! What the operand box offers while a contact's, coil's or jump's operand is typed: the
//! POU's variables and the project's globals of the right type (BOOL; for a coil only those
//! a rung may write), the BOOL outputs of its block instances (`T1.Q`), the direct
//! addresses its variables sit at, and for a jump the labels of its rungs.

use super::catalog::{Catalog, TypeKey, Variable};
use super::{Element, LadderPou};
use crate::syntax::ast::{AddressArea, AddressSize};

/// How many choices the box lists at most.
pub const MAX_CHOICES: usize = 40;

/// One choice of the operand box.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OperandChoice {
    /// What the choice puts into the box (`Start`, `T1.Q`, `%IX0.0`).
    pub text: String,
    /// What it is (`BOOL, VAR_INPUT at %IX0.0`), shown beside it.
    pub detail: String,
}

/// What an element's operand must be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Wanted {
    /// A BOOL to read (contacts).
    Read,
    /// A BOOL to write (coils).
    Write,
    /// A rung label (jumps).
    Label,
}

fn wanted(element: &Element) -> Option<Wanted> {
    Some(match element {
        Element::Contact { .. } => Wanted::Read,
        Element::Coil { .. } => Wanted::Write,
        Element::Jump { .. } => Wanted::Label,
        _ => return None,
    })
}

fn detail(v: &Variable) -> String {
    let mut text = format!("{}, {}", v.ty, v.section.keyword());
    if v.constant {
        text.push_str(" CONSTANT");
    }
    if let Some(a) = &v.address {
        text.push_str(" at ");
        text.push_str(&a.text);
    }
    text
}

/// Every choice for the operand of `element` in `pou`, unfiltered, in this order: the
/// variables as declared (the POU's, then the globals), the instances' BOOL outputs, the
/// direct addresses; or the rung labels for a jump.
pub fn all_operand_choices(
    catalog: &Catalog,
    pou: &LadderPou,
    element: &Element,
) -> Vec<OperandChoice> {
    let Some(want) = wanted(element) else { return Vec::new() };
    if want == Wanted::Label {
        return pou
            .rungs
            .iter()
            .enumerate()
            .filter_map(|(i, r)| {
                let label = r.label.as_deref().map(str::trim).filter(|l| !l.is_empty())?;
                Some(OperandChoice { text: label.to_string(), detail: format!("rung {}", i + 1) })
            })
            .collect();
    }
    let vars = catalog.variables(&pou.declarations);
    let mut choices: Vec<OperandChoice> = vars
        .iter()
        .filter(|v| v.ty.is_bool() && (want == Wanted::Read || v.writable()))
        .map(|v| OperandChoice { text: v.name.clone(), detail: detail(v) })
        .collect();
    if want == Wanted::Read {
        for v in &vars {
            let TypeKey::Named(ty) = &v.ty else { continue };
            let Some(block) = catalog.block(ty).filter(|b| b.is_function_block()) else { continue };
            for out in block.outputs.iter().filter(|o| o.ty.as_ref().is_some_and(TypeKey::is_bool))
            {
                choices.push(OperandChoice {
                    text: format!("{}.{}", v.name, out.name),
                    detail: format!("BOOL, output of {} {}", block.name, v.name),
                });
            }
        }
    }
    for v in &vars {
        let Some(address) = &v.address else { continue };
        let writes_input = want == Wanted::Write && address.area == AddressArea::Input;
        if address.size != AddressSize::Bit || writes_input {
            continue;
        }
        choices.push(OperandChoice {
            text: address.text.clone(),
            detail: format!("address of {}", v.name),
        });
    }
    choices
}

/// The choices for the operand of `element` in `pou` that match `typed`: those that start
/// with it first, then those that contain it (any case), at most [`MAX_CHOICES`]. A choice
/// that is exactly what was typed is left out (there is nothing to complete).
pub fn operand_choices(
    catalog: &Catalog,
    pou: &LadderPou,
    element: &Element,
    typed: &str,
) -> Vec<OperandChoice> {
    let typed = typed.trim().to_ascii_lowercase();
    let all = all_operand_choices(catalog, pou, element);
    let (mut starts, mut contains) = (Vec::new(), Vec::new());
    for c in all {
        let lower = c.text.to_ascii_lowercase();
        if lower == typed {
            continue;
        }
        if lower.starts_with(&typed) {
            starts.push(c);
        } else if lower.contains(&typed) {
            contains.push(c);
        }
    }
    starts.extend(contains);
    starts.truncate(MAX_CHOICES);
    starts
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ladder::{CoilKind, ContactKind, Rung};

    fn pou(declarations: &str) -> LadderPou {
        LadderPou {
            name: "Main".into(),
            kind: crate::ladder::LadderPouKind::Program,
            declarations: declarations.to_string(),
            rungs: vec![Rung::new(2, 4)],
        }
    }

    fn texts(list: &[OperandChoice]) -> Vec<&str> {
        list.iter().map(|c| c.text.as_str()).collect()
    }

    const DECLS: &str = "VAR_INPUT\n  Start AT %IX0.0 : BOOL;\n  Level : INT;\nEND_VAR\n\
        VAR_OUTPUT\n  Motor AT %QX0.0 : BOOL;\nEND_VAR\n\
        VAR\n  T1 : TON;\n  Latched : BOOL;\nEND_VAR\n\
        VAR CONSTANT\n  Always : BOOL := TRUE;\nEND_VAR\n";

    fn contact() -> Element {
        Element::Contact { kind: ContactKind::NormallyOpen, operand: String::new() }
    }

    fn coil() -> Element {
        Element::Coil { kind: CoilKind::Normal, operand: String::new() }
    }

    #[test]
    fn a_contact_is_offered_every_bool_it_can_read() {
        let catalog =
            Catalog::of_parts("VAR_GLOBAL\n  Alarm : BOOL;\n  Count : INT;\nEND_VAR\n", &[]);
        let list = all_operand_choices(&catalog, &pou(DECLS), &contact());
        assert_eq!(
            texts(&list),
            ["Start", "Motor", "Latched", "Always", "Alarm", "T1.Q", "%IX0.0", "%QX0.0"]
        );
        assert_eq!(list[0].detail, "BOOL, VAR_INPUT at %IX0.0");
        assert_eq!(list[3].detail, "BOOL, VAR CONSTANT");
        assert_eq!(list[5].detail, "BOOL, output of TON T1");
    }

    #[test]
    fn a_coil_is_offered_only_what_a_rung_may_write() {
        let catalog = Catalog::of_parts("", &[]);
        let list = all_operand_choices(&catalog, &pou(DECLS), &coil());
        assert_eq!(texts(&list), ["Motor", "Latched", "%QX0.0"]);
    }

    #[test]
    fn a_jump_is_offered_the_labels_of_the_rungs() {
        let catalog = Catalog::of_parts("", &[]);
        let mut p = pou(DECLS);
        let mut r = Rung::new(2, 4);
        r.label = Some("Done".into());
        p.rungs.push(r);
        let list = all_operand_choices(&catalog, &p, &Element::Jump { label: String::new() });
        assert_eq!(list, [OperandChoice { text: "Done".into(), detail: "rung 2".into() }]);
    }

    #[test]
    fn typing_narrows_the_list_prefix_first() {
        let catalog = Catalog::of_parts("", &[]);
        let p = pou(DECLS);
        assert_eq!(
            texts(&operand_choices(&catalog, &p, &contact(), "t")),
            ["T1.Q", "Start", "Motor", "Latched"]
        );
        assert_eq!(texts(&operand_choices(&catalog, &p, &contact(), "MOT")), ["Motor"]);
        assert!(operand_choices(&catalog, &p, &contact(), "Motor").is_empty());
        assert!(operand_choices(&catalog, &p, &Element::Wire, "").is_empty());
    }
}
