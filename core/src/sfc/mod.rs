//! Textual SFC (IEC 61131-3 §6.7): checks the sequential function charts of a parsed file
//! and turns each into ordinary statements and hidden variables, **before** the checker, so
//! that the one checker, compiler and VM run it like any ST body.
//!
//! - `chart.rs` resolves names (steps, transitions, actions, associations) and reports what
//!   names alone reveal; `walk.rs` checks the statements of actions and transition bodies;
//!   `structure.rs` finds unsafe and unreachable structures (warnings);
//! - `lower.rs` generates the evolution logic and the action controls (`build.rs` holds the
//!   node constructors);
//! - [`Desugared::reword`] renames the checker's findings in generated code (a transition
//!   condition that is not BOOL, a duration that is not TIME) after the chart's elements.
//!
//! Each step `S` becomes a variable of the structure type `SFC_STEP` (`S.X`, `S.T`), each
//! action `A` a structure holding its control (`A.Q`, `A.A` and the timers and flip-flops
//! its qualifiers need); the other hidden names contain `__`, which users cannot write, so
//! they never clash with the user's names. The rules are explained to students in
//! `docs/sfc.md`. This module never looks at types: the checker does, on the lowered code.

mod build;
mod chart;
mod lower;
mod structure;
mod walk;

use std::collections::HashMap;

use crate::diagnostics::{has_errors, Code, Diagnostic, Span};
use crate::syntax::ast::{Item, PouKind, SourceFile, TypeDef, VarSection};
use crate::syntax::sfc_ast::{SfcElement, TransitionCondition};
use build::At;

/// The structure type of every step variable (`X : BOOL; T : TIME`).
pub const STEP_TYPE: &str = "SFC_STEP";
/// TRUE once the chart has run its first scan (transitions are tested from the second).
const STARTED: &str = "SFC__Started";
/// Virtual time since the chart's previous scan.
const DT: &str = "SFC__Dt";
/// `SYS_CLOCK` at the chart's previous scan.
const LAST: &str = "SFC__Last";

/// How a checker diagnostic in generated code is reworded.
#[derive(Debug, Clone)]
enum Reword {
    /// A transition condition that is not BOOL; holds how to name the transition.
    Condition(String),
    /// Any other: this sentence, then the checker's message in parentheses.
    Wrap(String),
}

/// A checker diagnostic to reword: one of `codes` at exactly `span` becomes `code`.
#[derive(Debug, Clone)]
struct Rewrite {
    span: Span,
    codes: &'static [Code],
    code: Code,
    reword: Reword,
}

/// The outcome of [`desugar`]: the SFC diagnostics, and how to reword the checker's.
#[derive(Debug, Clone, Default)]
pub struct Desugared {
    /// Problems found in the charts (errors and warnings).
    pub diagnostics: Vec<Diagnostic>,
    rewrites: Vec<Rewrite>,
}

impl Desugared {
    /// Rewords the checker's diagnostics about generated code so they name the chart's
    /// elements (and carry the SFC codes E0558, E0559, E0565).
    pub fn reword(&self, diagnostics: Vec<Diagnostic>) -> Vec<Diagnostic> {
        diagnostics
            .into_iter()
            .map(|mut d| {
                let found =
                    self.rewrites.iter().find(|r| r.span == d.span && r.codes.contains(&d.code));
                if let Some(r) = found {
                    d.code = r.code;
                    d.message = match &r.reword {
                        Reword::Condition(what) => match d.message.split_once("must be BOOL, not ")
                        {
                            Some((_, ty)) => {
                                format!("the condition of {what} must be BOOL, not {ty}")
                            }
                            None => format!("the condition of {what} must be BOOL ({})", d.message),
                        },
                        Reword::Wrap(sentence) => format!("{sentence} ({})", d.message),
                    };
                }
                d
            })
            .collect()
    }
}

/// Checks every SFC body of `file` and replaces it by hidden declarations and statements.
/// POUs without an SFC body are left untouched; a file without any costs one pass.
pub fn desugar(file: &mut SourceFile) -> Desugared {
    let mut out = Desugared::default();
    let has_sfc = file.items.iter().any(|i| matches!(i, Item::Pou(p) if p.sfc.is_some()));
    if !has_sfc {
        return out;
    }
    let reserved_clash = check_reserved(file, &mut out.diagnostics);
    let globals = global_names(file);
    let mut lowered = Vec::new();
    for (index, item) in file.items.iter().enumerate() {
        let Item::Pou(pou) = item else { continue };
        let Some(body) = &pou.sfc else { continue };
        if pou.kind == PouKind::Function {
            let msg = format!(
                "FUNCTION `{}` cannot have an SFC body: a function keeps nothing between calls; make it a FUNCTION_BLOCK",
                pou.name.name
            );
            out.diagnostics.push(Diagnostic::error(Code::SfcNotAllowedHere, pou.name.span, msg));
            continue;
        }
        let mut scope = chart::Scope { globals: globals.clone(), ..Default::default() };
        for decl in pou.var_blocks.iter().flat_map(|b| &b.decls) {
            for n in &decl.names {
                scope.locals.insert(n.key(), n.span);
            }
        }
        let mut diags = Vec::new();
        let chart = chart::resolve(pou, body, &scope, &mut diags);
        check_statements(&chart, body, &mut diags);
        if !has_errors(&diags) {
            structure::check(&chart, &mut diags);
        }
        if !reserved_clash {
            lowered.push((index, lower::lower(&chart, &mut out.rewrites)));
        }
        out.diagnostics.extend(diags);
    }
    if lowered.is_empty() {
        return out;
    }
    let mut types: Vec<TypeDef> = Vec::new();
    for (index, l) in lowered {
        if let Some(Item::Pou(pou)) = file.items.get_mut(index) {
            if types.is_empty() {
                let at = At(pou.name.span);
                types.push(
                    at.struct_type(STEP_TYPE, vec![("X".into(), "BOOL"), ("T".into(), "TIME")]),
                );
            }
            types.extend(l.types);
            pou.var_blocks.push(l.vars);
            pou.body = l.body;
        }
    }
    file.items.push(Item::Types(types));
    out
}

/// Reports a user type or POU named like the step type (only when the file has a chart).
fn check_reserved(file: &SourceFile, diags: &mut Vec<Diagnostic>) -> bool {
    let mut clash = false;
    let mut report = |name: &crate::syntax::ast::Ident| {
        if name.name.eq_ignore_ascii_case(STEP_TYPE) {
            clash = true;
            let msg = format!(
                "`{}` is the type of SFC steps in a file with an SFC body; choose another name",
                name.name
            );
            diags.push(Diagnostic::error(Code::SfcReservedName, name.span, msg));
        }
    };
    for item in &file.items {
        match item {
            Item::Types(defs) => defs.iter().for_each(|d| report(&d.name)),
            Item::Pou(p) => report(&p.name),
            Item::Globals(_) => {}
        }
    }
    clash
}

/// The global variables of the file: top-level VAR_GLOBAL and PROGRAM VAR_GLOBAL blocks.
fn global_names(file: &SourceFile) -> HashMap<String, Span> {
    let mut out = HashMap::new();
    let blocks = file.items.iter().flat_map(|item| match item {
        Item::Globals(b) => vec![b],
        Item::Pou(p) => p.var_blocks.iter().filter(|b| b.section == VarSection::Global).collect(),
        Item::Types(_) => Vec::new(),
    });
    for b in blocks {
        for n in b.decls.iter().flat_map(|d| &d.names) {
            out.insert(n.key(), n.span);
        }
    }
    out
}

/// Checks the statements of actions and transitions: no writes to step flags or action
/// controls, no RETURN, and a statement body must assign the transition's name.
fn check_statements(
    chart: &chart::Chart,
    body: &crate::syntax::sfc_ast::SfcBody,
    diags: &mut Vec<Diagnostic>,
) {
    let mut protected: HashMap<String, &'static str> = HashMap::new();
    for s in &chart.steps {
        protected.insert(s.name.key(), "step");
    }
    for a in &chart.actions {
        if let chart::ActionKind::Declared(_) = a.kind {
            protected.insert(a.name.key(), "action");
        }
    }
    let no_return = |stmts: &[crate::syntax::ast::Stmt],
                     what: &str,
                     diags: &mut Vec<Diagnostic>| {
        if let Some(span) = walk::first_return(stmts) {
            let msg = format!(
                "RETURN cannot be used in {what}: it would leave the whole POU and skip the rest of the chart; use IF … END_IF instead"
            );
            diags.push(Diagnostic::error(Code::SfcReturnInAction, span, msg));
        }
    };
    for element in &body.elements {
        match element {
            SfcElement::Action(a) => {
                walk::check_writes(&a.body, &[], &protected, diags);
                no_return(&a.body, &format!("action `{}`", a.name.name), diags);
            }
            SfcElement::Transition(t) => match &t.condition {
                TransitionCondition::Expr(e) => walk::check_writes(&[], &[e], &protected, diags),
                TransitionCondition::Body(stmts) => {
                    walk::check_writes(stmts, &[], &protected, diags);
                    no_return(stmts, "a transition body", diags);
                    match &t.name {
                        None => {
                            let msg = "a transition written with statements needs a name to assign: `TRANSITION T1 FROM a TO b : T1 := …; END_TRANSITION` (or write `:= condition;`)";
                            diags.push(Diagnostic::error(
                                Code::SfcUnnamedTransitionBody,
                                t.header,
                                msg,
                            ));
                        }
                        Some(name) if !walk::assigns(stmts, name) => {
                            let msg = format!(
                                "the body of transition `{}` never assigns `{0}`, so the transition never fires",
                                name.name
                            );
                            diags.push(Diagnostic::warning(
                                Code::SfcTransitionNotAssigned,
                                name.span,
                                msg,
                            ));
                        }
                        Some(_) => {}
                    }
                }
            },
            SfcElement::Step(_) => {}
        }
    }
}

#[cfg(test)]
mod tests;
