//! Views and code that load on first use, each from its own chunk of the app's wasm module
//! (see docs/loading.md).
//!
//! A function marked `#[wasm_split(NAME, …)]` is a split point: `scripts/build-web.sh`
//! (wasm-split after cargo) moves it, and everything only it reaches, into the chunk
//! `split_NAME.wasm`; code that several chunks share goes into a `chunk_N.wasm` they both
//! load, and code the first screen reaches stays in the main module. Calling the function
//! fetches its chunk the first time (hence `async`); natively it is an ordinary call. Every
//! split function here is `fallible`: a chunk that cannot be fetched (offline before the
//! service worker cached it) gives [`LoadFailed`] instead of stopping the page.
//!
//! To make a view lazy: write a split function that returns it as an `AnyView` and show it
//! with [`lazy_view`], naming it by a [`What`]: that gives its `Loading …` (role=status)
//! and `Could not load …` sentences, and the style sheet it needs (`views.css`,
//! `exercises.css`: fetched with the first view that needs it).

use std::cell::Cell;
use std::future::Future;

use leptos::__reexports::send_wrapper::SendWrapper;
use leptos::prelude::*;
use leptos::wasm_split::wasm_split;
use plc_core::build::{LadderLowering, Lowerings, NetworkPass, PetriPass};
use plc_core::semantic::{IlPass, SfcPass};
use plc_core::sim::{BreakpointId, ScanOutcome, SimError, Simulator};

use crate::i18n::{t, K};

/// A chunk of the app could not be fetched.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LoadFailed;

impl From<leptos::wasm_split::SplitLoaderError> for LoadFailed {
    fn from(_: leptos::wasm_split::SplitLoaderError) -> Self {
        LoadFailed
    }
}

impl std::fmt::Display for LoadFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(t(K::lazy_load_failed))
    }
}

/// What a lazy view loads: its `Loading …` and `Could not load …` sentences, each
/// translated whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum What {
    Recording,
    NewPouDialog,
    LadderEditor,
    PetriEditor,
    SfcChart,
    NetworkView,
    ExerciseCatalogue,
    Exercise,
    Report,
    Explanation,
    PlantScene,
}

impl What {
    /// `Loading the ladder editor…`.
    fn loading(self) -> K {
        match self {
            What::Recording => K::lazy_loading_recording,
            What::NewPouDialog => K::lazy_loading_new_pou_dialog,
            What::LadderEditor => K::lazy_loading_ladder_editor,
            What::PetriEditor => K::lazy_loading_petri_editor,
            What::SfcChart => K::lazy_loading_sfc_chart,
            What::NetworkView => K::lazy_loading_network_view,
            What::ExerciseCatalogue => K::lazy_loading_exercise_catalogue,
            What::Exercise => K::lazy_loading_exercise,
            What::Report => K::lazy_loading_report,
            What::Explanation => K::lazy_loading_explanation,
            What::PlantScene => K::lazy_loading_plant_scene,
        }
    }

    /// `Could not load the ladder editor (is the network off?).`
    fn failed(self) -> K {
        match self {
            What::Recording => K::lazy_failed_recording,
            What::NewPouDialog => K::lazy_failed_new_pou_dialog,
            What::LadderEditor => K::lazy_failed_ladder_editor,
            What::PetriEditor => K::lazy_failed_petri_editor,
            What::SfcChart => K::lazy_failed_sfc_chart,
            What::NetworkView => K::lazy_failed_network_view,
            What::ExerciseCatalogue => K::lazy_failed_exercise_catalogue,
            What::Exercise => K::lazy_failed_exercise,
            What::Report => K::lazy_failed_report,
            What::Explanation => K::lazy_failed_explanation,
            What::PlantScene => K::lazy_failed_plant_scene,
        }
    }
}

/// Shows the view that `load` gives, with `Loading …` (role=status) naming `what` until
/// its chunk has come, and a `Retry` button if it could not be fetched.
pub fn lazy_view<F, Fut>(what: What, load: F) -> AnyView
where
    F: Fn() -> Fut + Send + Sync + 'static,
    Fut: Future<Output = Result<AnyView, LoadFailed>> + 'static,
{
    lazy_with(what, load)
}

impl What {
    /// The style sheet the view needs beyond the first load's: the diagrams' and the
    /// exercises' rules come with their views (in the app's folder, cached offline).
    fn sheet(self) -> Option<&'static str> {
        match self {
            What::Recording | What::Explanation => None,
            What::Exercise | What::ExerciseCatalogue | What::Report => Some("exercises.css"),
            What::NewPouDialog
            | What::LadderEditor
            | What::PetriEditor
            | What::SfcChart
            | What::NetworkView
            | What::PlantScene => Some("views.css"),
        }
    }
}

/// Loads the style sheet `name` from the app's folder, once for the page: resolves when
/// its rules apply. A sheet that could not be fetched is taken out again, so that `Retry`
/// asks for it anew.
async fn sheet(name: &'static str) -> Result<(), LoadFailed> {
    use wasm_bindgen::{closure::Closure, JsCast};
    let doc = web_sys::window().and_then(|w| w.document()).ok_or(LoadFailed)?;
    let link = match doc.query_selector(&format!("link[data-sheet=\"{name}\"]")) {
        Ok(Some(link)) => link,
        _ => {
            let link = doc.create_element("link").map_err(|_| LoadFailed)?;
            let _ = link.set_attribute("rel", "stylesheet");
            let _ = link.set_attribute("data-sheet", name);
            let _ = link.set_attribute("href", &format!("{}{name}", crate::import::app_base()));
            // The first listener marks the sheet loaded: a later caller that finds no mark
            // is in time for the event.
            let mark = link.clone();
            let loaded = Closure::once_into_js(move || {
                let _ = mark.set_attribute("data-loaded", "");
            });
            let _ = link.add_event_listener_with_callback("load", loaded.unchecked_ref());
            let head = doc.query_selector("head").ok().flatten().ok_or(LoadFailed)?;
            head.append_child(&link).map_err(|_| LoadFailed)?;
            link
        }
    };
    if link.has_attribute("data-loaded") {
        return Ok(());
    }
    let target = link.clone();
    let done = js_sys::Promise::new(&mut |resolve, reject| {
        let _ = target.add_event_listener_with_callback("load", &resolve);
        let _ = target.add_event_listener_with_callback("error", &reject);
    });
    match wasm_bindgen_futures::JsFuture::from(done).await {
        Ok(_) => Ok(()),
        Err(_) => {
            link.remove();
            Err(LoadFailed)
        }
    }
}

/// Shows `what`'s view once its chunk (and its style sheet) has come: `Loading …` until
/// then, a sentence and `Retry` if it could not be fetched.
fn lazy_with<F, Fut>(what: What, load: F) -> AnyView
where
    F: Fn() -> Fut + Send + Sync + 'static,
    Fut: Future<Output = Result<AnyView, LoadFailed>> + 'static,
{
    let attempt = RwSignal::new(0u32);
    let loading = move || {
        view! { <p class="lazy-loading" role="status">{t(what.loading())}</p> }
    };
    view! {
        <Suspense fallback=loading>
            {move || {
                attempt.track();
                let load = load();
                // The page is single-threaded: the future never leaves it.
                Suspend::new(SendWrapper::new(async move {
                    let styled = match what.sheet() {
                        Some(name) => sheet(name).await,
                        None => Ok(()),
                    };
                    match (styled, load.await) {
                        (Ok(()), Ok(view)) => view,
                        _ => view! {
                            <p class="lazy-failed" role="alert">
                                {t(what.failed())}" "
                                <button class="link" on:click=move |_| attempt.update(|n| *n += 1)>{t(K::lazy_retry)}</button>
                            </p>
                        }
                        .into_any(),
                    }
                }))
            }}
        </Suspense>
    }
    .into_any()
}

/// The ladder editor (`LadderView`) of the ladder POU `name`.
#[wasm_split(ladder, wasm_split_path = ::leptos::wasm_split, fallible, preload(preload_ladder))]
pub fn ladder_view(name: String) -> Result<AnyView, LoadFailed> {
    use crate::components::ladder::LadderView;
    Ok(view! { <LadderView name=name/> }.into_any())
}

/// The Petri net editor (`PetriView`) of the net POU `name`.
#[wasm_split(petri, wasm_split_path = ::leptos::wasm_split, fallible, preload(preload_petri))]
pub fn petri_view(name: String) -> Result<AnyView, LoadFailed> {
    use crate::components::petri::PetriView;
    Ok(view! { <PetriView name=name/> }.into_any())
}

/// The chart of the textual SFC POU `name`.
#[wasm_split(sfc, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn sfc_view(name: String) -> Result<AnyView, LoadFailed> {
    use crate::components::sfc::SfcView;
    Ok(view! { <SfcView name=name/> }.into_any())
}

/// The view of the network POU `name` (LD or FBD as an imported file drew it).
#[wasm_split(network, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn network_view(name: String) -> Result<AnyView, LoadFailed> {
    use crate::components::network::NetworkView;
    Ok(view! { <NetworkView name=name/> }.into_any())
}

/// The exercise catalogue, in place of the workspace.
#[wasm_split(exercise_ui, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn catalogue_view() -> Result<AnyView, LoadFailed> {
    use crate::exercises::Catalogue;
    Ok(view! { <Catalogue/> }.into_any())
}

/// The open exercise beside the editors (statement, interface, Check, report).
#[wasm_split(exercise_ui, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn exercise_panel_view() -> Result<AnyView, LoadFailed> {
    use crate::exercises::ExercisePanel;
    Ok(view! { <ExercisePanel/> }.into_any())
}

/// Reads an answer of the exercise worker (its decoder is a good part of the exercise
/// code, so it comes with the exercise views).
#[wasm_split(exercise_ui, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn read_exercise_reply(
    text: String,
) -> Result<Option<crate::exercises::protocol::Reply>, LoadFailed> {
    Ok(serde_json::from_str(&text).ok())
}

/// Reads the report of a check (the exercise worker's `Graded` answer): its decoder comes
/// with the report's view, fetched at the first check rather than when an exercise opens.
#[wasm_split(exercise_report, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn read_report(text: String) -> Result<Result<plc_core::exercise::Report, String>, LoadFailed> {
    Ok(serde_json::from_str(&text).map_err(|e| e.to_string()))
}

/// The report of the last check (`exercises::report`).
#[wasm_split(exercise_report, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn report_view() -> Result<AnyView, LoadFailed> {
    use crate::exercises::report::ReportView;
    Ok(view! { <ReportView/> }.into_any())
}

/// Opening an exercise: asking the worker, fetching its starter, opening the attempt. The
/// returned future does it (its code is in this chunk too).
#[wasm_split(exercise_ui, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn open_exercise(
    ex: crate::exercises::Exercises,
    state: crate::state::AppState,
    how: crate::exercises::OpenHow,
) -> Result<std::pin::Pin<Box<dyn Future<Output = ()>>>, LoadFailed> {
    Ok(Box::pin(ex.open_how(state, how)))
}

/// An example being opened: the project, or why it could not be opened.
pub type OpeningExample =
    std::pin::Pin<Box<dyn Future<Output = Result<plc_core::project::Project, String>>>>;

/// Fetches the shipped example `file` and opens it as a new project (reading an ST file
/// or a project file): fetched the first time an example is opened.
#[wasm_split(examples, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn open_example(file: String) -> Result<OpeningExample, LoadFailed> {
    Ok(Box::pin(async move { crate::examples::open(&file).await }))
}

/// Imports the file the student chose as a new project (reading it, asking the import
/// worker, the banner's words): fetched the first time a file is imported.
#[wasm_split(import_ui, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn import_file(
    state: crate::state::AppState,
    file: web_sys::File,
) -> Result<std::pin::Pin<Box<dyn Future<Output = ()>>>, LoadFailed> {
    Ok(Box::pin(crate::components::header::import_file(state, file)))
}

/// Starts the SCORM session when the page was launched by an LMS (false without one).
#[wasm_split(scorm, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn scorm_launch(
    ex: crate::exercises::Exercises,
    state: crate::state::AppState,
) -> Result<bool, LoadFailed> {
    Ok(crate::exercises::scorm::launch(ex, state))
}

/// Opens the attempt the LMS kept, once the launched exercise is open.
#[wasm_split(scorm, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn scorm_resume(
    ex: crate::exercises::Exercises,
    state: crate::state::AppState,
) -> Result<(), LoadFailed> {
    crate::exercises::scorm::resume(ex, state);
    Ok(())
}

/// Reports a graded attempt to the LMS (the score, passed or not, the attempt kept).
#[wasm_split(scorm, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn scorm_report(
    state: crate::state::AppState,
    id: String,
    report: plc_core::exercise::Report,
) -> Result<(), LoadFailed> {
    crate::exercises::scorm::report(state, &id, &report);
    Ok(())
}

/// The timeline as a file, CSV (`csv`) or VCD for GTKWave; `None` before a program runs.
#[wasm_split(exports, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn timeline_file(
    state: crate::state::AppState,
    csv: bool,
) -> Result<Option<String>, LoadFailed> {
    use plc_core::export::{trace_csv, trace_vcd};
    Ok(state.sim.with_value(|s| {
        s.as_ref().map(|s| if csv { trace_csv(s.trace()) } else { trace_vcd(s.trace()) })
    }))
}

/// The variable table as CSV; `None` without a program.
#[wasm_split(exports, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn variables_file(state: crate::state::AppState) -> Result<Option<String>, LoadFailed> {
    use plc_core::export::{snapshot, variables_csv};
    Ok(state.sim.with_value(|s| s.as_ref().map(|s| variables_csv(&snapshot(s)))))
}

/// The share fragment of `project` (`p=…`): its DEFLATE writer is only needed when the
/// user shares, so it comes with the exports (opening a share link needs only the reader).
#[wasm_split(exports, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn share_fragment(project: plc_core::project::Project) -> Result<String, LoadFailed> {
    Ok(plc_core::project::encode_share(&project))
}

/// The fragment of a link that carries the exercise `link` (`x=…`): the same DEFLATE
/// writer, fetched only when the student shares the exercise.
#[wasm_split(exports, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn exercise_fragment(link: plc_core::exercise::ExerciseLink) -> Result<String, LoadFailed> {
    Ok(link.fragment())
}

/// What an exercise link's fragment (`x=…`) carries, its exercise not read yet: the
/// share links' reader, fetched by the exercise worker only to open such a link.
#[wasm_split(share_reader, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn read_exercise_link(
    fragment: String,
) -> Result<Result<plc_core::exercise::ExerciseLink, String>, LoadFailed> {
    Ok(plc_core::exercise::ExerciseLink::unpack(&fragment).map_err(|e| e.to_string()))
}

/// The project in a share link's fragment (`#p=…`): its base64 and DEFLATE reader is
/// fetched only when the page opens a link.
#[wasm_split(share_reader, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn read_share(
    fragment: String,
) -> Result<Result<plc_core::project::Project, plc_core::project::ShareError>, LoadFailed> {
    Ok(plc_core::project::decode_share(&fragment))
}

/// The `Explanation` region (`Why?` buttons open it) and the core's why engine.
#[wasm_split(why, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn explanation_view() -> Result<AnyView, LoadFailed> {
    use crate::components::why::Explanation;
    Ok(view! { <Explanation/> }.into_any())
}

/// Shows recorded scan `scan`, rebuilt by replaying from the nearest snapshot (issue 36):
/// the replay comes with the first step back.
#[wasm_split(past, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn show_scan(state: crate::state::AppState, scan: u64) -> Result<(), LoadFailed> {
    state.show_scan_now(scan);
    Ok(())
}

/// The `Recorded scan` slider and the banner of a past scan.
#[wasm_split(past, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn recorded_view() -> Result<AnyView, LoadFailed> {
    use crate::components::recorded::Recorded;
    Ok(view! { <Recorded/> }.into_any())
}

/// Makes recorded scan `scan` the present, dropping the later ones up to `last`.
#[wasm_split(past, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn rewind(state: crate::state::AppState, scan: u64, last: u64) -> Result<(), LoadFailed> {
    state.rewind_now(scan, last);
    Ok(())
}

/// The plant's scene (its widgets drawn and its buttons and switches).
#[wasm_split(scene, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn scene_view() -> Result<AnyView, LoadFailed> {
    use crate::components::scene::ScenePanel;
    Ok(view! { <ScenePanel/> }.into_any())
}

/// The simulator watches a network PROGRAM needs for its function outputs
/// (`plc_core::network::live::function_watches`).
pub type NetworkWatches = fn(&plc_core::network::NetworkPou) -> Vec<((String, String), String)>;

thread_local! {
    /// The passes for diagram POUs loaded so far (`plc_core::build::Lowerings`).
    static PASSES: Cell<Lowerings> = const { Cell::new(Lowerings::NONE) };
    /// The engine's checker and compiler, once loaded.
    static ENGINE: Cell<Option<Engine>> = const { Cell::new(None) };
    /// The engine's chunk is being fetched.
    static ENGINE_LOADING: Cell<bool> = const { Cell::new(false) };
    /// The network watches, loaded with the network pass.
    static WATCHES: Cell<Option<NetworkWatches>> = const { Cell::new(None) };
    /// The project reader with the diagram models' readers, once loaded.
    static READER: Cell<Option<plc_core::project::ProjectReader>> = const { Cell::new(None) };
}

/// The network watches, once the network pass is loaded (it is before a project with a
/// network POU is built).
pub fn network_watches() -> Option<NetworkWatches> {
    WATCHES.with(Cell::get)
}

/// The passes for diagram POUs the page has loaded: a project is built with these
/// (`plc_core::build::build_project_by`).
pub fn lowerings() -> Lowerings {
    PASSES.with(Cell::get)
}

/// The engine: the ST parser, checker and compiler and the virtual machine that runs the
/// scans (a chunk fetched right after the first screen: the page holds simulators, reads
/// and draws them, and calls the engine's code through these).
#[derive(Clone, Copy)]
pub struct Engine {
    /// Builds a project with the passes loaded.
    pub build: fn(&plc_core::project::Project, &Lowerings) -> plc_core::build::ProjectBuild,
    /// The passes a project needs that are not loaded yet (`Lowerings::lacks`: it parses
    /// the ST source for SFC and IL bodies).
    pub lacks: fn(&Lowerings, &plc_core::project::Project) -> Vec<&'static str>,
    /// The POUs of an ST source that are written as SFC charts.
    pub charts: fn(&str) -> Vec<String>,
    /// Runs scans (the virtual machine).
    pub run_scans: fn(&mut Simulator, u64) -> ScanOutcome,
    /// Cold restart (the first scan runs).
    pub cold_restart: fn(&mut Simulator),
    /// Warm restart, RETAIN kept (the first scan runs).
    pub warm_restart: fn(&mut Simulator),
    /// The ST source with a declaration of a variable added for its use at a span
    /// (`syntax::fix::declare_variable`: it parses the source).
    pub declare: fn(&str, plc_core::diagnostics::Span, &str, &str) -> Option<String>,
    /// Powers a simulator on for a PROGRAM of a build, with its plant.
    pub simulator: PowerOn,
    /// Holds a variable at a value typed as an IEC literal.
    pub hold: SimText,
    /// Forces a variable to a value typed as an IEC literal.
    pub force: SimText,
    /// Writes a value typed as an IEC literal once.
    pub write: SimText,
    /// Watches an ST expression.
    pub add_watch: fn(&mut Simulator, &str) -> Result<(), SimError>,
    /// Adds a breakpoint on an ST condition.
    pub add_breakpoint: fn(&mut Simulator, &str) -> Result<BreakpointId, SimError>,
}

/// Powers a simulator on for PROGRAM `name` of a build (or the first), with its plant.
pub type PowerOn = fn(
    &plc_core::build::ProjectBuild,
    Option<&str>,
    Option<&str>,
) -> Result<Simulator, plc_core::build::ProjectDiagnostic>;

/// A simulator operation on a variable with a value typed as text.
pub type SimText = fn(&mut Simulator, &str, &str) -> Result<(), SimError>;

/// How the page reads a stored project: with the diagram models' readers once they are
/// here, else without them (a project with diagram POUs then waits for them:
/// `AppState::open`).
pub fn project_reader() -> plc_core::project::ProjectReader {
    // Natively (the tests) there are no chunks: the whole reader is there.
    #[cfg(not(target_arch = "wasm32"))]
    return plc_core::project::Project::from_file;
    #[cfg(target_arch = "wasm32")]
    READER.with(Cell::get).unwrap_or(plc_core::project::Project::from_file_without_diagrams)
}

/// Fetches the diagram models' readers when `text` is a project file with diagram POUs
/// (once for the page): [`project_reader`] then reads it whole.
pub async fn readers_for(text: &str) -> Result<(), LoadFailed> {
    use plc_core::project::{Project, ProjectError};
    let lacking =
        Project::from_file_without_diagrams(text) == Err(ProjectError::NeedsDiagramReaders);
    if lacking && READER.with(Cell::get).is_none() {
        load_project_reader().await?;
    }
    Ok(())
}

/// Fetches the readers of the diagram POUs' models (ladder, network, Petri net), the
/// first time a stored project with such POUs is opened.
pub async fn load_project_reader() -> Result<(), LoadFailed> {
    let reader = project_reader_chunk().await?;
    READER.with(|r| r.set(Some(reader)));
    Ok(())
}

/// Reads a project file with its diagram POUs (`Project::from_file`): the readers of the
/// ladder, network and Petri net models are a chunk of their own, which a project with
/// only ST never fetches.
#[wasm_split(project_reader, wasm_split_path = ::leptos::wasm_split, fallible)]
fn project_reader_chunk() -> Result<plc_core::project::ProjectReader, LoadFailed> {
    Ok(plc_core::project::Project::from_file)
}

/// The engine, once loaded.
pub fn engine() -> Option<Engine> {
    ENGINE.with(Cell::get)
}

/// Whether the engine's chunk is being fetched.
pub fn engine_loading() -> bool {
    ENGINE_LOADING.with(Cell::get)
}

/// Fetches the engine's chunk (the page does as it starts, with its first check).
pub async fn load_engine() -> Result<(), LoadFailed> {
    if engine().is_some() {
        return Ok(());
    }
    ENGINE_LOADING.with(|l| l.set(true));
    let loaded = engine_chunk().await;
    ENGINE_LOADING.with(|l| l.set(false));
    let engine = loaded?;
    ENGINE.with(|c| c.set(Some(engine)));
    Ok(())
}

/// The engine's parser, checker, compiler and virtual machine, and the simulator's
/// operations that read ST, a chunk of their own (`engine`, fetched as the page starts):
/// the first screen is drawn without them. Only reading a simulator's variables and trace
/// stays in the main module (the panels do it on every frame); every operation that
/// parses, compiles or scans is here.
#[wasm_split(engine, wasm_split_path = ::leptos::wasm_split, fallible)]
fn engine_chunk() -> Result<Engine, LoadFailed> {
    Ok(Engine {
        build: plc_core::build::build_project_by,
        lacks: Lowerings::lacks,
        charts: |source| {
            plc_core::sfc::outline::outlines(source).into_iter().map(|o| o.pou).collect()
        },
        run_scans: Simulator::run_scans,
        cold_restart: Simulator::cold_restart,
        warm_restart: Simulator::warm_restart,
        declare: plc_core::syntax::fix::declare_variable,
        simulator: |b, name, plant| b.simulator_with_plant(name, plant),
        hold: Simulator::hold,
        force: Simulator::force,
        write: Simulator::write,
        add_watch: Simulator::add_watch,
        add_breakpoint: Simulator::add_breakpoint,
    })
}

/// Fetches the editor of a new ladder (`petri` false) or Petri net POU and the pass that
/// builds it, while the user names the POU.
pub async fn preload_editor(petri: bool) -> Result<(), LoadFailed> {
    if petri {
        load_lowerings(&["petri"]).await?;
        preload_petri().await?;
    } else {
        load_lowerings(&["ladder"]).await?;
        preload_ladder().await?;
    }
    Ok(())
}

/// Fetches the passes named by `kinds` (as `Lowerings::lacks` names them).
pub async fn load_lowerings(kinds: &[&str]) -> Result<(), LoadFailed> {
    for kind in kinds {
        let mut passes = lowerings();
        match *kind {
            "ladder" => passes.ladder = Some(ladder_pass().await?),
            "network" => {
                passes.network = Some(network_pass().await?);
                let watches = network_watches_pass().await?;
                WATCHES.with(|w| w.set(Some(watches)));
            }
            "petri" => passes.petri = Some(petri_pass().await?),
            "sfc" => passes.text.sfc = Some(sfc_pass().await?),
            "il" => passes.text.il = Some(il_pass().await?),
            _ => {}
        }
        PASSES.with(|p| p.set(passes));
    }
    Ok(())
}

/// The ladder POUs' validation and lowering to ST.
#[wasm_split(ladder_pass, wasm_split_path = ::leptos::wasm_split, fallible)]
fn ladder_pass() -> Result<LadderLowering, LoadFailed> {
    Ok(LadderLowering { validate: plc_core::ladder::validate_with, lower: plc_core::ladder::lower })
}

/// The network POUs' ST (power flow, execution order, SFC charts).
#[wasm_split(network_pass, wasm_split_path = ::leptos::wasm_split, fallible)]
fn network_pass() -> Result<NetworkPass, LoadFailed> {
    Ok(plc_core::network::NetworkPou::to_st)
}

/// What the simulator watches for a network PROGRAM's function outputs.
#[wasm_split(network_pass, wasm_split_path = ::leptos::wasm_split, fallible)]
fn network_watches_pass() -> Result<NetworkWatches, LoadFailed> {
    Ok(plc_core::network::live::function_watches)
}

/// Textual SFC bodies (typed, or generated for an SFC network chart) lowered to
/// statements.
#[wasm_split(sfc_pass, wasm_split_path = ::leptos::wasm_split, fallible)]
fn sfc_pass() -> Result<SfcPass, LoadFailed> {
    Ok(plc_core::sfc::desugar)
}

/// Instruction List bodies lowered to statements.
#[wasm_split(il_pass, wasm_split_path = ::leptos::wasm_split, fallible)]
fn il_pass() -> Result<IlPass, LoadFailed> {
    Ok(plc_core::semantic::desugar_il)
}

/// The Petri net POUs' generated code and analysis.
#[wasm_split(petri_pass, wasm_split_path = ::leptos::wasm_split, fallible)]
fn petri_pass() -> Result<PetriPass, LoadFailed> {
    Ok(plc_core::petri::compile)
}

/// The `New ladder POU` (`petri` false) or `New Petri net POU` dialog; `open` goes false
/// when it closes.
#[wasm_split(new_pou, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn new_pou_dialog(petri: bool, open: RwSignal<bool>) -> Result<AnyView, LoadFailed> {
    use crate::components::new_pou::NewPouDialog;
    Ok(view! { <NewPouDialog petri=petri open=open/> }.into_any())
}

/// The `Start here` strip at `step` (`done`: its action was seen): what a screen reader
/// hears, `\u{1}`, the strip's markup (`components::tour::tour_text`).
#[wasm_split(tour, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn tour_text(step: usize, done: bool) -> Result<String, LoadFailed> {
    Ok(crate::components::tour::tour_text(step, done))
}

/// The content of the `Keyboard shortcuts` dialog.
#[wasm_split(help, wasm_split_path = ::leptos::wasm_split, fallible)]
pub fn shortcuts_text() -> Result<String, LoadFailed> {
    Ok(crate::components::help::shortcuts_html())
}
