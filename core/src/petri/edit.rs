//! Edits of a Petri net POU: the operations of the net editor. Each takes the POU as it is
//! and gives the next one, or says why it cannot be made (a typed [`NetEditError`]); the
//! web app keeps whole POUs in a [`History`](crate::project::History) for undo and redo,
//! and only maps gestures to these edits.
//!
//! New places and transitions get the next free number of their kind (`P4`, `T2`) as id
//! ([`PetriPou::next_id`]); the id stays when the element is renamed (its name is shown
//! instead), so arcs never break. Deleting an element deletes its arcs and takes it out of
//! the macro-places, processes and emergency that name it.

use std::fmt;

use super::{Arc, Emergency, PetriPou, Place, Position, Transition};

/// One edit of a Petri net POU.
#[derive(Debug, Clone, PartialEq)]
pub enum NetEdit {
    /// Adds a place with no tokens at `at` (its CASE label: the next free one).
    AddPlace {
        /// Its id (`P4`): from [`PetriPou::next_id`].
        id: String,
        /// Where it is drawn.
        at: Position,
    },
    /// Adds a transition with an empty guard (TRUE) at `at`.
    AddTransition {
        /// Its id (`T2`).
        id: String,
        /// Where it is drawn.
        at: Position,
    },
    /// Adds an arc of weight 1 between a place and a transition (either way).
    AddArc {
        /// The place or transition it leaves.
        from: String,
        /// The transition or place it enters.
        to: String,
    },
    /// Moves a place, transition or macro-place.
    Move {
        /// The element.
        id: String,
        /// Its new position.
        to: Position,
    },
    /// Deletes a place, transition or macro-place (and the arcs that touch it).
    Delete {
        /// The element.
        id: String,
    },
    /// Deletes an arc.
    DeleteArc {
        /// Where it starts.
        from: String,
        /// Where it ends.
        to: String,
    },
    /// Sets the name an element is shown by (empty: its id).
    SetName {
        /// The element.
        id: String,
        /// The name.
        name: String,
    },
    /// Sets a place's CASE label (the number of its state).
    SetLabel {
        /// The place.
        id: String,
        /// The label.
        label: i64,
    },
    /// Sets a place's initial tokens.
    SetTokens {
        /// The place.
        id: String,
        /// Tokens in the initial marking.
        tokens: u32,
    },
    /// Sets a place's capacity (`None`: unlimited).
    SetCapacity {
        /// The place.
        id: String,
        /// At most this many tokens.
        capacity: Option<u32>,
    },
    /// Sets a place's actions (ST statements run while it is marked).
    SetActions {
        /// The place.
        id: String,
        /// The statements.
        text: String,
    },
    /// Sets a transition's guard (an ST BOOL expression; empty is TRUE).
    SetGuard {
        /// The transition.
        id: String,
        /// The expression.
        text: String,
    },
    /// Sets a transition's priority (lower is tested first).
    SetPriority {
        /// The transition.
        id: String,
        /// The priority.
        priority: u32,
    },
    /// Sets an arc's weight (at least 1).
    SetWeight {
        /// Where it starts.
        from: String,
        /// Where it ends.
        to: String,
        /// The weight.
        weight: u32,
    },
    /// Sets the places a macro-place stands for.
    SetMacroPlaces {
        /// The macro-place.
        id: String,
        /// The ids of its places.
        places: Vec<String>,
    },
    /// Replaces the POU's declarations.
    SetDeclarations {
        /// The ST `VAR … END_VAR` blocks.
        text: String,
    },
}

/// Why a net edit cannot be made.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum NetEditError {
    /// No place, transition or macro-place has this id.
    NoSuchElement(String),
    /// The id is used already (ids are unique across the net).
    IdTaken(String),
    /// An id must be a name (letters, digits, underscores).
    NotAnId(String),
    /// An arc joins a place and a transition, never two of a kind.
    SameKind(String, String),
    /// There is an arc between them already.
    ArcExists(String, String),
    /// No such arc.
    NoSuchArc(String, String),
    /// Arcs end on the places inside a macro-place, not on the macro-place.
    ArcOnMacroPlace(String),
    /// A weight of 0 moves no token.
    ZeroWeight,
    /// Another place has this CASE label.
    LabelTaken(i64, String),
    /// The element is not of the kind the edit is for (a guard on a place).
    WrongKind(String, &'static str),
    /// A place would start with more tokens than its capacity: (place, tokens, capacity).
    OverCapacity(String, u32, u32),
}

impl fmt::Display for NetEditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NetEditError::NoSuchElement(id) => write!(f, "the net has no element {id}"),
            NetEditError::IdTaken(id) => write!(f, "the net has an element {id} already"),
            NetEditError::NotAnId(id) => write!(f, "“{id}” is not a name for a net element"),
            NetEditError::SameKind(a, b) => {
                write!(f, "an arc joins a place and a transition: {a} and {b} are of the same kind")
            }
            NetEditError::ArcExists(a, b) => write!(f, "there is an arc from {a} to {b} already"),
            NetEditError::NoSuchArc(a, b) => write!(f, "there is no arc from {a} to {b}"),
            NetEditError::ArcOnMacroPlace(id) => {
                write!(f, "{id} is a macro-place: draw the arc to one of the places inside it")
            }
            NetEditError::ZeroWeight => write!(f, "an arc's weight is at least 1"),
            NetEditError::LabelTaken(l, id) => write!(f, "place {id} has the CASE label {l}"),
            NetEditError::WrongKind(id, what) => write!(f, "{id} is not {what}"),
            NetEditError::OverCapacity(id, tokens, cap) => {
                write!(f, "place {id} cannot start with {tokens} tokens: its capacity is {cap}")
            }
        }
    }
}

impl std::error::Error for NetEditError {}

/// What an id names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementKind {
    /// A place.
    Place,
    /// A transition.
    Transition,
    /// A macro-place.
    MacroPlace,
}

impl PetriPou {
    /// What `id` names in the net, if anything.
    pub fn kind_of(&self, id: &str) -> Option<ElementKind> {
        let net = &self.net;
        if net.places.iter().any(|p| p.id == id) {
            Some(ElementKind::Place)
        } else if net.transitions.iter().any(|t| t.id == id) {
            Some(ElementKind::Transition)
        } else if net.macro_places.iter().any(|m| m.id == id) {
            Some(ElementKind::MacroPlace)
        } else {
            None
        }
    }

    /// The next free id with `prefix` (`P` → `P4` when `P1`…`P3` exist): one more than the
    /// highest number in use, so ids are given in the order of creation.
    pub fn next_id(&self, prefix: &str) -> String {
        let net = &self.net;
        let ids = net
            .places
            .iter()
            .map(|p| &p.id)
            .chain(net.transitions.iter().map(|t| &t.id))
            .chain(net.macro_places.iter().map(|m| &m.id));
        let highest = ids
            .filter_map(|id| id.strip_prefix(prefix).and_then(|n| n.parse::<u64>().ok()))
            .max()
            .unwrap_or(0);
        format!("{prefix}{}", highest + 1)
    }

    /// Applies `edit`, giving the next POU.
    pub fn apply(&self, edit: &NetEdit) -> Result<PetriPou, NetEditError> {
        let mut next = self.clone();
        next.apply_in_place(edit)?;
        Ok(next)
    }

    fn require(&self, id: &str, kind: ElementKind) -> Result<(), NetEditError> {
        match self.kind_of(id) {
            None => Err(NetEditError::NoSuchElement(id.to_string())),
            Some(k) if k == kind => Ok(()),
            Some(_) => Err(NetEditError::WrongKind(
                id.to_string(),
                match kind {
                    ElementKind::Place => "a place",
                    ElementKind::Transition => "a transition",
                    ElementKind::MacroPlace => "a macro-place",
                },
            )),
        }
    }

    fn new_id(&self, id: &str) -> Result<(), NetEditError> {
        if !crate::syntax::is_identifier(id) {
            return Err(NetEditError::NotAnId(id.to_string()));
        }
        if self.kind_of(id).is_some() {
            return Err(NetEditError::IdTaken(id.to_string()));
        }
        Ok(())
    }

    fn arc_index(&self, from: &str, to: &str) -> Result<usize, NetEditError> {
        self.net
            .arcs
            .iter()
            .position(|a| a.from == from && a.to == to)
            .ok_or_else(|| NetEditError::NoSuchArc(from.to_string(), to.to_string()))
    }

    fn apply_in_place(&mut self, edit: &NetEdit) -> Result<(), NetEditError> {
        match edit {
            NetEdit::AddPlace { id, at } => {
                self.new_id(id)?;
                let label = self.net.places.iter().map(|p| p.label).max().unwrap_or(0) + 1;
                let mut place = Place::new(id.clone(), label, 0);
                place.position = Some(*at);
                self.net.places.push(place);
            }
            NetEdit::AddTransition { id, at } => {
                self.new_id(id)?;
                let mut t = Transition::new(id.clone(), "");
                t.position = Some(*at);
                self.net.transitions.push(t);
            }
            NetEdit::AddArc { from, to } => {
                let (a, b) = (self.kind_of(from), self.kind_of(to));
                for (id, k) in [(from, a), (to, b)] {
                    match k {
                        None => return Err(NetEditError::NoSuchElement(id.clone())),
                        Some(ElementKind::MacroPlace) => {
                            return Err(NetEditError::ArcOnMacroPlace(id.clone()))
                        }
                        Some(_) => {}
                    }
                }
                if a == b {
                    return Err(NetEditError::SameKind(from.clone(), to.clone()));
                }
                if self.arc_index(from, to).is_ok() {
                    return Err(NetEditError::ArcExists(from.clone(), to.clone()));
                }
                self.net.arcs.push(Arc::new(from.clone(), to.clone()));
            }
            NetEdit::Move { id, to } => *self.name_and_position(id)?.1 = Some(*to),
            NetEdit::Delete { id } => {
                if self.kind_of(id).is_none() {
                    return Err(NetEditError::NoSuchElement(id.clone()));
                }
                let net = &mut self.net;
                net.places.retain(|p| p.id != *id);
                net.transitions.retain(|t| t.id != *id);
                net.macro_places.retain(|m| m.id != *id);
                net.arcs.retain(|a| a.from != *id && a.to != *id);
                for m in &mut net.macro_places {
                    m.places.retain(|p| p != id);
                }
                for p in &mut net.processes {
                    p.places.retain(|p| p != id);
                }
                net.processes.retain(|p| !p.places.is_empty());
                if net.emergency.as_ref().is_some_and(|e: &Emergency| e.place == *id) {
                    net.emergency = None;
                }
            }
            NetEdit::DeleteArc { from, to } => {
                let i = self.arc_index(from, to)?;
                self.net.arcs.remove(i);
            }
            NetEdit::SetName { id, name } => {
                *self.name_and_position(id)?.0 = name.trim().to_string()
            }
            NetEdit::SetLabel { id, label } => {
                self.require(id, ElementKind::Place)?;
                if let Some(other) =
                    self.net.places.iter().find(|p| p.label == *label && p.id != *id)
                {
                    return Err(NetEditError::LabelTaken(*label, other.id.clone()));
                }
                self.place_mut(id)?.label = *label;
            }
            NetEdit::SetTokens { id, tokens } => {
                let place = self.place_mut(id)?;
                if let Some(c) = place.capacity.filter(|c| tokens > c) {
                    return Err(NetEditError::OverCapacity(id.clone(), *tokens, c));
                }
                place.tokens = *tokens;
            }
            NetEdit::SetCapacity { id, capacity } => {
                let place = self.place_mut(id)?;
                if let Some(c) = capacity.filter(|c| *c < place.tokens) {
                    return Err(NetEditError::OverCapacity(id.clone(), place.tokens, c));
                }
                place.capacity = *capacity;
            }
            NetEdit::SetActions { id, text } => {
                self.place_mut(id)?.actions = text.clone();
            }
            NetEdit::SetGuard { id, text } => {
                self.transition_mut(id)?.guard = text.clone();
            }
            NetEdit::SetPriority { id, priority } => {
                self.transition_mut(id)?.priority = *priority;
            }
            NetEdit::SetWeight { from, to, weight } => {
                if *weight == 0 {
                    return Err(NetEditError::ZeroWeight);
                }
                let i = self.arc_index(from, to)?;
                self.net.arcs[i].weight = *weight;
            }
            NetEdit::SetMacroPlaces { id, places } => {
                self.require(id, ElementKind::MacroPlace)?;
                for p in places {
                    self.require(p, ElementKind::Place)?;
                }
                if let Some(m) = self.net.macro_places.iter_mut().find(|m| m.id == *id) {
                    m.places = places.clone();
                }
            }
            NetEdit::SetDeclarations { text } => self.declarations = text.clone(),
        }
        Ok(())
    }

    /// The name and position of the place, transition or macro-place `id`.
    fn name_and_position(
        &mut self,
        id: &str,
    ) -> Result<(&mut String, &mut Option<Position>), NetEditError> {
        let net = &mut self.net;
        net.places
            .iter_mut()
            .find(|p| p.id == id)
            .map(|p| (&mut p.name, &mut p.position))
            .or_else(|| {
                net.transitions
                    .iter_mut()
                    .find(|t| t.id == id)
                    .map(|t| (&mut t.name, &mut t.position))
            })
            .or_else(|| {
                net.macro_places
                    .iter_mut()
                    .find(|m| m.id == id)
                    .map(|m| (&mut m.name, &mut m.position))
            })
            .ok_or_else(|| NetEditError::NoSuchElement(id.to_string()))
    }

    fn place_mut(&mut self, id: &str) -> Result<&mut Place, NetEditError> {
        self.require(id, ElementKind::Place)?;
        self.net
            .places
            .iter_mut()
            .find(|p| p.id == id)
            .ok_or_else(|| NetEditError::NoSuchElement(id.to_string()))
    }

    fn transition_mut(&mut self, id: &str) -> Result<&mut Transition, NetEditError> {
        self.require(id, ElementKind::Transition)?;
        self.net
            .transitions
            .iter_mut()
            .find(|t| t.id == id)
            .ok_or_else(|| NetEditError::NoSuchElement(id.to_string()))
    }
}

#[cfg(test)]
mod tests;
