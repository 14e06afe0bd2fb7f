//! The problem codes' titles and explanations in Polish and Czech.
//!
//! English lives in the code tables (`codes.rs`, `explain.rs`); [`ProblemTexts::english`]
//! gathers it into the shape a translation has, and `plc explain --json` prints it as
//! `core/i18n/problems.en.json`, the file a translator starts from. The translations are
//! `core/i18n/problems.pl.json` and `problems.cs.json`, in the same shape. A test checks
//! that every code is translated in every language, with the program text between
//! backticks unchanged; a text a translation lacks falls back to English.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

use super::explain::{Example, PAGE_INTRO};
use super::Code;
use crate::i18n::Lang;

/// The words of the problem pages around the codes.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct PageWords {
    /// The page's heading: `Problem codes`.
    pub title: String,
    /// The paragraph under the heading.
    pub intro: String,
    /// The label of the example that gives the code: `Wrong`.
    pub wrong: String,
    /// The label of the example that avoids it: `Right`.
    pub right: String,
    /// The name of the links to the page in the other languages: `Language`.
    pub language: String,
}

/// One code's texts.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct CodeTexts {
    /// The one-line title.
    pub title: String,
    /// What the code means and how to fix it.
    pub text: String,
    /// The wrong example, when it is a described drawing (an ST example is program text
    /// and is never translated).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wrong: Option<String>,
    /// The right example, when it is a described drawing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub right: Option<String>,
}

/// The texts of the problem pages in one language: the page's words and every code's texts,
/// by code (`E0150`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ProblemTexts {
    /// The words around the codes.
    pub page: PageWords,
    /// Every code's texts.
    pub codes: BTreeMap<String, CodeTexts>,
}

impl ProblemTexts {
    /// The English texts, from the code tables.
    pub fn english() -> ProblemTexts {
        let drawn = |e: &Example| match e {
            Example::Drawn(t) => Some(t.to_string()),
            Example::St { .. } => None,
        };
        let codes = Code::all()
            .iter()
            .map(|c| {
                let e = c.explanation();
                let texts = CodeTexts {
                    title: c.title().to_string(),
                    text: e.map(|e| e.text.to_string()).unwrap_or_default(),
                    wrong: e.and_then(|e| drawn(&e.wrong)),
                    right: e.and_then(|e| drawn(&e.right)),
                };
                (c.as_str().to_string(), texts)
            })
            .collect();
        ProblemTexts {
            page: PageWords {
                title: "Problem codes".into(),
                intro: PAGE_INTRO.into(),
                wrong: "Wrong".into(),
                right: "Right".into(),
                language: "Language".into(),
            },
            codes,
        }
    }

    /// The texts in `lang`: its translation, with English for anything it lacks (or all
    /// English if its file cannot be read, which a test rules out).
    pub fn of(lang: Lang) -> &'static ProblemTexts {
        static EN: OnceLock<ProblemTexts> = OnceLock::new();
        static PL: OnceLock<ProblemTexts> = OnceLock::new();
        static CS: OnceLock<ProblemTexts> = OnceLock::new();
        let english = || EN.get_or_init(ProblemTexts::english);
        match lang {
            Lang::En => english(),
            Lang::Pl => PL.get_or_init(|| translated(TRANSLATIONS[0], english())),
            Lang::Cs => CS.get_or_init(|| translated(TRANSLATIONS[1], english())),
        }
    }

    /// The texts of `code`.
    pub fn code(&self, code: Code) -> Option<&CodeTexts> {
        self.codes.get(code.as_str())
    }

    /// These texts as the pretty JSON of a translation file.
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).unwrap_or_default();
        s.push('\n');
        s
    }
}

/// The translation files, Polish then Czech.
pub const TRANSLATIONS: [&str; 2] =
    [include_str!("../../i18n/problems.pl.json"), include_str!("../../i18n/problems.cs.json")];

/// A translation file read, or why it cannot be.
pub fn parse_translation(json: &str) -> Result<ProblemTexts, String> {
    serde_json::from_str(json).map_err(|e| format!("line {}, column {}: {e}", e.line(), e.column()))
}

/// `json`'s texts over `english`: a code or a drawn example the file lacks stays English.
fn translated(json: &str, english: &ProblemTexts) -> ProblemTexts {
    let Ok(mut t) = parse_translation(json) else { return english.clone() };
    let page = &english.page;
    for (word, en) in [
        (&mut t.page.title, &page.title),
        (&mut t.page.intro, &page.intro),
        (&mut t.page.wrong, &page.wrong),
        (&mut t.page.right, &page.right),
        (&mut t.page.language, &page.language),
    ] {
        if word.trim().is_empty() {
            *word = en.clone();
        }
    }
    for (code, en) in &english.codes {
        let entry = t.codes.entry(code.clone()).or_insert_with(|| en.clone());
        if entry.wrong.is_none() {
            entry.wrong = en.wrong.clone();
        }
        if entry.right.is_none() {
            entry.right = en.right.clone();
        }
    }
    t.codes.retain(|code, _| english.codes.contains_key(code));
    t
}
