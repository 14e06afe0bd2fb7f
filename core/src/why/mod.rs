//! "Why is this on?": the explanation of a value at a recorded scan.
//!
//! The simulator owns every scan and is deterministic, so a recorded scan can be run again
//! from the state before it with every write logged ([`Simulator::trace_scan`]). The last
//! write of the variable in that scan names its writer — a statement, a rung, a network
//! element, a Petri net transition or place action, an SFC transition or action, a value
//! from outside — through the debug map and the project's source map; the checked IR of the
//! writing statement names the values that decided it (its expression's operands and the
//! conditions of the IF, CASE or loop around it), read as they were when it ran. The
//! hidden variables of the front-ends (a rung's power flow, a net's scan copies, IL's
//! current result) are followed to the operands the user wrote, and a rung's power path is
//! kept. Each operand says since which scan it has had its value, found by walking the
//! recording backwards, so the student can follow the cause scan by scan.
//!
//! Nothing here runs on the hot path: recording costs the simulator a snapshot every few
//! scans, and the instrumented replay happens only when an explanation is asked for.
//! The same functions serve `plc why` and the web app (`docs/why.md`).

mod scan;

use serde::Serialize;
use serde_json::Value as Json;

use crate::build::{ProjectBuild, Site};
use crate::compile::Slot;
use crate::diagnostics::Span;
use crate::export::value_text;
use crate::petri::{NetElement, TextPart};
use crate::project::Project;
use crate::semantic::ir::{CallArg, ExprKind, Place, StmtKind};
use crate::semantic::types::PouId;
use crate::sim::{RecordError, SimError, Simulator};
use crate::syntax::VarSection;
use crate::vm::{self, Cause, Value};
use scan::{Frame, Scan, Writer};

#[cfg(test)]
mod tests;

/// How deep hidden variables are followed (a rung's power flow is one level per element).
const MAX_DEPTH: usize = 256;

/// What an explanation needs besides the simulator: the project and its build (for the
/// source text and where each line came from).
#[derive(Debug, Clone, Copy)]
pub struct Context<'a> {
    project: &'a Project,
    build: &'a ProjectBuild,
}

impl<'a> Context<'a> {
    /// The context of a project built by [`crate::build::build_project`] (the build the
    /// simulator was made from).
    pub fn new(project: &'a Project, build: &'a ProjectBuild) -> Context<'a> {
        Context { project, build }
    }

    fn text(&self, span: Span) -> String {
        let text = self.build.source.as_ref().map_or("", |s| s.text.as_str());
        let raw = text.get(span.start as usize..span.end as usize).unwrap_or_default();
        let words = raw.split_whitespace().collect::<Vec<_>>().join(" ");
        words.trim_end_matches(';').trim_end().to_string()
    }

    fn site(&self, span: Span) -> Site {
        self.build.site_of(span)
    }
}

/// What kind of thing wrote a value (`written_by.kind` in JSON).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// An ST or IL statement (also a Petri net's prologue or epilogue, an SFC's generated
    /// bookkeeping).
    Statement,
    /// A ladder rung.
    Rung,
    /// An element of a network POU (LD or FBD kept as drawn).
    Element,
    /// A Petri net or SFC transition firing.
    Transition,
    /// A Petri net place's or an SFC step's action.
    StepAction,
    /// A value from outside: a held input or a value written between scans.
    Input,
    /// A forced value.
    Forced,
    /// The declared initial value: nothing has written it since the start.
    Initial,
    /// Nothing wrote it on the scan asked about (see `since_scan` and `then`), or not
    /// since the first scan recorded.
    None,
}

/// What wrote the value (`written_by` in JSON).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WrittenBy {
    /// What kind of thing.
    pub kind: Kind,
    /// The POU it belongs to.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pou: Option<String>,
    /// The 1-based line in the project's ST source (ST, IL and SFC).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<u32>,
    /// The 1-based rung of a ladder POU.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rung: Option<usize>,
    /// The 1-based row of the ladder element that wrote it (its coil or block).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub row: Option<usize>,
    /// The 1-based column of that element.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub column: Option<usize>,
    /// The element: a network element's `localId`, a Petri net transition or place, an SFC
    /// transition or step, a ladder element in words (`coil Motor`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub element: Option<String>,
    /// The statement, rung or guard as text (`Motor := (Start OR Motor) AND NOT Stop`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text: Option<String>,
    /// For `none` and `initial`: the scan since which the value has been unchanged.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub since_scan: Option<u64>,
    /// For `none`: what wrote the value on scan `since_scan`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub then: Option<Box<WrittenBy>>,
    /// Where to show it (a statement's line, a rung's cell, a net element): the UI's link.
    #[serde(skip)]
    pub site: Option<Site>,
}

impl WrittenBy {
    fn of(kind: Kind) -> WrittenBy {
        WrittenBy {
            kind,
            pou: None,
            line: None,
            rung: None,
            row: None,
            column: None,
            element: None,
            text: None,
            since_scan: None,
            then: None,
            site: None,
        }
    }

    /// The writer in words: `Main line 9: Motor := …`, `Latch rung 1 (coil Motor): …`,
    /// `Weighing transition T2 (guard Start AND NOT Fault)`, `a held input`.
    pub fn describe(&self) -> String {
        let pou = self.pou.as_deref().unwrap_or("the program");
        let text = self.text.as_deref().unwrap_or_default();
        let with_text = |head: String| {
            if text.is_empty() {
                head
            } else {
                format!("{head}: {text}")
            }
        };
        match self.kind {
            Kind::Statement => match (self.line, &self.element) {
                (Some(l), _) => with_text(format!("{pou} line {l}")),
                (None, Some(e)) => with_text(format!("{pou} {e}")),
                (None, None) => with_text(pou.to_string()),
            },
            Kind::Rung => {
                let element =
                    self.element.as_deref().map(|e| format!(" ({e})")).unwrap_or_default();
                with_text(format!("{pou} rung {}{element}", self.rung.unwrap_or(0)))
            }
            Kind::Element => {
                with_text(format!("{pou} element {}", self.element.as_deref().unwrap_or_default()))
            }
            Kind::Transition => {
                let t = self.element.as_deref().unwrap_or_default();
                let line = self.line.map(|l| format!(" line {l}")).unwrap_or_default();
                match text.is_empty() {
                    true => format!("{pou} transition {t}{line}"),
                    false => format!("{pou} transition {t}{line} (condition {text})"),
                }
            }
            Kind::StepAction => {
                let e = self.element.as_deref().unwrap_or_default();
                let head = if e.starts_with("action ") {
                    format!("{pou} {e}")
                } else {
                    format!("{pou} {e} action")
                };
                match self.line {
                    Some(l) => with_text(format!("{head} (line {l})")),
                    None => with_text(head),
                }
            }
            Kind::Input => text_or(text, "a value from outside"),
            Kind::Forced => text_or(text, "forcing"),
            Kind::Initial => "its initial value".to_string(),
            Kind::None => match &self.then {
                Some(then) => then.describe(),
                None => "nothing since the first scan recorded".to_string(),
            },
        }
    }
}

fn text_or(text: &str, default: &str) -> String {
    if text.is_empty() {
        default.to_string()
    } else {
        text.to_string()
    }
}

/// A value that decided the explained one.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Operand {
    /// Its path, as [`Simulator::read`] takes it: the next `Why?` asks about it.
    pub name: String,
    /// Its value when the writer read it.
    pub value: Json,
    /// The first scan of the run of scans over which it has had this value (the scan
    /// asked about when it got the value on that very scan; the first scan recorded when
    /// it has had it since then).
    pub since_scan: u64,
    /// The value as IEC text (`TRUE`, `T#1s500ms`).
    #[serde(skip)]
    pub text: String,
}

/// One element of a rung and whether power left it (`path` in JSON).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PowerStep {
    /// 1-based row.
    pub row: usize,
    /// 1-based column.
    pub column: usize,
    /// The element in words (`NO contact Start`).
    pub element: String,
    /// Whether power left it.
    pub powered: bool,
}

/// The function block instance that wrote the value (`block` in JSON).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Block {
    /// Its path (`LampDelay`).
    pub instance: String,
    /// Its function block (`TON`).
    #[serde(rename = "type")]
    pub fb: String,
    /// The last changes of its BOOL inputs and outputs and of a counter's value up to the
    /// scan (at most [`HISTORY`] per variable), oldest first: a timer's IN and Q, a
    /// counter's CU and CV.
    pub history: Vec<Change>,
}

/// How many changes of each of a block's variables [`Block::history`] keeps.
pub const HISTORY: usize = 4;

/// A variable of a block took a value on a scan.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Change {
    /// The scan.
    pub scan: u64,
    /// The variable (`T1.IN`).
    pub name: String,
    /// Its value from that scan on.
    pub value: Json,
}

/// A Petri net place asked about (`place` in JSON).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PlaceToken {
    /// The place's id.
    pub id: String,
    /// The Petri net POU.
    pub pou: String,
    /// Whether it holds a token.
    pub holds_token: bool,
    /// The step variable read for it.
    pub step_variable: String,
    /// The value of the step variable that marks it.
    pub step_value: i64,
}

/// Why a variable has its value at a scan.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Explanation {
    /// The variable (for a place: the place's id).
    pub var: String,
    /// Its value at the end of the scan (for a place: whether it holds a token).
    pub value: Json,
    /// The scan.
    pub scan: u64,
    /// What wrote the value.
    pub written_by: WrittenBy,
    /// The values that decided it.
    pub operands: Vec<Operand>,
    /// For a rung: the elements and whether power left each.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub path: Vec<PowerStep>,
    /// For an output of a function block: the instance.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub block: Option<Block>,
    /// For a Petri net place: the place.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub place: Option<PlaceToken>,
    /// The last scan before this one on which the value changed.
    pub previous_change: Option<u64>,
    /// The first scan after this one on which it changed.
    pub next_change: Option<u64>,
    /// The value as IEC text.
    #[serde(skip)]
    pub value_text: String,
}

impl Explanation {
    /// As JSON (the object `plc why --json` prints).
    pub fn to_json(&self) -> Json {
        serde_json::to_value(self).unwrap_or(Json::Null)
    }

    /// In words, as `plc why` prints it: `Motor is TRUE at scan 12: written by Main line 9:
    /// Motor := (Start OR Motor) AND NOT Stop — Start FALSE (since scan 11), …`.
    pub fn to_text(&self) -> String {
        let head = match &self.place {
            Some(p) if p.holds_token => {
                format!(
                    "{} holds a token at scan {} ({} = {})",
                    p.id, self.scan, p.step_variable, p.step_value
                )
            }
            Some(p) => format!("{} holds no token at scan {}", p.id, self.scan),
            None => format!("{} is {} at scan {}", self.var, self.value_text, self.scan),
        };
        let w = &self.written_by;
        let mut out = match (w.kind, w.since_scan) {
            (Kind::None, Some(k)) => format!(
                "{head}: nothing wrote it on this scan; it has had this value since scan {k}, when {} wrote it",
                w.describe()
            ),
            (Kind::None, None) => format!("{head}: nothing wrote it since the first scan recorded"),
            (Kind::Initial, _) => format!("{head}: its initial value; nothing has written it since the start"),
            (Kind::Input | Kind::Forced, _) => format!("{head}: {}", w.describe()),
            _ => format!("{head}: written by {}", w.describe()),
        };
        if !self.operands.is_empty() {
            let ops: Vec<String> = self
                .operands
                .iter()
                .map(|o| format!("{} {} (since scan {})", o.name, o.text, o.since_scan))
                .collect();
            out.push_str(" — ");
            out.push_str(&ops.join(", "));
        }
        if let Some(b) = &self.block {
            out.push_str(&format!("; {} is a {}", b.instance, b.fb));
            if !b.history.is_empty() {
                let changes: Vec<String> = b
                    .history
                    .iter()
                    .map(|c| format!("{} {} at scan {}", c.name, json_text(&c.value), c.scan))
                    .collect();
                out.push_str(&format!(" ({})", changes.join(", ")));
            }
        }
        if !self.path.is_empty() {
            let steps: Vec<String> = self
                .path
                .iter()
                .map(|s| {
                    let state = if s.powered { "on" } else { "off" };
                    format!("{} {state}", s.element)
                })
                .collect();
            out.push_str(&format!("; power: {}", steps.join(", ")));
        }
        let change = |k: Option<u64>| k.map_or("none".to_string(), |k| format!("scan {k}"));
        out.push_str(&format!(
            "\nchanged before: {}; changes next: {}",
            change(self.previous_change),
            change(self.next_change)
        ));
        out
    }
}

/// A JSON value as IEC text would write it (`TRUE`, `3`, `T#2s`).
fn json_text(v: &Json) -> String {
    match v {
        Json::Bool(true) => "TRUE".to_string(),
        Json::Bool(false) => "FALSE".to_string(),
        Json::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// The accessible name of a `Why?` button: `Why is Motor TRUE?`.
pub fn why_label(name: &str, value: &Value) -> String {
    format!("Why is {name} {}?", value_text(value))
}

/// The accessible name of a place's `Why?` button: `Why does P3 hold a token?`.
pub fn why_place_label(place: &str) -> String {
    format!("Why does {place} hold a token?")
}

/// The accessible name of the change finder: `When did Motor change?`.
pub fn when_label(name: &str) -> String {
    format!("When did {name} change?")
}

/// Why an explanation cannot be given.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum WhyError {
    /// No such variable (or place).
    Unknown(String),
    /// The recording does not hold the scan (or recording is off).
    Record(RecordError),
}

impl std::fmt::Display for WhyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WhyError::Unknown(p) => write!(f, "the program has no variable or place `{p}`"),
            WhyError::Record(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for WhyError {}

impl From<RecordError> for WhyError {
    fn from(e: RecordError) -> Self {
        WhyError::Record(e)
    }
}

impl From<SimError> for WhyError {
    fn from(e: SimError) -> Self {
        match e {
            SimError::UnknownVariable(p) => WhyError::Unknown(p),
            other => WhyError::Unknown(other.to_string()),
        }
    }
}

/// The previous and next scans on which `path` changed, around `scan`: the last scan
/// before it whose value differs from the one before, and the first after it.
pub fn when_changed(
    sim: &Simulator,
    path: &str,
    scan: u64,
) -> Result<(Option<u64>, Option<u64>), WhyError> {
    let slot = sim.locate(path)?;
    let (first, _) = sim.recorded_range().ok_or(RecordError::NotRecording)?;
    let previous = if scan > first { sim.last_changes(&[slot], scan - 1)?[0] } else { None };
    Ok((previous, sim.next_change(&slot, scan)?))
}

/// Explains the value of variable `path` at the end of recorded scan `scan`.
pub fn explain(
    ctx: &Context<'_>,
    sim: &Simulator,
    path: &str,
    scan: u64,
) -> Result<Explanation, WhyError> {
    let slot = sim.locate(path)?;
    let mut ex = explain_slot(ctx, sim, path, slot, scan, true)?;
    let (previous, next) = when_changed(sim, path, scan)?;
    ex.previous_change = previous;
    ex.next_change = next;
    Ok(ex)
}

/// Explains why Petri net place `place` holds (or does not hold) a token at the end of
/// recorded scan `scan`: through the step variable that marks it.
pub fn explain_place(
    ctx: &Context<'_>,
    sim: &Simulator,
    place: &str,
    scan: u64,
) -> Result<Explanation, WhyError> {
    let unknown = || WhyError::Unknown(place.to_string());
    let segments = ctx.build.source.as_ref().map(|s| s.map.petri.as_slice()).unwrap_or_default();
    let main = sim.program().pou(sim.main_pou()).name.clone();
    let (pou, entry) = segments
        .iter()
        .flat_map(|s| s.generated.place_map.places.iter().map(move |p| (&s.pou, p)))
        .filter(|(_, p)| p.id.eq_ignore_ascii_case(place))
        // The running program's net first.
        .min_by_key(|(pou, _)| !pou.eq_ignore_ascii_case(&main))
        .ok_or_else(unknown)?;
    let var = if pou.eq_ignore_ascii_case(&main) {
        entry.step_variable.clone()
    } else {
        format!("{pou}.{}", entry.step_variable)
    };
    let mut ex = explain(ctx, sim, &var, scan).map_err(|e| match e {
        WhyError::Unknown(_) => unknown(),
        other => other,
    })?;
    let holds = ex.value.as_i64() == Some(entry.value);
    ex.place = Some(PlaceToken {
        id: entry.id.clone(),
        pou: pou.clone(),
        holds_token: holds,
        step_variable: var,
        step_value: entry.value,
    });
    ex.var = entry.id.clone();
    ex.value = Json::Bool(holds);
    ex.value_text = if holds { "TRUE" } else { "FALSE" }.to_string();
    Ok(ex)
}

fn explain_slot(
    ctx: &Context<'_>,
    sim: &Simulator,
    path: &str,
    slot: Slot,
    scan: u64,
    look_back: bool,
) -> Result<Explanation, WhyError> {
    let (first, last) = sim.recorded_range().ok_or(RecordError::NotRecording)?;
    if scan < first || scan > last {
        return Err(RecordError::OutOfRange { scan, first, last }.into());
    }
    let name = declared_name(sim, path);
    if scan == 0 {
        let view = sim.view_at(0)?;
        let value = view.read_slot(&slot);
        let mut w = WrittenBy::of(Kind::Initial);
        w.since_scan = Some(0);
        return Ok(Explanation {
            var: name,
            value: vm::to_json(&value),
            value_text: value_text(&value),
            scan,
            written_by: w,
            operands: Vec::new(),
            path: Vec::new(),
            block: None,
            place: None,
            previous_change: None,
            next_change: None,
        });
    }
    let traced = sim.trace_scan(scan)?;
    let sc = Scan::new(&traced);
    let value = traced.view.read_slot(&slot);
    let mut ex = Explainer {
        ctx,
        sim,
        sc: &sc,
        operands: Vec::new(),
        path: Vec::new(),
        block: None,
        tracked: Vec::new(),
    };
    let written_by = match sc.last_write(&slot, traced.events.len()) {
        Some(w) => ex.writer(w, &slot, 0),
        None => {
            let changed = if look_back { sim.last_changes(&[slot], scan)?[0] } else { None };
            match changed {
                Some(k) if k < scan => {
                    let then = explain_slot(ctx, sim, path, slot, k, false)?;
                    let mut w = WrittenBy::of(Kind::None);
                    w.since_scan = Some(k);
                    w.then = Some(Box::new(then.written_by));
                    return Ok(Explanation {
                        var: name,
                        value: vm::to_json(&value),
                        value_text: value_text(&value),
                        scan,
                        written_by: w,
                        ..then
                    });
                }
                _ if first == 0 && look_back => {
                    let mut w = WrittenBy::of(Kind::Initial);
                    w.since_scan = Some(0);
                    w
                }
                _ => {
                    let mut w = WrittenBy::of(Kind::None);
                    w.since_scan = look_back.then_some(first);
                    w
                }
            }
        }
    };
    let operands = ex.finish(scan)?;
    ex.history(scan)?;
    Ok(Explanation {
        var: name,
        value: vm::to_json(&value),
        value_text: value_text(&value),
        scan,
        written_by,
        operands,
        path: ex.path,
        block: ex.block,
        place: None,
        previous_change: None,
        next_change: None,
    })
}

/// The declared spelling of a variable of the main program (`motor` → `Motor`), else the
/// path as given.
fn declared_name(sim: &Simulator, path: &str) -> String {
    sim.executable()
        .main_vars()
        .iter()
        .find(|e| e.var.name.eq_ignore_ascii_case(path.trim()))
        .map_or_else(|| path.trim().to_string(), |e| e.var.name.clone())
}

/// An operand found, before its `since_scan` is known.
struct Found {
    name: String,
    slot: Slot,
    value: Value,
}

/// Gathers the writer, the operands and the power path of one explanation.
struct Explainer<'a, 'b> {
    ctx: &'a Context<'a>,
    sim: &'a Simulator,
    sc: &'b Scan<'b>,
    operands: Vec<Found>,
    path: Vec<PowerStep>,
    block: Option<Block>,
    /// The block's variables whose history is kept.
    tracked: Vec<(String, Slot)>,
}

impl Explainer<'_, '_> {
    /// What `w` is, gathering the operands that decided it.
    fn writer(&mut self, w: Writer, slot: &Slot, depth: usize) -> WrittenBy {
        match w {
            Writer::Outside { index, cause } => match cause {
                Cause::Held => {
                    let mut w = WrittenBy::of(Kind::Input);
                    w.text = Some("held from outside".to_string());
                    w
                }
                Cause::Written => {
                    let mut w = WrittenBy::of(Kind::Input);
                    w.text = Some("written from outside before the scan".to_string());
                    w
                }
                Cause::Forced => {
                    let mut w = WrittenBy::of(Kind::Forced);
                    w.text = Some("forced".to_string());
                    w
                }
                Cause::Link { from } => {
                    // A plant's output, a task's connection: whatever wrote the source.
                    let source = Slot { addr: from, ty: slot.ty, bit: None };
                    match self.sc.last_write(&source, index) {
                        Some(w) if depth < MAX_DEPTH => self.writer(w, &source, depth + 1),
                        _ => {
                            let mut w = WrittenBy::of(Kind::None);
                            w.text = Some("copied from a value of the scan before".to_string());
                            w
                        }
                    }
                }
            },
            Writer::Program { index, frame } => self.program_writer(index, frame, slot),
        }
    }

    fn program_writer(&mut self, index: usize, frame: Frame, slot: &Slot) -> WrittenBy {
        let sc = self.sc;
        let Some((span, pou)) = sc.exe.statement_at(frame.pc as usize) else {
            return WrittenBy::of(Kind::Statement);
        };
        let site = self.ctx.site(span);
        let mut w = WrittenBy::of(Kind::Statement);
        w.pou = Some(sc.program.pou(pou).name.clone());
        w.text = Some(self.ctx.text(span));
        let ancestors = self.gather(index, frame, span, pou, slot, 0);
        match &site {
            Site::St { line, .. } => {
                w.line = Some(*line);
                if let Some(part) = sfc_element(self.ctx, sc, pou, span) {
                    w.kind = part.kind;
                    w.element = Some(part.element);
                    if part.text.is_some() {
                        w.text = part.text;
                    }
                }
            }
            Site::Ladder { pou: name, cell } => {
                w.kind = Kind::Rung;
                w.pou = Some(name.clone());
                if let Some((r, row, col)) = *cell {
                    w.rung = Some(r + 1);
                    w.row = Some(row + 1);
                    w.column = Some(col + 1);
                    self.rung(name, r, index);
                    let lp = self.ctx.project.ladder.iter().find(|p| p.name == *name);
                    if let Some(lp) = lp {
                        let cell = lp.rungs.get(r).and_then(|g| g.cells.get(row)?.get(col));
                        w.element = cell.map(element_words);
                        let (text, map) = crate::ladder::st_view(lp);
                        let lines: Vec<&str> = text
                            .lines()
                            .enumerate()
                            .filter(|(i, _)| map.iter().any(|&(l, k)| l == *i as u32 + 1 && k == r))
                            .map(|(_, l)| l.trim())
                            .filter(|l| !l.starts_with("(*"))
                            .map(|l| l.trim_end_matches(';'))
                            .collect();
                        if !lines.is_empty() {
                            w.text = Some(lines.join("; "));
                        }
                    }
                }
            }
            Site::Network { pou: name, element } => {
                w.kind = Kind::Element;
                w.pou = Some(name.clone());
                w.element = element.clone();
            }
            Site::Petri { pou: name, element, at } => {
                w.pou = Some(name.clone());
                match element {
                    Some(NetElement::Transition(t)) => {
                        w.kind = Kind::Transition;
                        w.element = Some(t.clone());
                        // The guard: the condition of the IF around the firing.
                        w.text = ancestors.map(|s| self.ctx.text(s));
                    }
                    Some(NetElement::Place(p))
                        if at.as_ref().is_none_or(|a| a.part == TextPart::Actions) =>
                    {
                        w.kind = Kind::StepAction;
                        w.element = Some(format!("place {p}"));
                    }
                    Some(NetElement::Prologue) => {
                        w.element = Some(NetElement::Prologue.to_string());
                        // Outputs cleared here stay cleared unless a marked place's
                        // action sets them: the marking decides.
                        self.step_variables(name);
                    }
                    Some(e @ (NetElement::Epilogue | NetElement::Emergency)) => {
                        w.element = Some(e.to_string());
                    }
                    Some(e) => w.element = Some(e.to_string()),
                    None => {}
                }
            }
            Site::Declarations { pou: name, line, .. } => {
                w.pou = Some(name.clone());
                w.element = Some(format!("declarations line {line}"));
            }
            Site::Project => {}
        }
        w.site = Some(site);
        w
    }

    /// The operands of the statement at `span` (of POU `pou`) whose write is event
    /// `index`, and of the conditions around it. Returns the span of the condition of the
    /// innermost IF branch around it (a Petri net transition's guard).
    fn gather(
        &mut self,
        index: usize,
        frame: Frame,
        span: Span,
        pou: PouId,
        slot: &Slot,
        depth: usize,
    ) -> Option<Span> {
        let sc = self.sc;
        let candidates = scan::find_statements(sc.program, pou, span);
        let at_write = sc.memory_at(index);
        // Generated code gives several statements one span: the one that writes the slot
        // (with the value stored, when it stores a constant).
        let stored = sc.stored(index);
        let chosen = candidates
            .iter()
            .find(|(s, _)| match (&s.kind, frame.block) {
                (StmtKind::CallFb { instance, .. }, Some((_, b))) => {
                    sc.resolve(pou, frame.base, instance, &at_write).is_some_and(|i| i.addr == b)
                }
                (StmtKind::Assign(place, e), None) => {
                    let constant = match (&e.kind, stored) {
                        (ExprKind::Const(bits), Some(v)) if slot.bit.is_none() => *bits == v,
                        _ => true,
                    };
                    constant
                        && sc.resolve(pou, frame.base, place, &at_write).is_some_and(|p| p == *slot)
                }
                _ => false,
            })
            .or(candidates.first());
        let (stmt, ancestors) = chosen?;
        let entry = sc.entry_of(span, pou, frame.base, index + 1).unwrap_or(index);
        let mem = sc.memory_at(entry);
        let prefix = sc.prefix(pou, frame.base);
        let mut reads = Vec::new();
        match &stmt.kind {
            StmtKind::Assign(place, e) => {
                scan::reads(e, &mut reads);
                scan::place_reads(place, &mut reads);
            }
            StmtKind::CallFb { args, .. } => {
                for a in args {
                    match a {
                        CallArg::In(_, e) => scan::reads(e, &mut reads),
                        CallArg::InOut(_, p) | CallArg::Out(_, p, _) => {
                            scan::place_reads(p, &mut reads)
                        }
                    }
                }
                // The block's own inputs and outputs, for the value it wrote (not for a
                // hidden variable followed into the call).
                if let (Some((bq, bb)), 0) = (frame.block, depth) {
                    self.block_operands(bq, bb, slot);
                }
            }
            StmtKind::Eval(e) => scan::reads(e, &mut reads),
            StmtKind::For { from, to, by, .. } => {
                for e in [from, to, by] {
                    scan::reads(e, &mut reads);
                }
            }
            _ => {}
        }
        for (place, s) in reads {
            self.operand(pou, frame.base, &prefix, place, s, &mem, entry, depth);
        }
        let mut guard = None;
        for a in ancestors.iter() {
            let at = sc.entry_of(a.stmt.span, pou, frame.base, entry).unwrap_or(entry);
            let mem = sc.memory_at(at);
            for cond in scan::deciding(a) {
                if matches!(a.stmt.kind, StmtKind::If { .. }) {
                    guard = Some(cond.span);
                }
                let mut reads = Vec::new();
                scan::reads(cond, &mut reads);
                for (place, s) in reads {
                    self.operand(pou, frame.base, &prefix, place, s, &mem, at, depth);
                }
            }
        }
        guard
    }

    /// The step variables of Petri net POU `pou` (the marking), as at the end of the scan.
    fn step_variables(&mut self, pou: &str) {
        let sc = self.sc;
        let Some(source) = self.ctx.build.source.as_ref() else { return };
        let Some(seg) = source.map.petri.iter().find(|s| s.pou == pou) else { return };
        let main = sc.program.pou(sc.exe.main_pou()).name.eq_ignore_ascii_case(pou);
        for process in &seg.generated.place_map.processes {
            let var = &process.step_variable;
            let name = if main { var.clone() } else { format!("{pou}.{var}") };
            let Ok(slot) = sc.traced.view.locate(&name) else { continue };
            let value = sc.traced.view.read_slot(&slot);
            self.push(Found { name, slot, value });
        }
    }

    /// The inputs and outputs of the library block instance at `base` (POU `fb`), as
    /// they are at the end of the scan, but the one explained.
    fn block_operands(&mut self, fb: PouId, base: u32, explained: &Slot) {
        let sc = self.sc;
        let instance = sc.prefix(fb, base);
        let instance = instance.trim_end_matches('.').to_string();
        let pou = sc.program.pou(fb);
        let view = &sc.traced.view;
        let mut tracked = Vec::new();
        for v in &pou.vars {
            if !matches!(v.section, VarSection::Input | VarSection::Output) {
                continue;
            }
            let name = format!("{instance}.{}", v.name);
            let Ok(slot) = view.locate(&name) else { continue };
            // The history follows what switches: BOOLs and a counter's value.
            if v.ty == crate::semantic::Type::BOOL || v.name.eq_ignore_ascii_case("CV") {
                tracked.push((name.clone(), slot));
            }
            if slot == *explained {
                continue;
            }
            let value = view.read_slot(&slot);
            self.push(Found { name, slot, value });
        }
        self.block = Some(Block { instance, fb: pou.name.clone(), history: Vec::new() });
        self.tracked = tracked;
    }

    /// The block's history up to `scan`: the last changes of its tracked variables.
    fn history(&mut self, scan: u64) -> Result<(), WhyError> {
        let Some(block) = self.block.as_mut() else { return Ok(()) };
        let mut out = Vec::new();
        for (name, slot) in &self.tracked {
            let mut at = scan;
            for _ in 0..HISTORY {
                let Some(k) = self.sim.last_changes(&[*slot], at)?[0] else { break };
                let value = self.sim.view_at(k)?.read_slot(slot);
                out.push(Change { scan: k, name: name.clone(), value: vm::to_json(&value) });
                at = k - 1;
            }
        }
        crate::order::sort_by_key(&mut out, |c| c.scan);
        block.history = out;
        Ok(())
    }

    /// One place read by the writer (`at`: the event before which it was read, `mem`: the
    /// memory then). Hidden variables of the front-ends are followed to what they read.
    #[allow(clippy::too_many_arguments)]
    fn operand(
        &mut self,
        pou: PouId,
        base: u32,
        prefix: &str,
        place: &Place,
        span: Span,
        mem: &vm::Memory,
        at: usize,
        depth: usize,
    ) {
        let sc = self.sc;
        let Some(slot) = sc.resolve(pou, base, place, mem) else { return };
        // The variable's own path (generated code points its spans at the user's text).
        let canonical = match slot.bit {
            None => crate::program::refpath::path_of(sc.exe, slot.addr, slot.ty),
            Some(_) => None,
        };
        let text = self.ctx.text(span);
        let mut name = canonical.unwrap_or_else(|| format!("{prefix}{text}"));
        let hidden = |p: &str| p.split(['.', '[', ']']).any(crate::build::is_hidden_variable);
        if hidden(&name) {
            if depth >= MAX_DEPTH {
                return;
            }
            if let Some(Writer::Program { index, frame }) = sc.last_write(&slot, at) {
                if let Some((span, pou)) = sc.exe.statement_at(frame.pc as usize) {
                    self.gather(index, frame, span, pou, &slot, depth + 1);
                }
            }
            return;
        }
        if sc.exe.locate(&name).is_none() {
            // A plant's or a function's variable, read as `POU.name`.
            name = format!("{prefix}{text}");
        }
        let value = vm::read(mem, sc.exe, &slot);
        self.push(Found { name, slot, value });
    }

    fn push(&mut self, f: Found) {
        if !self.operands.iter().any(|o| o.name.eq_ignore_ascii_case(&f.name)) {
            self.operands.push(f);
        }
    }

    /// The power path of rung `r` of ladder POU `name`, read when event `index` happened.
    fn rung(&mut self, name: &str, r: usize, index: usize) {
        let Some(lp) = self.ctx.project.ladder.iter().find(|p| p.name == name) else { return };
        let sc = self.sc;
        let mem = sc.memory_at(index + 1);
        let main = sc.program.pou(sc.exe.main_pou()).name.eq_ignore_ascii_case(name);
        for (rung, row, col, var) in crate::ladder::power_map(lp) {
            if rung != r {
                continue;
            }
            let path = if main { var } else { format!("{name}.{var}") };
            let Some(slot) = sc.exe.locate(&path) else { continue };
            let Some(cell) = lp.rungs.get(r).and_then(|g| g.cells.get(row)?.get(col)) else {
                continue;
            };
            let powered = matches!(vm::read(&mem, sc.exe, &slot), Value::Bool(true));
            self.path.push(PowerStep {
                row: row + 1,
                column: col + 1,
                element: element_words(cell),
                powered,
            });
        }
        crate::order::sort_by_key(&mut self.path, |s| (s.column, s.row));
    }

    /// The operands with the scan since which each has had its value.
    fn finish(&mut self, scan: u64) -> Result<Vec<Operand>, WhyError> {
        let sc = self.sc;
        let before = vm::Memory { cells: sc.traced.before.clone() };
        let (first, _) = self.sim.recorded_range().ok_or(RecordError::NotRecording)?;
        let mut since: Vec<Option<u64>> = vec![Some(scan); self.operands.len()];
        let mut ask: Vec<(usize, Slot)> = Vec::new();
        for (k, f) in self.operands.iter().enumerate() {
            let was = vm::read(&before, sc.exe, &f.slot);
            if crate::sim::same_value(&was, &f.value) {
                ask.push((k, f.slot));
            }
        }
        if !ask.is_empty() {
            let slots: Vec<Slot> = ask.iter().map(|(_, s)| *s).collect();
            let found = self.sim.last_changes(&slots, scan - 1)?;
            for ((k, _), f) in ask.iter().zip(found) {
                since[*k] = Some(f.unwrap_or(first));
            }
        }
        Ok(self
            .operands
            .drain(..)
            .zip(since)
            .map(|(f, s)| Operand {
                name: f.name,
                value: vm::to_json(&f.value),
                since_scan: s.unwrap_or(scan),
                text: value_text(&f.value),
            })
            .collect())
    }
}

/// A ladder element in words (`NO contact Start`), without its link.
fn element_words(cell: &crate::ladder::Cell) -> String {
    let words = crate::ladder::describe_cell(cell);
    words.trim_end_matches(", linked down").to_string()
}

/// For a statement of a textual SFC: a transition (the statements that move the steps
/// are written at the transition's header) with its name and condition, or a step's
/// action association or an action's body, with the step or action.
fn sfc_element(ctx: &Context<'_>, sc: &Scan<'_>, pou: PouId, span: Span) -> Option<SfcPart> {
    let full = ctx.build.source.as_ref().map_or("", |s| s.text.as_str());
    let whole = sc.program.pou(pou).span;
    let body = full.get(whole.start as usize..whole.end as usize)?;
    if !body.to_ascii_uppercase().contains("END_STEP") {
        return None;
    }
    let text = ctx.text(span);
    let words: Vec<&str> = text.split_whitespace().collect();
    if words.first().is_some_and(|w| w.eq_ignore_ascii_case("TRANSITION")) {
        let named = words.get(1).filter(|w| !w.starts_with('(') && !w.eq_ignore_ascii_case("FROM"));
        let element = match named {
            Some(n) => n.to_string(),
            None => {
                let from = words.iter().position(|w| w.eq_ignore_ascii_case("FROM"))?;
                words[from..].join(" ")
            }
        };
        // The condition written after the header: `:= Start AND NOT Fault;`.
        let after = full.get(span.end as usize..whole.end as usize).unwrap_or_default();
        let condition = after.trim_start().strip_prefix(":=").and_then(|c| {
            let end = c.to_ascii_uppercase().find("END_TRANSITION")?;
            let c = c[..end].trim().trim_end_matches(';');
            Some(c.split_whitespace().collect::<Vec<_>>().join(" "))
        });
        return Some(SfcPart { kind: Kind::Transition, element, text: condition });
    }
    // Inside which STEP or ACTION the span lies, by the words before it.
    let before = full.get(whole.start as usize..span.start as usize)?;
    let mut inside: Option<String> = None;
    let mut tokens =
        before.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).filter(|w| !w.is_empty());
    while let Some(w) = tokens.next() {
        let upper = w.to_ascii_uppercase();
        match upper.as_str() {
            "STEP" | "INITIAL_STEP" => inside = tokens.next().map(|n| format!("step {n}")),
            "ACTION" => inside = tokens.next().map(|n| format!("action {n}")),
            "END_STEP" | "END_ACTION" => inside = None,
            _ => {}
        }
    }
    inside.map(|element| SfcPart { kind: Kind::StepAction, element, text: None })
}

/// What [`sfc_element`] found.
struct SfcPart {
    kind: Kind,
    element: String,
    text: Option<String>,
}
