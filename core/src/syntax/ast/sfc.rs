//! The syntax tree of a textual sequential function chart (IEC 61131-3 §6.7, textual form):
//! the body of a PROGRAM or FUNCTION_BLOCK written as steps, transitions and actions.
//!
//! The parser produces it (`parser/sfc.rs`); `crate::sfc` checks the chart and turns it into
//! ordinary statements before the checker runs. Data only: no parsing, no checking.

use super::{Expr, Ident, Stmt};
use crate::diagnostics::Span;

/// A POU body written as a sequential function chart.
#[derive(Debug, Clone, PartialEq)]
pub struct SfcBody {
    /// The steps, transitions and actions in source order.
    pub elements: Vec<SfcElement>,
    /// From the first element to the end of the last.
    pub span: Span,
}

/// One element of an SFC body.
#[derive(Debug, Clone, PartialEq)]
pub enum SfcElement {
    /// `STEP name : … END_STEP` or `INITIAL_STEP name : … END_STEP`.
    Step(SfcStep),
    /// `TRANSITION … FROM … TO … END_TRANSITION`.
    Transition(SfcTransition),
    /// `ACTION name : … END_ACTION`.
    Action(SfcAction),
}

/// A step with its action associations.
#[derive(Debug, Clone, PartialEq)]
pub struct SfcStep {
    /// The step's name.
    pub name: Ident,
    /// Written `INITIAL_STEP`.
    pub initial: bool,
    /// The associations `Action(qualifier, …);` in source order.
    pub associations: Vec<ActionAssociation>,
    /// The keyword and the name (where diagnostics about the step point).
    pub header: Span,
    /// From the keyword to `END_STEP`.
    pub span: Span,
}

/// An action qualifier (IEC 61131-3 Table 56 of the 3rd edition).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Qualifier {
    /// Non-stored: active while the step is active (also when no qualifier is written).
    N,
    /// Overriding reset of a stored action.
    R,
    /// Set (stored).
    S,
    /// Pulse: one scan on the rising edge of the association.
    P,
    /// Pulse on the rising edge (step activation), run once.
    P1,
    /// Pulse on the falling edge (step deactivation), run once.
    P0,
    /// Time limited.
    L,
    /// Time delayed.
    D,
    /// Stored and time delayed.
    SD,
    /// Delayed and stored.
    DS,
    /// Stored and time limited.
    SL,
}

impl Qualifier {
    /// Every qualifier, in the order the standard lists them.
    pub const ALL: [Qualifier; 11] = [
        Qualifier::N,
        Qualifier::R,
        Qualifier::S,
        Qualifier::L,
        Qualifier::D,
        Qualifier::P,
        Qualifier::SD,
        Qualifier::DS,
        Qualifier::SL,
        Qualifier::P1,
        Qualifier::P0,
    ];

    /// The qualifier spelled `text` (any case).
    pub fn from_name(text: &str) -> Option<Qualifier> {
        Qualifier::ALL.into_iter().find(|q| q.name().eq_ignore_ascii_case(text))
    }

    /// The qualifier as written in the standard (`SD`).
    pub fn name(self) -> &'static str {
        match self {
            Qualifier::N => "N",
            Qualifier::R => "R",
            Qualifier::S => "S",
            Qualifier::P => "P",
            Qualifier::P1 => "P1",
            Qualifier::P0 => "P0",
            Qualifier::L => "L",
            Qualifier::D => "D",
            Qualifier::SD => "SD",
            Qualifier::DS => "DS",
            Qualifier::SL => "SL",
        }
    }

    /// True for the qualifiers that need a duration: L, D, SD, DS, SL.
    pub fn is_timed(self) -> bool {
        matches!(self, Qualifier::L | Qualifier::D | Qualifier::SD | Qualifier::DS | Qualifier::SL)
    }
}

/// `Action(qualifier[, duration][, indicator…]);` inside a step.
#[derive(Debug, Clone, PartialEq)]
pub struct ActionAssociation {
    /// The action: an `ACTION` of the body, or a BOOL variable (a boolean action).
    pub action: Ident,
    /// The qualifier (N when none is written).
    pub qualifier: Qualifier,
    /// Where the qualifier is written (the action name when it is left out).
    pub qualifier_span: Span,
    /// The duration of a timed qualifier: a TIME literal or a TIME variable.
    pub duration: Option<Expr>,
    /// Indicator variables named after the qualifier.
    pub indicators: Vec<Ident>,
    /// The whole association up to its `;`.
    pub span: Span,
}

/// A transition between steps.
#[derive(Debug, Clone, PartialEq)]
pub struct SfcTransition {
    /// `TRANSITION name …`, when named.
    pub name: Option<Ident>,
    /// `(PRIORITY := n)`: lower numbers win; with its place in the source.
    pub priority: Option<(u32, Span)>,
    /// The steps it leaves (all must be active: AND convergence when several).
    pub from: Vec<Ident>,
    /// The steps it activates (AND divergence when several).
    pub to: Vec<Ident>,
    /// When it is cleared.
    pub condition: TransitionCondition,
    /// From `TRANSITION` to the end of the TO list (where diagnostics about it point).
    pub header: Span,
    /// From `TRANSITION` to `END_TRANSITION`.
    pub span: Span,
}

/// How a transition's condition is written.
#[derive(Debug, Clone, PartialEq)]
pub enum TransitionCondition {
    /// `:= expression;`
    Expr(Expr),
    /// `: statements` that assign the transition's name.
    Body(Vec<Stmt>),
}

/// `ACTION name : statements END_ACTION`.
#[derive(Debug, Clone, PartialEq)]
pub struct SfcAction {
    /// The action's name.
    pub name: Ident,
    /// Its statements.
    pub body: Vec<Stmt>,
    /// The keyword and the name.
    pub header: Span,
    /// From `ACTION` to `END_ACTION`.
    pub span: Span,
}
