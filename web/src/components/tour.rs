//! `Start here`: a short guided lesson shown on the first visit, in a box at the top of the
//! simulation column (never modal, never over the page, and the editors do not move when it
//! shows, changes or closes; above the exercise catalogue while that is shown). Each step says what to do, marks the controls to use, and moves on
//! when the student has done it (an input flipped, the ST edited, a rung drawn, a Step
//! pressed, an exercise opened) or on `Next`. Finished or skipped, it stays closed after
//! reloads; `Help` → `Start here` opens it again.

use std::collections::BTreeMap;

use leptos::prelude::*;
use plc_core::ladder::Element;
use plc_core::project::{Project, StorageBackend};

use crate::exercises::Exercises;
use crate::i18n::{t, tf, I18n, K};
use crate::state::AppState;
use crate::storage::LocalStorage;

/// The local storage key noting that the tour was finished or skipped (in the trainer's
/// versioned key space).
const DONE_KEY: &str = "plc-trainer/v1/tour";

/// How long a step shows that it is done before the next one.
const ADVANCE_DELAY: std::time::Duration = std::time::Duration::from_millis(1200);

/// One step of the lesson (its markup is made by a chunk loaded on first use:
/// `lazy::tour_text`).
struct Step {
    title: K,
    text: K,
}

/// What the page marks at each step (`data-tour-target` on the document, matched by the
/// CSS).
const TARGETS: [&str; 5] = ["run io", "st", "ladder", "step", "exercises"];

/// The lesson (its words in the catalogue).
const STEPS: [Step; 5] = [
    Step { title: K::tour_step1_title, text: K::tour_step1_text },
    Step { title: K::tour_step2_title, text: K::tour_step2_text },
    Step { title: K::tour_step3_title, text: K::tour_step3_text },
    Step { title: K::tour_step4_title, text: K::tour_step4_text },
    Step { title: K::tour_step5_title, text: K::tour_step5_text },
];

/// The title and text shown once the last step is done.
const FINISHED: (K, K) = (K::tour_ready_title, K::tour_ready_text);

/// What the page showed when a step began, to tell when the student has done it.
#[derive(Debug, Clone, PartialEq)]
enum Mark {
    /// The inputs held by the I/O panel.
    Held(BTreeMap<String, String>),
    /// The open project's id and ST text.
    Source(Option<String>, String),
    /// How many rungs have a contact and a coil.
    Rungs(usize),
    /// How many Steps were taken.
    Steps(u64),
    /// The open exercise's id.
    Exercise(Option<String>),
}

/// Whether the student did what the step asks between `before` and `now`.
fn acted(before: &Mark, now: &Mark) -> bool {
    match (before, now) {
        (Mark::Held(b), Mark::Held(n)) => n.iter().any(|(k, v)| b.get(k) != Some(v)),
        (Mark::Source(bid, b), Mark::Source(nid, n)) => bid == nid && b != n,
        (Mark::Rungs(b), Mark::Rungs(n)) => n > b,
        (Mark::Steps(b), Mark::Steps(n)) => n > b,
        (Mark::Exercise(b), Mark::Exercise(n)) => n.is_some() && n != b,
        _ => false,
    }
}

/// The rungs of the project's ladder POUs that hold a contact and a coil.
fn drawn_rungs(project: &Project) -> usize {
    project
        .ladder
        .iter()
        .flat_map(|pou| &pou.rungs)
        .filter(|rung| {
            let has = |f: fn(&Element) -> bool| rung.cells.iter().flatten().any(|c| f(&c.element));
            has(|e| matches!(e, Element::Contact { .. }))
                && has(|e| matches!(e, Element::Coil { .. }))
        })
        .count()
}

/// The tour's place, shared by the strip and the `Help` menu.
#[derive(Clone, Copy)]
pub struct Tour {
    /// The step shown (`None`: closed; `TARGETS.len()`: finished).
    pub step: RwSignal<Option<usize>>,
    /// The step's action was seen: it says so for a moment, then the next step shows.
    pub done: RwSignal<bool>,
    /// The strip's markup for the step shown, and what it says to a screen reader.
    content: RwSignal<Option<(String, String)>>,
}

impl Tour {
    /// Open at the first step unless it was finished or skipped in this browser.
    pub fn new() -> Self {
        let done = LocalStorage::open().get(DONE_KEY).ok().flatten().is_some();
        Tour {
            step: RwSignal::new((!done).then_some(0)),
            done: RwSignal::new(false),
            content: RwSignal::new(None),
        }
    }

    /// Opens the tour at its first step (`Help` → `Start here`).
    pub fn restart(self) {
        self.content.set(None);
        self.step.set(Some(0));
    }

    /// Notes in storage that the tour was seen to its end or skipped.
    fn remember_done() {
        let _ = LocalStorage::open().set(DONE_KEY, "done");
    }

    fn go(self, step: usize) {
        if step >= TARGETS.len() {
            Self::remember_done();
        }
        self.step.set(Some(step.min(TARGETS.len())));
    }

    fn skip(self) {
        Self::remember_done();
        self.step.set(None);
    }
}

/// What the page shows of `step` now (read reactively).
fn mark(state: AppState, ex: Exercises, step: usize) -> Mark {
    match step {
        0 => Mark::Held(state.held.get()),
        1 => Mark::Source(state.project_id.get(), state.project.with(|p| p.source.clone())),
        2 => Mark::Rungs(state.project.with(drawn_rungs)),
        3 => Mark::Steps(state.steps_taken.get()),
        _ => Mark::Exercise(ex.open.with(|o| o.as_ref().map(|o| o.opened.view.id.clone()))),
    }
}

/// Marks the step's controls on the page (`data-tour-target` on the document element).
fn point_at(target: Option<&str>) {
    let Some(root) =
        web_sys::window().and_then(|w| w.document()).and_then(|d| d.document_element())
    else {
        return;
    };
    let _ = match target {
        Some(t) => root.set_attribute("data-tour-target", t),
        None => root.remove_attribute("data-tour-target"),
    };
}

impl Tour {
    /// Watches what the current step asks for, from the moment the step began, and marks
    /// the step's controls on the page (once for the page: the strip is shown in two
    /// places, the workspace and the exercise catalogue).
    pub fn watch(self, state: AppState, ex: Exercises) {
        let (tour, done) = (self, self.done);
        Effect::new(move |prev: Option<Option<(usize, Mark)>>| {
            let step = tour.step.get().filter(|s| *s < TARGETS.len())?;
            let now = mark(state, ex, step);
            match prev.flatten() {
                Some((s, before)) if s == step => {
                    if !done.get_untracked() && acted(&before, &now) {
                        done.set(true);
                        set_timeout(
                            move || {
                                if tour.step.try_get_untracked() == Some(Some(step)) {
                                    tour.go(step + 1);
                                }
                            },
                            ADVANCE_DELAY,
                        );
                    }
                    Some((s, before))
                }
                _ => {
                    done.set(false);
                    Some((step, now))
                }
            }
        });
        // The strip's words are made anew when the language shown changes.
        let shown = use_context::<I18n>().map(|i| i.shown);
        Effect::new(move |_| {
            if let Some(shown) = shown {
                shown.track();
            }
            let step = tour.step.get();
            point_at(step.and_then(|s| TARGETS.get(s)).copied());
            let Some(step) = step else { return };
            let done = tour.done.get();
            leptos::task::spawn_local(async move {
                if let Ok(text) = crate::lazy::tour_text(step, done).await {
                    if let Some((spoken, html)) = text.split_once('\u{1}') {
                        tour.content.set(Some((spoken.to_string(), html.to_string())));
                    }
                }
            });
        });
    }
}

/// What a screen reader hears of `step`, then `\u{1}`, then the strip's markup
/// ([`tour_html`]), in the language shown: `lazy::tour_text` gives it from its chunk.
pub fn tour_text(step: usize, done: bool) -> String {
    let spoken = match STEPS.get(step) {
        Some(s) => tf(
            K::tour_spoken,
            &[
                ("n", &(step + 1).to_string()),
                ("total", &STEPS.len().to_string()),
                ("title", t(s.title)),
            ],
        ),
        None => t(FINISHED.0).to_string(),
    };
    format!("{spoken}\u{1}{}", tour_html(step, done))
}

/// The strip's content at `step` (`TARGETS.len()`: finished); `done`: the step's action was
/// seen. Fixed markup whose buttons name their action in `data-tour-action`.
fn tour_html(step: usize, done: bool) -> String {
    let total = TARGETS.len();
    let (count, title, text) = match STEPS.get(step) {
        Some(s) => (
            tf(K::tour_count, &[("n", &(step + 1).to_string()), ("total", &total.to_string())]),
            t(s.title),
            t(s.text),
        ),
        None => (t(K::tour_finished).to_string(), t(FINISHED.0), t(FINISHED.1)),
    };
    let done = if done {
        format!(r#"<span class="tour-done"> ✓ {}</span>"#, t(K::tour_done))
    } else {
        String::new()
    };
    let back = if step == 0 { " disabled" } else { "" };
    let buttons = if step < total {
        format!(
            r#"<button class="primary" data-tour-action="next">{}</button><button data-tour-action="skip">{}</button>"#,
            t(K::tour_next),
            t(K::tour_skip)
        )
    } else {
        format!(r#"<button class="primary" data-tour-action="close">{}</button>"#, t(K::tour_close))
    };
    format!(
        r#"<p class="tour-name">{name}</p><p class="tour-count">{count}</p><div class="tour-body"><h2 class="tour-title">{title}{done}</h2><p class="tour-text">{text}</p></div><div class="tour-actions"><button data-tour-action="back"{back}>{back_word}</button>{buttons}</div>"#,
        name = t(K::tour_start_here),
        back_word = t(K::tour_back),
    )
}

/// The `Start here` strip. Its content is fixed markup handled by one click listener (far
/// less code in the page than a view per element; the first load has a size budget).
pub fn tour_panel() -> impl IntoView {
    use wasm_bindgen::JsCast;
    let tour = expect_context::<Tour>();
    let on_click = move |e: leptos::ev::MouseEvent| {
        let action = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
            .and_then(|t| t.closest("[data-tour-action]").ok().flatten())
            .and_then(|t| t.get_attribute("data-tour-action"));
        let Some(step) = tour.step.get_untracked() else { return };
        match action.as_deref() {
            Some("back") => tour.go(step.saturating_sub(1)),
            Some("next") => tour.go(step + 1),
            Some("skip") => return tour.skip(),
            Some("close") => return tour.step.set(None),
            _ => return,
        }
        // The buttons are made anew: the focus goes back to the one pressed (or the first
        // button that is there now).
        let action = action.unwrap_or_default();
        request_animation_frame(move || {
            let doc = web_sys::window().and_then(|w| w.document());
            let find = |sel: &str| doc.as_ref().and_then(|d| d.query_selector(sel).ok().flatten());
            let button = find(&format!(".tour [data-tour-action={action}]:not([disabled])"))
                .or_else(|| find(".tour .primary"))
                .and_then(|b| b.dyn_into::<web_sys::HtmlElement>().ok());
            if let Some(b) = button {
                let _ = b.focus();
            }
        });
    };
    move || {
        tour.step.get()?;
        let (spoken, html) = tour.content.get()?;
        Some(view! {
            <section class="tour" role="region" aria-label=t(K::tour_start_here) on:click=on_click>
                <div class="tour-grid" inner_html=html></div>
                <p class="visually-hidden" aria-live="polite">{spoken}</p>
            </section>
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::ladder::{Cell, CoilKind, ContactKind, LadderPouKind};

    #[test]
    fn each_step_waits_for_its_own_action() {
        let held = |pairs: &[(&str, &str)]| {
            Mark::Held(pairs.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect())
        };
        assert!(acted(&held(&[]), &held(&[("Start", "TRUE")])));
        assert!(acted(&held(&[("Start", "TRUE")]), &held(&[("Start", "FALSE")])));
        assert!(!acted(&held(&[("Start", "TRUE")]), &held(&[])), "another project cleared them");
        let src = |id: &str, text: &str| Mark::Source(Some(id.into()), text.into());
        assert!(acted(&src("a", "x := 1;"), &src("a", "x := 2;")));
        assert!(!acted(&src("a", "x := 1;"), &src("b", "y := 1;")), "another project opened");
        assert!(acted(&Mark::Rungs(0), &Mark::Rungs(1)));
        assert!(!acted(&Mark::Rungs(1), &Mark::Rungs(0)));
        assert!(acted(&Mark::Steps(4), &Mark::Steps(5)));
        assert!(acted(&Mark::Exercise(None), &Mark::Exercise(Some("latch".into()))));
        assert!(!acted(&Mark::Exercise(Some("latch".into())), &Mark::Exercise(None)));
        assert!(!acted(&Mark::Steps(0), &Mark::Rungs(3)), "marks of different steps");
    }

    #[test]
    fn a_rung_is_drawn_once_it_has_a_contact_and_a_coil() {
        let mut p = Project::new("p");
        p.add_ladder_pou("L", LadderPouKind::Program).unwrap();
        assert_eq!(drawn_rungs(&p), 0);
        p.ladder[0].rungs[0].cells[0][0] = Cell {
            element: Element::Contact { kind: ContactKind::NormallyOpen, operand: "A".into() },
            ..Cell::default()
        };
        assert_eq!(drawn_rungs(&p), 0, "a contact alone");
        p.ladder[0].rungs[0].cells[0][1] = Cell {
            element: Element::Coil { kind: CoilKind::Normal, operand: "B".into() },
            ..Cell::default()
        };
        assert_eq!(drawn_rungs(&p), 1);
        assert_eq!(STEPS.len(), TARGETS.len());
    }

    #[test]
    fn the_strip_names_the_step_and_offers_what_fits() {
        let first = tour_html(0, false);
        assert!(first.contains(r#"<p class="tour-count">Step 1 of 5</p>"#), "{first}");
        assert!(first.contains(r#"<button data-tour-action="back" disabled>Back</button>"#));
        assert!(first.contains(">Next<") && first.contains(">Skip tour<") && !first.contains("✓"));
        let done = tour_html(2, true);
        assert!(done.contains("Draw one rung<span class=\"tour-done\"> ✓ Done</span>"), "{done}");
        assert!(done.contains(r#"<button data-tour-action="back">Back</button>"#));
        let end = tour_html(5, false);
        assert!(
            end.contains(">Finished<") && end.contains(">Close tour<") && !end.contains(">Next<")
        );
        // Inserted as HTML: the texts must hold no markup of their own.
        for k in STEPS.iter().flat_map(|s| [s.title, s.text]).chain([FINISHED.0, FINISHED.1]) {
            let text = t(k);
            assert!(!text.contains(['<', '>', '&']), "{text}");
        }
    }
}
