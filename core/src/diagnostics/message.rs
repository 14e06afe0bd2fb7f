//! Diagnostics as data (issue 33): a problem is reported as a [`Msg`] (a key of the message
//! catalogue `core/i18n/messages.LANG.json`) and named arguments, and its text is made from
//! the catalogue of the language asked for.
//!
//! An argument is program text ([`Arg::Text`]: names, types, values, literals, never
//! translated) or a phrase that is itself a message ([`Arg::Msg`], such as the parser's
//! `expected a type name`), translated with the rest. English templates are built in and
//! every diagnostic carries its English text ([`super::Diagnostic::message`]), made where the
//! diagnostic is made from the template as a literal ([`msg!`](crate::msg)), so a part of the
//! engine that loads lazily keeps its texts. Polish and Czech are read from their catalogues
//! only when [`Message::render`] is asked for them (the command line; the page renders from
//! its own fetched catalogue).

use std::collections::BTreeMap;
use std::sync::OnceLock;

use crate::i18n::Lang;

include!(concat!(env!("OUT_DIR"), "/messages.rs"));
pub(crate) use msg_en;

/// A phrase that is a message of its own, with its English template: an argument that is
/// translated (the parser's `a type name` in `expected a type name, found …`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Phrase {
    /// The phrase's key.
    pub key: Msg,
    /// Its English template.
    pub en: &'static str,
}

/// A message's argument.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Arg {
    /// Program text (a name, a type, a value, a literal) or a number: never translated.
    Text(String),
    /// A phrase, translated with the message (rendered with no arguments of its own).
    Msg(Phrase),
    /// A whole message with arguments of its own, translated with the message (the
    /// checker's words that an SFC sentence puts in parentheses).
    Said(Box<Said>),
}

impl Arg {
    /// The argument in English.
    pub fn en(&self) -> &str {
        match self {
            Arg::Text(s) => s,
            Arg::Msg(p) => p.en,
            Arg::Said(s) => &s.english,
        }
    }
}

impl From<String> for Arg {
    fn from(s: String) -> Self {
        Arg::Text(s)
    }
}
impl From<&String> for Arg {
    fn from(s: &String) -> Self {
        Arg::Text(s.clone())
    }
}
impl From<&str> for Arg {
    fn from(s: &str) -> Self {
        Arg::Text(s.to_string())
    }
}
impl From<&&str> for Arg {
    fn from(s: &&str) -> Self {
        Arg::Text(s.to_string())
    }
}
impl From<Phrase> for Arg {
    fn from(p: Phrase) -> Self {
        Arg::Msg(p)
    }
}
macro_rules! arg_from_number {
    ($($t:ty),*) => {$(
        impl From<$t> for Arg {
            fn from(n: $t) -> Self {
                Arg::Text(n.to_string())
            }
        }
    )*};
}
arg_from_number!(u8, u16, u32, u64, usize, i8, i16, i32, i64, i128, u128, char, f64);

/// A diagnostic's message as data: the key and the named arguments.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    /// Which message.
    pub key: Msg,
    /// The arguments, by placeholder name (`name` fills `{name}`).
    pub args: Vec<(&'static str, Arg)>,
}

/// A message with its English text, as a diagnostic is made from it ([`msg!`](crate::msg)).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Said {
    /// The message as data.
    pub message: Message,
    /// Its English text.
    pub english: String,
}

impl Said {
    /// `key` with `args`, its English text made from `en` (the key's English template).
    /// One function for every message made (not inlined): a diagnostic's place in the code
    /// costs only its arguments' addresses.
    /// `names` and `args` go in pairs (a static list of names: a place costs one address
    /// per argument and one for the names).
    #[inline(never)]
    pub fn new(
        key: Msg,
        en: &'static str,
        names: &'static [&'static str],
        args: &[&dyn ToArg],
    ) -> Said {
        let args: Vec<(&'static str, Arg)> =
            names.iter().zip(args).map(|(n, a)| (*n, a.to_arg())).collect();
        let english = fill(en, |name| args.iter().find(|(n, _)| *n == name).map(|(_, a)| a.en()));
        Said { message: Message { key, args }, english }
    }
}

/// What a message's argument is made from ([`msg!`](crate::msg)): program text (a name, a
/// type, a number) or a phrase.
pub trait ToArg {
    /// The argument.
    fn to_arg(&self) -> Arg;
}
impl ToArg for str {
    fn to_arg(&self) -> Arg {
        Arg::Text(self.to_string())
    }
}
impl ToArg for String {
    fn to_arg(&self) -> Arg {
        Arg::Text(self.clone())
    }
}
impl ToArg for Phrase {
    fn to_arg(&self) -> Arg {
        Arg::Msg(*self)
    }
}
impl ToArg for Said {
    fn to_arg(&self) -> Arg {
        Arg::Said(Box::new(self.clone()))
    }
}
impl ToArg for Arg {
    fn to_arg(&self) -> Arg {
        self.clone()
    }
}
impl<T: ToArg + ?Sized> ToArg for &T {
    fn to_arg(&self) -> Arg {
        (**self).to_arg()
    }
}
macro_rules! to_arg_by_display {
    ($($t:ty),*) => {$(
        impl ToArg for $t {
            fn to_arg(&self) -> Arg {
                Arg::Text(self.to_string())
            }
        }
    )*};
}
to_arg_by_display!(u8, u16, u32, u64, usize, i8, i16, i32, i64, i128, u128, char, f64);

/// An English text the engine has not yet made data (key [`Msg::Text`]): shown as it is in
/// every language.
impl From<String> for Said {
    fn from(text: String) -> Said {
        Said {
            message: Message { key: Msg::Text, args: vec![("text", Arg::Text(text.clone()))] },
            english: text,
        }
    }
}
impl From<&str> for Said {
    fn from(text: &str) -> Said {
        Said::from(text.to_string())
    }
}

/// `template` with each `{name}` replaced by `arg(name)` (left as it is when there is none).
pub fn fill<'a>(template: &str, arg: impl Fn(&str) -> Option<&'a str>) -> String {
    let mut out = String::with_capacity(template.len() + 16);
    let mut rest = template;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        match after.find('}').map(|close| (&after[..close], close)) {
            Some((name, close)) if name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') => {
                match arg(name) {
                    Some(v) => out.push_str(v),
                    None => out.push_str(&rest[open..open + close + 2]),
                }
                rest = &after[close + 1..];
            }
            _ => {
                out.push('{');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// The `{name}` placeholders of `template`, sorted (a translation has the same).
pub fn placeholders(template: &str) -> Vec<&str> {
    let mut found: Vec<&str> = template
        .split('{')
        .skip(1)
        .filter_map(|part| part.split_once('}').map(|(name, _)| name))
        .collect();
    found.sort_unstable();
    found
}

/// The English catalogue, in the shape a translation has (key → template).
pub fn english_catalogue() -> BTreeMap<&'static str, &'static str> {
    Msg::ALL.iter().map(|m| (m.key(), m.en())).collect()
}

/// The catalogue file of a translation, as written (`core/i18n/messages.pl.json`).
pub fn catalogue_source(lang: Lang) -> Option<&'static str> {
    match lang {
        Lang::En => None,
        Lang::Pl => Some(include_str!("../../i18n/messages.pl.json")),
        Lang::Cs => Some(include_str!("../../i18n/messages.cs.json")),
    }
}

/// The templates of `lang` in [`Msg`] order; a template the translation lacks is English.
fn templates(lang: Lang) -> &'static [String] {
    static PL: OnceLock<Vec<String>> = OnceLock::new();
    static CS: OnceLock<Vec<String>> = OnceLock::new();
    let cell = match lang {
        Lang::Cs => &CS,
        _ => &PL,
    };
    cell.get_or_init(|| {
        let read: BTreeMap<String, String> =
            catalogue_source(lang).and_then(|s| serde_json::from_str(s).ok()).unwrap_or_default();
        Msg::ALL
            .iter()
            .map(|m| {
                read.get(m.key())
                    .filter(|t| !t.trim().is_empty())
                    .cloned()
                    .unwrap_or_else(|| m.en().to_string())
            })
            .collect()
    })
}

impl Msg {
    /// The template in `lang` (English when the translation lacks it).
    pub fn template(self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.en(),
            _ => templates(lang).get(self as usize).map_or(self.en(), String::as_str),
        }
    }
}

impl Message {
    /// An English text that is not data yet ([`Msg::Text`]), shown as it is in every language.
    pub fn text(text: String) -> Message {
        Message { key: Msg::Text, args: vec![("text", Arg::Text(text))] }
    }

    /// The message in `lang`.
    pub fn render(&self, lang: Lang) -> String {
        self.render_from(|m| Some(m.template(lang))).unwrap_or_default()
    }

    /// The message with each template from `template` (the page's fetched translation);
    /// `None` when it has none for the message itself. A phrase argument it lacks stays
    /// English; program text is put in as it is.
    pub fn render_from<'a>(&self, template: impl Fn(Msg) -> Option<&'a str>) -> Option<String> {
        self.render_by(&template)
    }

    fn render_by<'a>(&self, template: &dyn Fn(Msg) -> Option<&'a str>) -> Option<String> {
        let own = template(self.key)?;
        let nested: Vec<Option<String>> = self
            .args
            .iter()
            .map(|(_, a)| match a {
                Arg::Said(s) => {
                    Some(s.message.render_by(template).unwrap_or_else(|| s.english.clone()))
                }
                _ => None,
            })
            .collect();
        Some(fill(own, |name| {
            let i = self.args.iter().position(|(n, _)| *n == name)?;
            Some(match &self.args[i].1 {
                Arg::Text(s) => s.as_str(),
                Arg::Msg(p) => template(p.key).unwrap_or(p.en),
                Arg::Said(_) => nested[i].as_deref().unwrap_or_default(),
            })
        }))
    }
}

/// A diagnostic's message from its key and named arguments, with its English text:
/// `msg!(UndeclaredName, name = &id.name)`; a phrase argument is `phrase!(ExpectTypeName)`.
#[macro_export]
macro_rules! msg {
    ($key:ident $(, $name:ident = $val:expr)* $(,)?) => {
        $crate::diagnostics::Said::new(
            $crate::diagnostics::Msg::$key,
            $crate::diagnostics::msg_en!($key),
            &[$( stringify!($name) ),*],
            &[$( &$val as &dyn $crate::diagnostics::ToArg ),*],
        )
    };
}

/// A translated phrase used as a message's argument: `phrase!(ExpectTypeName)`.
#[macro_export]
macro_rules! phrase {
    ($key:ident) => {
        $crate::diagnostics::Phrase {
            key: $crate::diagnostics::Msg::$key,
            en: $crate::diagnostics::msg_en!($key),
        }
    };
}

/// The argument in English (for a message still made with `format!`).
impl std::fmt::Display for Arg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.en())
    }
}
