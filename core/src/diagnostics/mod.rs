//! Located diagnostics: spans, line/column lookup and the table of problem codes.
//!
//! Every stage reports problems as [`Diagnostic`] values carrying a stable [`Code`]; nothing
//! here prints or panics. The codes live in one table (`codes.rs`), their explanations and examples in
//! another (`explain.rs`), their Polish and Czech texts in `core/i18n/` (`translations.rs`),
//! and `pages.rs` makes `plc explain`'s text and the problems pages (`docs/problems.md`,
//! `problems.html`, `problems.pl.html`, `problems.cs.html`) from them.

mod codes;
mod explain;
mod message;
mod pages;
mod span;
pub mod suggest;
mod translations;

pub use codes::Code;
pub use explain::{Example, Explanation, EXPLANATIONS};
pub(crate) use message::msg_en;
pub use message::{
    catalogue_source, english_catalogue, fill, placeholders, Arg, Message, Msg, Phrase, Said,
    ToArg, MSG_COUNT,
};
pub use pages::{
    explain_text, explain_text_in, problems_html, problems_html_in, problems_markdown,
    problems_page_name,
};
pub use span::{LineIndex, Location, Span};
pub use translations::{parse_translation, CodeTexts, PageWords, ProblemTexts, TRANSLATIONS};

use serde::Serialize;

use crate::i18n::Lang;

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
    /// A message a student understands, naming things as the user wrote them (English).
    pub message: String,
    /// The message as data: its key and arguments, to be shown in any language
    /// ([`Diagnostic::render`]).
    pub msg: Message,
    /// Where the problem is.
    pub span: Span,
    /// The declared name the one at `span` probably misspells; the message ends with
    /// `did you mean NAME?`, and putting it in place of the span's text is the editors'
    /// `Replace with NAME` fix.
    pub suggestion: Option<String>,
    /// For an undeclared name: the type its use implies when the checker knows it (`BOOL`
    /// for a condition, the value's type for the target of an assignment); the editors'
    /// `Declare NAME` fix declares it with this type.
    pub implied_type: Option<String>,
}

impl Diagnostic {
    /// An error with `code` at `span`.
    pub fn error(code: Code, span: Span, message: impl Into<Said>) -> Self {
        let Said { message, english } = message.into();
        Diagnostic {
            severity: Severity::Error,
            code,
            message: english,
            msg: message,
            span,
            suggestion: None,
            implied_type: None,
        }
    }

    /// A warning with `code` at `span`.
    pub fn warning(code: Code, span: Span, message: impl Into<Said>) -> Self {
        let Said { message, english } = message.into();
        Diagnostic {
            severity: Severity::Warning,
            code,
            message: english,
            msg: message,
            span,
            suggestion: None,
            implied_type: None,
        }
    }

    /// This diagnostic with `suggestion` (when there is one) as its
    /// [`Diagnostic::suggestion`] and `; did you mean NAME?` at the end of its message.
    pub fn suggesting(mut self, suggestion: Option<&str>) -> Self {
        if let Some(s) = suggestion {
            self.message.push_str(&suggest::hint(Some(s)));
            self.suggestion = Some(s.to_string());
        }
        self
    }

    /// The message in `lang`, with its `did you mean NAME?` when it has one.
    pub fn render(&self, lang: Lang) -> String {
        render_with_hint(&self.msg, self.suggestion.as_deref(), lang)
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

/// `message` in `lang`, ending in `; did you mean NAME?` when there is a `suggestion`.
pub fn render_with_hint(message: &Message, suggestion: Option<&str>, lang: Lang) -> String {
    let mut text = message.render(lang);
    if let Some(s) = suggestion {
        text.push_str("; ");
        text.push_str(&fill(Msg::DidYouMean.template(lang), |_| Some(s)));
    }
    text
}
