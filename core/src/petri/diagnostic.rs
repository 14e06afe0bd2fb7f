//! Problems found in a Petri net POU, located at the net element (a place, a transition,
//! an arc…) and, for ST text held by an element, at the line and column inside that text.

use std::fmt;

use serde::Serialize;

use crate::diagnostics::{Code, Message, Said, Severity};

/// The element of a Petri net POU a problem or a generated line belongs to.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", content = "id")]
pub enum NetElement {
    /// The POU as a whole.
    Pou,
    /// The ST declarations.
    Declarations,
    /// The statements run before the net.
    Prologue,
    /// The statements run after the net.
    Epilogue,
    /// A place, by id.
    Place(String),
    /// A transition, by id.
    Transition(String),
    /// An arc, by index in [`Net::arcs`](super::Net::arcs).
    Arc(usize),
    /// A macro-place, by id.
    MacroPlace(String),
    /// A declared process, by name.
    Process(String),
    /// The emergency place and condition.
    Emergency,
}

/// Which text of an element a position refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum TextPart {
    /// A transition's guard.
    Guard,
    /// A place's actions.
    Actions,
    /// The emergency condition.
    Condition,
    /// The POU's declarations, prologue or epilogue.
    Text,
}

/// A position inside the ST text held by an element (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct TextPosition {
    /// Which text.
    pub part: TextPart,
    /// 1-based line inside that text.
    pub line: u32,
    /// 1-based column inside that text.
    pub column: u32,
}

/// One problem of a Petri net POU.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PetriDiagnostic {
    /// The stable problem code.
    pub code: Code,
    /// Error or warning.
    pub severity: Severity,
    /// A message a student understands (English).
    pub message: String,
    /// The message as data, to be shown in any language.
    #[serde(skip)]
    pub msg: Message,
    /// The element it is about.
    pub element: NetElement,
    /// Where inside the element's ST text, when the problem is in a guard or actions.
    pub at: Option<TextPosition>,
}

impl PetriDiagnostic {
    /// An error about `element`.
    pub fn error(code: Code, element: NetElement, message: impl Into<Said>) -> Self {
        let Said { message: msg, english: message } = message.into();
        PetriDiagnostic { code, severity: Severity::Error, message, msg, element, at: None }
    }

    /// A warning about `element`.
    pub fn warning(code: Code, element: NetElement, message: impl Into<Said>) -> Self {
        let Said { message: msg, english: message } = message.into();
        PetriDiagnostic { code, severity: Severity::Warning, message, msg, element, at: None }
    }

    /// The same diagnostic at a position inside the element's text.
    pub fn at(mut self, at: TextPosition) -> Self {
        self.at = Some(at);
        self
    }

    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

impl NetElement {
    /// The element as data, its English text its `Display` (`transition T1`, `arc #2`).
    pub fn said(&self) -> Said {
        match self {
            NetElement::Pou => crate::msg!(PlaceNet),
            NetElement::Declarations => crate::msg!(PlaceDeclarationsPart),
            NetElement::Prologue => crate::msg!(PlacePrologue),
            NetElement::Epilogue => crate::msg!(PlaceEpilogue),
            NetElement::Place(id) => crate::msg!(PlacePlace, id = id),
            NetElement::Transition(id) => crate::msg!(PlaceTransition, id = id),
            NetElement::Arc(i) => crate::msg!(PlaceArc, n = i + 1),
            NetElement::MacroPlace(id) => crate::msg!(PlaceMacroPlace, id = id),
            NetElement::Process(name) => crate::msg!(PlaceProcess, name = name),
            NetElement::Emergency => crate::msg!(PlaceEmergency),
        }
    }
}

impl TextPosition {
    /// The position as data, its English text its `Display` (`guard line 1, column 2`).
    pub fn said(&self) -> Said {
        let (line, column) = (self.line, self.column);
        match self.part {
            TextPart::Guard => crate::msg!(PlaceGuard, line = line, column = column),
            TextPart::Actions => crate::msg!(PlaceActions, line = line, column = column),
            TextPart::Condition => crate::msg!(PlaceCondition, line = line, column = column),
            TextPart::Text => crate::msg!(PlaceText, line = line, column = column),
        }
    }
}

impl fmt::Display for NetElement {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NetElement::Pou => f.write_str("the net"),
            NetElement::Declarations => f.write_str("declarations"),
            NetElement::Prologue => f.write_str("prologue"),
            NetElement::Epilogue => f.write_str("epilogue"),
            NetElement::Place(id) => write!(f, "place {id}"),
            NetElement::Transition(id) => write!(f, "transition {id}"),
            NetElement::Arc(i) => write!(f, "arc #{}", i + 1),
            NetElement::MacroPlace(id) => write!(f, "macro-place {id}"),
            NetElement::Process(name) => write!(f, "process {name}"),
            NetElement::Emergency => f.write_str("emergency"),
        }
    }
}

impl fmt::Display for TextPosition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let part = match self.part {
            TextPart::Guard => "guard",
            TextPart::Actions => "actions",
            TextPart::Condition => "condition",
            TextPart::Text => "text",
        };
        write!(f, "{part} line {}, column {}", self.line, self.column)
    }
}

impl fmt::Display for PetriDiagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.at {
            Some(at) => write!(f, "{} ({at}): {}", self.element, self.message),
            None => write!(f, "{}: {}", self.element, self.message),
        }
    }
}

/// True when any diagnostic is an error.
pub fn has_errors(diags: &[PetriDiagnostic]) -> bool {
    diags.iter().any(PetriDiagnostic::is_error)
}
