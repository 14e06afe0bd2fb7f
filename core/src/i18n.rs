//! The languages the trainer speaks and what every translation keeps from English.
//!
//! English is the source of every text; Polish and Czech translations live in files a
//! translator edits (`core/i18n/*.pl.json`, `*.cs.json`), following the terms of
//! `docs/i18n-glossary.md`. Program text is never translated: whatever stands between
//! backticks in English (keywords, literals such as `T#1s`, identifiers, values) stands
//! unchanged between backticks in every translation, and [`code_spans`] lets a test say so.

use std::fmt;
use std::str::FromStr;

/// A language of the page, the CLI and the exercises.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub enum Lang {
    /// English, the source language and the fallback.
    #[default]
    En,
    /// Polish.
    Pl,
    /// Czech.
    Cs,
}

impl Lang {
    /// Every language, English first.
    pub const ALL: [Lang; 3] = [Lang::En, Lang::Pl, Lang::Cs];

    /// The BCP 47 tag: `en`, `pl`, `cs` (what `<html lang>` and `?lang=` take).
    pub fn tag(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Pl => "pl",
            Lang::Cs => "cs",
        }
    }

    /// The language's own name, as a language menu shows it.
    pub fn native_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Pl => "Polski",
            Lang::Cs => "Čeština",
        }
    }

    /// The language of a BCP 47 tag such as `pl-PL` or `cs`; `None` for one not spoken here.
    pub fn from_tag(tag: &str) -> Option<Lang> {
        let primary = tag.split(['-', '_']).next().unwrap_or_default().to_ascii_lowercase();
        Lang::ALL.into_iter().find(|l| l.tag() == primary)
    }
}

impl fmt::Display for Lang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.tag())
    }
}

/// A language tag that is not `en`, `pl` or `cs`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownLang(pub String);

impl fmt::Display for UnknownLang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown language `{}` (expected en, pl or cs)", self.0)
    }
}

impl std::error::Error for UnknownLang {}

impl FromStr for Lang {
    type Err = UnknownLang;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Lang::from_tag(s).ok_or_else(|| UnknownLang(s.to_string()))
    }
}

/// The spans of a text between backticks, in order: the program text a translation keeps
/// exactly as it is.
pub fn code_spans(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_name_languages_whatever_their_region() {
        assert_eq!(Lang::from_tag("pl-PL"), Some(Lang::Pl));
        assert_eq!(Lang::from_tag("CS_cz"), Some(Lang::Cs));
        assert_eq!(Lang::from_tag("en-GB"), Some(Lang::En));
        assert_eq!(Lang::from_tag("de"), None);
        assert_eq!("cs".parse::<Lang>(), Ok(Lang::Cs));
        assert!("fr".parse::<Lang>().is_err());
    }

    #[test]
    fn code_spans_are_the_text_between_backticks() {
        assert_eq!(code_spans("a `T#1s` b `x := 1;` c"), vec!["T#1s", "x := 1;"]);
        assert!(code_spans("no code").is_empty());
    }
}
