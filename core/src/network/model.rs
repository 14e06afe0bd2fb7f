//! The network model: an LD or FBD body as PLCopen holds it — elements at free positions,
//! each input wired by the `localId` of the element its value or power comes from.

use serde::{Deserialize, Serialize};

use crate::ladder::{CoilKind, ContactKind};

/// A POU whose body is a network.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NetworkPou {
    /// The POU's name.
    pub name: String,
    /// PROGRAM, FUNCTION_BLOCK or FUNCTION.
    pub kind: NetworkPouKind,
    /// A FUNCTION's result type (ST type text).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub return_type: Option<String>,
    /// The body's language.
    pub language: NetworkLanguage,
    /// The declarations, as ST `VAR … END_VAR` blocks.
    pub declarations: String,
    /// The elements in the file's order.
    pub elements: Vec<NetElement>,
    /// An SFC POU's named actions (`<actions>`), their bodies in ST.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub actions: Vec<NamedBody>,
    /// An SFC POU's named transitions (`<transitions>`), their bodies in ST.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub transitions: Vec<NamedBody>,
}

/// A named action or transition of an SFC POU, with its ST body.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NamedBody {
    /// Its name.
    pub name: String,
    /// Its body in ST (statements; for a transition, an expression or statements that
    /// assign the transition's name).
    pub st: String,
    /// 1-based line and column of its element in the file (not kept in the project file).
    #[serde(skip)]
    pub at: (u32, u32),
}

/// What a network POU is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NetworkPouKind {
    /// `PROGRAM`.
    Program,
    /// `FUNCTION_BLOCK`.
    FunctionBlock,
    /// `FUNCTION`.
    Function,
}

impl NetworkPouKind {
    /// The ST keyword that opens such a POU.
    pub fn keyword(self) -> &'static str {
        match self {
            NetworkPouKind::Program => "PROGRAM",
            NetworkPouKind::FunctionBlock => "FUNCTION_BLOCK",
            NetworkPouKind::Function => "FUNCTION",
        }
    }
}

/// The language a network is drawn in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum NetworkLanguage {
    /// Ladder diagram: power flows from the left rail.
    #[serde(rename = "LD")]
    Ld,
    /// Function block diagram: values flow along wires.
    #[serde(rename = "FBD")]
    Fbd,
    /// Sequential function chart: steps and transitions, their conditions in ST or wired
    /// from the chart's own LD/FBD elements.
    #[serde(rename = "SFC")]
    Sfc,
}

impl NetworkLanguage {
    /// The language's short name, as PLCopen tags its body (`LD`, `FBD`, `SFC`).
    pub fn name(self) -> &'static str {
        match self {
            NetworkLanguage::Ld => "LD",
            NetworkLanguage::Fbd => "FBD",
            NetworkLanguage::Sfc => "SFC",
        }
    }
}

/// One element of a network.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NetElement {
    /// Its `localId` (empty for a comment that has none).
    pub id: String,
    /// What it is.
    pub kind: NetKind,
    /// Its top-left corner.
    pub x: f64,
    /// Its top-left corner.
    pub y: f64,
    /// Its size.
    pub width: f64,
    /// Its size.
    pub height: f64,
    /// Its `executionOrderId` (0: none).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub order: u32,
    /// Its inputs: one per `connectionPointIn` (a contact, a coil, an output variable, a
    /// right rail's several), or a block's input and in-out pins by name.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<Pin>,
    /// Its outputs: a block's output and in-out pins by name, or the one connection point
    /// of the others (a left rail's several).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<Pin>,
    /// 1-based line and column of the element in the file it was imported from (not kept in
    /// the project file).
    #[serde(skip)]
    pub at: (u32, u32),
}

fn is_zero(n: &u32) -> bool {
    *n == 0
}

/// What an element is.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NetKind {
    /// The left power rail.
    LeftRail,
    /// The right power rail.
    RightRail,
    /// A contact on `operand`.
    Contact {
        /// The variable read.
        operand: String,
        /// Normally open, closed, or edge.
        contact: ContactKind,
    },
    /// A coil on `operand`.
    Coil {
        /// The variable written.
        operand: String,
        /// Normal, negated, set, reset, or edge.
        coil: CoilKind,
    },
    /// A function or function block.
    Block {
        /// Its type (`TON`, `ADD`, a POU of the project).
        type_name: String,
        /// The instance of a function block.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        instance: Option<String>,
    },
    /// A variable or constant read (`inVariable`).
    InVar {
        /// Its expression.
        expr: String,
    },
    /// A variable written (`outVariable`).
    OutVar {
        /// Its expression.
        expr: String,
    },
    /// A variable read and written (`inOutVariable`).
    InOutVar {
        /// Its expression.
        expr: String,
    },
    /// A comment box.
    Comment {
        /// Its text.
        text: String,
    },
    /// A jump target.
    Label {
        /// Its name.
        label: String,
    },
    /// A jump to a label.
    Jump {
        /// The label.
        label: String,
    },
    /// A return.
    Return,
    /// A connector: the value wired into it continues at the continuations of its name.
    Connector {
        /// Its name.
        name: String,
    },
    /// A continuation of the connector of its name.
    Continuation {
        /// Its name.
        name: String,
    },
    /// An SFC step: its input (`""`) from the transitions before it, its output (`""`) to
    /// the transitions after it, and its `action` output to its action blocks.
    Step {
        /// Its name.
        name: String,
        /// The step the chart starts in.
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        initial: bool,
    },
    /// An SFC transition: its input (`""`) from the steps before it, and, for a wired
    /// condition, a `condition` input.
    Transition {
        /// When it may fire.
        condition: SfcCondition,
        /// Its condition is negated.
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        negated: bool,
        /// Its priority among the transitions leaving the same step (lower first).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        priority: Option<u32>,
    },
    /// One step to one of several branches (the first transition true wins).
    SelectionDivergence,
    /// Several branches back to one.
    SelectionConvergence,
    /// One transition to several branches run at once.
    SimultaneousDivergence,
    /// Several branches run at once, all finished, to one transition.
    SimultaneousConvergence,
    /// A jump to a step of the chart.
    JumpStep {
        /// The step.
        target: String,
    },
    /// The actions of a step, wired to its `action` output.
    ActionBlock {
        /// Its rows.
        actions: Vec<SfcAction>,
    },
}

/// The condition of an SFC transition.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SfcCondition {
    /// An ST expression written on the transition.
    Inline {
        /// The expression.
        st: String,
    },
    /// A named transition of the POU ([`NetworkPou::transitions`]).
    Reference {
        /// Its name.
        name: String,
    },
    /// The value wired to the transition's `condition` input.
    Wired,
}

/// One row of an action block: an action with its qualifier.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SfcAction {
    /// `N`, `S`, `R`, `L`, `D`, `P`, `P1`, `P0`, `SD`, `DS`, `SL`.
    pub qualifier: String,
    /// The time of `L`, `D`, `SD`, `DS`, `SL` (`T#2s`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duration: Option<String>,
    /// The indicator variable.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub indicator: Option<String>,
    /// The action: a named action of the POU, a BOOL variable, or an inline body.
    pub action: SfcActionBody,
}

/// What an action block row runs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SfcActionBody {
    /// An action of the POU or a BOOL variable, by name.
    Reference {
        /// The name.
        name: String,
    },
    /// Statements written in the block.
    Inline {
        /// The statements in ST.
        st: String,
    },
}

impl NetKind {
    /// Whether the element belongs to an SFC chart (not to the LD/FBD network beside it).
    pub fn is_chart(&self) -> bool {
        matches!(
            self,
            NetKind::Step { .. }
                | NetKind::Transition { .. }
                | NetKind::SelectionDivergence
                | NetKind::SelectionConvergence
                | NetKind::SimultaneousDivergence
                | NetKind::SimultaneousConvergence
                | NetKind::JumpStep { .. }
                | NetKind::ActionBlock { .. }
        )
    }
}

/// A connection point of an element.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pin {
    /// The pin's formal parameter (`IN`, `Q`); empty for the one point of an element that
    /// is not a block.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// Where it is, relative to the element's corner.
    pub dx: f64,
    /// Where it is, relative to the element's corner.
    pub dy: f64,
    /// The wires into it (inputs only).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub wires: Vec<Wire>,
    /// A negated or edge-triggered block input.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub modifier: Option<PinModifier>,
    /// A block's in-out pin (listed among both the inputs and the outputs).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub in_out: bool,
}

/// A wire into an input: where it comes from and the path it is drawn along.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Wire {
    /// The `localId` of the element it comes from.
    pub from: String,
    /// The output pin of that element, when it has several.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub param: Option<String>,
    /// The points it is drawn through, from the input back to the output (as PLCopen
    /// lists them).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<(f64, f64)>,
}

/// How a block input changes the value wired to it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PinModifier {
    /// `negated="true"`: the pin reads NOT the value.
    Negated,
    /// `edge="rising"`: the pin reads the value's rising edge.
    Rising,
    /// `edge="falling"`: the pin reads its falling edge.
    Falling,
}
