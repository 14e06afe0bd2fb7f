//! What a page shows of an exercise: its title, level, languages, the statement as HTML,
//! the interface and the scenarios' names and weights — never the scenarios' steps and
//! expectations, which the grader keeps.

use serde::{Deserialize, Serialize};

use std::collections::BTreeMap;

use super::format::{Exercise, InterfaceVar};
use super::grade::Report;
use super::translation::Translation;
use crate::i18n::Lang;

/// An exercise as the page shows it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExerciseView {
    /// Its id (`latch`).
    pub id: String,
    /// Its title.
    pub title: String,
    /// 1 (beginner) … 5 (advanced).
    pub level: u8,
    /// The languages a solution may use (`st`, `ld`, `petri`, `sfc`).
    pub languages: Vec<String>,
    /// The statement, rendered (see [`crate::exercise::statement_html`]).
    pub statement_html: String,
    /// The variables the solution declares.
    pub interface: Vec<InterfaceVar>,
    /// Each scenario's name and weight, in order.
    pub scenarios: Vec<ScenarioView>,
    /// The PROGRAM the exercise names as the one it grades, if it names one.
    #[serde(default)]
    pub program: Option<String>,
    /// The name of the exercise's plant PROGRAM, if it has one (never the one graded).
    #[serde(default)]
    pub plant: Option<String>,
    /// The exercise's translations by language tag (`pl`, `cs`), each statement rendered
    /// (`statement_html`) and never as Markdown: [`ExerciseView::localised`] picks one.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub translations: BTreeMap<String, Translation>,
}

/// A scenario as the page lists it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ScenarioView {
    /// Its name.
    pub name: String,
    /// Its weight.
    pub weight: u32,
    /// Whether it runs random input histories.
    pub random: bool,
}

impl ExerciseView {
    /// The view of `exercise`; relative links in its statement are resolved against
    /// `base`, the exercise file's address.
    pub fn of(exercise: &Exercise, base: Option<&str>) -> ExerciseView {
        let (rendered, html) = exercise.clone().rendered(base);
        ExerciseView::with_statement(&rendered, html)
    }

    /// The view of `exercise` with its statement already rendered (the built form).
    pub fn with_statement(exercise: &Exercise, statement_html: String) -> ExerciseView {
        ExerciseView {
            id: exercise.id.clone(),
            title: exercise.title.clone(),
            level: exercise.level,
            languages: exercise.languages.clone(),
            statement_html,
            interface: exercise.interface.clone(),
            scenarios: exercise
                .scenarios
                .iter()
                .map(|s| ScenarioView {
                    name: s.name.clone(),
                    weight: s.weight,
                    random: s.random.is_some(),
                })
                .collect(),
            program: exercise.program.clone(),
            plant: exercise.plant.as_ref().map(|p| p.name.clone()),
            translations: exercise
                .lang
                .iter()
                .map(|(k, t)| (k.clone(), Translation { statement: None, ..t.clone() }))
                .collect(),
        }
    }

    /// The title in `lang` (English where the exercise has no translation of it).
    pub fn title_in(&self, lang: Lang) -> &str {
        self.translations.get(lang.tag()).and_then(|t| t.title.as_deref()).unwrap_or(&self.title)
    }

    /// The view in `lang`: title, statement, meanings and scenario names translated where
    /// the exercise translates them, English where it does not.
    pub fn localised(&self, lang: Lang) -> ExerciseView {
        let mut v = self.clone();
        let Some(t) = self.translations.get(lang.tag()) else { return v };
        if let Some(html) = &t.statement_html {
            v.statement_html = html.clone();
        }
        t.put_names(
            &mut v.title,
            v.interface.iter_mut().map(|i| (i.name.as_str(), &mut i.meaning)),
            v.scenarios.iter_mut().map(|s| &mut s.name),
        );
        v
    }

    /// A report of this exercise with its scenario names and hints in `lang` where the
    /// exercise translates them (a report names scenarios in English).
    pub fn localised_report(&self, lang: Lang, mut report: Report) -> Report {
        let Some(t) = self.translations.get(lang.tag()) else { return report };
        for s in &mut report.scenarios {
            if let Some(st) = t.scenario.get(&s.name) {
                if let (Some(hint), Some(_)) = (&st.hint, &s.hint) {
                    s.hint = Some(hint.clone());
                }
                if let Some(name) = &st.name {
                    s.name = name.clone();
                }
            }
        }
        report
    }
}

impl Exercise {
    /// A program that declares the interface and does nothing else: the Structured Text
    /// starter when the exercise names none.
    pub fn blank_program(&self) -> String {
        self.generated_starter(super::Language::St, &self.program_name(None)).source
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::project::Project;

    const FILE: &str = r#"
id = "lamp"
title = "Lamp"
level = 1
statement = "Light `Lamp` while **Start** is held."

[[interface]]
name = "Start"
type = "BOOL"
direction = "input"
meaning = "a button (NO)"

[[interface]]
name = "Lamp"
type = "BOOL"
direction = "output"

[[scenario]]
name = "Follows"
weight = 3
step = [ { at = "0s", set = { Start = true } } ]
expect = [ { that = "Lamp", at = "20ms" } ]
"#;

    #[test]
    fn the_view_has_the_statement_as_html_and_no_expectations() {
        let e = Exercise::from_toml(FILE).unwrap();
        let v = ExerciseView::of(&e, None);
        assert!(v.statement_html.contains("<code>Lamp</code>"));
        assert_eq!(
            v.scenarios,
            vec![ScenarioView { name: "Follows".into(), weight: 3, random: false }]
        );
        let json = serde_json::to_string(&v).unwrap();
        assert!(!json.contains("20ms"), "{json}");
        let back: ExerciseView = serde_json::from_str(&json).unwrap();
        assert_eq!(back, v);
    }

    #[test]
    fn the_blank_program_declares_the_interface_and_fails() {
        let e = Exercise::from_toml(FILE).unwrap();
        let text = e.blank_program();
        assert!(
            text.contains("VAR_INPUT\n    Start : BOOL; (* a button (NO) *)\nEND_VAR"),
            "{text}"
        );
        let mut p = Project::new("attempt");
        p.source = text;
        let report = super::super::grade(&e, &p).unwrap();
        assert_eq!((report.error, report.score, report.total), (None, 0, 3));
    }
}
