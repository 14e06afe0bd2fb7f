//! Pure text operations of the editor: offset conversions (bytes ↔ UTF-16 ↔ characters),
//! the indentation edits, and the HTML of the highlight layer and the gutter.
//!
//! Every function clamps its offsets to the text and to character boundaries, so no input
//! (stale diagnostics, non-ASCII text, a selection past the end) can make it panic.

use plc_core::syntax::{highlight_spans, TokenClass};

/// Spaces inserted by Tab.
pub const INDENT: &str = "    ";

/// A diagnostic as the highlight layer needs it: byte span and severity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mark {
    /// First byte.
    pub start: usize,
    /// One past the last byte.
    pub end: usize,
    /// Error (true) or warning.
    pub error: bool,
}

/// The text after an edit and its new selection (byte offsets).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Edit {
    /// The whole new text.
    pub text: String,
    /// Selection start.
    pub start: usize,
    /// Selection end.
    pub end: usize,
}

/// The largest character boundary at or before `b` (clamped to the text).
pub fn floor_boundary(text: &str, b: usize) -> usize {
    let mut b = b.min(text.len());
    while b > 0 && !text.is_char_boundary(b) {
        b -= 1;
    }
    b
}

/// The smallest character boundary at or after `b` (clamped to the text).
pub fn ceil_boundary(text: &str, b: usize) -> usize {
    let mut b = b.min(text.len());
    while b < text.len() && !text.is_char_boundary(b) {
        b += 1;
    }
    b
}

/// The byte offset of UTF-16 offset `u` (as a text area reports it), clamped.
pub fn utf16_to_byte(text: &str, u: u32) -> usize {
    let mut units = 0u32;
    for (i, c) in text.char_indices() {
        if units >= u {
            return i;
        }
        units += c.len_utf16() as u32;
    }
    text.len()
}

/// The UTF-16 offset of byte offset `b` (floored to a character boundary).
pub fn byte_to_utf16(text: &str, b: usize) -> u32 {
    let b = floor_boundary(text, b);
    text[..b].chars().map(|c| c.len_utf16() as u32).sum()
}

/// The 1-based line and character column of byte `b`.
pub fn line_col(text: &str, b: usize) -> (usize, usize) {
    let b = floor_boundary(text, b);
    let before = &text[..b];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[line_start..].chars().count() + 1)
}

/// The byte offset of 1-based `line` and character `column`, clamped to the text and to
/// the line (a column past the end of the line gives the end of the line).
pub fn offset_of(text: &str, line: u32, column: u32) -> usize {
    let mut start = 0usize;
    for _ in 1..line.max(1) {
        match text[start..].find('\n') {
            Some(i) => start += i + 1,
            None => return text.len(),
        }
    }
    let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let rest = &text[start..line_end];
    let skip = column.max(1) as usize - 1;
    rest.char_indices().nth(skip).map_or(line_end, |(i, _)| start + i)
}

fn line_start(text: &str, b: usize) -> usize {
    text[..b].rfind('\n').map_or(0, |i| i + 1)
}

/// Orders and clamps a selection.
fn clamp_sel(text: &str, start: usize, end: usize) -> (usize, usize) {
    let (a, b) = (floor_boundary(text, start), floor_boundary(text, end));
    (a.min(b), a.max(b))
}

/// Replaces the selection with `insert`, the caret after it.
pub fn insert(text: &str, start: usize, end: usize, insert: &str) -> Edit {
    let (s, e) = clamp_sel(text, start, end);
    let mut out = String::with_capacity(text.len() + insert.len());
    out.push_str(&text[..s]);
    out.push_str(insert);
    out.push_str(&text[e..]);
    let caret = s + insert.len();
    Edit { text: out, start: caret, end: caret }
}

/// The starts of the lines a selection touches (a selection ending at the start of a
/// line does not touch that line).
fn touched_lines(text: &str, s: usize, e: usize) -> Vec<usize> {
    let mut starts = vec![line_start(text, s)];
    let last = if e > s && line_start(text, e) == e { e - 1 } else { e };
    let mut pos = starts[0];
    while let Some(i) = text[pos..].find('\n') {
        let next = pos + i + 1;
        if next > last || next > text.len() {
            break;
        }
        starts.push(next);
        pos = next;
    }
    starts
}

/// Tab: four spaces in place of a one-line selection; a selection over several lines
/// indents each of them.
pub fn indent(text: &str, start: usize, end: usize) -> Edit {
    let (s, e) = clamp_sel(text, start, end);
    if !text[s..e].contains('\n') {
        return insert(text, s, e, INDENT);
    }
    let lines = touched_lines(text, s, e);
    let mut out = String::with_capacity(text.len() + lines.len() * INDENT.len());
    let mut prev = 0;
    for &l in &lines {
        out.push_str(&text[prev..l]);
        out.push_str(INDENT);
        prev = l;
    }
    out.push_str(&text[prev..]);
    let new_start = s + INDENT.len();
    let new_end = e + INDENT.len() * lines.len();
    Edit { text: out, start: new_start, end: new_end }
}

/// How much indentation Shift+Tab removes from the line starting at `l`.
fn outdent_width(text: &str, l: usize) -> usize {
    let rest = &text[l..];
    if rest.starts_with('\t') {
        1
    } else {
        rest.bytes().take(INDENT.len()).take_while(|&b| b == b' ').count()
    }
}

/// Shift+Tab: removes up to four leading spaces (or one tab) from each touched line.
pub fn outdent(text: &str, start: usize, end: usize) -> Edit {
    let (s, e) = clamp_sel(text, start, end);
    let lines: Vec<(usize, usize)> =
        touched_lines(text, s, e).into_iter().map(|l| (l, outdent_width(text, l))).collect();
    let mut out = String::with_capacity(text.len());
    let mut prev = 0;
    for &(l, n) in &lines {
        out.push_str(&text[prev..l]);
        prev = l + n;
    }
    out.push_str(&text[prev..]);
    // Bytes removed before position `p` (a position inside removed indentation moves to
    // the line start).
    let removed_before = |p: usize| -> usize {
        lines.iter().map(|&(l, n)| if p >= l + n { n } else { p.saturating_sub(l) }).sum()
    };
    let ns = floor_boundary(&out, s - removed_before(s));
    let ne = floor_boundary(&out, e - removed_before(e));
    Edit { text: out, start: ns, end: ne }
}

/// Enter: a line break followed by the current line's indentation.
pub fn newline(text: &str, start: usize, end: usize) -> Edit {
    let (s, e) = clamp_sel(text, start, end);
    let ls = line_start(text, s);
    let indent: String = text[ls..s].chars().take_while(|c| *c == ' ' || *c == '\t').collect();
    insert(text, s, e, &format!("\n{indent}"))
}

/// Escapes text for HTML.
pub fn escape(out: &mut String, text: &str) {
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
}

/// The highlight layer's HTML: coloured tokens, squiggles under diagnostics, and a point
/// marker where a diagnostic has no width (at a line end or the end of the text).
pub fn highlight_html(text: &str, marks: &[Mark]) -> String {
    let spans: Vec<(usize, usize, TokenClass)> = highlight_spans(text)
        .into_iter()
        .map(|(s, c)| (s.start as usize, s.end as usize, c))
        .filter(|&(s, e, _)| s < e && e <= text.len())
        .collect();
    // Normalised diagnostic ranges and zero-width points.
    let mut ranges: Vec<Mark> = Vec::new();
    let mut points: Vec<Mark> = Vec::new();
    for m in marks.iter().take(500) {
        let s = floor_boundary(text, m.start);
        let mut e = ceil_boundary(text, m.end.max(s));
        if e <= s {
            match text[s..].chars().next() {
                Some(c) if c != '\n' && c != '\r' => e = s + c.len_utf8(),
                _ => {
                    points.push(Mark { start: s, end: s, error: m.error });
                    continue;
                }
            }
        }
        ranges.push(Mark { start: s, end: e, error: m.error });
    }
    let mut cuts: Vec<usize> = vec![0, text.len()];
    for &(s, e, _) in &spans {
        cuts.push(s);
        cuts.push(e);
    }
    for r in &ranges {
        cuts.push(r.start);
        cuts.push(r.end);
    }
    for p in &points {
        cuts.push(p.start);
    }
    cuts.retain(|&c| text.is_char_boundary(c));
    plc_core::order::sort(&mut cuts);
    cuts.dedup();

    let mut out = String::with_capacity(text.len() * 2 + 64);
    let mut tok = 0usize;
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        emit_points(&mut out, &points, a);
        while tok < spans.len() && spans[tok].1 <= a {
            tok += 1;
        }
        let class = spans.get(tok).filter(|t| t.0 <= a && a < t.1).map(|t| t.2);
        let diag = ranges
            .iter()
            .filter(|r| r.start <= a && a < r.end)
            .map(|r| r.error)
            .reduce(|x, y| x || y);
        let seg = &text[a..b];
        if class.is_none() && diag.is_none() {
            escape(&mut out, seg);
            continue;
        }
        out.push_str("<span class=\"");
        if let Some(c) = class {
            out.push_str("tok-");
            out.push_str(c.css());
        }
        match diag {
            Some(true) => out.push_str(" sq-err"),
            Some(false) => out.push_str(" sq-warn"),
            None => {}
        }
        out.push_str("\">");
        escape(&mut out, seg);
        out.push_str("</span>");
    }
    emit_points(&mut out, &points, text.len());
    // A final line break needs a line after it to be shown, plus room to scroll.
    out.push_str("\n ");
    out
}

/// One line of read-only code as highlighted HTML, without the blank line
/// [`highlight_html`] adds for an editor's overlay: for views that put each line in a
/// block of its own (the ladder's ST and IL views beside the rungs).
pub fn highlight_line_html(line: &str) -> String {
    let mut html = highlight_html(line.trim_end_matches(['\n', '\r']), &[]);
    if html.ends_with("\n ") {
        html.truncate(html.len() - 2);
    }
    html
}

fn emit_points(out: &mut String, points: &[Mark], at: usize) {
    let mut err = None;
    for p in points.iter().filter(|p| p.start == at) {
        err = Some(err.unwrap_or(false) || p.error);
    }
    match err {
        Some(true) => out.push_str("<span class=\"sq-point sq-err\"></span>"),
        Some(false) => out.push_str("<span class=\"sq-point sq-warn\"></span>"),
        None => {}
    }
}

/// A line's marker in the gutter.
#[derive(Debug, Clone, Default)]
pub struct LineInfo {
    /// Worst severity on the line: Some(true) error, Some(false) warning.
    pub diag: Option<bool>,
    /// The messages (for the tooltip).
    pub messages: Vec<String>,
}

/// The gutter's HTML: one numbered row per line, with diagnostic and fault markers.
pub fn gutter_html(
    line_count: usize,
    info: &std::collections::BTreeMap<usize, LineInfo>,
    marked: Option<usize>,
) -> String {
    let mut out = String::with_capacity(line_count * 24);
    for n in 1..=line_count.max(1) {
        out.push_str("<div class=\"ln");
        let li = info.get(&n);
        match li.and_then(|l| l.diag) {
            Some(true) => out.push_str(" ln-err"),
            Some(false) => out.push_str(" ln-warn"),
            None => {}
        }
        if marked == Some(n) {
            out.push_str(" ln-marked");
        }
        out.push('"');
        if let Some(li) = li.filter(|l| !l.messages.is_empty()) {
            out.push_str(" title=\"");
            escape(&mut out, &li.messages.join("\n"));
            out.push('"');
        }
        out.push('>');
        out.push_str(&n.to_string());
        out.push_str("</div>");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_survive_non_ascii() {
        let t = "a := 1; (* čeština 🙂 *)\nb";
        for u in 0..40 {
            let b = utf16_to_byte(t, u);
            assert!(t.is_char_boundary(b));
            let _ = byte_to_utf16(t, b);
            let _ = line_col(t, b);
        }
        for b in 0..t.len() + 3 {
            let _ = byte_to_utf16(t, b);
            let _ = line_col(t, b);
            let _ = highlight_html(t, &[Mark { start: b, end: b + 1, error: true }]);
        }
        let emoji = t.find('🙂').unwrap();
        assert_eq!(utf16_to_byte(t, byte_to_utf16(t, emoji) + 2), emoji + 4);
        assert_eq!(offset_of(t, 2, 1), t.len() - 1);
        assert_eq!(offset_of(t, 9, 9), t.len());
        assert_eq!(line_col(t, t.len()), (2, 2));
    }

    #[test]
    fn indentation_edits() {
        assert_eq!(newline("    x", 5, 5).text, "    x\n    ");
        let e = indent("a\nb\nc", 0, 3);
        assert_eq!(e.text, "    a\n    b\nc");
        let o = outdent(&e.text, 4, 10);
        assert_eq!(o.text, "a\nb\nc");
        assert!(o.start <= o.end && o.end <= o.text.len());
        assert_eq!(outdent("  x", 3, 3), Edit { text: "x".into(), start: 1, end: 1 });
        assert_eq!(indent("ab", 1, 1).text, "a    b");
    }

    #[test]
    fn a_highlighted_line_is_one_line() {
        for line in ["LD Start", "Motor := (Start OR Motor) AND NOT Stop;\n", "(* a < b *)"] {
            let html = highlight_line_html(line);
            assert!(!html.contains('\n'), "{line:?} gave {html:?}");
            assert!(html.contains("Start") || html.contains("&lt;"), "{html:?}");
        }
    }

    #[test]
    fn highlight_escapes_and_marks() {
        let h = highlight_html("x := a < b;\n", &[Mark { start: 12, end: 12, error: true }]);
        assert!(h.contains("&lt;"));
        assert!(h.contains("sq-point"));
        assert!(h.contains("tok-op"));
    }
}
