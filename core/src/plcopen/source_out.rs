//! The ST text an import writes, with where each of its lines came from in the file (see
//! [`FileMap`](crate::build::FileMap)): problems the checker finds in it are reported at
//! the file's own line and column.

use super::xml::Node;
use crate::build::SourceLine;

/// ST text being written, line origins beside it.
#[derive(Debug, Default)]
pub(crate) struct SourceOut {
    /// The text.
    pub text: String,
    /// Entry `k`: where line `k + 1` came from.
    pub lines: Vec<Option<SourceLine>>,
}

impl SourceOut {
    /// Appends `text` written from the element at `from` (every column reported there).
    pub fn push(&mut self, text: &str, from: Option<(u32, u32)>) {
        let origin = from.map(|(line, column)| SourceLine { line, column, verbatim: false });
        self.text.push_str(text);
        self.fill(|_| origin);
    }

    /// [`SourceOut::push`] from the element `node`.
    pub fn push_from(&mut self, text: &str, node: &Node) {
        self.push(text, Some((node.line, node.column)));
    }

    /// Appends `text`, which is the file's own text from `line`, `column` on.
    pub fn push_verbatim(&mut self, text: &str, line: u32, column: u32) {
        let first = self.lines.len().max(1) - 1;
        let starts_line = self.text.is_empty() || self.text.ends_with('\n');
        self.text.push_str(text);
        let base = self.lines.len();
        self.fill(|k| {
            // Line `k` of the source is line `k - first` of `text` when `text` continues a
            // line already begun; the begun line keeps its own origin.
            let n = if starts_line { k - base } else { k - first };
            Some(SourceLine {
                line: line + n as u32,
                column: if n == 0 { column } else { 1 },
                verbatim: true,
            })
        });
    }

    /// Appends another tracked text.
    pub fn append(&mut self, other: SourceOut) {
        let starts_line = self.text.is_empty() || self.text.ends_with('\n');
        if !starts_line {
            self.lines.pop();
        }
        self.text.push_str(&other.text);
        self.lines.extend(other.lines);
        self.fill(|_| None);
    }

    /// Gives every line not yet in `lines` (through the one being written) an origin.
    fn fill(&mut self, origin: impl Fn(usize) -> Option<SourceLine>) {
        let count = self.text.matches('\n').count() + usize::from(!self.text.ends_with('\n'));
        while self.lines.len() < count {
            let k = self.lines.len();
            self.lines.push(origin(k));
        }
        self.lines.truncate(count);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_keep_their_origin() {
        let mut out = SourceOut::default();
        out.push("PROGRAM P\n", Some((5, 3)));
        out.push_verbatim("x := 1;\n  y := 2;\n", 10, 20);
        out.push("END_PROGRAM\n", None);
        assert_eq!(out.text.lines().count(), out.lines.len());
        let at = |k: usize| out.lines[k].map(|l| (l.line, l.column, l.verbatim));
        assert_eq!(at(0), Some((5, 3, false)));
        assert_eq!(at(1), Some((10, 20, true)));
        assert_eq!(at(2), Some((11, 1, true)));
        assert_eq!(at(3), None);
    }

    #[test]
    fn appended_text_keeps_its_lines() {
        let mut decl = SourceOut::default();
        decl.push("VAR\n", Some((2, 1)));
        decl.push("  a : INT;\n", Some((3, 5)));
        let mut out = SourceOut::default();
        out.push("FUNCTION_BLOCK F\n", Some((1, 1)));
        out.append(decl);
        let lines: Vec<u32> = out.lines.iter().map(|l| l.map_or(0, |l| l.line)).collect();
        assert_eq!(lines, vec![1, 2, 3]);
    }
}
