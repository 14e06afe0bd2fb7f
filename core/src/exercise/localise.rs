//! An exercise as a student reading Polish or Czech sees it ([`Exercise::localised`]) and
//! the checks of its translations ([`Exercise::untranslated`]): the `[lang.*]` tables of
//! [`super::translation`] applied to the file's [`Exercise`].

use super::format::Exercise;
use super::translation::Translation;
use crate::i18n::{code_spans, Lang};

impl Exercise {
    /// The translation into `lang`, if the file has one (never for English).
    pub fn translation(&self, lang: Lang) -> Option<&Translation> {
        self.lang.get(lang.tag())
    }

    /// The exercise as a student reading `lang` sees it: its title, statement, interface
    /// meanings, scenario names and hints in that language where the file translates
    /// them, in English where it does not. Everything graded (names, steps,
    /// expectations) is the same.
    pub fn localised(&self, lang: Lang) -> Exercise {
        let mut e = self.clone();
        let Some(t) = self.translation(lang) else { return e };
        if let Some(statement) = &t.statement {
            e.statement = statement.clone();
        }
        // Hints first: they are found by the scenario's English name.
        for s in &mut e.scenarios {
            if let Some(hint) = t.scenario.get(&s.name).and_then(|st| st.hint.as_ref()) {
                s.hint = Some(hint.clone());
            }
        }
        t.put_names(
            &mut e.title,
            e.interface.iter_mut().map(|v| (v.name.as_str(), &mut v.meaning)),
            e.scenarios.iter_mut().map(|s| &mut s.name),
        );
        e
    }

    /// The exercise with its statements rendered (relative links against `base`): the
    /// English one returned, each translation's put in its `statement_html`, as a page
    /// shows them.
    pub fn rendered(mut self, base: Option<&str>) -> (Exercise, String) {
        for t in self.lang.values_mut() {
            if let Some(s) = &t.statement {
                t.statement_html = Some(super::statement_html(s, base));
            }
        }
        let html = super::statement_html(&self.statement, base);
        (self, html)
    }

    /// What is wrong in the translations, each located (`lang.pl.meaning: …`): a meaning
    /// of a variable the interface does not have, a scenario the exercise does not have,
    /// a text whose program text (between backticks) differs from the English.
    pub fn translation_problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (key, t) in &self.lang {
            let names: Vec<&str> = self.interface.iter().map(|v| v.name.as_str()).collect();
            for (name, meaning) in &t.meaning {
                match self.interface.iter().find(|v| &v.name == name) {
                    None => out.push(format!(
                        "lang.{key}.meaning: “{name}” is not a variable of the interface ({}): a translation keeps the English names",
                        names.join(", ")
                    )),
                    Some(v) => program_text(
                        &format!("lang.{key}.meaning.{name}"),
                        &v.meaning,
                        meaning,
                        &mut out,
                    ),
                }
            }
            for (name, st) in &t.scenario {
                let place = format!("lang.{key}.scenario.“{name}”");
                match self.scenarios.iter().find(|s| &s.name == name) {
                    None => {
                        let names: Vec<String> =
                            self.scenarios.iter().map(|s| format!("“{}”", s.name)).collect();
                        out.push(format!(
                            "{place}: there is no scenario of that name ({}): a translation is keyed by the English name",
                            names.join(", ")
                        ));
                    }
                    Some(s) => {
                        if let Some(n) = &st.name {
                            program_text(&format!("{place}.name"), &s.name, n, &mut out);
                        }
                        if let Some(h) = &st.hint {
                            let en = s.hint.as_deref().unwrap_or_default();
                            program_text(&format!("{place}.hint"), en, h, &mut out);
                        }
                    }
                }
            }
            if let Some(title) = &t.title {
                program_text(&format!("lang.{key}.title"), &self.title, title, &mut out);
            }
            if let Some(statement) = &t.statement {
                program_text(
                    &format!("lang.{key}.statement"),
                    &self.statement,
                    statement,
                    &mut out,
                );
            }
        }
        out
    }

    /// What a translation into `lang` leaves in English (`title`, `meaning.Start`,
    /// `scenario.“Start”.hint` …): empty when it is complete.
    pub fn untranslated(&self, lang: Lang) -> Vec<String> {
        let empty = Translation::default();
        let t = self.translation(lang).unwrap_or(&empty);
        let mut out = Vec::new();
        let given = |s: &Option<String>| s.as_deref().is_some_and(|s| !s.trim().is_empty());
        if !given(&t.title) {
            out.push("title".to_string());
        }
        if !self.statement.trim().is_empty() && !given(&t.statement) && t.statement_html.is_none() {
            out.push("statement".to_string());
        }
        for v in self.interface.iter().filter(|v| !v.meaning.trim().is_empty()) {
            if t.meaning.get(&v.name).is_none_or(|m| m.trim().is_empty()) {
                out.push(format!("meaning.{}", v.name));
            }
        }
        for s in &self.scenarios {
            let st = t.scenario.get(&s.name);
            if st.is_none_or(|st| !given(&st.name)) {
                out.push(format!("scenario.“{}”.name", s.name));
            }
            if s.hint.is_some() && st.is_none_or(|st| !given(&st.hint)) {
                out.push(format!("scenario.“{}”.hint", s.name));
            }
        }
        out
    }
}

/// A problem when `translated` does not carry the program text of `en` (the spans between
/// backticks, in any order: a sentence may put them elsewhere, never change them).
fn program_text(place: &str, en: &str, translated: &str, out: &mut Vec<String>) {
    let mut a = code_spans(en);
    let mut b = code_spans(translated);
    a.sort_unstable();
    b.sort_unstable();
    if a != b {
        let missing: Vec<&str> = a.iter().filter(|s| !b.contains(s)).copied().collect();
        let added: Vec<&str> = b.iter().filter(|s| !a.contains(s)).copied().collect();
        let mut what = Vec::new();
        if !missing.is_empty() {
            what.push(format!("English has {}", spans(&missing)));
        }
        if !added.is_empty() {
            what.push(format!("the translation has {}", spans(&added)));
        }
        if what.is_empty() {
            what.push(format!("English has {} spans, the translation {}", a.len(), b.len()));
        }
        out.push(format!(
            "{place}: the program text between backticks differs from English: {}",
            what.join(", ")
        ));
    }
}

fn spans(list: &[&str]) -> String {
    list.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>().join(", ")
}
