//! The page as a SCORM activity (a package from `plc exercise scorm` or `Export SCORM
//! package`, launched by an LMS as `index.html?exercise=…&scorm=1`): it finds the LMS's
//! runtime API — SCORM 2004's `API_1484_11`, else SCORM 1.2's `API` — in this window and
//! its parents up to the top, then in the opener's (the specification's discovery
//! algorithm, with a depth limit), initializes it, resumes the attempt kept in
//! `cmi.suspend_data`, reports every Check of that exercise (score, status, the attempt
//! compressed as share links are, then a commit), and finishes when the page goes away.
//! With no API the exercise is a plain one. Whatever the LMS reports as an error is shown
//! in the banner; nothing is thrown.

use std::cell::RefCell;

use leptos::prelude::*;
use plc_core::exercise::{Report, SCORM_12_SUSPEND_LIMIT};
use plc_core::project::{decode_share, encode_share};
use wasm_bindgen::closure::Closure;
use wasm_bindgen::{JsCast, JsValue};

use super::Exercises;
use crate::i18n::{said_text, t, tf, K};
use crate::state::AppState;

/// How many windows up the discovery climbs before it gives up.
const MAX_DEPTH: usize = 10;

/// SCORM 2004's `cmi.suspend_data` limit.
const SCORM_2004_SUSPEND_LIMIT: usize = 64_000;

/// The LMS's runtime API and which SCORM it speaks.
struct Session {
    api: JsValue,
    v2004: bool,
    /// The launched exercise's id, once it is open: only its checks are reported.
    exercise: Option<String>,
    /// When the session started (ms since the epoch), for `session_time`.
    started: f64,
    /// `Terminate`/`LMSFinish` was called: nothing more is sent.
    finished: bool,
}

thread_local! {
    static SESSION: RefCell<Option<Session>> = const { RefCell::new(None) };
}

/// `name` on window `w`, when it is an object (a cross-origin window answers nothing).
fn api_on(w: &JsValue, name: &str) -> Option<JsValue> {
    js_sys::Reflect::get(w, &JsValue::from_str(name)).ok().filter(JsValue::is_object)
}

/// The API named `name` on `start` or one of its parents (at most [`MAX_DEPTH`] up).
fn find_up(start: web_sys::Window, name: &str) -> Option<JsValue> {
    let mut w = start;
    for _ in 0..=MAX_DEPTH {
        if let Some(api) = api_on(&w, name) {
            return Some(api);
        }
        let parent = w.parent().ok().flatten()?;
        if js_sys::Object::is(&parent, &w) {
            return None;
        }
        w = parent;
    }
    None
}

/// The API named `name` from this window up, then from the opener up.
fn discover(name: &str) -> Option<JsValue> {
    let window = web_sys::window()?;
    find_up(window.clone(), name).or_else(|| {
        let opener = window.opener().ok().filter(|o| o.is_object())?;
        find_up(opener.unchecked_into(), name)
    })
}

/// A JS value as text (an API's answer is a string; some return booleans or numbers).
fn text_of(v: &JsValue) -> String {
    v.as_string()
        .or_else(|| v.as_bool().map(|b| b.to_string()))
        .or_else(|| v.as_f64().map(|n| n.to_string()))
        .unwrap_or_default()
}

impl Session {
    /// The API's method name for `v12` (SCORM 1.2) or its SCORM 2004 name.
    fn method<'a>(&self, v12: &'a str) -> &'a str {
        if !self.v2004 {
            return v12;
        }
        match v12 {
            "LMSInitialize" => "Initialize",
            "LMSFinish" => "Terminate",
            other => other.strip_prefix("LMS").unwrap_or(other),
        }
    }

    /// Calls the API's method `v12` (named for SCORM 1.2) with `args`.
    fn call(&self, v12: &str, args: &[&str]) -> Result<String, String> {
        let name = self.method(v12);
        let f: js_sys::Function = js_sys::Reflect::get(&self.api, &JsValue::from_str(name))
            .ok()
            .and_then(|f| f.dyn_into().ok())
            .ok_or_else(|| tf(K::exercise_lms_missing, &[("name", name)]))?;
        let list = js_sys::Array::new();
        for a in args {
            list.push(&JsValue::from_str(a));
        }
        f.apply(&self.api, &list).map(|r| text_of(&r)).map_err(|e| {
            let why = js_sys::Reflect::get(&e, &JsValue::from_str("message"))
                .ok()
                .and_then(|m| m.as_string())
                .unwrap_or_else(|| text_of(&e));
            tf(K::exercise_lms_failed, &[("name", name), ("why", &why)])
        })
    }

    /// The LMS's last error as `CODE text`, when there is one.
    fn last_error(&self) -> Option<String> {
        let code = self.call("LMSGetLastError", &[]).ok()?;
        if code.is_empty() || code == "0" {
            return None;
        }
        let text = self.call("LMSGetErrorString", &[&code]).unwrap_or_default();
        Some(format!("{code} {text}").trim().to_string())
    }

    /// Calls a method that answers `"true"` on success; the LMS's error otherwise.
    fn act(&self, v12: &str, args: &[&str], what: &str) -> Result<(), String> {
        let answer = self.call(v12, args)?;
        if answer == "true" {
            return Ok(());
        }
        let why = self
            .last_error()
            .unwrap_or_else(|| tf(K::exercise_lms_answered, &[("answer", &answer)]));
        Err(tf(K::exercise_lms_refused, &[("what", what), ("why", &why)]))
    }

    fn set(&self, element: &str, value: &str) -> Result<(), String> {
        self.act("LMSSetValue", &[element, value], element)
    }

    /// An element's value ("" when the LMS has none).
    fn get(&self, element: &str) -> String {
        self.call("LMSGetValue", &[element]).unwrap_or_default()
    }

    fn commit(&self) -> Result<(), String> {
        self.act("LMSCommit", &[""], t(K::exercise_lms_commit))
    }

    /// The time since the session started, as the edition writes it.
    fn session_time(&self) -> String {
        let cs = ((js_sys::Date::now() - self.started).max(0.0) / 10.0) as u64;
        let (h, m, s) = (cs / 360_000, cs / 6000 % 60, cs % 6000);
        if self.v2004 {
            format!("PT{h}H{m}M{}.{:02}S", s / 100, s % 100)
        } else {
            format!("{h:04}:{m:02}:{:02}.{:02}", s / 100, s % 100)
        }
    }

    /// Keeps the attempt in `cmi.suspend_data`, or says why it cannot.
    fn keep_attempt(&self, state: AppState) -> Result<(), String> {
        let data = state.project.with_untracked(encode_share);
        let (limit, edition) = if self.v2004 {
            (SCORM_2004_SUSPEND_LIMIT, t(K::exercise_lms_keeps_2004))
        } else {
            (SCORM_12_SUSPEND_LIMIT, t(K::exercise_lms_keeps_12))
        };
        if data.len() > limit {
            return Err(tf(
                K::exercise_lms_too_big,
                &[("size", &data.len().to_string()), ("edition", edition)],
            ));
        }
        self.set("cmi.suspend_data", &data)
    }
}

/// Whether the page is a launched activity that has not finished (cheap: the page asks
/// before it fetches this chunk to report a score).
pub fn in_session() -> bool {
    SESSION.with(|s| s.borrow().as_ref().is_some_and(|s| !s.finished))
}

/// Runs `f` on the session, if the page is a launched activity that has not finished.
fn with_session<R>(f: impl FnOnce(&mut Session) -> R) -> Option<R> {
    SESSION.with(|s| s.borrow_mut().as_mut().filter(|s| !s.finished).map(f))
}

/// Starts the session when the page was launched as a SCORM activity and an LMS is found:
/// initializes it and marks the page (the catalogue is hidden: the activity is this
/// exercise alone). False when there is no LMS (a plain exercise).
pub fn launch(ex: Exercises, state: AppState) -> bool {
    let (api, v2004) = match discover("API_1484_11") {
        Some(api) => (api, true),
        None => match discover("API") {
            Some(api) => (api, false),
            None => return false,
        },
    };
    let session =
        Session { api, v2004, exercise: None, started: js_sys::Date::now(), finished: false };
    if let Err(e) = session.act("LMSInitialize", &[""], t(K::exercise_lms_start)) {
        state.error(e);
        return false;
    }
    let status = if v2004 { "cmi.completion_status" } else { "cmi.core.lesson_status" };
    if matches!(session.get(status).as_str(), "" | "not attempted" | "unknown") {
        let _ = session.set(status, "incomplete");
    }
    SESSION.with(|s| *s.borrow_mut() = Some(session));
    if let Some(root) =
        web_sys::window().and_then(|w| w.document()).and_then(|d| d.document_element())
    {
        let _ = root.set_attribute("data-lms", if v2004 { "scorm-2004" } else { "scorm-1.2" });
    }
    // The page goes away (closed, reloaded, left): keep the attempt, then finish.
    let on_hide = Closure::<dyn Fn()>::new(move || finish(ex, state));
    if let Some(w) = web_sys::window() {
        let _ = w.add_event_listener_with_callback("pagehide", on_hide.as_ref().unchecked_ref());
    }
    on_hide.forget();
    true
}

/// Once the launched exercise is open: notes it, and opens the attempt the LMS kept.
pub fn resume(ex: Exercises, state: AppState) {
    let Some(id) = ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.id.clone())) else {
        return;
    };
    let kept = with_session(|s| {
        s.exercise = Some(id);
        s.get("cmi.suspend_data")
    });
    let Some(kept) = kept.filter(|k| !k.is_empty()) else { return };
    match decode_share(&kept) {
        Ok(project) => {
            state.replace_contents(project);
            state.info(t(K::exercise_lms_resumed));
        }
        Err(e) => state.error(tf(K::exercise_lms_unreadable, &[("error", &said_text(e.said()))])),
    }
}

/// A percentage with at most two decimals (`33.33`, `100`).
fn percent(score: u32, total: u32) -> String {
    let p = if total == 0 { 0.0 } else { 100.0 * f64::from(score) / f64::from(total) };
    let p = format!("{:.2}", (p * 100.0).round() / 100.0);
    p.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Reports a Check of exercise `id` to the LMS: the score, the status, the attempt, then
/// a commit. A check of another exercise (one opened from elsewhere) is not reported.
pub fn report(state: AppState, id: &str, report: &Report) {
    let problems = with_session(|s| {
        if s.exercise.as_deref() != Some(id) {
            return Vec::new();
        }
        let passed = report.error.is_none() && report.score == report.total;
        let raw = percent(report.score, report.total);
        let scaled = if report.total == 0 {
            "0".to_string()
        } else {
            format!("{:.4}", f64::from(report.score) / f64::from(report.total))
        };
        let sets: Vec<(&str, &str)> = if s.v2004 {
            vec![
                ("cmi.score.scaled", scaled.as_str()),
                ("cmi.score.raw", raw.as_str()),
                ("cmi.score.min", "0"),
                ("cmi.score.max", "100"),
                ("cmi.success_status", if passed { "passed" } else { "failed" }),
                ("cmi.completion_status", if passed { "completed" } else { "incomplete" }),
            ]
        } else {
            vec![
                ("cmi.core.score.raw", raw.as_str()),
                ("cmi.core.score.min", "0"),
                ("cmi.core.score.max", "100"),
                ("cmi.core.lesson_status", if passed { "passed" } else { "incomplete" }),
            ]
        };
        let mut problems: Vec<String> =
            sets.into_iter().filter_map(|(k, v)| s.set(k, v).err()).collect();
        problems.extend(s.keep_attempt(state).err());
        problems.extend(s.commit().err());
        problems
    });
    if let Some(first) = problems.and_then(|p| p.into_iter().next()) {
        state.error(first);
    }
}

/// The page goes away: the attempt, the session time and "suspend" (so the next launch
/// resumes), a commit, then `LMSFinish` / `Terminate`.
fn finish(ex: Exercises, state: AppState) {
    with_session(|s| {
        let open = ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.id.clone()));
        if open.is_some() && open == s.exercise {
            let _ = s.keep_attempt(state);
        }
        let (time, exit) = if s.v2004 {
            ("cmi.session_time", "cmi.exit")
        } else {
            ("cmi.core.session_time", "cmi.core.exit")
        };
        let _ = s.set(time, &s.session_time());
        let _ = s.set(exit, "suspend");
        let _ = s.commit();
        let _ = s.act("LMSFinish", &[""], t(K::exercise_lms_end));

        s.finished = true;
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scores_are_percentages_with_two_decimals_at_most() {
        assert_eq!(percent(3, 3), "100");
        assert_eq!(percent(1, 3), "33.33");
        assert_eq!(percent(0, 3), "0");
        assert_eq!(percent(1, 8), "12.5");
        assert_eq!(percent(0, 0), "0");
    }
}
