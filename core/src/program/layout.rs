//! The memory layout a compiled program keeps: where every POU's variables and every
//! struct's fields are. The compiler (`compile/layout.rs`) fills it in; the locator and the
//! VM's boundary read it.

use crate::semantic::types::StructId;

/// The layout of one POU's frame (instance).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PouLayout {
    /// Offset of each variable in the frame.
    pub offsets: Vec<u32>,
    /// Cells taken by the variables; temporaries follow.
    pub vars_size: u32,
    /// Whole frame, temporaries included (valid when `complete`).
    pub size: u32,
    /// The dry compile finished.
    pub complete: bool,
}

/// Layout facts for every POU and struct, computed on demand.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Layouts {
    /// Each POU's frame layout, once computed.
    pub pous: Vec<Option<PouLayout>>,
    /// POUs whose layout is being computed (to find types that contain themselves).
    pub busy: Vec<bool>,
    /// Each struct's field offsets followed by its size, once computed.
    pub structs: Vec<Option<Vec<u32>>>,
    /// Absolute address of each global (valid when `real`).
    pub globals: Vec<u32>,
    /// Absolute static frame of each FUNCTION (valid when `real`).
    pub frames: Vec<Option<u32>>,
    /// Absolute address of the main instance (valid when `real`).
    pub main_base: u32,
    /// Absolute addresses are final (false during dry compiles).
    pub real: bool,
}

impl Layouts {
    /// Field offsets of struct `s` (followed by its size) if already computed.
    pub fn cached_struct(&self, s: StructId) -> Option<&[u32]> {
        self.structs.get(s as usize)?.as_deref()
    }
}
