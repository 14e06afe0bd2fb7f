//! The interpreted Petri net model behind the net editor (serde, part of the project file).
//!
//! A [`PetriPou`] is a PROGRAM whose body is generated from its net by the CASE OF method
//! (see `docs/petri.md`). Places carry a CASE label and ST actions, transitions an ST guard
//! and a priority; arcs join a place and a transition. Elements are named by stable ids
//! (`P1`, `T3`) so that the editor can rename them without breaking the arcs.
//!
//! A [`MacroPlace`] is a place that stands for a sub-net (P30 of the weighing process,
//! `docs/weighing.md`): it is a named
//! group of ordinary places, drawn as one box. The arcs, the analysis and the generated code
//! all use the places inside it (the refined, flat net); the macro-place is marked whenever
//! one of its places is marked, which is how the place map shows it. It has no CASE label of
//! its own and no arc may end on it.

use serde::{Deserialize, Serialize};

/// A Petri net POU: declarations in ST syntax, optional statements around the net, the net
/// and how its code is generated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PetriPou {
    /// The PROGRAM's name.
    pub name: String,
    /// Variable declarations, as ST `VAR_INPUT … END_VAR` blocks (as ladder POUs have).
    #[serde(default)]
    pub declarations: String,
    /// ST statements run on every scan before the net (e.g. clearing the outputs).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub prologue: String,
    /// ST statements run on every scan after the net (e.g. a timer driven by a step).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub epilogue: String,
    /// The net.
    pub net: Net,
    /// Code generation options.
    #[serde(default)]
    pub options: GenerationOptions,
}

/// A place/transition net with its interpretation (actions, guards, priorities).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Net {
    /// The places, in the order the generated CASE branches follow.
    pub places: Vec<Place>,
    /// The transitions.
    pub transitions: Vec<Transition>,
    /// The arcs (each joins a place and a transition).
    pub arcs: Vec<Arc>,
    /// Macro-places: named groups of places standing for a sub-net.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub macro_places: Vec<MacroPlace>,
    /// The sequential processes (state-machine components) the code is generated for, in
    /// order. Empty: chosen automatically from the net's state-machine components.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub processes: Vec<Process>,
    /// The emergency place and the condition that forces the net into it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub emergency: Option<Emergency>,
}

/// A position on the editor's canvas.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Position {
    /// Horizontal coordinate.
    pub x: f64,
    /// Vertical coordinate.
    pub y: f64,
}

/// A place: a state of a sequential process.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Place {
    /// Stable id, unique among the net's places, transitions and macro-places.
    pub id: String,
    /// The name shown to the user (`P1 ready`); the id is shown when empty.
    #[serde(default)]
    pub name: String,
    /// The value of the step variable while this place is marked (the CASE label).
    pub label: i64,
    /// Tokens in the initial marking.
    #[serde(default)]
    pub tokens: u32,
    /// At most this many tokens (`None`: unlimited). A transition that would put more
    /// into the place is not enabled. The CASE OF code gives each place of a process one
    /// token at most, so a capacity of 1 or more changes nothing in it; the analysis and
    /// the token game apply it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub capacity: Option<u32>,
    /// ST statements executed on every scan while the place is marked.
    #[serde(default)]
    pub actions: String,
    /// Where the editor draws it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<Position>,
    /// A comment kept in the generated code.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
}

/// A transition: a step from one marking to the next, taken when its guard holds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Transition {
    /// Stable id, unique among the net's places, transitions and macro-places.
    pub id: String,
    /// The name shown to the user; the id is shown when empty.
    #[serde(default)]
    pub name: String,
    /// An ST boolean expression over the program's variables; empty means TRUE.
    #[serde(default)]
    pub guard: String,
    /// Among the transitions leaving one place, lower numbers are tested first; equal
    /// priorities keep the order of [`Net::transitions`].
    #[serde(default)]
    pub priority: u32,
    /// Where the editor draws it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<Position>,
    /// A comment kept in the generated code.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
}

fn one() -> u32 {
    1
}

fn is_one(w: &u32) -> bool {
    *w == 1
}

/// An arc from a place to a transition (an input of the transition) or from a transition
/// to a place (an output).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Arc {
    /// Id of the source place or transition.
    pub from: String,
    /// Id of the target transition or place.
    pub to: String,
    /// How many tokens the arc moves (at least 1).
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub weight: u32,
}

/// A place standing for a sub-net: a named group of places (see the module comment).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MacroPlace {
    /// Stable id, unique among the net's places, transitions and macro-places.
    pub id: String,
    /// The name shown to the user.
    #[serde(default)]
    pub name: String,
    /// Ids of the places inside it.
    pub places: Vec<String>,
    /// Where the editor draws it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<Position>,
    /// A comment kept in the generated code.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
}

/// A sequential process: a state-machine component of the net with its own step variable.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Process {
    /// The process's name (an identifier: flags are named after it, e.g. `PA_Start`).
    pub name: String,
    /// The INT step variable holding the label of the process's marked place.
    pub step_variable: String,
    /// Ids of the places of the component.
    pub places: Vec<String>,
}

/// The emergency: while `condition` is TRUE, every process is forced into its emergency
/// place at the start of the scan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Emergency {
    /// The emergency place (e.g. the alarm place P20). Processes that do not contain it go
    /// to the place they start in (their initially marked place).
    pub place: String,
    /// An ST boolean expression.
    pub condition: String,
}

/// How the generated code is shaped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct GenerationOptions {
    /// Declare the step variables (and state flags) RETAIN, so that a warm restart resumes
    /// the process where it was.
    pub retain: bool,
    /// How a transition shared by several processes (a fork or a join) is coded.
    pub sync: SyncStyle,
}

/// How forks and joins are coded (both as Franczok's method allows; the firing rule is the
/// same).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum SyncStyle {
    /// The deciding process reads and writes the other processes' step variables.
    #[default]
    StepVariables,
    /// The paper's `Pn_Start` / `Pn_End` flags: a process raises `_End` while it waits at a
    /// shared transition, and the deciding process raises `_Start` to move it on.
    Flags,
}

impl Net {
    /// The place with id `id`.
    pub fn place(&self, id: &str) -> Option<&Place> {
        self.places.iter().find(|p| p.id == id)
    }

    /// The transition with id `id`.
    pub fn transition(&self, id: &str) -> Option<&Transition> {
        self.transitions.iter().find(|t| t.id == id)
    }
}

impl Place {
    /// A place with an id, a CASE label and initial tokens (name, actions empty).
    pub fn new(id: impl Into<String>, label: i64, tokens: u32) -> Self {
        Place {
            id: id.into(),
            name: String::new(),
            label,
            tokens,
            capacity: None,
            actions: String::new(),
            position: None,
            comment: String::new(),
        }
    }
}

impl Transition {
    /// A transition with an id and a guard (priority 0).
    pub fn new(id: impl Into<String>, guard: impl Into<String>) -> Self {
        Transition {
            id: id.into(),
            name: String::new(),
            guard: guard.into(),
            priority: 0,
            position: None,
            comment: String::new(),
        }
    }
}

impl Arc {
    /// An arc of weight 1.
    pub fn new(from: impl Into<String>, to: impl Into<String>) -> Self {
        Arc { from: from.into(), to: to.into(), weight: 1 }
    }
}
