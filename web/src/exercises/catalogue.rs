//! The exercise catalogue: every shipped exercise with its level and languages, filtered
//! by level and language, with a tick for each one passed in this browser.

use leptos::ev;
use leptos::prelude::*;

use super::{catalogue, language_name, Exercises, Screen};
use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// A level's name for the filter.
fn level_name(level: u8) -> String {
    match level {
        1 => t(K::exercise_level_beginner).into(),
        5 => t(K::exercise_level_advanced).into(),
        n => n.to_string(),
    }
}

/// An exercise's title in `lang` (the app draws the catalogue again when the language
/// changes).
fn title_in(id: &str, english: &'static str, lang: plc_core::i18n::Lang) -> &'static str {
    let titles = super::list::TITLES.iter().find(|t| t.0 == id);
    match (lang, titles) {
        (plc_core::i18n::Lang::Pl, Some(t)) => t.1,
        (plc_core::i18n::Lang::Cs, Some(t)) => t.2,
        _ => english,
    }
}

/// The catalogue, in place of the workspace.
#[component]
pub fn Catalogue() -> impl IntoView {
    let state = expect_context::<AppState>();
    let ex = expect_context::<Exercises>();
    // The ticks as kept (another tab may have passed one meanwhile).
    ex.passed.set(super::store::passed());
    let lang = expect_context::<crate::i18n::I18n>().shown.get_untracked();
    let level = RwSignal::new(0u8);
    let language = RwSignal::new(String::new());
    let all = catalogue();
    let total = all.len();
    let languages: Vec<&'static str> = {
        let mut v: Vec<&'static str> = Vec::new();
        for code in ["st", "ld", "petri", "sfc"] {
            if all.iter().any(|e| e.languages.contains(&code)) {
                v.push(code);
            }
        }
        v
    };
    let shown = move || {
        let (level, language) = (level.get(), language.get());
        catalogue()
            .into_iter()
            .filter(|e| level == 0 || e.level == level)
            .filter(|e| language.is_empty() || e.languages.contains(&language.as_str()))
            .collect::<Vec<_>>()
    };
    let count = move || {
        let passed = ex.passed.with(|p| catalogue().iter().filter(|e| p.contains(e.id)).count());
        tf(
            K::exercise_catalogue_count,
            &[
                ("shown", &shown().len().to_string()),
                ("total", &total.to_string()),
                ("passed", &passed.to_string()),
            ],
        )
    };
    view! {
        <main class="catalogue" aria-labelledby="catalogue-title">
            <div class="catalogue-head">
                <h2 id="catalogue-title">{t(K::exercise_catalogue_title)}</h2>
                <label>{t(K::exercise_level)}" "
                    <select aria-label=t(K::exercise_level) on:change=move |e: ev::Event| level.set(event_target_value(&e).parse().unwrap_or(0))>
                        <option value="0">{t(K::exercise_all_levels)}</option>
                        {(1..=5u8).map(|n| view! { <option value=n.to_string()>{level_name(n)}</option> }).collect_view()}
                    </select>
                </label>
                <label>{t(K::exercise_language)}" "
                    <select aria-label=t(K::exercise_language) on:change=move |e: ev::Event| language.set(event_target_value(&e))>
                        <option value="">{t(K::exercise_all_languages)}</option>
                        {languages.into_iter().map(|code| view! { <option value=code>{language_name(code)}</option> }).collect_view()}
                    </select>
                </label>
                <span class="catalogue-count" aria-live="polite">{count}</span>
                <button on:click=move |_| ex.screen.set(Screen::Workspace)>{t(K::exercise_back_to_project)}</button>
            </div>
            <p class="catalogue-intro">{t(K::exercise_catalogue_intro)}</p>
            <ul class="catalogue-list" aria-label=t(K::exercise_list)>
                {move || {
                    let passed = ex.passed.get();
                    shown().into_iter().map(|e| {
                        let id = e.id;
                        let done = passed.contains(id);
                        let langs = e.languages.iter().map(|l| language_name(l)).collect::<Vec<_>>().join(", ");
                        view! {
                            <li class="catalogue-item" class:passed=done data-exercise=id>
                                <button class="catalogue-open" on:click=move |_| ex.open_shipped(state, id)>{title_in(id, e.title, lang)}</button>
                                {done.then(|| view! { <span class="tick" role="img" aria-label=t(K::exercise_passed) title=t(K::exercise_passed)>"✓"</span> })}
                                <span class="catalogue-level">{tf(K::exercise_level_n, &[("level", &e.level.to_string())])}</span>

                                <span class="catalogue-langs">{langs}</span>
                            </li>
                        }
                    }).collect_view()
                }}
            </ul>
        </main>
    }
}
