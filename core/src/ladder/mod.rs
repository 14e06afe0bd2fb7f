//! Ladder diagrams (LD): the rung grid model, validation with located diagnostics,
//! lowering to ST (so ladder runs on the one ST compiler and VM), and the readable ST view.

pub(crate) mod blocks;
pub(crate) mod catalog;
pub mod complete;
pub mod edit;
pub mod il_view;
pub mod lower;
pub(crate) mod model;
mod network;
pub mod st_view;
pub mod validate;
mod walk;

pub use catalog::{Catalog, Variable};
pub use complete::{operand_choices, OperandChoice};
pub use edit::{
    declare, describe_cell, implied_declaration, replace_name, CellRef, EditError, LadderEdit,
    PinKind,
};
pub use il_view::{has_il_view, il_view};
pub use lower::{is_hidden_name, lower, power_map, power_var, LineMap, LoweredPou};
pub use model::*;
pub use st_view::{st_view, st_view_pou};
pub use validate::{validate, validate_with, LadderDiagnostic};

#[cfg(test)]
mod tests;
