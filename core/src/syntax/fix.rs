//! Quick fixes of the ST source, as pure functions from a source and a problem's span to
//! the new source (the editors apply the result as one undoable edit):
//! - [`replace_span`]: `Replace with Motor` puts the name a `did you mean` hint names in
//!   place of the misspelled one;
//! - [`declare_variable`]: `Declare Lamp2` declares a name used undeclared in the POU
//!   where it is used, in the section its uses imply, as the ladder editor's fix does: a
//!   name the POU writes is an output (a lamp in the I/O panel; a local of a FUNCTION), a
//!   name it only reads is an input (a switch).

use super::ast::{Item, Pou, PouKind, VarBlock, VarSection};
use super::lexer::{lex, TokenKind};
use crate::diagnostics::Span;

/// `source` with the text at `span` replaced by `with`; `None` when the span does not lie
/// on character boundaries of `source`.
pub fn replace_span(source: &str, span: Span, with: &str) -> Option<String> {
    let (start, end) = (span.start as usize, span.end as usize);
    if start > end || !source.is_char_boundary(start) || !source.is_char_boundary(end) {
        return None;
    }
    source.get(start..end)?;
    let mut out = String::with_capacity(source.len() + with.len());
    out.push_str(&source[..start]);
    out.push_str(with);
    out.push_str(&source[end..]);
    Some(out)
}

/// The section [`declare_variable`] declares `name` in, in POU `pou` of `source`: an
/// output (a FUNCTION's local) when the POU writes it (`name :=`, `=> name`, IL `ST name`,
/// `S name`, `R name`), else an input.
fn implied_section(source: &str, pou: &Pou, name: &str) -> VarSection {
    let tokens = lex(source).tokens;
    let (start, end) = (pou.span.start, pou.span.end);
    let inside: Vec<_> =
        tokens.iter().filter(|t| t.span.start >= start && t.span.end <= end).collect();
    let text = |i: usize| source.get(inside[i].span.start as usize..inside[i].span.end as usize);
    let written = (0..inside.len()).any(|i| {
        let t = inside[i];
        if t.kind != TokenKind::Ident || !text(i).is_some_and(|n| n.eq_ignore_ascii_case(name)) {
            return false;
        }
        let before = i.checked_sub(1).map(|k| inside[k]);
        if before.is_some_and(|b| b.kind == TokenKind::Dot || b.kind == TokenKind::Hash) {
            return false;
        }
        let assigned = inside.get(i + 1).is_some_and(|n| n.kind == TokenKind::Assign);
        let output = before.is_some_and(|b| b.kind == TokenKind::Arrow);
        let stored = i.checked_sub(1).is_some_and(|k| {
            inside[k].kind == TokenKind::Ident
                && text(k).is_some_and(|op| {
                    ["ST", "STN", "S", "R"].iter().any(|w| op.eq_ignore_ascii_case(w))
                })
        });
        assigned || output || stored
    });
    match (written, pou.kind) {
        (true, PouKind::Function) => VarSection::Var,
        (true, _) => VarSection::Output,
        (false, _) => VarSection::Input,
    }
}

/// The byte offset where line `offset` is on starts.
fn line_start(source: &str, offset: usize) -> usize {
    source[..offset].rfind('\n').map_or(0, |i| i + 1)
}

/// The byte offset just after the end of the line `offset` is on (after its `\n`).
fn next_line(source: &str, offset: usize) -> usize {
    source[offset..].find('\n').map_or(source.len(), |i| offset + i + 1)
}

/// The indentation of the line `offset` is on.
fn indentation(source: &str, offset: usize) -> &str {
    let start = line_start(source, offset);
    let rest = &source[start..];
    &rest[..rest.len() - rest.trim_start_matches([' ', '\t']).len()]
}

/// Adds `line` (a declaration without indentation or line end) to `block` of `source`:
/// on its own line before `END_VAR`, indented as the block's last declaration.
fn add_to_block(source: &str, block: &VarBlock, line: &str) -> Option<String> {
    let (start, end) = (block.span.start as usize, block.span.end as usize);
    let text = source.get(start..end)?;
    let end_var = start + text.to_ascii_uppercase().rfind("END_VAR")?;
    let at_line = line_start(source, end_var);
    if source[at_line..end_var].trim().is_empty() && at_line > start {
        let indent = match block.decls.last() {
            Some(d) => {
                d.names.first().map_or("    ", |n| indentation(source, n.span.start as usize))
            }
            None => "    ",
        };
        let indent = if indent.is_empty() { "    " } else { indent };
        let mut out = source.to_string();
        out.insert_str(at_line, &format!("{indent}{line}\n"));
        return Some(out);
    }
    // `VAR x : INT; END_VAR` on one line: the declaration goes before `END_VAR` there.
    let mut out = source.to_string();
    out.insert_str(end_var, &format!("{line} "));
    Some(out)
}

/// `source` with `name` declared as `name : ty;` in the POU that holds `at` (where it is
/// used undeclared), in the section its uses imply (see the module comment): added to
/// the first block of that section (not CONSTANT), or in a new block after the POU's last
/// one. `None` when `at` is in no POU, the name is not an identifier, or the text at `at`
/// is a member, an enumeration value or a typed literal rather than a variable.
pub fn declare_variable(source: &str, at: Span, name: &str, ty: &str) -> Option<String> {
    if !super::is_identifier(name) || ty.trim().is_empty() {
        return None;
    }
    let (file, _) = super::parse(source);
    let pou = file.items.iter().find_map(|item| match item {
        Item::Pou(p) if p.span.start <= at.start && at.end <= p.span.end => Some(p),
        _ => None,
    })?;
    // `s.Motr`, `Mode#Rnu`: not a variable of its own.
    let before = source.get(..at.start as usize)?.trim_end();
    if before.ends_with('.') || before.ends_with('#') {
        return None;
    }
    let declared = pou
        .var_blocks
        .iter()
        .flat_map(|b| &b.decls)
        .flat_map(|d| &d.names)
        .any(|n| n.name.eq_ignore_ascii_case(name));
    if declared {
        return None;
    }
    let section = implied_section(source, pou, name);
    let line = format!("{name} : {};", ty.trim());
    let block = pou.var_blocks.iter().find(|b| b.section == section && !b.constant);
    if let Some(block) = block {
        return add_to_block(source, block, &line);
    }
    // A new block: after the POU's last block, or after its header line when it has none.
    let after = match pou.var_blocks.last() {
        Some(b) => b.span.end as usize,
        None => pou.name.span.end as usize,
    }
    .min(source.len());
    let at_line = next_line(source, after);
    let mut out = source.to_string();
    if at_line > at.start as usize {
        // Written on one line with the use (`PROGRAM P VAR … END_VAR x := 1; …`).
        out.insert_str(after, &format!(" {} {line} END_VAR", section.keyword()));
        return Some(out);
    }
    let indent = indentation(source, pou.span.start as usize);
    let block_text =
        format!("{indent}{}\n{indent}    {line}\n{indent}END_VAR\n", section.keyword());
    out.insert_str(at_line, &block_text);
    Some(out)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn span_of(source: &str, word: &str, nth: usize) -> Span {
        let start = source.match_indices(word).nth(nth).unwrap().0;
        Span::new(start, start + word.len())
    }

    const LATCH: &str = "PROGRAM Main
VAR_INPUT
    Start : BOOL; (* start button *)
    Stop : BOOL;  (* stop button *)
END_VAR
VAR_OUTPUT
    Motor : BOOL; (* motor contactor *)
END_VAR

Motr := (Start OR Motor) AND NOT Stop;
END_PROGRAM
";

    #[test]
    fn replace_puts_the_suggestion_in_place_of_the_span() {
        let at = span_of(LATCH, "Motr", 0);
        let fixed = replace_span(LATCH, at, "Motor").unwrap();
        assert!(fixed.contains("\nMotor := (Start OR Motor) AND NOT Stop;\n"), "{fixed}");
        assert_eq!(replace_span("é", Span::new(1, 2), "x"), None, "not on a char boundary");
        assert_eq!(replace_span("ab", Span::new(1, 9), "x"), None, "outside the text");
    }

    #[test]
    fn a_written_name_becomes_an_output_of_the_program() {
        let src = LATCH.replace("Motr :=", "Lamp2 :=");
        let at = span_of(&src, "Lamp2", 0);
        let fixed = declare_variable(&src, at, "Lamp2", "BOOL").unwrap();
        assert!(
            fixed.contains(
                "VAR_OUTPUT\n    Motor : BOOL; (* motor contactor *)\n    Lamp2 : BOOL;\nEND_VAR"
            ),
            "{fixed}"
        );
        assert!(crate::semantic::analyze(&fixed).diagnostics.is_empty(), "{fixed}");
        // Declared already (a second click): nothing to do.
        assert_eq!(declare_variable(&fixed, span_of(&fixed, "Lamp2 :=", 0), "Lamp2", "BOOL"), None);
    }

    #[test]
    fn a_name_only_read_becomes_an_input() {
        let src = LATCH.replace("AND NOT Stop", "AND NOT Stop AND Guard");
        let at = span_of(&src, "Guard", 0);
        let fixed = declare_variable(&src, at, "Guard", "BOOL").unwrap();
        assert!(
            fixed.contains("    Stop : BOOL;  (* stop button *)\n    Guard : BOOL;\nEND_VAR"),
            "{fixed}"
        );
    }

    #[test]
    fn a_missing_section_gets_a_block_after_the_last_one() {
        let src = "PROGRAM P\nVAR\n  n : INT;\nEND_VAR\nn := Level + 1;\nEND_PROGRAM\n";
        let fixed = declare_variable(src, span_of(src, "Level", 0), "Level", "INT").unwrap();
        assert_eq!(
            fixed,
            "PROGRAM P\nVAR\n  n : INT;\nEND_VAR\nVAR_INPUT\n    Level : INT;\nEND_VAR\nn := Level + 1;\nEND_PROGRAM\n"
        );
        // No block at all: after the header.
        let src = "PROGRAM P\nLamp := TRUE;\nEND_PROGRAM\n";
        let fixed = declare_variable(src, span_of(src, "Lamp", 0), "Lamp", "BOOL").unwrap();
        assert_eq!(
            fixed,
            "PROGRAM P\nVAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\nLamp := TRUE;\nEND_PROGRAM\n"
        );
        assert!(crate::semantic::analyze(&fixed).diagnostics.is_empty(), "{fixed}");
    }

    #[test]
    fn the_pou_that_uses_the_name_gets_it() {
        let src = "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\ntmp := a * 2;\nF := tmp;\nEND_FUNCTION\n\
                   PROGRAM Main\nVAR x : INT; END_VAR\nx := F(1);\nEND_PROGRAM\n";
        let fixed = declare_variable(src, span_of(src, "tmp", 0), "tmp", "INT").unwrap();
        // A FUNCTION's written name is a local of its own; the one-line block gets it.
        assert!(
            fixed.starts_with(
                "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nVAR\n    tmp : INT;\nEND_VAR\n"
            ),
            "{fixed}"
        );
        assert!(crate::semantic::analyze(&fixed).diagnostics.is_empty(), "{fixed}");
        let one_line = "PROGRAM P VAR_OUTPUT q : BOOL; END_VAR q := TRUE; r := q; END_PROGRAM";
        let fixed = declare_variable(one_line, span_of(one_line, "r", 0), "r", "BOOL").unwrap();
        assert_eq!(
            fixed,
            "PROGRAM P VAR_OUTPUT q : BOOL; r : BOOL; END_VAR q := TRUE; r := q; END_PROGRAM"
        );
    }

    #[test]
    fn il_stores_write_and_members_are_not_declared() {
        let src = "PROGRAM P\nVAR_INPUT a : BOOL; END_VAR\nLD a\nST Lamp\nEND_PROGRAM\n";
        let fixed = declare_variable(src, span_of(src, "Lamp", 0), "Lamp", "BOOL").unwrap();
        assert!(fixed.contains("VAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\n"), "{fixed}");
        let member = "PROGRAM P\nVAR t : TON; b : BOOL; END_VAR\nb := t.Qx;\nEND_PROGRAM\n";
        assert_eq!(declare_variable(member, span_of(member, "Qx", 0), "Qx", "BOOL"), None);
        assert_eq!(declare_variable("x := 1;", Span::new(0, 1), "x", "INT"), None, "in no POU");
    }
}
