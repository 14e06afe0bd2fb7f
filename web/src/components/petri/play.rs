//! Playing a net without the PLC: the token game (the student fires enabled transitions by
//! clicking them, guards ignored) and a deadlock's firing sequence from the analysis, both
//! stepped with `Previous` / `Next`. The marking shown is the initial one fired through the
//! first `step` transitions of the path.

use leptos::prelude::*;
use plc_core::petri::{Marking, PtNet};

use crate::i18n::{t, tf, K};

/// What is being played.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Play {
    /// Transitions fired from the initial marking, in order (indices into the net).
    pub path: Vec<usize>,
    /// How many of them are shown fired.
    pub step: usize,
    /// The token game (clicks fire) rather than a deadlock's path.
    pub game: bool,
}

impl Play {
    /// The marking after the first `step` firings (a transition that is not enabled there,
    /// after an edit, is skipped) and the transition fired last.
    pub fn marking(&self, net: &PtNet) -> (Marking, Option<usize>) {
        let mut m = net.initial.clone();
        let mut last = None;
        for &t in self.path.iter().take(self.step) {
            if t < net.transitions() && net.enabled(&m, t) {
                m = net.fire(&m, t);
                last = Some(t);
            }
        }
        (m, last)
    }

    /// Fires transition `t` after the shown step (what came after it is dropped), when it
    /// is enabled there.
    pub fn fire(&mut self, net: &PtNet, t: usize) -> bool {
        let (m, _) = self.marking(net);
        if t >= net.transitions() || !net.enabled(&m, t) {
            return false;
        }
        self.path.truncate(self.step);
        self.path.push(t);
        self.step += 1;
        true
    }
}

/// The controls of the token game and of a played path.
#[component]
pub fn PlayControls(play: RwSignal<Option<Play>>, net: Memo<Option<PtNet>>) -> impl IntoView {
    let game_on = move || play.with(|p| p.as_ref().is_some_and(|p| p.game));
    let toggle = move |_| {
        if game_on() {
            play.set(None);
        } else {
            play.set(Some(Play { game: true, ..Play::default() }));
        }
    };
    let at_start = move || play.with(|p| p.as_ref().is_none_or(|p| p.step == 0));
    let at_end = move || play.with(|p| p.as_ref().is_none_or(|p| p.step >= p.path.len()));
    let note = move || {
        play.with(|p| {
            let p = p.as_ref()?;
            let names = net
                .with(|n| {
                    n.as_ref().map(|n| {
                        p.path
                            .iter()
                            .take(p.step)
                            .filter_map(|&t| n.transition_names.get(t).cloned())
                            .collect::<Vec<_>>()
                    })
                })
                .unwrap_or_default();
            let fired = if names.is_empty() {
                String::new()
            } else {
                format!(" {}", tf(K::petri_play_fired, &[("names", &names.join(" → "))]))
            };
            Some(if p.game {
                tf(K::petri_token_game_note, &[("fired", &fired)])
            } else {
                tf(
                    K::petri_deadlock_path,
                    &[
                        ("step", &p.step.to_string()),
                        ("steps", &p.path.len().to_string()),
                        ("fired", &fired),
                    ],
                )
            })
        })
    };
    view! {
        <div class="pn-play" role="group" aria-label=t(K::petri_play)>
            <button aria-pressed=move || if game_on() { "true" } else { "false" } on:click=toggle
                title=t(K::petri_token_game_title)>{t(K::petri_token_game)}</button>
            {move || play.with(Option::is_some).then(|| view! {
                <button disabled=at_start on:click=move |_| play.update(|p| if let Some(p) = p { p.step = p.step.saturating_sub(1) })>{t(K::petri_previous)}</button>
                <button disabled=at_end on:click=move |_| play.update(|p| if let Some(p) = p { p.step = (p.step + 1).min(p.path.len()) })>{t(K::petri_next)}</button>
                {move || if game_on() {
                    view! { <button on:click=move |_| play.set(Some(Play { game: true, ..Play::default() }))>{t(K::petri_reset_marking)}</button> }.into_any()
                } else {
                    view! { <button on:click=move |_| play.set(None)>{t(K::petri_stop_playing)}</button> }.into_any()
                }}
                <span class="muted small-text pn-play-note" role="status" title=note>{note}</span>
            })}
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::petri::{build, Arc, Net, Place, Transition};

    /// P1 → T1 → P2 → T2 → P1, one token in P1.
    fn ring() -> PtNet {
        let mut net = Net::default();
        net.places.push(Place::new("P1", 1, 1));
        net.places.push(Place::new("P2", 2, 0));
        net.transitions.push(Transition::new("T1", ""));
        net.transitions.push(Transition::new("T2", ""));
        for (a, b) in [("P1", "T1"), ("T1", "P2"), ("P2", "T2"), ("T2", "P1")] {
            net.arcs.push(Arc::new(a, b));
        }
        build(&net).unwrap_or_else(|_| panic!("the ring builds"))
    }

    #[test]
    fn the_game_fires_only_enabled_transitions_and_steps_back_and_forth() {
        let net = ring();
        let mut play = Play { game: true, ..Play::default() };
        assert!(!play.fire(&net, 1), "T2 needs a token in P2");
        assert!(play.fire(&net, 0));
        assert_eq!(play.marking(&net), (vec![0, 1], Some(0)));
        assert!(play.fire(&net, 1));
        assert_eq!(play.marking(&net), (vec![1, 0], Some(1)));
        play.step = 1;
        assert_eq!(play.marking(&net), (vec![0, 1], Some(0)), "Previous shows one firing");
        assert!(play.fire(&net, 1), "firing after Previous drops what came after");
        assert_eq!((play.path.len(), play.step), (2, 2));
        play.step = 0;
        assert_eq!(play.marking(&net), (vec![1, 0], None));
        let stale = Play { path: vec![1, 7], step: 2, game: false };
        assert_eq!(stale.marking(&net), (vec![1, 0], None), "a path no longer possible is skipped");
    }
}
