//! The checker: resolves names (case-insensitively), types every expression, inserts the
//! implicit widening conversions, folds constants, and turns the syntax tree into the typed
//! [`ir`] that the compiler consumes. Problems become located diagnostics with stable codes.
//!
//! It never executes user code and never panics on a bad program: every check failure is a
//! diagnostic, and checking goes on so that one mistake does not hide the next.

mod builtins;
mod calls;
mod check;
mod config;
mod consts;
mod decl;
mod expr;
mod image;
pub mod ir;
mod nesting;
mod prelude;
mod ref_init;
mod refs;
mod stmt;
pub mod types;

pub use builtins::is_builtin;
pub use image::{image_name, image_spot, is_image_name};
pub use ir::{BinOp, Builtin, CallArg, Expr, ExprKind, InitValue, Place, Program, SysVar, UnOp};
pub use types::{Elem, PouId, Type, TypeTable};

/// The implicit widening rule, for front-ends that check operands before the checker runs.
pub(crate) use expr::can_widen;
/// The standard function blocks' ST source (their pins are read from it by the ladder).
pub(crate) use prelude::SOURCE as PRELUDE_SOURCE;

use crate::diagnostics::{has_errors, Diagnostic};
use crate::syntax;

/// The outcome of checking a source text.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The checked program, when there were no errors.
    pub program: Option<Program>,
    /// Every diagnostic (errors and warnings), sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

/// Parses and checks `source` together with the standard library prelude. Textual SFC
/// and Instruction List bodies are lowered to statements first (`crate::sfc`, `crate::il`).
pub fn analyze(source: &str) -> Analysis {
    analyze_by(source, &TextPasses::ALL)
}

/// The passes that lower textual SFC and Instruction List bodies to statements before the
/// check. The web app's page loads each as a chunk of its wasm the first time a project
/// has such a body (`crate::build::Lowerings::lacks`), so an ST-only page never downloads
/// them; every other build of the engine uses [`TextPasses::ALL`].
#[derive(Debug, Clone, Copy)]
pub struct TextPasses {
    /// Textual SFC bodies ([`crate::sfc::desugar`]).
    pub sfc: Option<SfcPass>,
    /// Instruction List bodies ([`desugar_il`]).
    pub il: Option<IlPass>,
}

/// The SFC pass of [`TextPasses`].
pub type SfcPass = fn(&mut syntax::SourceFile) -> crate::sfc::Desugared;

/// The Instruction List pass of [`TextPasses`].
pub type IlPass = fn(&mut syntax::SourceFile) -> Vec<Diagnostic>;

impl TextPasses {
    /// Both passes.
    pub const ALL: TextPasses = TextPasses { sfc: Some(crate::sfc::desugar), il: Some(desugar_il) };
}

/// Lowers the Instruction List bodies of `file` to statements, typing their operands with
/// the checker.
pub fn desugar_il(file: &mut syntax::SourceFile) -> Vec<Diagnostic> {
    crate::il::desugar(file, check::IlTyping::new)
}

/// Which text passes `source` needs: `(sfc, il)`, whether some POU has a textual SFC or an
/// Instruction List body.
pub fn text_passes_needed(source: &str) -> (bool, bool) {
    let (file, _) = syntax::parse(source);
    let pous = || {
        file.items.iter().filter_map(|i| match i {
            syntax::Item::Pou(p) => Some(p),
            _ => None,
        })
    };
    (pous().any(|p| p.sfc.is_some()), pous().any(|p| p.il.is_some()))
}

/// [`analyze`] with the text passes `passes` has: a body whose pass is missing is left
/// out of the check (the page loads the pass first; see [`TextPasses`]).
pub fn analyze_by(source: &str, passes: &TextPasses) -> Analysis {
    let (mut file, mut diagnostics) = syntax::parse(source);
    let sfc = passes.sfc.map(|desugar| desugar(&mut file)).unwrap_or_default();
    diagnostics.extend(sfc.diagnostics.iter().cloned());
    if let Some(desugar) = passes.il {
        diagnostics.extend(desugar(&mut file));
    }
    let (program, more) = check::check_with_prelude(&file);
    diagnostics.extend(sfc.reword(more));
    crate::order::sort_by_key(&mut diagnostics, |d| (d.span.start, d.span.end));
    let program = if has_errors(&diagnostics) { None } else { program };
    Analysis { program, diagnostics }
}

/// Checks `source`, an ST boolean expression, in the scope of POU `pou` of `program` (a
/// breakpoint condition such as `Level > 80 AND Pump`).
pub fn check_condition(
    program: &Program,
    pou: PouId,
    source: &str,
) -> Result<Expr, Vec<Diagnostic>> {
    let expr = syntax::parse_expression(source)?;
    check::check_expression_in(program, pou, &expr, Some(Type::BOOL), true)
}

/// Checks `source`, an ST expression of a single value (`ADD(N, 5)`, `T1.ET`), in the scope
/// of POU `pou` of `program`, for a watch evaluated between scans: it may not call a
/// FUNCTION of the program (one may write globals), and its type must be elementary.
pub fn check_watch(program: &Program, pou: PouId, source: &str) -> Result<Expr, Vec<Diagnostic>> {
    let expr = syntax::parse_expression(source)?;
    let checked = check::check_expression_in(program, pou, &expr, None, true)?;
    let refuse = |message: &str| {
        vec![Diagnostic::error(crate::diagnostics::Code::TypeMismatch, checked.span, message)]
    };
    if calls_a_function(&checked) {
        return Err(refuse("a watch cannot call a FUNCTION of the program"));
    }
    if !matches!(checked.ty, Type::Elem(_) | Type::Enum(_)) {
        return Err(refuse("a watch shows a single value of an elementary type"));
    }
    Ok(checked)
}

/// The subrange declared for the variable at `path` (`Level`, `Arr[2]`) in the scope of
/// POU `pou`, if it has one (values written from outside the program are checked
/// against it).
pub fn subrange_of(program: &Program, pou: PouId, path: &str) -> Option<(i64, i64)> {
    let expr = syntax::parse_expression(path).ok()?;
    check::subrange_in(program, pou, &expr)
}

/// Whether `e` calls a FUNCTION (not a built-in) anywhere in its operands.
fn calls_a_function(e: &Expr) -> bool {
    match &e.kind {
        ir::ExprKind::Call { .. } => true,
        ir::ExprKind::Unary(_, a) | ir::ExprKind::Convert(a) | ir::ExprKind::Trunc(a) => {
            calls_a_function(a)
        }
        ir::ExprKind::Binary(_, a, b) => calls_a_function(a) || calls_a_function(b),
        ir::ExprKind::Builtin { args, .. } => args.iter().any(calls_a_function),
        ir::ExprKind::Const(_)
        | ir::ExprKind::ConstStr(_)
        | ir::ExprKind::Load(_)
        | ir::ExprKind::RefOf(_) => false,
        ir::ExprKind::Sys(_) => false,
    }
}

/// Parses `text`, an IEC literal or constant expression (`TRUE`, `42`, `-1.5`, `T#2s`,
/// `'text'`, an enumerator), as a value of type `ty` in the scope of POU `pou`.
pub fn parse_value(
    program: &Program,
    pou: PouId,
    ty: Type,
    text: &str,
) -> Result<InitValue, String> {
    let expr = syntax::parse_expression(text).map_err(|d| first_message(&d))?;
    let checked = check::check_expression_in(program, pou, &expr, Some(ty), false)
        .map_err(|d| first_message(&d))?;
    consts::to_init_value(&checked).ok_or_else(|| format!("`{text}` is not a constant value"))
}

fn first_message(diags: &[Diagnostic]) -> String {
    diags.first().map_or_else(|| "invalid value".to_string(), |d| d.message.clone())
}

#[cfg(test)]
mod tests;
