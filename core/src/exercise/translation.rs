//! An exercise in Polish and Czech: the `[lang.pl]` and `[lang.cs]` tables of its file
//! (`docs/exercises.md`). English is the top-level fields and the fallback for whatever a
//! translation leaves out. Program text (identifiers, keywords, literals) is never
//! translated: the interface keeps its names, and the spans between backticks of a
//! translated text are the English ones ([`crate::i18n::code_spans`]).

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

use crate::i18n::Lang;

/// The languages an exercise is translated into (English is the file's own fields).
pub const TRANSLATED: [Lang; 2] = [Lang::Pl, Lang::Cs];

/// An exercise's texts in one language.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Translation {
    /// The title.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub title: Option<String>,
    /// The task, in Markdown.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub statement: Option<String>,
    /// The task rendered: only in the built form and in a page's view (never in a file).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub statement_html: Option<String>,
    /// Each interface variable's meaning, by the variable's name (`Start = "…"`).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub meaning: BTreeMap<String, String>,
    /// Each scenario's name and hint, by its English name (`[lang.pl.scenario."Start"]`).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub scenario: BTreeMap<String, ScenarioTranslation>,
}

/// A scenario's name and hint in one language.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioTranslation {
    /// The name the report shows.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The hint shown when it fails.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hint: Option<String>,
}

impl Translation {
    /// Puts this translation's title, interface meanings (each by its variable's name) and
    /// scenario names (each by its English name) over the English ones, where it has
    /// them: what every view of a translated exercise shares.
    pub fn put_names<'a>(
        &self,
        title: &mut String,
        meanings: impl Iterator<Item = (&'a str, &'a mut String)>,
        scenario_names: impl Iterator<Item = &'a mut String>,
    ) {
        if let Some(t) = &self.title {
            title.clone_from(t);
        }
        for (name, meaning) in meanings {
            if let Some(m) = self.meaning.get(name) {
                meaning.clone_from(m);
            }
        }
        for name in scenario_names {
            if let Some(n) = self.scenario.get(name.as_str()).and_then(|s| s.name.as_ref()) {
                name.clone_from(n);
            }
        }
    }
}
