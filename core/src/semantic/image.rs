//! The process image (IEC 61131-3 §2.4.1.1, as on a real PLC): the directly represented
//! variables of each area (`%I`, `%Q`, `%M`) share one memory, so `%IX0.0` is bit 0 of
//! `%IB0`, of `%IW0` and of `%ID0`, and two variables at one address are one variable.
//!
//! Each area is a hidden global `ARRAY OF LWORD` (`__IMAGE_I`, `__IMAGE_Q`, `__IMAGE_M`),
//! as long as the highest address the program uses. Addresses count in units of their size,
//! as CODESYS counts them: `%IB5` is byte 5, `%IW1` bytes 2–3, `%ID1` bytes 4–7, `%IL1`
//! bytes 8–15, `%IX1.3` bit 3 of byte 1; the least significant byte comes first, so no
//! access crosses a cell. A located variable of an elementary type reads and writes its
//! raw bits there ([`Place::Bit`] for a BOOL, [`Place::Slice`] for the others: a REAL is
//! its 32 IEEE bits). Arrays at an address, and addresses with more than the usual
//! numbers (`%IX1.2.3`), keep a cell of their own.

use super::check::Checker;
use super::ir::{Expr, ExprKind, Place, Var};
use super::types::{ArrayDef, Elem, Type};
use crate::syntax::{AddressArea, AddressSize, DirectAddress, VarSection};

/// The most cells (of 8 bytes) an area's image has: addresses beyond keep their own cell.
pub const MAX_IMAGE_CELLS: u64 = 8192;

/// The hidden global holding an area's image.
pub fn image_name(area: AddressArea) -> &'static str {
    match area {
        AddressArea::Input => "__IMAGE_I",
        AddressArea::Output => "__IMAGE_Q",
        AddressArea::Memory => "__IMAGE_M",
    }
}

/// Whether `name` is one of the image's hidden globals.
pub fn is_image_name(name: &str) -> bool {
    [AddressArea::Input, AddressArea::Output, AddressArea::Memory]
        .iter()
        .any(|&a| image_name(a).eq_ignore_ascii_case(name))
}

/// Where the value at `loc` is in its area's image: the cell and the value's first bit in
/// it; `None` for an address that keeps a cell of its own.
pub fn image_spot(loc: &DirectAddress) -> Option<(u32, u32)> {
    let (byte, bit) = match (loc.size, loc.path.as_slice()) {
        (AddressSize::Bit, [byte, bit]) if *bit < 8 => (u64::from(*byte), *bit),
        (AddressSize::Byte, [n]) => (u64::from(*n), 0),
        (AddressSize::Word, [n]) => (u64::from(*n) * 2, 0),
        (AddressSize::DWord, [n]) => (u64::from(*n) * 4, 0),
        (AddressSize::LWord, [n]) => (u64::from(*n) * 8, 0),
        _ => return None,
    };
    let cell = byte / 8;
    (cell < MAX_IMAGE_CELLS).then(|| (cell as u32, (byte % 8) as u32 * 8 + bit))
}

impl Checker<'_> {
    /// Sizes the image for every located variable declared (so that later checks, such as
    /// a breakpoint condition naming one, find their area's image).
    pub(super) fn place_located_vars(&mut self) {
        let located: Vec<Var> = self
            .globals
            .iter()
            .chain(self.pous.iter().filter(|p| !p.library).flat_map(|p| &p.vars))
            .filter(|v| v.location.is_some())
            .cloned()
            .collect();
        for v in &located {
            self.image_place(v);
        }
    }

    /// The place of a located variable in the process image (`None`: it keeps its own
    /// cell). The area's image grows to hold it.
    pub(super) fn image_place(&mut self, var: &Var) -> Option<Place> {
        let loc = var.location.as_ref()?;
        let Type::Elem(elem) = var.ty else { return None };
        let (cell, shift) = image_spot(loc)?;
        let (g, arr) = self.image_global(loc.area)?;
        let def = self.types.arrays.get_mut(arr as usize)?;
        if let Some(dim) = def.dims.first_mut() {
            dim.1 = dim.1.max(i64::from(cell));
        }
        let index = Expr {
            kind: ExprKind::Const(u64::from(cell)),
            ty: Type::Elem(Elem::LInt),
            span: loc.span,
        };
        let base = Box::new(Place::Element(Box::new(Place::Global(g)), arr, vec![index]));
        Some(if elem == Elem::Bool {
            Place::Bit(base, shift, Elem::LWord)
        } else {
            Place::Slice(base, shift, elem)
        })
    }

    /// The global holding the image of `area` and its array type, made on first use.
    fn image_global(&mut self, area: AddressArea) -> Option<(u32, u32)> {
        let name = image_name(area);
        if let Some(&g) = self.global_index.get(name) {
            return match self.globals.get(g as usize)?.ty {
                Type::Array(a) => Some((g, a)),
                _ => None,
            };
        }
        let arr = self.types.arrays.len() as u32;
        self.types.arrays.push(ArrayDef {
            dims: vec![(0, 0)],
            element: Type::Elem(Elem::LWord),
            element_range: None,
            element_init: None,
        });
        let g = self.globals.len() as u32;
        self.global_index.insert(name.to_string(), g);
        self.globals.push(Var {
            name: name.to_string(),
            ty: Type::Array(arr),
            section: VarSection::Global,
            retain: false,
            constant: false,
            location: None,
            init: None,
            range: None,
            comment: None,
            span: Default::default(),
        });
        Some((g, arr))
    }
}
