//! Syntax highlighting: the source cut into classified spans, from the real lexer.
//!
//! The editor renders these spans over its text area. Whitespace between tokens is not
//! covered; comments and pragmas are (as [`TokenClass::Comment`]).

use super::lexer::{lex, Token, TokenKind};
use crate::diagnostics::Span;

/// How a piece of source is coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TokenClass {
    /// A reserved word (`IF`, `VAR`, `AND`, `TRUE` …).
    Keyword,
    /// An elementary type or standard function block name (`BOOL`, `TIME`, `TON` …).
    Type,
    /// A number.
    Literal,
    /// A string or wide string.
    String,
    /// A duration, date, time-of-day or date-and-time literal.
    Time,
    /// A comment or pragma.
    Comment,
    /// Punctuation and operators.
    Operator,
    /// Any other name.
    Identifier,
    /// A directly represented variable (`%IX0.0`).
    Direct,
    /// A character the lexer could not read.
    Error,
}

impl TokenClass {
    /// A short CSS-friendly name (`kw`, `ty`, `num`, `str`, `time`, `com`, `op`, `id`,
    /// `dir`, `err`).
    pub fn css(self) -> &'static str {
        match self {
            TokenClass::Keyword => "kw",
            TokenClass::Type => "ty",
            TokenClass::Literal => "num",
            TokenClass::String => "str",
            TokenClass::Time => "time",
            TokenClass::Comment => "com",
            TokenClass::Operator => "op",
            TokenClass::Identifier => "id",
            TokenClass::Direct => "dir",
            TokenClass::Error => "err",
        }
    }
}

/// The tokens of `source` (without comments), ending with an end-of-text token.
pub fn tokens(source: &str) -> Vec<Token> {
    lex(source).tokens
}

const TYPE_NAMES: &[&str] = &[
    "BOOL",
    "SINT",
    "INT",
    "DINT",
    "LINT",
    "USINT",
    "UINT",
    "UDINT",
    "ULINT",
    "BYTE",
    "WORD",
    "DWORD",
    "LWORD",
    "REAL",
    "LREAL",
    "TIME",
    "LTIME",
    "DATE",
    "LDATE",
    "TIME_OF_DAY",
    "TOD",
    "LTOD",
    "LTIME_OF_DAY",
    "DATE_AND_TIME",
    "DT",
    "LDT",
    "LDATE_AND_TIME",
    "STRING",
    "WSTRING",
    "TON",
    "TOF",
    "TP",
    "CTU",
    "CTD",
    "CTUD",
    "CTU_INT",
    "CTU_DINT",
    "CTU_LINT",
    "CTU_UDINT",
    "CTU_ULINT",
    "CTD_INT",
    "CTD_DINT",
    "CTD_LINT",
    "CTD_UDINT",
    "CTD_ULINT",
    "CTUD_INT",
    "CTUD_DINT",
    "CTUD_LINT",
    "CTUD_UDINT",
    "CTUD_ULINT",
    "R_TRIG",
    "F_TRIG",
    "SR",
    "RS",
];

fn is_type_name(word: &str) -> bool {
    TYPE_NAMES.iter().any(|t| t.eq_ignore_ascii_case(word))
}

fn class_of(kind: TokenKind, text: &str) -> Option<TokenClass> {
    use TokenKind as T;
    Some(match kind {
        T::Eof => return None,
        T::Ident if is_type_name(text) => TokenClass::Type,
        T::Ident => TokenClass::Identifier,
        T::Integer | T::Real => TokenClass::Literal,
        T::String | T::WString => TokenClass::String,
        T::Duration | T::Date | T::TimeOfDay | T::DateTime => TokenClass::Time,
        T::Direct => TokenClass::Direct,
        T::Error => TokenClass::Error,
        T::Assign
        | T::Arrow
        | T::Colon
        | T::Semicolon
        | T::Comma
        | T::Dot
        | T::DotDot
        | T::Hash
        | T::LParen
        | T::RParen
        | T::LBracket
        | T::RBracket
        | T::Plus
        | T::Minus
        | T::Star
        | T::Slash
        | T::Power
        | T::Eq
        | T::Ne
        | T::Lt
        | T::Le
        | T::Gt
        | T::Ge
        | T::Ampersand
        | T::Caret => TokenClass::Operator,
        _ => TokenClass::Keyword,
    })
}

/// True for the SFC words the parser recognises from context (`STEP S1`, `ACTION A`,
/// `TRANSITION T1`/`TRANSITION (`/`TRANSITION FROM`, `FROM a`/`FROM (`, `(PRIORITY :=`),
/// given the kinds of the tokens before and after; `Step := 1` stays a name.
fn is_sfc_word(text: &str, before: Option<TokenKind>, after: Option<TokenKind>) -> bool {
    use TokenKind as T;
    let word = text.to_ascii_uppercase();
    match word.as_str() {
        "STEP" | "ACTION" => after == Some(T::Ident),
        "TRANSITION" => matches!(after, Some(T::Ident | T::LParen)),
        "FROM" => {
            matches!(after, Some(T::Ident | T::LParen))
                && matches!(before, Some(T::Ident | T::RParen))
        }
        "PRIORITY" => before == Some(T::LParen) && after == Some(T::Assign),
        _ => false,
    }
}

/// True for an IL operator (`LD`, `ANDN`, `JMPC`, `S1`, …) where an IL body has one: first
/// on its line (or after a label `L1:`) and followed on that line by an operand, or `RET`,
/// `RETC`, `RETCN` alone. `S := 1;` and `LD` as a name in ST stay names.
fn is_il_word(source: &str, tokens: &[Token], i: usize) -> bool {
    let gap = |a: &Token, b: &Token| source.get(a.span.end as usize..b.span.start as usize);
    let on_new_line = |a: &Token, b: &Token| gap(a, b).is_none_or(|g| g.contains('\n'));
    let Some(t) = tokens.get(i) else { return false };
    let text = source.get(t.span.start as usize..t.span.end as usize).unwrap_or("");
    let upper = text.to_ascii_uppercase();
    if !super::parser::is_il_operator(&upper) {
        return false;
    }
    let first = match i.checked_sub(1).and_then(|p| tokens.get(p)) {
        None => true,
        Some(prev) if on_new_line(prev, t) => true,
        Some(prev) => {
            prev.kind == TokenKind::Colon
                && i >= 2
                && tokens.get(i - 2).is_some_and(|l| {
                    l.kind == TokenKind::Ident
                        && (i < 3 || tokens.get(i - 3).is_none_or(|b| on_new_line(b, l)))
                })
        }
    };
    if !first {
        return false;
    }
    match tokens.get(i + 1) {
        Some(next) if !on_new_line(t, next) => super::parser::starts_operand(next.kind),
        _ => matches!(upper.as_str(), "RET" | "RETC" | "RETCN"),
    }
}

/// The classified spans of `source`, in source order and never overlapping. Spans lie on
/// character boundaries of `source`; whitespace is left out.
pub fn highlight_spans(source: &str) -> Vec<(Span, TokenClass)> {
    let lexed = lex(source);
    let mut spans: Vec<(Span, TokenClass)> =
        Vec::with_capacity(lexed.tokens.len() + lexed.comments.len());
    let text_of = |t: &Token| source.get(t.span.start as usize..t.span.end as usize).unwrap_or("");
    for (i, t) in lexed.tokens.iter().enumerate() {
        let text = text_of(t);
        let kind_at = |k: usize| lexed.tokens.get(k).map(|t| t.kind);
        let class = if t.kind == TokenKind::Ident
            && (is_sfc_word(text, kind_at(i.wrapping_sub(1)), kind_at(i + 1))
                || is_il_word(source, &lexed.tokens, i))
        {
            Some(TokenClass::Keyword)
        } else {
            class_of(t.kind, text)
        };
        if let Some(class) = class {
            if !t.span.is_empty() {
                spans.push((t.span, class));
            }
        }
    }
    for c in &lexed.comments {
        if !c.span.is_empty() {
            spans.push((c.span, TokenClass::Comment));
        }
    }
    crate::order::sort_by_key(&mut spans, |(s, _)| (s.start, s.end));
    // Pragmas `{ … }` are dropped by the lexer: colour any gap that starts with `{`.
    let mut out = Vec::with_capacity(spans.len());
    let mut pos = 0usize;
    let push_gap = |out: &mut Vec<(Span, TokenClass)>, from: usize, to: usize| {
        let Some(gap) = source.get(from..to) else { return };
        let trimmed = gap.trim_start();
        if trimmed.starts_with('{') {
            let start = from + (gap.len() - trimmed.len());
            let end = from + gap.trim_end().len();
            if end > start {
                out.push((Span::new(start, end), TokenClass::Comment));
            }
        }
    };
    for (span, class) in spans {
        let (s, e) = (span.start as usize, span.end as usize);
        if s < pos || e > source.len() || !source.is_char_boundary(s) || !source.is_char_boundary(e)
        {
            continue;
        }
        push_gap(&mut out, pos, s);
        out.push((span, class));
        pos = e;
    }
    push_gap(&mut out, pos, source.len());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn classes(src: &str) -> Vec<(&str, TokenClass)> {
        highlight_spans(src)
            .into_iter()
            .map(|(s, c)| (&src[s.start as usize..s.end as usize], c))
            .collect()
    }

    #[test]
    fn classifies_every_kind_of_token() {
        use TokenClass as C;
        let src = "VAR x AT %IX0.0 : BOOL; t : TON; END_VAR (* čeština *)\nx := 16#FF + 1.5 > T#5s; s := 'a'; {pragma}";
        assert_eq!(
            classes(src),
            vec![
                ("VAR", C::Keyword),
                ("x", C::Identifier),
                ("AT", C::Keyword),
                ("%IX0.0", C::Direct),
                (":", C::Operator),
                ("BOOL", C::Type),
                (";", C::Operator),
                ("t", C::Identifier),
                (":", C::Operator),
                ("TON", C::Type),
                (";", C::Operator),
                ("END_VAR", C::Keyword),
                ("(* čeština *)", C::Comment),
                ("x", C::Identifier),
                (":=", C::Operator),
                ("16#FF", C::Literal),
                ("+", C::Operator),
                ("1.5", C::Literal),
                (">", C::Operator),
                ("T#5s", C::Time),
                (";", C::Operator),
                ("s", C::Identifier),
                (":=", C::Operator),
                ("'a'", C::String),
                (";", C::Operator),
                ("{pragma}", C::Comment),
            ]
        );
    }

    #[test]
    fn sfc_words_are_keywords_only_where_the_parser_reads_them_so() {
        use TokenClass as C;
        let src = "STEP S1 : END_STEP TRANSITION T1 (PRIORITY := 1) FROM S1 TO S2 := x; END_TRANSITION Step := 1;";
        let kw: Vec<&str> =
            classes(src).into_iter().filter(|(_, c)| *c == C::Keyword).map(|(t, _)| t).collect();
        assert_eq!(
            kw,
            ["STEP", "END_STEP", "TRANSITION", "PRIORITY", "FROM", "TO", "END_TRANSITION"]
        );
    }

    #[test]
    fn il_operators_are_keywords_only_where_an_il_body_has_them() {
        use TokenClass as C;
        let src = "PROGRAM P VAR S, LD : BOOL; T1 : TON; END_VAR\n  LD S\n  ANDN LD (* c *)\nL1: ST S\n  CAL T1(IN := S)\n  IN T1\n  JMPC L1\n  RET\nEND_PROGRAM\nS := LD;";
        let kw: Vec<&str> =
            classes(src).into_iter().filter(|(_, c)| *c == C::Keyword).map(|(t, _)| t).collect();
        assert_eq!(
            kw,
            [
                "PROGRAM",
                "VAR",
                "END_VAR",
                "LD",
                "ANDN",
                "ST",
                "CAL",
                "IN",
                "JMPC",
                "RET",
                "END_PROGRAM"
            ]
        );
    }

    #[test]
    fn never_panics_on_odd_input() {
        for src in ["", "(* open", "'open\n", "čš ž € 🙂 := ;", "{ open", "%", "16#", "T#"] {
            let spans = highlight_spans(src);
            let mut last = 0;
            for (s, _) in spans {
                assert!(s.start as usize >= last && src.is_char_boundary(s.start as usize));
                assert!(src.is_char_boundary(s.end as usize));
                last = s.end as usize;
            }
        }
        assert!(!tokens("a := 1;").is_empty());
    }
}
