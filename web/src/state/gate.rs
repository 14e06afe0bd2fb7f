//! Whether Run, Step and Step N may start, and what the page says when the simulator holds
//! an older build than the text on the screen (the project has errors since). Nothing runs
//! an old build without the user choosing it.

use leptos::prelude::*;

use super::{plural, AppState, Notice, NoticeAction, RunMode};
use crate::i18n::{t, tf, K};

/// What a press of Run, Step or Step N does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Gate {
    /// Scan the simulator: it holds the project on the screen, or the user chose to run
    /// the last version that built.
    Go,
    /// The project has no PROGRAM to run (and no errors).
    NoProgram,
    /// The project has `errors` errors: say so instead of scanning. `offer_old`: a version
    /// built before, which the user may choose to run.
    Refuse {
        /// How many errors to fix.
        errors: usize,
        /// Whether an older build can run.
        offer_old: bool,
    },
}

/// The decision: `errors` in the project now, whether a simulator is loaded (the last
/// build that succeeded), whether the user chose to run it anyway.
pub fn gate(errors: usize, has_sim: bool, old_chosen: bool) -> Gate {
    match (errors, has_sim) {
        (0, true) => Gate::Go,
        (0, false) => Gate::NoProgram,
        (_, true) if old_chosen => Gate::Go,
        (errors, has_sim) => Gate::Refuse { errors, offer_old: has_sim },
    }
}

/// The forms of `Fix N errors to run your changes`.
const FIX: [K; 3] = [K::state_fix_one, K::state_fix_few, K::state_fix_many];

/// `Fix 1 error to run your changes` / `Fix 3 errors to run your changes`.
pub fn fix_text(errors: usize) -> String {
    let n = errors as u64;
    tf(plural(n, FIX[0], FIX[1], FIX[2]), &[("errors", &n.to_string())])
}

/// The status line under the controls when the simulator holds an older build than the
/// text on the screen (`None` when it holds the text on the screen, or nothing).
pub fn version_text(stale: bool, mode: RunMode) -> Option<&'static str> {
    if !stale {
        return None;
    }
    Some(match mode {
        RunMode::Running => t(K::state_running_old),
        RunMode::Paused | RunMode::Stopped => t(K::state_holding_old),
    })
}

impl AppState {
    /// The errors of the last check. (The exercise grader builds the project file itself,
    /// so `Check` never grades an older build; `stale` says when the simulator does.)
    pub fn error_count(&self) -> usize {
        self.diagnostics.with_untracked(|ds| ds.iter().filter(|d| d.error).count())
    }

    /// Checks now when an edit has not been checked yet (the editors check a moment after
    /// an edit; Run must not act on the text before that). Only then: a check powers a
    /// fresh simulator on.
    pub fn check_if_pending(&self) {
        if self.check_pending.get_value() {
            self.check_now();
        }
    }

    /// Decides whether Run, Step or Step N may scan; when not, says why in the banner
    /// (with a link to the first problem and, when a version built before, the choice to
    /// run that one).
    pub(super) fn may_scan(&self) -> bool {
        self.check_if_pending();
        let has_sim = self.sim.with_value(Option::is_some);
        match gate(self.error_count(), has_sim, self.run_old.get_untracked()) {
            Gate::Go => {
                self.clear_refusal();
                true
            }
            Gate::NoProgram => {
                self.error(t(K::state_no_program));
                false
            }
            Gate::Refuse { errors, offer_old } => {
                let site = self
                    .diagnostics
                    .with_untracked(|ds| ds.iter().find(|d| d.error).map(|d| d.site.clone()));
                let actions = if offer_old { vec![NoticeAction::RunLastBuilt] } else { Vec::new() };
                self.notice.set(Some(Notice {
                    error: true,
                    text: format!("{}.", fix_text(errors)),
                    site,
                    actions,
                }));
                false
            }
        }
    }

    /// Takes a `Fix N errors…` message away (the project builds again, or runs).
    pub(super) fn clear_refusal(&self) {
        let shown = self.notice.with_untracked(|n| n.as_ref().is_some_and(is_refusal));
        if shown {
            self.notice.set(None);
        }
    }

    /// `Run the last version that built`: the user's explicit choice to run the build the
    /// simulator holds although the text on the screen has errors.
    pub fn run_last_built(&self) {
        self.run_old.set(true);
        self.run();
    }
}

/// Whether the banner shows a refusal to run (made by [`AppState::may_scan`]): one of the
/// forms of [`fix_text`] in the language shown, with its full stop.
fn is_refusal(n: &Notice) -> bool {
    n.error
        && FIX.iter().any(|k| match t(*k).split_once("{errors}") {
            Some((before, after)) => {
                n.text.starts_with(before)
                    && n.text.strip_suffix('.').is_some_and(|s| s.ends_with(after))
            }
            None => n.text.strip_suffix('.') == Some(t(*k)),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_clean_build_runs_and_errors_never_run_an_old_build_unasked() {
        assert_eq!(gate(0, true, false), Gate::Go);
        assert_eq!(gate(0, false, false), Gate::NoProgram);
        assert_eq!(gate(1, true, false), Gate::Refuse { errors: 1, offer_old: true });
        assert_eq!(gate(2, true, true), Gate::Go, "the user chose the old build");
        // A program that never built: only the message, nothing older to offer.
        assert_eq!(gate(3, false, false), Gate::Refuse { errors: 3, offer_old: false });
        assert_eq!(gate(3, false, true), Gate::Refuse { errors: 3, offer_old: false });
    }

    #[test]
    fn the_words_count_the_errors_and_name_the_version() {
        assert_eq!(fix_text(1), "Fix 1 error to run your changes");
        assert_eq!(fix_text(3), "Fix 3 errors to run your changes");
        assert_eq!(version_text(false, RunMode::Running), None);
        assert_eq!(
            version_text(true, RunMode::Running),
            Some("Running the last version that built (before your latest edits)")
        );
        assert!(version_text(true, RunMode::Paused).unwrap().contains("last version that built"));
    }
}
