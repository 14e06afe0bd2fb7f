//! Checks of a Petri net POU that come before code generation: the ST texts held by its
//! elements parse on their own (so a bad guard is reported at its transition, and no text
//! can break the structure of the generated program), names are identifiers, CASE labels
//! fit an INT, every transition has an input place, and the emergency place exists.
//! Type errors in guards and actions are found later by the ST checker on the generated
//! program and mapped back to the element by the line map (see `codegen`).

use super::diagnostic::{NetElement, PetriDiagnostic, TextPart, TextPosition};
use super::model::PetriPou;
use super::net::PtNet;
use crate::diagnostics::{Code, Diagnostic, LineIndex, Said};
use crate::syntax::{self, Item};

pub use crate::syntax::is_identifier;

fn position(text: &str, offset: u32, part: TextPart) -> TextPosition {
    let loc = LineIndex::new(text).location(offset.min(text.len() as u32));
    TextPosition { part, line: loc.line, column: loc.column }
}

fn located(
    code: Code,
    element: &NetElement,
    text: &str,
    part: TextPart,
    d: &Diagnostic,
    shift: u32,
) -> PetriDiagnostic {
    let offset = d.span.start.saturating_sub(shift);
    let said = Said { message: d.msg.clone(), english: d.message.clone() };
    PetriDiagnostic::error(code, element.clone(), said).at(position(text, offset, part))
}

/// Checks that `text` is one ST expression; problems are located inside it.
pub fn check_expression(text: &str, element: &NetElement, part: TextPart) -> Vec<PetriDiagnostic> {
    if text.trim().is_empty() {
        return Vec::new();
    }
    match syntax::parse_expression(text) {
        Ok(_) => Vec::new(),
        Err(diags) => diags
            .iter()
            .take(1)
            .map(|d| located(Code::PetriBadGuard, element, text, part, d, 0))
            .collect(),
    }
}

/// Checks that `text` is a list of ST statements (no declarations, no END of the POU).
pub fn check_statements(text: &str, element: &NetElement, part: TextPart) -> Vec<PetriDiagnostic> {
    if text.trim().is_empty() {
        return Vec::new();
    }
    const HEAD: &str = "PROGRAM PnCheck\n";
    let wrapped = format!("{HEAD}{text}\nEND_PROGRAM\n");
    let (file, diags) = syntax::parse(&wrapped);
    let shift = HEAD.len() as u32;
    if let Some(d) = diags.first() {
        return vec![located(Code::PetriBadActions, element, text, part, d, shift)];
    }
    let pous: Vec<&syntax::Pou> = file
        .items
        .iter()
        .filter_map(|i| if let Item::Pou(p) = i { Some(p) } else { None })
        .collect();
    let problem = if file.items.len() != 1 || pous.len() != 1 {
        Some((text.len() as u32, crate::msg!(PetriTextEndsPouEarly)))
    } else {
        pous[0]
            .var_blocks
            .first()
            .map(|b| (b.span.start.saturating_sub(shift), crate::msg!(PetriDeclareInDeclarations)))
    };
    problem
        .map(|(offset, message)| {
            PetriDiagnostic::error(Code::PetriBadActions, element.clone(), message)
                .at(position(text, offset, part))
        })
        .into_iter()
        .collect()
}

/// Every check of this module on a POU whose net built.
pub fn check_pou(pou: &PetriPou, net: &PtNet) -> Vec<PetriDiagnostic> {
    let mut diags = Vec::new();
    if !is_identifier(pou.name.trim()) {
        diags.push(PetriDiagnostic::error(
            Code::PetriBadName,
            NetElement::Pou,
            crate::msg!(PetriBadPouName, name = pou.name),
        ));
    }
    for proc in &pou.net.processes {
        for (step, name) in [(false, &proc.name), (true, &proc.step_variable)] {
            if !is_identifier(name.trim()) {
                let said = if step {
                    crate::msg!(PetriBadStepVariable, name = name)
                } else {
                    crate::msg!(PetriBadProcessName, name = name)
                };
                diags.push(PetriDiagnostic::error(
                    Code::PetriBadName,
                    NetElement::Process(proc.name.clone()),
                    said,
                ));
            }
        }
    }
    for place in &pou.net.places {
        let here = NetElement::Place(place.id.clone());
        if i64::from(i16::MIN) > place.label || place.label > i64::from(i16::MAX) {
            diags.push(PetriDiagnostic::error(
                Code::PetriLabelRange,
                here.clone(),
                crate::msg!(PetriLabelRange, label = place.label),
            ));
        }
        diags.extend(check_statements(&place.actions, &here, TextPart::Actions));
    }
    for (i, t) in pou.net.transitions.iter().enumerate() {
        let here = NetElement::Transition(t.id.clone());
        diags.extend(check_expression(&t.guard, &here, TextPart::Guard));
        if net.pre[i].is_empty() {
            diags.push(PetriDiagnostic::error(
                Code::PetriSourceTransition,
                here,
                crate::msg!(PetriSourceTransition),
            ));
        }
    }
    diags.extend(check_statements(&pou.prologue, &NetElement::Prologue, TextPart::Text));
    diags.extend(check_statements(&pou.epilogue, &NetElement::Epilogue, TextPart::Text));
    if let Some(e) = &pou.net.emergency {
        if pou.net.place(&e.place).is_none() {
            diags.push(PetriDiagnostic::error(
                Code::PetriBadEmergency,
                NetElement::Emergency,
                crate::msg!(PetriEmergencyNotPlace, place = e.place),
            ));
        }
        if e.condition.trim().is_empty() {
            diags.push(PetriDiagnostic::error(
                Code::PetriBadGuard,
                NetElement::Emergency,
                crate::msg!(PetriEmergencyConditionEmpty),
            ));
        }
        diags.extend(check_expression(&e.condition, &NetElement::Emergency, TextPart::Condition));
    }
    diags
}
