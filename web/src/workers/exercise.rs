//! The exercise worker's work: reading exercise files (shipped, fetched or carried by a
//! link), rendering their statements and grading attempts, in a chunk of the app
//! (`split_exercise_worker.wasm`) that only the exercise worker loads (it runs the page's
//! module, so the engine is not downloaded twice). It answers each message — a JSON
//! [`Request`] — with a JSON [`Reply`] (see `src/exercises/protocol.rs`), or, for a SCORM
//! package, with the ZIP's bytes (the packing and its ZIP writer stay in this chunk).
//!
//! The shipped exercises are files next to the app (`exercises/ID.json`, written by
//! `build.rs`) in the built form: JSON with the statement rendered, read without a TOML
//! reader or a Markdown renderer. An exercise file in TOML (from an address or a link)
//! is read by a chunk of its own (`exercise_toml`), fetched only then.

use crate::exercises::protocol::{Failure, Opened, Reply, Request, StarterFile};
use plc_core::exercise::{is_built, Exercise, ExerciseLink, ExerciseView, SITE_FILE_LIST};
use plc_core::open::open_plain_by;
use plc_core::project::Project;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_futures::JsFuture;

/// The reply to one request.
async fn answer(request: Request) -> Reply {
    match request {
        Request::Shipped(id) => match shipped(&id).await {
            Ok(link) => open(link, None).await,
            Err(e) => Reply::Error(e),
        },
        Request::File { link, base } => open(link, base).await,
        Request::Link(fragment) => match crate::lazy::read_exercise_link(fragment).await {
            Ok(Ok(link)) => match read(&link.exercise, None).await {
                Ok(_) => open(link, None).await,
                Err(e) => Reply::Error(Failure::LinkUnusable(e)),
            },
            Ok(Err(e)) => Reply::Error(Failure::Plain(e)),
            Err(e) => Reply::Error(Failure::Plain(e.to_string())),
        },
        Request::Grade { exercise, project } => {
            let exercise = match read(&exercise, None).await {
                Ok((e, _)) => e,
                Err(e) => return Reply::Error(Failure::FileUnusable(e)),
            };
            // A submission with diagram POUs is read with their models' readers (a chunk).
            if let Err(e) = crate::lazy::readers_for(&project).await {
                return Reply::Error(Failure::CannotGrade(e.to_string()));
            }
            let project = match crate::lazy::project_reader()(&project) {
                Ok(p) => p,
                Err(e) => return Reply::Error(Failure::ProjectUnreadable(e.to_string())),
            };
            // The passes for the submission's diagram POUs are chunks, fetched as needed.
            let passes = match super::passes_for(&project).await {
                Ok(passes) => passes,
                Err(e) => return Reply::Error(Failure::CannotGrade(e.to_string())),
            };
            match super::grade_report(exercise, project, passes).await {
                Ok(Ok(report)) => Reply::Graded(report),
                Ok(Err(e)) => Reply::Error(Failure::CannotGrade(e)),
                Err(e) => Reply::Error(Failure::CannotGrade(e.to_string())),
            }
        }
        // Answered by `reply` (with the package's bytes).
        Request::Scorm { .. } => Reply::Error(Failure::NotText),
    }
}

/// Reads an exercise text and renders its statement (relative links against `base`): the
/// built form here, TOML in the `exercise_toml` chunk.
async fn read(text: &str, base: Option<&str>) -> Result<(Exercise, String), String> {
    if is_built(text) {
        return Exercise::from_built(text).map_err(|e| e.to_string());
    }
    super::read_toml(text.to_string(), base.map(str::to_string))
        .await
        .unwrap_or_else(|e| Err(e.to_string()))
}

/// The link that opens the shipped exercise `id` (the file `build.rs` wrote).
async fn shipped(id: &str) -> Result<ExerciseLink, Failure> {
    let missing = || Failure::NoExercise(id.to_string());
    if id.is_empty() || !id.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_') {
        return Err(missing());
    }
    let text = shipped_file(id).await?.ok_or_else(missing)?;
    serde_json::from_str(&text)
        .map_err(|e| Failure::ExerciseUnreadable(id.to_string(), e.to_string()))
}

/// The text of `exercises/ID.json` next to the worker's script, `None` when there is none.
#[cfg(target_arch = "wasm32")]
async fn shipped_file(id: &str) -> Result<Option<String>, Failure> {
    let failed = |_| Failure::ExerciseOffline(id.to_string());
    let scope: web_sys::WorkerGlobalScope = js_sys::global().unchecked_into();
    let response: web_sys::Response =
        JsFuture::from(scope.fetch_with_str(&format!("exercises/{id}.json")))
            .await
            .map_err(failed)?
            .unchecked_into();
    if response.status() == 404 {
        return Ok(None);
    }
    if !response.ok() {
        return Err(Failure::ExerciseHttp(id.to_string(), response.status()));
    }
    let text = JsFuture::from(response.text().map_err(failed)?).await.map_err(failed)?;
    Ok(text.as_string())
}

/// Natively (tests) the files are built in.
#[cfg(not(target_arch = "wasm32"))]
async fn shipped_file(id: &str) -> Result<Option<String>, Failure> {
    mod files {
        include!(concat!(env!("OUT_DIR"), "/exercise_files.rs"));
    }
    Ok(files::FILES.iter().find(|(i, _)| *i == id).map(|(_, text)| (*text).to_string()))
}

/// The bytes at `url`.
async fn fetch_bytes(url: &str) -> Result<Vec<u8>, Failure> {
    let failed = |_| Failure::UrlUnreadable(url.to_string());
    let scope: web_sys::WorkerGlobalScope = js_sys::global().unchecked_into();
    let response: web_sys::Response = JsFuture::from(scope.fetch_with_str(url))
        .await
        .map_err(failed)?
        .dyn_into()
        .map_err(failed)?;
    if !response.ok() {
        return Err(Failure::UrlHttp(url.to_string(), response.status()));
    }
    let buffer = JsFuture::from(response.array_buffer().map_err(failed)?).await.map_err(failed)?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}

/// The SCORM package of `link`: the files of the site at `site` (its root URL, ending in
/// `/`) as its `site-files.txt` lists them, the exercise and its starter, and the manifest.
async fn package(link: ExerciseLink, site: &str) -> Result<Vec<u8>, Failure> {
    let list = fetch_bytes(&format!("{site}{SITE_FILE_LIST}"))
        .await
        .map_err(|_| Failure::NoFileList(SITE_FILE_LIST.to_string()))?;
    let mut files = Vec::new();
    for path in String::from_utf8_lossy(&list).lines().map(str::trim).filter(|l| !l.is_empty()) {
        files.push((path.to_string(), fetch_bytes(&format!("{site}{path}")).await?));
    }
    let starters: Vec<_> = link.starter.into_iter().chain(link.starters).collect();
    super::scorm_zip(link.exercise, starters, files)
        .await
        .map_err(|e| Failure::Plain(e.to_string()))?
        .map_err(Failure::Plain)
}

/// The answer to one message: a SCORM package's bytes (a `Uint8Array`), or the JSON text
/// of a [`Reply`].
pub async fn reply(message: JsValue) -> JsValue {
    let text = message.as_string().unwrap_or_default();
    if let Ok(Request::Scorm { link, site }) = serde_json::from_str::<Request>(&text) {
        return match package(link, &site).await {
            Ok(zip) => js_sys::Uint8Array::from(zip.as_slice()).into(),
            Err(e) => {
                JsValue::from_str(&serde_json::to_string(&Reply::Error(e)).unwrap_or_default())
            }
        };
    }
    JsValue::from_str(&reply_text(&text).await)
}

/// Opens an exercise file with its starter.
async fn open(link: ExerciseLink, base: Option<String>) -> Reply {
    let (exercise, statement_html) = match read(&link.exercise, base.as_deref()).await {
        Ok(read) => read,
        Err(e) => return Reply::Error(Failure::FileUnusable(e)),
    };
    let link = link.arranged(&exercise);
    let missing: Vec<String> = exercise
        .starter_files()
        .into_iter()
        .filter(|name| link.file(name).is_none())
        .map(String::from)
        .collect();
    let mut starters = Vec::new();
    if missing.is_empty() {
        // The starter files are ST or project files; the XML reader (a chunk of its own,
        // shared with the import worker) is fetched only for a PLCopen XML or PNML one.
        let mut files: Vec<(String, Result<Project, String>)> = Vec::new();
        let mut passes = plc_core::build::Lowerings::NONE;
        for name in exercise.starter_files() {
            let Some(file) = link.file(name) else { continue };
            let stem = file.name.split('.').next().unwrap_or("starter");
            if let Err(e) = crate::lazy::readers_for(&file.text).await {
                return Reply::Error(Failure::StarterBroken(e.to_string()));
            }
            let opened = match open_plain_by(stem, &file.text, crate::lazy::project_reader()) {
                Ok(Some(opened)) => Ok(opened.project),
                Ok(None) => match super::open_xml(stem.to_string(), file.text.clone()).await {
                    Ok(r) => r.map(|o| o.project),
                    Err(e) => Err(e.to_string()),
                },
                Err(e) => Err(e.to_string()),
            };
            if let Ok(project) = &opened {
                // The passes its diagram POUs need, fetched when missing.
                match super::passes_for(project).await {
                    Ok(p) => passes = p,
                    Err(e) => return Reply::Error(Failure::StarterBroken(e.to_string())),
                }
            }
            files.push((name.to_string(), opened));
        }
        let opened = exercise.starters_by(
            |name| match files.iter().find(|(n, _)| n == name) {
                Some((_, opened)) => opened.clone(),
                None => Err("it was not given".to_string()),
            },
            &passes,
        );
        match opened {
            // The exercise's plant and its scene are in each starter (the grader puts its
            // own plant back in whatever the student changes).
            Ok(list) => {
                starters = list
                    .into_iter()
                    .map(|(language, project)| StarterFile {
                        language: language.code().to_string(),
                        project: project.to_file(),
                    })
                    .collect();
            }
            Err(e) => return Reply::Error(Failure::Plain(e.to_string())),
        }
    }
    let view = ExerciseView::with_statement(&exercise, statement_html);
    Reply::Opened(Box::new(Opened { view, link, base, starters, missing }))
}

/// The reply to a message's text.
pub async fn reply_text(text: &str) -> String {
    let reply = match serde_json::from_str::<Request>(text) {
        Ok(request) => answer(request).await,
        Err(e) => Reply::Error(Failure::BadRequest(e.to_string())),
    };
    serde_json::to_string(&reply).unwrap_or_else(|_| r#"{"Error":"Unwritable"}"#.into())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn ask(request: Request) -> Reply {
        serde_json::from_str(&reply(&serde_json::to_string(&request).unwrap())).unwrap()
    }

    /// The report a `Graded` reply carries (as JSON text, as the page reads it).
    fn report_of(reply: Reply) -> plc_core::exercise::Report {
        let Reply::Graded(text) = reply else { panic!("{reply:?}") };
        serde_json::from_str(&text).unwrap()
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
        let catalogue = crate::exercises::catalogue();
        assert!(catalogue.len() >= 2);
        for id in catalogue.iter().map(|e| e.id) {
            let Reply::Opened(opened) = ask(Request::Shipped((*id).to_string())) else {
                panic!("{id} does not open");
            };
            assert_eq!(opened.view.id, *id);
            assert!(opened.missing.is_empty(), "{id}");
            assert!(!opened.starters.is_empty(), "{id}");
            for s in &opened.starters {
                let p = Project::from_file(&s.project).unwrap();
                assert!(p.settings.program.is_some(), "{id} in {}", s.language);
            }
        }
    }

    /// A shipped exercise opens with its Polish and Czech texts, statements rendered, and
    /// the report of a check names its scenarios in the language chosen.
    #[test]
    fn a_shipped_exercise_opens_with_its_translations() {
        use plc_core::i18n::Lang;
        let Reply::Opened(opened) = ask(Request::Shipped("lamp".into())) else { panic!() };
        let v = &opened.view;
        let pl = v.localised(Lang::Pl);
        assert_eq!(pl.title, "Przycisk zapala lampkę");
        assert!(
            pl.statement_html.contains("<code>Lamp := Button;</code>"),
            "{}",
            pl.statement_html
        );
        assert!(pl.statement_html.contains("<strong>Sprawdź</strong>"), "{}", pl.statement_html);
        assert_eq!(pl.interface[1].meaning, "lampka sygnalizacyjna");
        assert_eq!(pl.scenarios[0].name, "Wciśnięcie i puszczenie");
        assert_eq!(v.localised(Lang::Cs).title, "Tlačítko rozsvítí kontrolku");
        assert_eq!(v.localised(Lang::En).title, "A button lights a lamp");
        let exercise = opened.link.exercise.clone();
        let project = opened.starters[0].project.clone();
        let report = report_of(ask(Request::Grade { exercise, project }));
        let r = v.localised_report(Lang::Cs, report);
        assert_eq!(r.scenarios[0].name, "Stisk a puštění");
        assert!(r.scenarios[0].hint.as_deref().unwrap().starts_with("Zapisuje se Lamp"));
    }

    /// An exercise with a plant opens with the plant and its scene in the starter, and
    /// the grader runs its own plant even when the student deleted theirs.
    #[test]
    fn a_plant_exercise_brings_its_plant_and_grades_with_it() {
        let Reply::Opened(opened) = ask(Request::Shipped("tank-plant".into())) else { panic!() };
        let starter = Project::from_file(&opened.starters[0].project).unwrap();
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
        let report = report_of(graded);
        assert_eq!(report.score, report.total, "{report:?}");
    }

    #[test]
    fn the_starter_fails_and_the_link_reopens_the_exercise() {
        let Reply::Opened(opened) = ask(Request::Shipped("latch".into())) else { panic!() };
        let graded = ask(Request::Grade {
            exercise: opened.link.exercise.clone(),
            project: opened.starters[0].project.clone(),
        });
        let report = report_of(graded);
        assert!(report.score < report.total);
        let failure = report.scenarios.iter().find_map(|s| s.failure.as_ref()).unwrap();
        assert!(failure.window.len() > 11, "the page's window is wide");
        let Reply::Opened(again) = ask(Request::Link(format!("#{}", opened.link.fragment())))
        else {
            panic!()
        };
        assert_eq!(again.view, opened.view);
    }

    /// The latch opens with a starter in ST and one in ladder, each naming PROGRAM Main;
    /// the ladder reference in the ladder starter's place is graded as that ladder POU.
    #[test]
    fn an_exercise_opens_in_each_of_its_languages() {
        let Reply::Opened(opened) = ask(Request::Shipped("latch".into())) else { panic!() };
        let languages: Vec<&str> = opened.starters.iter().map(|s| s.language.as_str()).collect();
        assert_eq!(languages, ["st", "ld"]);
        let ld = Project::from_file(&opened.starters[1].project).unwrap();
        assert_eq!(ld.settings.program.as_deref(), Some("Main"));
        assert_eq!((ld.ladder.len(), ld.source.trim()), (1, ""));
        assert!(ld.ladder[0].declarations.contains("Motor : BOOL; (* motor contactor *)"));
        let mut solved = ld.clone();
        let reference: Project =
            Project::from_file(include_str!("../../../exercises/latch/reference-ld.plcproj.json"))
                .unwrap();
        solved.ladder[0].rungs = reference.ladder[0].rungs.clone();
        let report = report_of(ask(Request::Grade {
            exercise: opened.link.exercise.clone(),
            project: solved.to_file(),
        }));
        assert_eq!((report.score, report.total), (3, 3));
        assert_eq!(report.checked_line().unwrap(), "Checked PROGRAM Main (ladder)");
        // A file given without its starter names it as missing (the page fetches it).
        let bare = ExerciseLink {
            exercise: opened.link.exercise.clone(),
            starter: None,
            starters: Vec::new(),
        };
        let Reply::Opened(bare) = ask(Request::File { link: bare, base: None }) else { panic!() };
        assert_eq!(
            (bare.missing.as_slice(), bare.starters.len()),
            (&["starter.st".to_string()][..], 0)
        );
    }

    #[test]
    fn bad_requests_get_messages() {
        let Reply::Error(e) = serde_json::from_str(&reply("nonsense")).unwrap() else { panic!() };
        assert!(e.text().contains("cannot read"));
        let Reply::Error(e) = ask(Request::Shipped("nope".into())) else { panic!() };
        assert!(e.text().contains("nope"));
        let Reply::Error(e) = ask(Request::Link("x=AAAA".into())) else { panic!() };
        let e = e.text();
        assert!(e.contains("damaged"), "{e}");
        let bad = ExerciseLink { exercise: "id = 1".into(), starter: None, starters: Vec::new() };
        let Reply::Error(e) = ask(Request::File { link: bad, base: None }) else { panic!() };
        let e = e.text();
        assert!(e.starts_with("the exercise file cannot be used: line 1"), "{e}");
        let Reply::Error(e) = ask(Request::Grade {
            exercise: "id = \"a\"\ntitle = \"A\"\nlevel = 1\n".into(),
            project: "{".into(),
        }) else {
            panic!()
        };
        let e = e.text();
        assert!(e.contains("project cannot be read"), "{e}");
    }
}
