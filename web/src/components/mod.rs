//! The page's components, one file per panel.

pub mod controls;
pub mod editor;
pub mod header;
pub mod io;
pub mod timeline;
pub mod variables;
