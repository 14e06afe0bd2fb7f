use super::*;
use TokenKind as T;

fn kinds(src: &str) -> Vec<TokenKind> {
    lex(src).tokens.iter().map(|t| t.kind).collect()
}

fn texts(src: &str) -> Vec<String> {
    lex(src)
        .tokens
        .iter()
        .filter(|t| t.kind != T::Eof)
        .map(|t| src[t.span.start as usize..t.span.end as usize].to_string())
        .collect()
}

fn codes(src: &str) -> Vec<&'static str> {
    lex(src).diagnostics.iter().map(|d| d.code.as_str()).collect()
}

#[test]
fn keywords_are_case_insensitive() {
    assert_eq!(kinds("if Then end_IF"), vec![T::If, T::Then, T::EndIf, T::Eof]);
    assert_eq!(kinds("Motor_1 INT"), vec![T::Ident, T::Ident, T::Eof]);
}

#[test]
fn comments_and_pragmas_are_skipped_and_kept_aside() {
    let src = "a (* one *) b /* two */ c // three\n{ pragma } d";
    assert_eq!(texts(src), vec!["a", "b", "c", "d"]);
    let comments: Vec<String> = lex(src).comments.into_iter().map(|c| c.text).collect();
    assert_eq!(comments, vec!["one", "two", "three"]);
    // Not nested: the first `*)` closes.
    assert_eq!(texts("(* a (* b *) c *)"), vec!["c", "*", ")"]);
}

#[test]
fn unterminated_comment_and_string() {
    assert_eq!(codes("x (* never"), vec!["E0002"]);
    assert_eq!(codes("x := 'abc\ny := 1;"), vec!["E0003"]);
    // The next line still lexes normally.
    assert_eq!(texts("x := 'abc\ny;"), vec!["x", ":=", "'abc", "y", ";"]);
}

#[test]
fn numbers_ranges_and_bits() {
    assert_eq!(kinds("1..10"), vec![T::Integer, T::DotDot, T::Integer, T::Eof]);
    assert_eq!(
        kinds("1.5 1.234e-6 1E3 3.14159_26"),
        vec![T::Real, T::Real, T::Real, T::Real, T::Eof]
    );
    assert_eq!(kinds("x.3"), vec![T::Ident, T::Dot, T::Integer, T::Eof]);
    assert_eq!(texts("x.3.1"), vec!["x", ".", "3", ".", "1"]);
    assert_eq!(texts("arr[1].x"), vec!["arr", "[", "1", "]", ".", "x"]);
    assert_eq!(texts("16#FF 2#1110_0000"), vec!["16#FF", "2#1110_0000"]);
    assert_eq!(codes("12abc"), vec!["E0004"]);
}

#[test]
fn prefixed_literals() {
    assert_eq!(texts("T#5d14h12m18s3.5ms"), vec!["T#5d14h12m18s3.5ms"]);
    assert_eq!(kinds("t#-14ms"), vec![T::Duration, T::Eof]);
    assert_eq!(kinds("LTIME#1s"), vec![T::Duration, T::Eof]);
    assert_eq!(kinds("D#2006-03-20"), vec![T::Date, T::Eof]);
    assert_eq!(kinds("TOD#10:42:23.78"), vec![T::TimeOfDay, T::Eof]);
    assert_eq!(texts("DT#2006-03-20-10:42:23.78;"), vec!["DT#2006-03-20-10:42:23.78", ";"]);
    assert_eq!(texts("T#1s+x"), vec!["T#1s", "+", "x"]);
    assert_eq!(kinds("DINT#5"), vec![T::Ident, T::Hash, T::Integer, T::Eof]);
    assert_eq!(kinds("Color#Red"), vec![T::Ident, T::Hash, T::Ident, T::Eof]);
    assert_eq!(kinds("UINT#16#FE"), vec![T::Ident, T::Hash, T::Integer, T::Eof]);
}

#[test]
fn strings_with_escaped_quotes() {
    assert_eq!(texts("'it$'s' x"), vec!["'it$'s'", "x"]);
    assert_eq!(texts("\"a$\"b\" x"), vec!["\"a$\"b\"", "x"]);
    assert_eq!(kinds("'a' \"b\""), vec![T::String, T::WString, T::Eof]);
}

#[test]
fn operators() {
    assert_eq!(
        kinds(":= => : ; , . .. # ( ) [ ] + - * / ** = <> < <= > >= &"),
        vec![
            T::Assign,
            T::Arrow,
            T::Colon,
            T::Semicolon,
            T::Comma,
            T::Dot,
            T::DotDot,
            T::Hash,
            T::LParen,
            T::RParen,
            T::LBracket,
            T::RBracket,
            T::Plus,
            T::Minus,
            T::Star,
            T::Slash,
            T::Power,
            T::Eq,
            T::Ne,
            T::Lt,
            T::Le,
            T::Gt,
            T::Ge,
            T::Ampersand,
            T::Eof
        ]
    );
}

#[test]
fn direct_addresses() {
    assert_eq!(texts("%IX0.0 %QW4 %I* x.%X3"), vec!["%IX0.0", "%QW4", "%I*", "x", ".", "%X3"]);
}

#[test]
fn bad_identifiers_and_characters() {
    assert_eq!(codes("motor_"), vec!["E0011"]);
    assert_eq!(codes("a__b"), vec!["E0011"]);
    assert_eq!(kinds("motor_"), vec![T::Ident, T::Eof]);
    assert_eq!(codes("a ? b"), vec!["E0001"]);
    // An accented letter keeps the name in one piece, with one error.
    assert_eq!(codes("Čas := 1"), vec!["E0001"]);
    assert_eq!(kinds("Čas"), vec![T::Ident, T::Eof]);
    assert_eq!(codes("x := 1 € 2"), vec!["E0001"]);
}
