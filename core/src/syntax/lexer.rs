//! The lexer: source text → tokens, comments and lexical diagnostics.
//!
//! Tokens carry only their kind and byte span; their text is read back from the source.
//! Literal values are not computed here (see `literal.rs`): the lexer only finds where a
//! literal starts and ends. Comments and pragmas are dropped from the token stream but
//! comments are kept aside so the parser can attach a declaration's description.
//! The lexer never fails: every byte either becomes part of a token or a diagnostic.

use crate::diagnostics::{Code, Diagnostic, Said, Span};
use crate::msg;

/// One token: what it is and where it stands. Its text is `&source[span]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Token {
    /// The kind of token.
    pub kind: TokenKind,
    /// Its bytes in the source.
    pub span: Span,
}

/// The kinds of token. Keywords are recognised case-insensitively.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TokenKind {
    /// A name that is not a keyword (type names such as `INT` or `STRING` are names too).
    Ident,
    /// An integer literal: `123_456`, `2#1010`, `16#FF`.
    Integer,
    /// A real literal: `1.5`, `1.234e-6`.
    Real,
    /// A `'…'` string literal (quotes included).
    String,
    /// A `"…"` wide string literal (quotes included).
    WString,
    /// A duration literal with its prefix: `T#1s`, `LTIME#5ms`.
    Duration,
    /// A date literal with its prefix: `D#2006-03-20`.
    Date,
    /// A time-of-day literal with its prefix: `TOD#10:42:23`.
    TimeOfDay,
    /// A date-and-time literal with its prefix: `DT#2006-03-20-10:42:23`.
    DateTime,
    /// A directly represented variable: `%IX0.0`, `%QW4` (also `%X3` in bit access).
    Direct,
    /// `:=`
    Assign,
    /// `=>`
    Arrow,
    /// `:`
    Colon,
    /// `;`
    Semicolon,
    /// `,`
    Comma,
    /// `.`
    Dot,
    /// `..`
    DotDot,
    /// `#`
    Hash,
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `[`
    LBracket,
    /// `]`
    RBracket,
    /// `+`
    Plus,
    /// `-`
    Minus,
    /// `*`
    Star,
    /// `/`
    Slash,
    /// `**`
    Power,
    /// `=`
    Eq,
    /// `<>`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `&`
    Ampersand,
    /// `^` (dereference of a reference, IEC 61131-3 ed. 3)
    Caret,
    /// `PROGRAM`
    Program,
    /// `END_PROGRAM`
    EndProgram,
    /// `FUNCTION`
    Function,
    /// `END_FUNCTION`
    EndFunction,
    /// `FUNCTION_BLOCK`
    FunctionBlock,
    /// `END_FUNCTION_BLOCK`
    EndFunctionBlock,
    /// `TYPE`
    Type,
    /// `END_TYPE`
    EndType,
    /// `STRUCT`
    Struct,
    /// `END_STRUCT`
    EndStruct,
    /// `VAR`
    Var,
    /// `VAR_INPUT`
    VarInput,
    /// `VAR_OUTPUT`
    VarOutput,
    /// `VAR_IN_OUT`
    VarInOut,
    /// `VAR_GLOBAL`
    VarGlobal,
    /// `VAR_EXTERNAL`
    VarExternal,
    /// `VAR_TEMP`
    VarTemp,
    /// `END_VAR`
    EndVar,
    /// `RETAIN`
    Retain,
    /// `NON_RETAIN`
    NonRetain,
    /// `PERSISTENT`
    Persistent,
    /// `CONSTANT`
    Constant,
    /// `AT`
    At,
    /// `ARRAY`
    Array,
    /// `OF`
    Of,
    /// `IF`
    If,
    /// `THEN`
    Then,
    /// `ELSIF`
    Elsif,
    /// `ELSE`
    Else,
    /// `END_IF`
    EndIf,
    /// `CASE`
    Case,
    /// `END_CASE`
    EndCase,
    /// `FOR`
    For,
    /// `TO`
    To,
    /// `BY`
    By,
    /// `DO`
    Do,
    /// `END_FOR`
    EndFor,
    /// `WHILE`
    While,
    /// `END_WHILE`
    EndWhile,
    /// `REPEAT`
    Repeat,
    /// `UNTIL`
    Until,
    /// `END_REPEAT`
    EndRepeat,
    /// `EXIT`
    Exit,
    /// `CONTINUE`
    Continue,
    /// `RETURN`
    Return,
    /// `NOT`
    Not,
    /// `AND`
    And,
    /// `AND_THEN`
    AndThen,
    /// `OR`
    Or,
    /// `OR_ELSE`
    OrElse,
    /// `XOR`
    Xor,
    /// `MOD`
    Mod,
    /// `TRUE`
    True,
    /// `FALSE`
    False,
    /// `CONFIGURATION`
    Configuration,
    /// `END_CONFIGURATION`
    EndConfiguration,
    /// `RESOURCE`
    Resource,
    /// `END_RESOURCE`
    EndResource,
    /// `INITIAL_STEP` (textual SFC; `STEP`, `TRANSITION`, `ACTION`, `FROM` and `PRIORITY`
    /// are recognised by the parser from context, so they stay usable as names)
    InitialStep,
    /// `END_STEP`
    EndStep,
    /// `END_TRANSITION`
    EndTransition,
    /// `END_ACTION`
    EndAction,
    /// A character that cannot start any token (already reported by the lexer).
    Error,
    /// The end of the text.
    Eof,
}

impl TokenKind {
    /// The keyword spelled `word` (any case), if it is one.
    pub(crate) fn keyword(word: &str) -> Option<TokenKind> {
        use TokenKind::*;
        let upper = word.to_ascii_uppercase();
        Some(match upper.as_str() {
            "PROGRAM" => Program,
            "END_PROGRAM" => EndProgram,
            "FUNCTION" => Function,
            "END_FUNCTION" => EndFunction,
            "FUNCTION_BLOCK" => FunctionBlock,
            "END_FUNCTION_BLOCK" => EndFunctionBlock,
            "TYPE" => Type,
            "END_TYPE" => EndType,
            "STRUCT" => Struct,
            "END_STRUCT" => EndStruct,
            "VAR" => Var,
            "VAR_INPUT" => VarInput,
            "VAR_OUTPUT" => VarOutput,
            "VAR_IN_OUT" => VarInOut,
            "VAR_GLOBAL" => VarGlobal,
            "VAR_EXTERNAL" => VarExternal,
            "VAR_TEMP" => VarTemp,
            "END_VAR" => EndVar,
            "RETAIN" => Retain,
            "NON_RETAIN" => NonRetain,
            "PERSISTENT" => Persistent,
            "CONSTANT" => Constant,
            "AT" => At,
            "ARRAY" => Array,
            "OF" => Of,
            "IF" => If,
            "THEN" => Then,
            "ELSIF" => Elsif,
            "ELSE" => Else,
            "END_IF" => EndIf,
            "CASE" => Case,
            "END_CASE" => EndCase,
            "FOR" => For,
            "TO" => To,
            "BY" => By,
            "DO" => Do,
            "END_FOR" => EndFor,
            "WHILE" => While,
            "END_WHILE" => EndWhile,
            "REPEAT" => Repeat,
            "UNTIL" => Until,
            "END_REPEAT" => EndRepeat,
            "EXIT" => Exit,
            "CONTINUE" => Continue,
            "RETURN" => Return,
            "NOT" => Not,
            "AND" => And,
            "AND_THEN" => AndThen,
            "OR" => Or,
            "OR_ELSE" => OrElse,
            "XOR" => Xor,
            "MOD" => Mod,
            "TRUE" => True,
            "FALSE" => False,
            "CONFIGURATION" => Configuration,
            "END_CONFIGURATION" => EndConfiguration,
            "RESOURCE" => Resource,
            "END_RESOURCE" => EndResource,
            "INITIAL_STEP" => InitialStep,
            "END_STEP" => EndStep,
            "END_TRANSITION" => EndTransition,
            "END_ACTION" => EndAction,
            _ => return None,
        })
    }
}

/// A comment found between tokens: its whole span and its text without delimiters.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Comment {
    /// The whole comment including its delimiters.
    pub span: Span,
    /// The text inside the delimiters.
    pub text: String,
}

/// Everything the lexer found in one source text.
#[derive(Debug, Clone, Default)]
pub(crate) struct Lexed {
    /// The tokens, ending with one [`TokenKind::Eof`].
    pub tokens: Vec<Token>,
    /// The comments, in source order.
    pub comments: Vec<Comment>,
    /// Lexical problems, in source order.
    pub diagnostics: Vec<Diagnostic>,
}

/// Which special literal an identifier followed by `#` introduces.
#[derive(Clone, Copy)]
enum HashLiteral {
    Duration,
    Date,
    TimeOfDay,
    DateTime,
}

fn hash_literal(prefix: &str) -> Option<HashLiteral> {
    match prefix.to_ascii_uppercase().as_str() {
        "T" | "TIME" | "LT" | "LTIME" => Some(HashLiteral::Duration),
        "D" | "DATE" | "LD" | "LDATE" => Some(HashLiteral::Date),
        "TOD" | "TIME_OF_DAY" | "LTOD" | "LTIME_OF_DAY" => Some(HashLiteral::TimeOfDay),
        "DT" | "DATE_AND_TIME" | "LDT" | "LDATE_AND_TIME" => Some(HashLiteral::DateTime),
        _ => None,
    }
}

/// Splits `source` into tokens. Never fails; problems are returned as diagnostics.
pub(crate) fn lex(source: &str) -> Lexed {
    let mut lexer = Lexer { src: source, bytes: source.as_bytes(), pos: 0, out: Lexed::default() };
    lexer.run();
    lexer.out
}

struct Lexer<'a> {
    src: &'a str,
    bytes: &'a [u8],
    pos: usize,
    out: Lexed,
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_char(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

impl Lexer<'_> {
    fn peek(&self, ahead: usize) -> u8 {
        self.bytes.get(self.pos + ahead).copied().unwrap_or(0)
    }

    fn error(&mut self, code: Code, start: usize, end: usize, msg: impl Into<Said>) {
        self.out.diagnostics.push(Diagnostic::error(code, Span::new(start, end), msg));
    }

    fn push(&mut self, kind: TokenKind, start: usize) {
        self.out.tokens.push(Token { kind, span: Span::new(start, self.pos) });
    }

    fn last_kind(&self) -> Option<TokenKind> {
        self.out.tokens.last().map(|t| t.kind)
    }

    fn run(&mut self) {
        while self.pos < self.bytes.len() {
            let start = self.pos;
            let b = self.bytes[start];
            match b {
                b' ' | b'\t' | b'\r' | b'\n' | 0x0c | 0x0b => self.pos += 1,
                b'(' if self.peek(1) == b'*' => self.block_comment(b"*)"),
                b'/' if self.peek(1) == b'*' => self.block_comment(b"*/"),
                b'/' if self.peek(1) == b'/' => self.line_comment(),
                b'{' => self.pragma(),
                b'\'' => self.string(b'\'', TokenKind::String),
                b'"' => self.string(b'"', TokenKind::WString),
                b'%' => self.direct(),
                b'0'..=b'9' => self.number(),
                _ if is_ident_start(b) => self.ident(),
                _ if b >= 0x80 => self.non_ascii(),
                _ => self.punct(b),
            }
        }
        let end = self.bytes.len();
        self.out.tokens.push(Token { kind: TokenKind::Eof, span: Span::new(end, end) });
    }

    fn block_comment(&mut self, close: &[u8]) {
        let start = self.pos;
        self.pos += 2;
        let body_start = self.pos;
        loop {
            if self.pos >= self.bytes.len() {
                let opener = if close == b"*)" { "(*" } else { "/*" };
                let closer = if close == b"*)" { "*)" } else { "*/" };
                self.error(
                    Code::UnterminatedComment,
                    start,
                    (start + 2).min(self.bytes.len()),
                    msg!(CommentNotClosed, opener = opener, closer = closer),
                );
                let text = self.src.get(body_start..).unwrap_or("").trim().to_string();
                self.out.comments.push(Comment { span: Span::new(start, self.pos), text });
                return;
            }
            if self.bytes[self.pos..].starts_with(close) {
                let text = self.src.get(body_start..self.pos).unwrap_or("").trim().to_string();
                self.pos += 2;
                self.out.comments.push(Comment { span: Span::new(start, self.pos), text });
                return;
            }
            self.pos += 1;
        }
    }

    fn line_comment(&mut self) {
        let start = self.pos;
        while self.pos < self.bytes.len() && self.bytes[self.pos] != b'\n' {
            self.pos += 1;
        }
        let text = self.src.get(start + 2..self.pos).unwrap_or("").trim().to_string();
        self.out.comments.push(Comment { span: Span::new(start, self.pos), text });
    }

    fn pragma(&mut self) {
        let start = self.pos;
        while self.pos < self.bytes.len() && self.bytes[self.pos] != b'}' {
            self.pos += 1;
        }
        if self.pos >= self.bytes.len() {
            self.error(Code::UnterminatedComment, start, start + 1, msg!(PragmaNotClosed));
        } else {
            self.pos += 1;
        }
    }

    /// A string runs to its closing quote; a line break before it means it was never
    /// closed (the token then ends at the line break so the next line lexes normally).
    fn string(&mut self, quote: u8, kind: TokenKind) {
        let start = self.pos;
        self.pos += 1;
        loop {
            match self.bytes.get(self.pos).copied() {
                None | Some(b'\n') | Some(b'\r') => {
                    let what = if quote == b'\'' { "'" } else { "\"" };
                    self.error(
                        Code::UnterminatedString,
                        start,
                        self.pos,
                        msg!(StringNotClosed, quote = what),
                    );
                    break;
                }
                Some(b'$') => {
                    // `$'` and `$"` must not end the string; other escapes are checked later.
                    self.pos += 1;
                    if matches!(self.bytes.get(self.pos), Some(b'\'') | Some(b'"') | Some(b'$')) {
                        self.pos += 1;
                    }
                }
                Some(c) if c == quote => {
                    self.pos += 1;
                    break;
                }
                Some(_) => self.pos += 1,
            }
        }
        self.push(kind, start);
    }

    /// `%` followed by letters, digits, dots between digits and `*`.
    fn direct(&mut self) {
        let start = self.pos;
        self.pos += 1;
        loop {
            let b = self.peek(0);
            let dot_digit = b == b'.' && self.peek(1).is_ascii_digit();
            if b.is_ascii_alphanumeric() || b == b'_' || b == b'*' || dot_digit {
                self.pos += 1;
            } else {
                break;
            }
        }
        self.push(TokenKind::Direct, start);
    }

    fn digits(&mut self, pred: impl Fn(u8) -> bool) {
        while self.pos < self.bytes.len()
            && (pred(self.bytes[self.pos]) || self.bytes[self.pos] == b'_')
        {
            self.pos += 1;
        }
    }

    fn number(&mut self) {
        let start = self.pos;
        self.digits(|b| b.is_ascii_digit());
        let mut kind = TokenKind::Integer;
        if self.peek(0) == b'#' {
            // A based integer `16#FF`; the value check (digits fit the base) comes later.
            self.pos += 1;
            self.digits(|b| b.is_ascii_alphanumeric());
        } else if self.last_kind() == Some(TokenKind::Dot) {
            // `x.3` bit access: never a real, so `x.3.1` stays `x . 3 . 1`.
        } else {
            if self.peek(0) == b'.' && self.peek(1).is_ascii_digit() {
                kind = TokenKind::Real;
                self.pos += 1;
                self.digits(|b| b.is_ascii_digit());
            }
            let e = self.peek(0);
            if e == b'e' || e == b'E' {
                let sign = usize::from(matches!(self.peek(1), b'+' | b'-'));
                if self.peek(1 + sign).is_ascii_digit() {
                    kind = TokenKind::Real;
                    self.pos += 1 + sign;
                    self.digits(|b| b.is_ascii_digit());
                }
            }
        }
        // Letters glued to a number (`5d`, `12abc`) make a malformed number.
        if is_ident_char(self.peek(0)) {
            while is_ident_char(self.peek(0)) {
                self.pos += 1;
            }
            let text = &self.src[start..self.pos];
            self.error(Code::InvalidNumber, start, self.pos, msg!(InvalidNumber, text = text));
        }
        self.push(kind, start);
    }

    fn ident(&mut self) {
        let start = self.pos;
        while self.pos < self.bytes.len() {
            let b = self.bytes[self.pos];
            if is_ident_char(b) {
                self.pos += 1;
            } else if b >= 0x80 && self.non_ascii_letter_here() {
                // Keep accented letters inside the name (one error) rather than splitting it.
                let (ch, len) = self.char_here();
                self.error(
                    Code::UnexpectedCharacter,
                    self.pos,
                    self.pos + len,
                    msg!(CharacterInName, ch = ch),
                );
                self.pos += len;
            } else {
                break;
            }
        }
        let word = &self.src[start..self.pos];
        if self.peek(0) == b'#' {
            if let Some(which) = hash_literal(word) {
                self.pos += 1;
                self.hash_body(which);
                let kind = match which {
                    HashLiteral::Duration => TokenKind::Duration,
                    HashLiteral::Date => TokenKind::Date,
                    HashLiteral::TimeOfDay => TokenKind::TimeOfDay,
                    HashLiteral::DateTime => TokenKind::DateTime,
                };
                self.push(kind, start);
                return;
            }
        }
        if let Some(kw) = TokenKind::keyword(word) {
            self.push(kw, start);
            return;
        }
        if word.ends_with('_') || word.contains("__") {
            self.error(
                Code::InvalidIdentifier,
                start,
                self.pos,
                msg!(InvalidIdentifier, name = word),
            );
        }
        self.push(TokenKind::Ident, start);
    }

    /// The body of a duration or date literal after its `#`.
    fn hash_body(&mut self, which: HashLiteral) {
        if matches!(which, HashLiteral::Duration) && matches!(self.peek(0), b'+' | b'-') {
            self.pos += 1;
        }
        loop {
            let b = self.peek(0);
            let ok = match which {
                HashLiteral::Duration => b.is_ascii_alphanumeric() || b == b'_' || b == b'.',
                HashLiteral::Date => b.is_ascii_digit() || b == b'-' || b == b'_',
                HashLiteral::TimeOfDay => b.is_ascii_digit() || b == b':' || b == b'.' || b == b'_',
                HashLiteral::DateTime => {
                    b.is_ascii_digit() || b == b'-' || b == b':' || b == b'.' || b == b'_'
                }
            };
            // A `.` must be followed by a digit to belong to the literal (`T#1s.x` is odd).
            if !ok || (b == b'.' && !self.peek(1).is_ascii_digit()) {
                break;
            }
            self.pos += 1;
        }
    }

    fn char_here(&self) -> (char, usize) {
        let ch = self.src.get(self.pos..).and_then(|s| s.chars().next()).unwrap_or('\u{fffd}');
        (ch, ch.len_utf8().max(1))
    }

    fn non_ascii_letter_here(&self) -> bool {
        self.char_here().0.is_alphabetic()
    }

    fn non_ascii(&mut self) {
        if self.non_ascii_letter_here() {
            // An accented letter starting a name: lex the name with one error.
            self.ident();
            return;
        }
        let start = self.pos;
        let (ch, len) = self.char_here();
        self.pos += len;
        self.error(Code::UnexpectedCharacter, start, self.pos, msg!(UnexpectedCharacter, ch = ch));
        self.push(TokenKind::Error, start);
    }

    fn punct(&mut self, b: u8) {
        use TokenKind::*;
        let start = self.pos;
        let next = self.peek(1);
        let (kind, len) = match (b, next) {
            (b':', b'=') => (Assign, 2),
            (b'=', b'>') => (Arrow, 2),
            (b'.', b'.') => (DotDot, 2),
            (b'*', b'*') => (Power, 2),
            (b'<', b'>') => (Ne, 2),
            (b'<', b'=') => (Le, 2),
            (b'>', b'=') => (Ge, 2),
            (b':', _) => (Colon, 1),
            (b';', _) => (Semicolon, 1),
            (b',', _) => (Comma, 1),
            (b'.', _) => (Dot, 1),
            (b'#', _) => (Hash, 1),
            (b'(', _) => (LParen, 1),
            (b')', _) => (RParen, 1),
            (b'[', _) => (LBracket, 1),
            (b']', _) => (RBracket, 1),
            (b'+', _) => (Plus, 1),
            (b'-', _) => (Minus, 1),
            (b'*', _) => (Star, 1),
            (b'/', _) => (Slash, 1),
            (b'=', _) => (Eq, 1),
            (b'<', _) => (Lt, 1),
            (b'>', _) => (Gt, 1),
            (b'&', _) => (Ampersand, 1),
            (b'^', _) => (Caret, 1),
            _ => {
                self.pos += 1;
                let shown = if b.is_ascii_graphic() {
                    msg!(UnexpectedCharacter, ch = b as char)
                } else {
                    msg!(UnexpectedControlCharacter, hex = format!("{b:02X}"))
                };
                self.error(Code::UnexpectedCharacter, start, self.pos, shown);
                self.push(Error, start);
                return;
            }
        };
        self.pos += len;
        self.push(kind, start);
    }
}

#[cfg(test)]
mod tests;
