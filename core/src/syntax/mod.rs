//! The ST front-end: lexer, parser and the syntax tree.
//!
//! Input is source text; output is a [`SourceFile`] plus located diagnostics. The parser
//! recovers from errors (one bad line gives one error, not a cascade) so the checker can
//! still report on the rest. This module never looks at names or types.

pub mod ast;
pub mod fix;
mod highlight;
mod lexer;
mod literal;
mod parser;

pub use ast::il::*;
pub use ast::sfc::*;
pub use ast::*;
pub use highlight::{highlight_spans, tokens, TokenClass};
pub use lexer::{Token, TokenKind};
pub(crate) use parser::il_operator_names;

use crate::diagnostics::Diagnostic;

/// Parses a whole source file. Always returns a tree (possibly partial) and every problem
/// found, in source order.
pub fn parse(source: &str) -> (SourceFile, Vec<Diagnostic>) {
    parser::parse_source(source)
}

/// Parses a single expression (a breakpoint condition, a `--set` value). Text after the
/// expression is an error.
pub fn parse_expression(source: &str) -> Result<Expr, Vec<Diagnostic>> {
    parser::parse_single_expression(source)
}

/// Whether `word` (any case) is a keyword of ST (`IF`, `END_VAR`, `TRUE`), which cannot name
/// a variable or a POU.
pub fn is_keyword(word: &str) -> bool {
    lexer::TokenKind::keyword(word).is_some()
}

/// Whether `name` is an IEC identifier (letters, digits, single underscores, not starting
/// with a digit, not ending with an underscore).
pub fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    let Some(first) = chars.next() else { return false };
    (first.is_ascii_alphabetic() || first == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.contains("__")
        && !name.ends_with('_')
}
