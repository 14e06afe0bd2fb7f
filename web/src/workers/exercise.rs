//! The exercise worker's work: reading exercise files (shipped, fetched or carried by a
//! link), rendering their statements and grading attempts, in a chunk of the app
//! (`split_exercise_worker.wasm`) that only the exercise worker loads (it runs the page's
//! module, so the engine is not downloaded twice). It answers each message — a JSON
//! [`Request`] — with a JSON [`Reply`] (see `src/exercises/protocol.rs`).

use crate::exercises::protocol::{Opened, Reply, Request};
use plc_core::exercise::{
    grade_by, Exercise, ExerciseLink, ExerciseView, GradeOptions, LinkedFile,
};
use plc_core::open::open_plain;
use plc_core::project::Project;

mod shipped {
    include!(concat!(env!("OUT_DIR"), "/exercise_files.rs"));
}

/// Scans shown around a failure on the page's timeline.
const PAGE_WINDOW: usize = 100;

/// The reply to one request.
async fn answer(request: Request) -> Reply {
    match request {
        Request::Shipped(id) => match shipped::FILES.iter().find(|(i, _, _)| *i == id) {
            Some((_, text, starter)) => {
                let starter =
                    starter.map(|(name, text)| LinkedFile { name: name.into(), text: text.into() });
                open(ExerciseLink { exercise: (*text).to_string(), starter }, None).await
            }
            None => Reply::Error(format!("there is no exercise “{id}” in this trainer")),
        },
        Request::File { link, base } => open(link, base).await,
        Request::Link(fragment) => match ExerciseLink::decode(&fragment) {
            Ok((link, _)) => open(link, None).await,
            Err(e) => Reply::Error(e.to_string()),
        },
        Request::Grade { exercise, project } => {
            let exercise = match Exercise::from_toml(&exercise) {
                Ok(e) => e,
                Err(e) => return Reply::Error(format!("the exercise file cannot be used: {e}")),
            };
            let project = match Project::from_file(&project) {
                Ok(p) => p,
                Err(e) => return Reply::Error(format!("the project cannot be read: {e}")),
            };
            // The passes for the submission's diagram POUs are chunks, fetched as needed.
            let passes = match super::passes_for(&project).await {
                Ok(passes) => passes,
                Err(e) => return Reply::Error(format!("the exercise cannot grade: {e}")),
            };
            let options = GradeOptions { window: PAGE_WINDOW };
            match grade_by(&exercise, &project, options, &passes) {
                Ok(report) => Reply::Graded(report),
                Err(e) => Reply::Error(format!("the exercise cannot grade: {e}")),
            }
        }
    }
}

/// Opens an exercise file with its starter.
async fn open(link: ExerciseLink, base: Option<String>) -> Reply {
    let exercise = match Exercise::from_toml(&link.exercise) {
        Ok(e) => e,
        Err(e) => return Reply::Error(format!("the exercise file cannot be used: {e}")),
    };
    let fragment = match link.encode() {
        Ok(f) => f,
        Err(e) => return Reply::Error(format!("the exercise file cannot be used: {e}")),
    };
    let starter = match (&exercise.starter, &link.starter) {
        (None, _) => {
            let mut p = Project::new(&exercise.title);
            p.source = exercise.blank_program();
            Some(exercise.with_plant_by(&p, &plc_core::build::Lowerings::NONE).to_file())
        }
        (Some(_), None) => None,
        (Some(_), Some(file)) => {
            let stem = file.name.split('.').next().unwrap_or("starter");
            // Starters are ST or project files; the XML reader (a chunk of its own, shared
            // with the import worker) is fetched only for a PLCopen XML or PNML starter.
            let opened = match open_plain(stem, &file.text) {
                Ok(Some(opened)) => Ok(opened),
                Ok(None) => super::open_xml(stem.to_string(), file.text.clone())
                    .await
                    .unwrap_or_else(|e| Err(e.to_string())),
                Err(e) => Err(e.to_string()),
            };
            match opened {
                // The exercise's plant and its scene join the starter (the grader puts
                // its own plant back in whatever the student changes).
                Ok(opened) => match super::passes_for(&opened.project).await {
                    Ok(passes) => Some(exercise.with_plant_by(&opened.project, &passes).to_file()),
                    Err(e) => return Reply::Error(format!("the starter cannot be opened: {e}")),
                },
                Err(e) => {
                    return Reply::Error(format!("the starter {} cannot be opened: {e}", file.name))
                }
            }
        }
    };
    let view = ExerciseView::of(&exercise, base.as_deref());
    Reply::Opened(Box::new(Opened { view, link, base, fragment, starter }))
}

/// The reply to a message's text.
pub async fn reply_text(text: &str) -> String {
    let reply = match serde_json::from_str::<Request>(text) {
        Ok(request) => answer(request).await,
        Err(e) => Reply::Error(format!("the exercise worker got a request it cannot read: {e}")),
    };
    serde_json::to_string(&reply)
        .unwrap_or_else(|_| r#"{"Error":"the answer could not be written"}"#.into())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn ask(request: Request) -> Reply {
        serde_json::from_str(&reply(&serde_json::to_string(&request).unwrap())).unwrap()
    }

    /// `reply_text` run to its end (natively nothing in it waits).
    fn reply(text: &str) -> String {
        block_on(reply_text(text))
    }

    fn block_on<F: std::future::Future>(f: F) -> F::Output {
        use std::task::{Context, Poll, Waker};
        let mut f = std::pin::pin!(f);
        let mut cx = Context::from_waker(Waker::noop());
        loop {
            if let Poll::Ready(out) = f.as_mut().poll(&mut cx) {
                return out;
            }
        }
    }

    #[test]
    fn every_shipped_exercise_opens_with_its_starter() {
        assert!(shipped::FILES.len() >= 2);
        for (id, _, _) in shipped::FILES {
            let Reply::Opened(opened) = ask(Request::Shipped((*id).to_string())) else {
                panic!("{id} does not open");
            };
            assert_eq!(opened.view.id, *id);
            assert!(Project::from_file(opened.starter.as_deref().unwrap()).is_ok(), "{id}");
        }
    }

    /// An exercise with a plant opens with the plant and its scene in the starter, and
    /// the grader runs its own plant even when the student deleted theirs.
    #[test]
    fn a_plant_exercise_brings_its_plant_and_grades_with_it() {
        let Reply::Opened(opened) = ask(Request::Shipped("tank-plant".into())) else { panic!() };
        let starter = Project::from_file(opened.starter.as_deref().unwrap()).unwrap();
        assert_eq!(starter.settings.plant.as_deref(), Some("TankPlant"));
        assert_eq!(starter.settings.program.as_deref(), Some("TankControl"));
        assert!(starter.source.contains("PROGRAM TankPlant"));
        assert!(starter.scene.is_some());
        let mut solved = starter.clone();
        let reference = include_str!("../../../exercises/tank-plant/reference.st");
        solved.source = reference.to_string();
        let graded = ask(Request::Grade {
            exercise: opened.link.exercise.clone(),
            project: solved.to_file(),
        });
        let Reply::Graded(report) = graded else { panic!("{graded:?}") };
        assert_eq!(report.score, report.total, "{report:?}");
    }

    #[test]
    fn the_starter_fails_and_the_link_reopens_the_exercise() {
        let Reply::Opened(opened) = ask(Request::Shipped("latch".into())) else { panic!() };
        let graded = ask(Request::Grade {
            exercise: opened.link.exercise.clone(),
            project: opened.starter.clone().unwrap(),
        });
        let Reply::Graded(report) = graded else { panic!("{graded:?}") };
        assert!(report.score < report.total);
        let failure = report.scenarios.iter().find_map(|s| s.failure.as_ref()).unwrap();
        assert!(failure.window.len() > 11, "the page's window is wide");
        let Reply::Opened(again) = ask(Request::Link(format!("#{}", opened.fragment))) else {
            panic!()
        };
        assert_eq!(again.view, opened.view);
    }

    #[test]
    fn bad_requests_get_messages() {
        assert!(reply("nonsense").contains("cannot read"));
        let Reply::Error(e) = ask(Request::Shipped("nope".into())) else { panic!() };
        assert!(e.contains("nope"));
        let Reply::Error(e) = ask(Request::Link("x=AAAA".into())) else { panic!() };
        assert!(e.contains("damaged"), "{e}");
        let bad = ExerciseLink { exercise: "id = 1".into(), starter: None };
        let Reply::Error(e) = ask(Request::File { link: bad, base: None }) else { panic!() };
        assert!(e.starts_with("the exercise file cannot be used: line 1"), "{e}");
        let Reply::Error(e) = ask(Request::Grade {
            exercise: "id = \"a\"\ntitle = \"A\"\nlevel = 1\n".into(),
            project: "{".into(),
        }) else {
            panic!()
        };
        assert!(e.contains("project cannot be read"), "{e}");
    }
}
