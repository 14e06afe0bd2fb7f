//! The page's components, one file per panel.

pub mod code_field;
pub mod controls;
pub mod editor;
pub mod header;
pub mod help;
pub mod io;
pub mod ladder;
pub mod network;
pub mod new_pou;
pub mod petri;
pub mod pinch;
pub mod pou_actions;
pub mod pou_pane;
pub mod problems;
pub mod recorded;
pub mod scene;
pub mod sfc;
pub mod share_box;
pub mod theme;
pub mod timeline;
pub mod tour;
pub mod variables;
pub mod why;
