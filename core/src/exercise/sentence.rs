//! A sentence of a grading report as data (issue 33): the report keeps its English text
//! (`expected`, `actual`, `error`, as before) and beside it the sentence's [`Message`], so
//! the page shows it in the language shown and the command line in the one asked for. A
//! sentence made of other sentences (a FAULT's own message, the place, a build error's
//! message) names them as its parts: each is rendered first and put in for its argument.

use std::sync::Mutex;

use serde::{Deserialize, Serialize};

use crate::diagnostics::{Arg, Message, Msg, Phrase, Said};
use crate::i18n::Lang;

/// A report's sentence: a message and the sentences some of its arguments are made of.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "Data", into = "Data")]
pub struct Sentence {
    /// The message; an argument that is a part holds the part's English text.
    pub message: Message,
    /// `(argument, sentence)`: the argument shown as that sentence in the language asked.
    pub parts: Vec<(&'static str, Sentence)>,
}

impl From<Message> for Sentence {
    fn from(message: Message) -> Self {
        Sentence { message, parts: Vec::new() }
    }
}

impl From<Said> for Sentence {
    fn from(said: Said) -> Self {
        Sentence::from(said.message)
    }
}

impl Sentence {
    /// The sentence with its argument `name` shown as `part`.
    pub fn with(mut self, name: &'static str, part: impl Into<Sentence>) -> Self {
        self.parts.push((name, part.into()));
        self
    }

    /// The sentence with each template from `template` (`None` when it lacks the
    /// sentence's own message; a part it lacks stays as its English text).
    pub fn render_by<'a>(&self, template: &dyn Fn(Msg) -> Option<&'a str>) -> Option<String> {
        let mut message = self.message.clone();
        for (name, part) in &self.parts {
            if let Some(text) = part.render_by(template) {
                if let Some(arg) = message.args.iter_mut().find(|(n, _)| n == name) {
                    arg.1 = Arg::Text(text);
                }
            }
        }
        message.render_from(template)
    }

    /// The sentence in `lang`.
    pub fn render(&self, lang: Lang) -> String {
        self.render_by(&|m| Some(m.template(lang))).unwrap_or_default()
    }
}

/// A sentence as JSON: the message by its place in [`Msg`] order (the worker and the page
/// are one build), its arguments and its parts.
#[derive(Serialize, Deserialize)]
struct Data {
    key: usize,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    args: Vec<(String, Value)>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    parts: Vec<(String, Sentence)>,
}

/// An argument as JSON: program text, or a phrase by its place in [`Msg`] order.
#[derive(Serialize, Deserialize)]
enum Value {
    #[serde(rename = "text")]
    Text(String),
    #[serde(rename = "phrase")]
    Phrase(usize),
}

impl From<Sentence> for Data {
    fn from(s: Sentence) -> Self {
        let mut parts: Vec<(String, Sentence)> =
            s.parts.into_iter().map(|(n, p)| (n.to_string(), p)).collect();
        let args = s
            .message
            .args
            .into_iter()
            .map(|(n, a)| {
                let value = match a {
                    Arg::Text(t) => Value::Text(t),
                    Arg::Msg(p) => Value::Phrase(p.key.index()),
                    // A message inside the message: its English as the argument, the
                    // message itself as a part (rendered first, in the language asked).
                    Arg::Said(said) => {
                        let english = said.english.clone();
                        parts.push((n.to_string(), Sentence::from(*said)));
                        Value::Text(english)
                    }
                };
                (n.to_string(), value)
            })
            .collect();
        Data { key: s.message.key.index(), args, parts }
    }
}

/// The message at `index` in [`Msg`] order.
fn msg_at(index: usize) -> Result<Msg, String> {
    Msg::ALL.get(index).copied().ok_or_else(|| format!("no message {index}"))
}

/// An argument's name as the message keeps it (`&'static`): the names are few (a
/// template's placeholders), each kept once.
fn name(n: String) -> &'static str {
    static NAMES: Mutex<Vec<&'static str>> = Mutex::new(Vec::new());
    let Ok(mut names) = NAMES.lock() else { return "" };
    if let Some(found) = names.iter().find(|k| **k == n) {
        return found;
    }
    let kept: &'static str = Box::leak(n.into_boxed_str());
    names.push(kept);
    kept
}

impl TryFrom<Data> for Sentence {
    type Error = String;

    fn try_from(d: Data) -> Result<Self, String> {
        let mut args = Vec::with_capacity(d.args.len());
        for (n, v) in d.args {
            let arg = match v {
                Value::Text(t) => Arg::Text(t),
                // The page renders a phrase from its own catalogue; English is the report's.
                Value::Phrase(i) => Arg::Msg(Phrase { key: msg_at(i)?, en: "" }),
            };
            args.push((name(n), arg));
        }
        Ok(Sentence {
            message: Message { key: msg_at(d.key)?, args },
            parts: d.parts.into_iter().map(|(n, p)| (name(n), p)).collect(),
        })
    }
}
