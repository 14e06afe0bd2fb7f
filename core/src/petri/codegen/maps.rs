//! What code generation hands out besides the text: where each generated line comes from
//! (to report problems at the place or transition) and the place map (to draw tokens from
//! the running program's step variables).

use std::ops::Range;

use serde::Serialize;

use crate::petri::diagnostic::{NetElement, TextPart, TextPosition};

/// Where a generated line comes from.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LineSource {
    /// The net element.
    pub element: NetElement,
    /// The element's text the line holds, when it holds user text (guard, actions…).
    pub part: Option<TextPart>,
    /// 1-based line inside that text.
    pub text_line: u32,
    /// Characters on the generated line before the text starts.
    pub column_shift: u32,
}

/// A process as the UI sees it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct ProcessEntry {
    /// Its name.
    pub name: String,
    /// Its INT step variable.
    pub step_variable: String,
    /// Ids of its places.
    pub places: Vec<String>,
}

/// Where a place's token is read: it is marked when `step_variable = value`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PlaceEntry {
    /// The place's id.
    pub id: String,
    /// The step variable of the first process containing it.
    pub step_variable: String,
    /// The place's CASE label.
    pub value: i64,
}

/// A macro-place as the UI sees it: marked when any of its places is.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct MacroEntry {
    /// Its id.
    pub id: String,
    /// Ids of its places.
    pub places: Vec<String>,
}

/// How to read the marking from the running program's variables.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PlaceMap {
    /// The processes, in the order their CASE statements run.
    pub processes: Vec<ProcessEntry>,
    /// Every place, in net order.
    pub places: Vec<PlaceEntry>,
    /// The macro-places.
    pub macro_places: Vec<MacroEntry>,
}

impl PlaceMap {
    /// The marking (tokens per place, net order) given a way to read INT variables.
    pub fn marking(&self, mut read: impl FnMut(&str) -> Option<i64>) -> Vec<u32> {
        self.places.iter().map(|p| u32::from(read(&p.step_variable) == Some(p.value))).collect()
    }
}

/// A generated PROGRAM with its maps.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    /// The complete POU as ST text.
    pub st: String,
    /// Per line of `st` (index 0 is line 1): where it comes from.
    pub lines: Vec<Option<LineSource>>,
    /// 1-based lines of `st` holding the user's declarations (end exclusive).
    pub declaration_lines: Range<u32>,
    /// Place → step variable and value.
    pub place_map: PlaceMap,
}

impl Generated {
    /// The element behind 1-based `line` and `column` of [`Generated::st`], and the position
    /// inside the element's text when the line holds user text.
    pub fn locate(&self, line: u32, column: u32) -> Option<(NetElement, Option<TextPosition>)> {
        let src = self.lines.get(line.checked_sub(1)? as usize)?.as_ref()?;
        let at = src.part.map(|part| TextPosition {
            part,
            line: src.text_line,
            column: column.saturating_sub(src.column_shift).max(1),
        });
        Some((src.element.clone(), at))
    }
}
