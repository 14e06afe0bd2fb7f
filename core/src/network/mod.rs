//! Networks: LD, FBD and SFC bodies as PLCopen holds them (ARCHITECTURE "Two ladder models") —
//! elements at free positions wired by `localId` ([`model`]), their logical view with
//! connectors resolved ([`logical`]), and their lowering to ST statements by power flow and
//! execution order ([`lower`]); an SFC body's chart becomes textual SFC ([`chart`]).
//! Files from OpenPLC Editor and Beremiz hold their LD and FBD
//! this way; an LD network that fits the rung grid becomes rungs
//! ([`LadderPou`](crate::ladder::LadderPou)), any other stays a network and runs through
//! this lowering.

pub mod chart;
pub mod live;
pub mod logical;
pub mod lower;
pub mod model;
pub mod source;

pub use logical::logical;
pub use lower::lower;
pub use model::{
    NamedBody, NetElement, NetKind, NetworkLanguage, NetworkPou, NetworkPouKind, Pin, PinModifier,
    SfcAction, SfcActionBody, SfcCondition, Wire,
};
pub use source::{declares, NetworkText};

use std::fmt;

/// A problem with an element of a network.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetError {
    /// The element's `localId`.
    pub element: String,
    /// What is wrong (English).
    pub message: String,
    /// What is wrong, as data to be shown in any language.
    pub msg: crate::diagnostics::Message,
}

impl NetError {
    /// A problem with the element of `localId` `element`.
    pub fn new(element: String, said: crate::diagnostics::Said) -> NetError {
        NetError { element, message: said.english, msg: said.message }
    }

    /// The message with its English text.
    pub fn said(&self) -> crate::diagnostics::Said {
        crate::diagnostics::Said { message: self.msg.clone(), english: self.message.clone() }
    }
}

impl fmt::Display for NetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "element localId {}: {}", self.element, self.message)
    }
}

impl std::error::Error for NetError {}
