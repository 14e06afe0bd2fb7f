//! The colour theme (issue 34): `System` follows the browser's `prefers-color-scheme`,
//! `Light` and `Dark` override it. The choice is kept in local storage and applied at once
//! as `data-theme` on the root element; the colours themselves are CSS custom properties
//! (public/style.css: `:root` for light, `[data-theme=dark]` and the dark media query).

use leptos::ev;
use leptos::prelude::*;
use plc_core::project::StorageBackend;

use crate::i18n::{t, K};
use crate::storage::LocalStorage;

/// Where the choice is kept (absent: `System`).
const THEME_KEY: &str = "plc-trainer/v1/theme";

/// A theme the user can pick.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Theme {
    System,
    Light,
    Dark,
}

impl Theme {
    const ALL: [Theme; 3] = [Theme::System, Theme::Light, Theme::Dark];

    /// The stored and the option's value.
    fn value(self) -> &'static str {
        match self {
            Theme::System => "system",
            Theme::Light => "light",
            Theme::Dark => "dark",
        }
    }

    /// The option's label.
    fn label(self) -> &'static str {
        match self {
            Theme::System => t(K::theme_system),
            Theme::Light => t(K::theme_light),
            Theme::Dark => t(K::theme_dark),
        }
    }

    /// Reads a stored or chosen value; anything unknown is `System`.
    fn parse(value: &str) -> Theme {
        Theme::ALL.into_iter().find(|t| t.value() == value).unwrap_or(Theme::System)
    }
}

/// The theme kept in local storage.
pub fn stored() -> Theme {
    LocalStorage::open().get(THEME_KEY).ok().flatten().map_or(Theme::System, |v| Theme::parse(&v))
}

/// Colours the page in `theme` (no reload: the CSS variables follow `data-theme`).
pub fn apply(theme: Theme) {
    let Some(root) =
        web_sys::window().and_then(|w| w.document()).and_then(|d| d.document_element())
    else {
        return;
    };
    let _ = match theme {
        Theme::System => root.remove_attribute("data-theme"),
        other => root.set_attribute("data-theme", other.value()),
    };
}

/// The header's `Theme` select.
#[component]
pub fn ThemeSwitch() -> impl IntoView {
    let theme = RwSignal::new(stored());
    let on_change = move |ev: ev::Event| {
        let chosen = Theme::parse(&event_target_value(&ev));
        theme.set(chosen);
        apply(chosen);
        let mut store = LocalStorage::open();
        // A browser without storage still switches, for this visit.
        let _ = match chosen {
            Theme::System => store.remove(THEME_KEY),
            other => store.set(THEME_KEY, other.value()),
        };
    };
    view! {
        <label class="theme-select" title=t(K::theme_title)>
            <span class="visually-hidden">{t(K::theme_theme)}</span>
            <select aria-label=t(K::theme_theme) on:change=on_change prop:value=move || theme.get().value()>
                {Theme::ALL.into_iter().map(|t| view! {
                    <option value=t.value() selected=move || theme.get() == t>{t.label()}</option>
                }).collect_view()}
            </select>
        </label>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_and_unknown_is_system() {
        for t in Theme::ALL {
            assert_eq!(Theme::parse(t.value()), t);
        }
        assert_eq!(Theme::parse(""), Theme::System);
        assert_eq!(Theme::parse("solarized"), Theme::System);
        assert_eq!(Theme::ALL.map(Theme::label), ["System", "Light", "Dark"]);
    }
}
