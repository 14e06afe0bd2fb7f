//! Located diagnostics: spans, line/column lookup and the table of problem codes.
//!
//! Every stage reports problems as [`Diagnostic`] values carrying a stable [`Code`]; nothing
//! here prints or panics. The codes live in one table (`codes.rs`), their explanations and examples in
//! another (`explain.rs`), from which `docs/problems.md` is generated.

mod codes;
mod explain;
mod span;

pub use codes::Code;
pub use explain::{
    explain_text, problems_html, problems_markdown, Example, Explanation, EXPLANATIONS,
};
pub use span::{LineIndex, Location, Span};

use serde::Serialize;

/// How bad a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// The program cannot run.
    Error,
    /// The program runs, but probably not as meant.
    Warning,
}

impl Severity {
    /// The word the command line prints before a code: `error` or `warning`.
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// One problem found in a source text.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// The stable problem code (`E0042`).
    pub code: Code,
    /// A message a student understands, naming things as the user wrote them.
    pub message: String,
    /// Where the problem is.
    pub span: Span,
}

impl Diagnostic {
    /// An error with `code` at `span`.
    pub fn error(code: Code, span: Span, message: impl Into<String>) -> Self {
        Diagnostic { severity: Severity::Error, code, message: message.into(), span }
    }

    /// A warning with `code` at `span`.
    pub fn warning(code: Code, span: Span, message: impl Into<String>) -> Self {
        Diagnostic { severity: Severity::Warning, code, message: message.into(), span }
    }

    /// True when this diagnostic stops the program from running.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// True when any of `diagnostics` is an error.
pub fn has_errors(diagnostics: &[Diagnostic]) -> bool {
    diagnostics.iter().any(Diagnostic::is_error)
}
