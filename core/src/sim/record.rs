//! Recording: the recent history of a run, so that any recorded scan can be shown again,
//! explained, or made the present again.
//!
//! The simulator is deterministic: a scan's result depends only on the state before it
//! (memory, the CASE branches last taken, the clock, the tasks' schedule) and on what came
//! from outside (held inputs, forced values, values written between scans, the cycle time
//! and the watchdog). So the recorder keeps
//! - a **snapshot** of that state at the end of every `interval`-th scan (and when
//!   recording starts), the interval chosen from the size of the program's memory image;
//! - every **control** (a change from outside) with the scan after which it happened.
//!
//! Any recorded scan `n` is rebuilt by taking the last snapshot at or before `n` and
//! running the scans after it again, each preceded by the controls recorded before it.
//! Ordinary scans pay one comparison for this (and, every `interval` scans, the copy of
//! the image); replays never touch the live simulator.
//!
//! Memory is bounded by [`limits::RECORD_BUDGET_BYTES`]: the oldest snapshots (and the
//! controls before them) are dropped once the history covers more than the capacity
//! ([`limits::RECORD_SCANS`], one simulated hour at 10 ms, or fewer when the image is so
//! large that the budget affords fewer) or the budget is spent.

use std::collections::{HashMap, VecDeque};
use std::sync::{Arc, Mutex};

use super::{tasks, Pinned, SimState, Simulator};
use crate::compile::{Executable, Slot};
use crate::limits;
use crate::program::locate::element_size;
use crate::program::memory::Memory;
use crate::semantic::{PouId, Program};
use crate::vm::trace::{Hook, Tracer};
use crate::vm::{self, Cause, Machine, TraceEvent, Value};

/// A change of the run from outside, recorded with the scan after which it happened.
/// Kept small (16 bytes, 24 with its scan): a plant model or a test bench may hold an input at a new value
/// before every scan, and that common change is [`Control::Held`]; the rare ones are boxed.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Control {
    /// A value written once (the variable table, `--set` of a non-input).
    Write(Box<(Slot, Value)>),
    /// An input held at a value ([`Simulator::hold`]; a path held already goes last).
    Hold(Box<Pinned>),
    /// The input held `k`-th given the scalar value of cell bits `bits`
    /// ([`Simulator::hold_value`] of a path held already: it keeps its place).
    Held {
        /// Its place in the held list.
        k: u32,
        /// The value's bits (`Value::from_bits` of the slot's type).
        bits: u64,
    },
    /// An input held for the first time by [`Simulator::hold_value`], or at a value that
    /// is not a scalar: it keeps its place when held already.
    HoldInPlace(Box<Pinned>),
    /// An input released.
    Release(Box<Arc<str>>),
    /// A variable forced.
    Force(Box<Pinned>),
    /// Forcing removed.
    Unforce(Box<Arc<str>>),
    /// The cycle time.
    Cycle(i64),
    /// The watchdog budget.
    Watchdog(u64),
}

impl Control {
    /// Bytes this control is counted as.
    fn bytes(&self) -> usize {
        let value = |v: &Value| match v {
            Value::Str(b) => b.len(),
            Value::WStr(w) => 2 * w.len(),
            _ => 0,
        };
        let boxed = std::mem::size_of::<Pinned>();
        std::mem::size_of::<(u64, Control)>()
            + match self {
                Control::Write(w) => boxed + value(&w.1),
                Control::Hold(p) | Control::Force(p) | Control::HoldInPlace(p) => {
                    boxed + value(&p.value)
                }
                _ => 0,
            }
    }
}

/// The cell bits of a scalar value, when `Value::from_bits` gives it back exactly.
pub(super) fn scalar_bits(slot: &Slot, value: &Value, exe: &Executable) -> Option<u64> {
    // The common cases, without decoding again.
    match (value, slot.ty) {
        (Value::Bool(b), crate::semantic::Type::Elem(crate::semantic::Elem::Bool)) => {
            return Some(u64::from(*b))
        }
        (Value::Int(v, e), crate::semantic::Type::Elem(t)) if *e == t && t.is_integral() => {
            let bits = crate::values::arith::norm(*e, *v);
            if crate::values::arith::to_i128(*e, bits) == *v {
                return Some(bits);
            }
        }
        _ => {}
    }
    let bits = match value {
        Value::Bool(b) => u64::from(*b),
        Value::Int(v, e) => crate::values::arith::norm(*e, *v),
        Value::Real(f, _) => f.to_bits(),
        Value::Time(t) | Value::Date(t) | Value::Tod(t) | Value::Dt(t) => *t as u64,
        Value::Enum { value, .. } => *value as u64,
        _ => return None,
    };
    (Value::from_bits(slot.ty, bits, exe.type_table()) == *value).then_some(bits)
}

/// The state at the end of one scan, in one allocation: the memory image, then the CASE
/// branches last taken (two per cell), then the held values' bits when they are scalars.
#[derive(Debug, Clone)]
pub(super) struct Snapshot {
    scans: u64,
    time_ns: i64,
    first_scan: bool,
    /// How many cells of `data` are memory, and how many CASE tables follow.
    cells: u32,
    cases: u32,
    data: Box<[u64]>,
    schedule: Option<Box<tasks::Schedule>>,
    /// The held inputs (paths and slots shared with the snapshot before while they do not
    /// change); their values are the bits after the CASE branches when `held_bits`.
    held: Arc<Vec<Pinned>>,
    held_bits: bool,
    forced: Arc<Vec<Pinned>>,
    cycle_ns: i64,
    watchdog: u64,
    /// The bytes it was counted as when kept.
    size: usize,
}

impl Snapshot {
    /// The simulator's state now.
    pub(super) fn of(sim: &Simulator, recorder: &Recorder) -> Snapshot {
        let last = recorder.snapshots.back();
        let cells = sim.machine.memory().cells.get(..sim.state_cells).unwrap_or_default();
        let cases = sim.machine.case_state();
        let bits: Option<Vec<u64>> =
            sim.held.iter().map(|p| scalar_bits(&p.slot, &p.value, &sim.exe)).collect();
        let mut data = Vec::with_capacity(cells.len() + cases.len() + sim.held.len());
        data.extend_from_slice(cells);
        data.extend(cases.iter().map(|&(a, b)| u64::from(a) << 32 | u64::from(b)));
        let same_pins = |a: &[Pinned], b: &[Pinned]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.path == y.path && x.slot == y.slot)
        };
        let (held, held_bits) = match bits {
            Some(bits) => {
                data.extend(bits);
                let held = match last {
                    Some(l) if same_pins(&l.held, &sim.held) => Arc::clone(&l.held),
                    _ => Arc::new(sim.held.clone()),
                };
                (held, true)
            }
            None => (Arc::new(sim.held.clone()), false),
        };
        let forced = match last {
            Some(l) if *l.forced == sim.forced => Arc::clone(&l.forced),
            _ => Arc::new(sim.forced.clone()),
        };
        Snapshot {
            scans: sim.scans,
            time_ns: sim.time_ns,
            first_scan: sim.first_scan,
            cells: cells.len() as u32,
            cases: cases.len() as u32,
            data: data.into_boxed_slice(),
            schedule: sim.schedule.clone().map(Box::new),
            held,
            held_bits,
            forced,
            cycle_ns: sim.cycle_ns,
            watchdog: sim.watchdog,
            size: 0,
        }
    }

    fn cells(&self) -> &[u64] {
        self.data.get(..self.cells as usize).unwrap_or_default()
    }

    fn case_hits(&self) -> Vec<(u32, u32)> {
        let end = (self.cells + self.cases) as usize;
        let packed = self.data.get(self.cells as usize..end).unwrap_or_default();
        packed.iter().map(|&c| ((c >> 32) as u32, c as u32)).collect()
    }

    /// The held inputs with their values.
    fn held(&self, exe: &Executable) -> Vec<Pinned> {
        let mut held = self.held.to_vec();
        if self.held_bits {
            let bits = self.data.get((self.cells + self.cases) as usize..).unwrap_or_default();
            for (p, &b) in held.iter_mut().zip(bits) {
                p.value = Value::from_bits(p.slot.ty, b, exe.type_table());
            }
        }
        held
    }

    /// Bytes it takes (its lists counted when it does not share them with `before`).
    fn bytes(&self, before: Option<&Snapshot>) -> usize {
        let pins = |list: &Arc<Vec<Pinned>>, kept: Option<&Arc<Vec<Pinned>>>| {
            if kept.is_some_and(|k| Arc::ptr_eq(k, list)) {
                0
            } else {
                list.len() * (std::mem::size_of::<Pinned>() + 16)
            }
        };
        std::mem::size_of::<Snapshot>()
            + 8 * self.data.len()
            + self.schedule.as_ref().map_or(0, |_| std::mem::size_of::<tasks::Schedule>() + 128)
            + pins(&self.held, before.map(|b| &b.held))
            + pins(&self.forced, before.map(|b| &b.forced))
    }
}

/// The recent history of a run (see the module comment).
#[derive(Debug)]
pub(crate) struct Recorder {
    /// A snapshot every this many scans.
    interval: u64,
    /// The scan at whose end the next snapshot is due.
    next: u64,
    /// The history kept covers at least this many scans (the budget permitting).
    capacity: u64,
    snapshots: VecDeque<Snapshot>,
    /// `(after scan, control)`, in the order they happened.
    events: VecDeque<(u64, Control)>,
    /// Bytes the snapshots and controls take.
    bytes: usize,
    /// Per complete stretch between two snapshots (by its first scan): the cells that
    /// changed on some scan of it, one bit each, found when a search first replays it.
    changes: Mutex<ChangeIndex>,
}

#[derive(Debug, Default)]
struct ChangeIndex {
    stretches: HashMap<u64, Box<[u64]>>,
    bytes: usize,
}

impl Clone for Recorder {
    fn clone(&self) -> Self {
        Recorder {
            interval: self.interval,
            next: self.next,
            capacity: self.capacity,
            snapshots: self.snapshots.clone(),
            events: self.events.clone(),
            bytes: self.bytes,
            changes: Mutex::new(ChangeIndex::default()),
        }
    }
}

impl Recorder {
    /// A recorder for snapshots of `cells` cells and `cases` CASE tables, or `None` when
    /// one snapshot alone would not fit the budget.
    fn new(cells: usize, cases: usize) -> Option<Recorder> {
        let snapshot = std::mem::size_of::<Snapshot>() + 8 * (cells + cases) + 64;
        let for_snapshots = limits::RECORD_BUDGET_BYTES / 2;
        if snapshot > for_snapshots {
            return None;
        }
        let wanted = limits::RECORD_SCANS as usize;
        let interval = (wanted.saturating_mul(snapshot).div_ceil(for_snapshots) as u64)
            .clamp(limits::RECORD_MIN_INTERVAL, limits::RECORD_MAX_INTERVAL);
        let affordable = (for_snapshots / snapshot) as u64 * interval;
        Some(Recorder {
            interval,
            next: 0,
            capacity: affordable.min(limits::RECORD_SCANS),
            snapshots: VecDeque::new(),
            events: VecDeque::new(),
            bytes: 0,
            changes: Mutex::new(ChangeIndex::default()),
        })
    }

    /// Whether a snapshot is due at the end of scan `scans`.
    pub(super) fn due(&self, scans: u64) -> bool {
        scans >= self.next
    }

    /// Keeps a snapshot, then drops the oldest history beyond the capacity or the budget.
    pub(super) fn push(&mut self, mut snapshot: Snapshot) {
        let now = snapshot.scans;
        self.next = (now / self.interval + 1) * self.interval;
        snapshot.size = snapshot.bytes(self.snapshots.back());
        self.bytes += snapshot.size;
        self.snapshots.push_back(snapshot);
        while self.snapshots.len() > 1 {
            let next = self.snapshots[1].scans;
            let covered = now.saturating_sub(next) >= self.capacity;
            if !covered && self.bytes <= limits::RECORD_BUDGET_BYTES {
                break;
            }
            if let Some(old) = self.snapshots.pop_front() {
                self.bytes = self.bytes.saturating_sub(old.size);
                if let Ok(mut index) = self.changes.lock() {
                    if let Some(b) = index.stretches.remove(&old.scans) {
                        index.bytes = index.bytes.saturating_sub(8 * b.len());
                    }
                }
            }
            while self.events.front().is_some_and(|(after, _)| *after < next) {
                if let Some((_, c)) = self.events.pop_front() {
                    self.bytes = self.bytes.saturating_sub(c.bytes());
                }
            }
        }
    }

    fn event(&mut self, after: u64, control: Control) {
        self.bytes += control.bytes();
        self.events.push_back((after, control));
    }

    fn oldest(&self) -> u64 {
        self.snapshots.front().map_or(0, |s| s.scans)
    }

    /// The last snapshot at or before scan `n`.
    fn snapshot_for(&self, n: u64) -> Option<&Snapshot> {
        let k = self.snapshots.partition_point(|s| s.scans <= n);
        self.snapshots.get(k.checked_sub(1)?)
    }

    /// Drops everything after the end of scan `n` (the controls recorded after it too).
    fn truncate(&mut self, n: u64) {
        self.next = (n / self.interval + 1) * self.interval;
        while self.snapshots.back().is_some_and(|s| s.scans > n) {
            if let Some(s) = self.snapshots.pop_back() {
                self.bytes = self.bytes.saturating_sub(s.size);
            }
        }
        while self.events.back().is_some_and(|(after, _)| *after >= n) {
            if let Some((_, c)) = self.events.pop_back() {
                self.bytes = self.bytes.saturating_sub(c.bytes());
            }
        }
        if let Ok(mut index) = self.changes.lock() {
            *index = ChangeIndex::default();
        }
    }
}

/// Why a recorded scan cannot be shown.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum RecordError {
    /// Recording is off.
    NotRecording,
    /// The scan is outside the recorded range.
    OutOfRange {
        /// The scan asked for.
        scan: u64,
        /// The first scan recorded.
        first: u64,
        /// The last scan recorded (the present).
        last: u64,
    },
    /// The program's memory image is too large for the recording budget.
    TooLarge {
        /// Bytes one snapshot of the image takes.
        bytes: usize,
    },
    /// A replay did not reach the scan (it faulted; a recording that cannot happen).
    Replay(String),
}

impl std::fmt::Display for RecordError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RecordError::NotRecording => write!(f, "recording is off: the history is not kept"),
            RecordError::OutOfRange { scan, first, last } => write!(
                f,
                "scan {scan} is not recorded: the recording holds scans {first} to {last}"
            ),
            RecordError::TooLarge { bytes } => {
                let kb = bytes / 1024;
                f.write_str(&crate::msg!(MemoryTooLargeToRecord, kb = kb).english)
            }
            RecordError::Replay(m) => write!(f, "the scan could not be replayed: {m}"),
        }
    }
}

impl std::error::Error for RecordError {}

/// What the recording holds now.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Recording {
    /// The first scan that can be shown (0: the initial values, before the first scan).
    pub first: u64,
    /// The last one: the present.
    pub last: u64,
    /// A snapshot of memory is kept every this many scans: showing a scan replays at
    /// most this many.
    pub interval: u64,
    /// The history kept covers at least this many scans (older ones are dropped).
    pub capacity: u64,
    /// Bytes the recording takes.
    pub bytes: usize,
}

/// The state at the end of one recorded scan, read as the live simulator is read.
#[derive(Debug, Clone)]
pub struct ScanView {
    program: Arc<Program>,
    exe: Arc<Executable>,
    machine: Machine,
    scan: u64,
    time_ns: i64,
    state_cells: usize,
    /// Memory at the end of the scan before (`None` for the first scan recorded).
    previous: Option<Vec<u64>>,
    watches: Vec<(String, Option<Value>)>,
}

impl ScanView {
    /// The scan shown (0: the initial values).
    pub fn scan(&self) -> u64 {
        self.scan
    }

    /// The virtual time at the end of the scan, in nanoseconds.
    pub fn time_ns(&self) -> i64 {
        self.time_ns
    }

    /// The checked program.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// The compiled program (layout, debug map).
    pub fn executable(&self) -> &Executable {
        &self.exe
    }

    /// The main PROGRAM.
    pub fn main_pou(&self) -> PouId {
        self.exe.main_pou()
    }

    /// The memory at the end of the scan.
    pub fn memory(&self) -> &Memory {
        self.machine.memory()
    }

    /// Where a variable lives (as [`Simulator::locate`]).
    pub fn locate(&self, path: &str) -> Result<Slot, super::SimError> {
        self.exe.locate(path).ok_or_else(|| super::SimError::UnknownVariable(path.to_string()))
    }

    /// Reads a variable at a slot.
    pub fn read_slot(&self, slot: &Slot) -> Value {
        vm::read(self.machine.memory(), &self.exe, slot)
    }

    /// Reads a variable (as [`Simulator::read`]).
    pub fn read(&self, path: &str) -> Result<Value, super::SimError> {
        Ok(self.read_slot(&self.locate(path)?))
    }

    /// Reads a variable as it was at the end of the scan before (`None` when that scan is
    /// not recorded, or no such variable): the marking before a Petri net's transitions
    /// fired on this scan.
    pub fn read_previous(&self, path: &str) -> Option<Value> {
        let cells = self.previous.as_ref()?;
        let slot = self.exe.locate(path)?;
        let mut mem = Memory { cells: cells.clone() };
        mem.cells.resize(self.machine.memory().cells.len().max(cells.len()), 0);
        Some(vm::read(&mem, &self.exe, &slot))
    }

    /// Every variable of the main program as JSON (as [`Simulator::vars_json`]).
    pub fn vars_json(&self) -> serde_json::Map<String, serde_json::Value> {
        super::vars_json_of(self.machine.memory(), &self.exe)
    }

    /// The first statement of the branch each CASE took on its last execution up to this
    /// scan (as [`Simulator::active_case_branches`]).
    pub fn active_case_branches(&self) -> Vec<crate::diagnostics::Span> {
        super::case_branches(&self.machine, &self.exe)
    }

    /// The value of an expression the live simulator watches ([`Simulator::add_watch`]),
    /// at the end of this scan.
    pub fn watch(&self, source: &str) -> Option<&Value> {
        self.watches.iter().find(|w| w.0 == source).and_then(|w| w.1.as_ref())
    }

    /// The program's own memory at the end of the scan (without the scratch cells of
    /// breakpoint and watch conditions): what a replay must rebuild bit for bit.
    pub fn state_memory(&self) -> &[u64] {
        let cells = &self.machine.memory().cells;
        &cells[..self.state_cells.min(cells.len())]
    }
}

/// What the panels read, from the live simulator or from a recorded scan alike: a view of
/// a past scan is shown by the same code that shows the present.
pub trait Readout {
    /// The compiled program (layout, debug map, the main program's variables).
    fn executable(&self) -> &Executable;
    /// Reads a variable (`Name`, `Name.field`, `Arr[2]`, `Fb.Q`, `Word.3`).
    fn read(&self, path: &str) -> Result<Value, super::SimError>;
    /// The scans completed (the scan shown).
    fn scan_count(&self) -> u64;
    /// The virtual time at the end of that scan, in nanoseconds.
    fn time_ns(&self) -> i64;
}

impl Readout for Simulator {
    fn executable(&self) -> &Executable {
        Simulator::executable(self)
    }
    fn read(&self, path: &str) -> Result<Value, super::SimError> {
        Simulator::read(self, path)
    }
    fn scan_count(&self) -> u64 {
        Simulator::scan_count(self)
    }
    fn time_ns(&self) -> i64 {
        Simulator::time_ns(self)
    }
}

impl Readout for ScanView {
    fn executable(&self) -> &Executable {
        ScanView::executable(self)
    }
    fn read(&self, path: &str) -> Result<Value, super::SimError> {
        ScanView::read(self, path)
    }
    fn scan_count(&self) -> u64 {
        self.scan
    }
    fn time_ns(&self) -> i64 {
        self.time_ns
    }
}

/// One recorded scan run again with every write logged: what `crate::why` explains.
#[derive(Debug, Clone)]
pub struct TracedScan {
    /// The scan (1-based).
    pub scan: u64,
    /// Memory at the end of the scan before.
    pub before: Vec<u64>,
    /// Everything written during the scan, in order: values written from outside between
    /// the scans (`Cause::Written`), then the scan itself.
    pub events: Vec<TraceEvent>,
    /// The state at the end of the scan.
    pub view: ScanView,
}

/// Tells `hook` the cells of `slot` (as they are now in `mem`) were written for `cause`.
pub(super) fn log_slot<H: Hook>(
    hook: &mut H,
    mem: &Memory,
    exe: &Executable,
    slot: &Slot,
    cause: Cause,
) {
    let n = if slot.bit.is_some() { 1 } else { element_size(exe, slot.ty).unwrap_or(1) };
    for addr in slot.addr..slot.addr.saturating_add(n) {
        if let Some(&bits) = mem.cells.get(addr as usize) {
            hook.external(addr, bits, cause);
        }
    }
}

/// Whether two values are the same (reals by their bits, so NaN equals itself).
pub(crate) fn same_value(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Real(x, e), Value::Real(y, f)) => x.to_bits() == y.to_bits() && e == f,
        _ => a == b,
    }
}

impl Simulator {
    /// Turns recording on (keeping the history from now on; the present is its first
    /// scan) or off (dropping it). Fails when the program's memory is too large for
    /// [`limits::RECORD_BUDGET_BYTES`].
    pub fn set_recording(&mut self, on: bool) -> Result<(), RecordError> {
        if !on {
            self.recorder = None;
            return Ok(());
        }
        if self.recorder.is_none() {
            self.start_recording();
            if self.recorder.is_none() {
                return Err(RecordError::TooLarge { bytes: 8 * self.state_cells });
            }
        }
        Ok(())
    }

    /// Keeps a snapshot of the present.
    pub(super) fn take_snapshot(&mut self) {
        let Some(mut recorder) = self.recorder.take() else { return };
        let snapshot = Snapshot::of(self, &recorder);
        recorder.push(snapshot);
        self.recorder = Some(recorder);
    }

    /// (Re)starts the history at the present.
    pub(super) fn start_recording(&mut self) {
        self.recorder = Recorder::new(self.state_cells, self.machine.case_state().len()).map(|r| {
            let mut r = Box::new(r);
            let snapshot = Snapshot::of(self, &r);
            r.push(snapshot);
            r
        });
    }

    /// What the recording holds (`None` when recording is off).
    pub fn recording(&self) -> Option<Recording> {
        let r = self.recorder.as_ref()?;
        Some(Recording {
            first: r.oldest(),
            last: self.scans,
            interval: r.interval,
            capacity: r.capacity,
            // What the deques hold in reserve counts too.
            bytes: r.bytes
                + (r.events.capacity() - r.events.len()) * std::mem::size_of::<(u64, Control)>()
                + (r.snapshots.capacity() - r.snapshots.len()) * std::mem::size_of::<Snapshot>()
                + r.changes.lock().map_or(0, |i| i.bytes)
                + self.machine.memory().cells.len() * 8,
        })
    }

    /// The first and last scans that can be shown (`None` when recording is off); scan 0
    /// is the initial state, before the first scan.
    pub fn recorded_range(&self) -> Option<(u64, u64)> {
        self.recording().map(|r| (r.first, r.last))
    }

    fn check_recorded(&self, scan: u64) -> Result<&Recorder, RecordError> {
        let r = self.recorder.as_deref().ok_or(RecordError::NotRecording)?;
        let first = r.oldest();
        if scan < first || scan > self.scans {
            return Err(RecordError::OutOfRange { scan, first, last: self.scans });
        }
        Ok(r)
    }

    /// Applies a change from outside, and records it when recording.
    pub(super) fn control(&mut self, c: Control) {
        self.apply_control(&c);
        self.record(c);
    }

    /// Records a change from outside already applied.
    pub(super) fn record(&mut self, c: Control) {
        let scans = self.scans;
        if let Some(r) = &mut self.recorder {
            r.event(scans, c);
        }
    }

    fn apply_control(&mut self, c: &Control) {
        let pin = |list: &mut Vec<Pinned>, p: &Pinned, in_place: bool| {
            let at = list.iter().position(|q| q.path.eq_ignore_ascii_case(&p.path));
            match at {
                Some(k) if in_place => list[k] = p.clone(),
                _ => {
                    list.retain(|q| !q.path.eq_ignore_ascii_case(&p.path));
                    list.push(p.clone());
                }
            }
        };
        let mem = self.machine.memory_mut();
        match c {
            Control::Write(w) => {
                let _ = vm::write(mem, &self.exe, &w.0, &w.1);
            }
            Control::Hold(p) => {
                let _ = vm::write(mem, &self.exe, &p.slot, &p.value);
                pin(&mut self.held, p, false);
            }
            Control::HoldInPlace(p) => {
                let _ = vm::write(mem, &self.exe, &p.slot, &p.value);
                pin(&mut self.held, p, true);
            }
            Control::Held { k, bits } => {
                if let Some(p) = self.held.get_mut(*k as usize) {
                    p.value = Value::from_bits(p.slot.ty, *bits, self.exe.type_table());
                    let _ = vm::write(mem, &self.exe, &p.slot, &p.value);
                }
            }
            Control::Force(p) => {
                let _ = vm::write(mem, &self.exe, &p.slot, &p.value);
                pin(&mut self.forced, p, false);
            }
            Control::Release(path) => self.held.retain(|q| !q.path.eq_ignore_ascii_case(path)),
            Control::Unforce(path) => self.forced.retain(|q| !q.path.eq_ignore_ascii_case(path)),
            Control::Cycle(ns) => self.cycle_ns = *ns,
            Control::Watchdog(n) => self.watchdog = *n,
        }
    }

    /// A simulator in the state of `snap`, without breakpoints, trace or recording.
    fn replica(&self, snap: &Snapshot) -> Simulator {
        let mut machine = Machine::new(&self.exe);
        machine.restore(snap.cells(), &snap.case_hits());
        Simulator {
            program: Arc::clone(&self.program),
            exe: Arc::clone(&self.exe),
            machine,
            cycle_ns: snap.cycle_ns,
            time_ns: snap.time_ns,
            scans: snap.scans,
            first_scan: snap.first_scan,
            state: SimState::Ready,
            held: snap.held(&self.exe),
            forced: snap.forced.to_vec(),
            breakpoints: Vec::new(),
            next_breakpoint: 0,
            trace: super::Trace::new(Vec::new(), 0),
            watchdog: snap.watchdog,
            watches: Vec::new(),
            plant: self.plant.clone(),
            schedule: snap.schedule.as_deref().cloned(),
            state_cells: self.state_cells,
            recorder: None,
        }
    }

    /// Applies the controls recorded after scan `after` to a replica.
    fn replay_controls(&self, r: &mut Simulator, recorder: &Recorder, after: u64) {
        let k = recorder.events.partition_point(|(a, _)| *a < after);
        for (_, c) in recorder.events.range(k..).take_while(|(a, _)| *a == after) {
            r.apply_control(c);
        }
    }

    /// A replica at the end of recorded scan `n`, after calling `each` with the replica
    /// at the end of every scan from the snapshot it starts from up to `n`.
    fn replay(&self, n: u64, each: impl FnMut(&Simulator)) -> Result<Simulator, RecordError> {
        let recorder = self.check_recorded(n)?;
        let snap = recorder.snapshot_for(n).ok_or(RecordError::NotRecording)?;
        self.replay_from(recorder, snap, n, each)
    }

    /// As [`Simulator::replay`], from snapshot `snap` (at or before `n`).
    fn replay_from(
        &self,
        recorder: &Recorder,
        snap: &Snapshot,
        n: u64,
        mut each: impl FnMut(&Simulator),
    ) -> Result<Simulator, RecordError> {
        let mut r = self.replica(snap);
        each(&r);
        while r.scans < n {
            let at = r.scans;
            self.replay_controls(&mut r, recorder, at);
            if let Err(info) = r.scan_hooked(&mut crate::vm::trace::NoHook) {
                return Err(RecordError::Replay(format!("scan {}: {}", info.scan, info.fault)));
            }
            each(&r);
        }
        Ok(r)
    }

    fn view_of(&self, mut r: Simulator, previous: Option<Vec<u64>>) -> ScanView {
        r.watches = self.watches.clone();
        r.refresh_watches();
        ScanView {
            program: Arc::clone(&self.program),
            exe: Arc::clone(&self.exe),
            scan: r.scans,
            time_ns: r.time_ns,
            state_cells: self.state_cells,
            previous,
            watches: r.watches.iter().map(|w| (w.source.clone(), w.value.clone())).collect(),
            machine: r.machine,
        }
    }

    /// The state at the end of recorded scan `scan` (scan 0: the initial state), rebuilt by
    /// replaying from the nearest snapshot: at most [`Recording::interval`] scans.
    pub fn view_at(&self, scan: u64) -> Result<ScanView, RecordError> {
        let mut previous = None;
        let r = self.replay(scan, |r| {
            if r.scans + 1 == scan {
                previous = Some(r.machine.memory().cells.clone());
            }
        })?;
        Ok(self.view_of(r, previous))
    }

    /// Makes recorded scan `scan` the present: the simulator returns to the state at its
    /// end (memory, clock, held inputs, forced values), and everything after it — the
    /// recorded future, the timeline's samples after it — is dropped. Scanning, or a change
    /// of an input, then starts a new future from there.
    pub fn rewind_to(&mut self, scan: u64) -> Result<(), RecordError> {
        let r = self.replay(scan, |_| {})?;
        let mut machine = r.machine;
        // Scratch cells of conditions compiled since the snapshot's machine was made.
        let n = machine.memory().cells.len();
        if let Some(extra) = self.machine.memory().cells.get(n..) {
            machine.memory_mut().cells.extend_from_slice(extra);
        }
        self.machine = machine;
        self.time_ns = r.time_ns;
        self.scans = r.scans;
        self.first_scan = r.first_scan;
        self.state = SimState::Ready;
        self.held = r.held;
        self.forced = r.forced;
        self.cycle_ns = r.cycle_ns;
        self.watchdog = r.watchdog;
        self.schedule = r.schedule;
        if let Some(recorder) = &mut self.recorder {
            recorder.truncate(scan);
        }
        self.trace.truncate_after(scan);
        let sys = crate::vm::SysState { first_scan: false, time_ns: self.time_ns };
        for i in 0..self.breakpoints.len() {
            let cond = self.breakpoints[i].condition;
            let now = self
                .machine
                .eval_condition(&self.exe, cond, sys, self.watchdog)
                .unwrap_or_default();
            self.breakpoints[i].was_true = now;
        }
        self.refresh_watches();
        Ok(())
    }

    /// Replays recorded scan `scan` (at least 1, and after the first scan recorded) with
    /// every write logged: the values written between the scans, the held and forced
    /// values, every store of the program, the plant's and the tasks' copies.
    pub fn trace_scan(&self, scan: u64) -> Result<TracedScan, RecordError> {
        let recorder = self.check_recorded(scan)?;
        if scan == 0 || scan == recorder.oldest() {
            let (first, last) = (recorder.oldest() + 1, self.scans);
            return Err(RecordError::OutOfRange { scan, first, last });
        }
        let mut r = self.replay(scan - 1, |_| {})?;
        let before = r.machine.memory().cells.clone();
        let exe = Arc::clone(&self.exe);
        let mut tracer = Tracer::new(&exe);
        self.replay_controls(&mut r, recorder, scan - 1);
        for (addr, (was, now)) in before.iter().zip(&r.machine.memory().cells).enumerate() {
            if was != now {
                tracer.external(addr as u32, *now, Cause::Written);
            }
        }
        if let Err(info) = r.scan_hooked(&mut tracer) {
            return Err(RecordError::Replay(format!("scan {}: {}", info.scan, info.fault)));
        }
        let events = std::mem::take(&mut tracer.events);
        let view = self.view_of(r, Some(before.clone()));
        Ok(TracedScan { scan, before, events, view })
    }

    /// For each slot, the last scan `k` at or before `scan` on which its value changed
    /// (differs from its value at the end of scan `k - 1`), `None` when it did not change
    /// since the first scan recorded. Replays the history backwards stretch by stretch
    /// (from one snapshot to the next), skipping the stretches where none of the slots'
    /// cells changed once an earlier search has found that out.
    pub fn last_changes(&self, slots: &[Slot], scan: u64) -> Result<Vec<Option<u64>>, RecordError> {
        let recorder = self.check_recorded(scan)?;
        let cells: Vec<Vec<usize>> = slots.iter().map(|s| self.cells_of(s)).collect();
        let mut found: Vec<Option<u64>> = vec![None; slots.len()];
        let mut k = recorder.snapshots.partition_point(|s| s.scans <= scan);
        while k > 0 {
            k -= 1;
            let open: Vec<usize> = (0..slots.len()).filter(|&i| found[i].is_none()).collect();
            if open.is_empty() {
                break;
            }
            let snap = &recorder.snapshots[k];
            let next = recorder.snapshots.get(k + 1).map(|s| s.scans);
            let to = next.unwrap_or(self.scans).min(scan);
            if snap.scans >= to {
                continue;
            }
            let complete = next == Some(to);
            let known = self.known_changes(recorder, snap.scans, complete);
            let wanted: Vec<usize> = open
                .into_iter()
                .filter(|&i| known.as_ref().is_none_or(|ch| cells[i].iter().any(|&c| bit(ch, c))))
                .collect();
            if wanted.is_empty() {
                continue;
            }
            let mut stretch = Stretch::new(self.state_cells, complete && known.is_none());
            let mut last: Vec<Option<Value>> = vec![None; slots.len()];
            self.replay_from(recorder, snap, to, |r| {
                for &i in &wanted {
                    let v = r.read_slot(&slots[i]);
                    if last[i].as_ref().is_some_and(|old| !same_value(old, &v)) {
                        found[i] = Some(r.scans);
                    }
                    last[i] = Some(v);
                }
                stretch.see(&r.machine.memory().cells);
            })?;
            stretch.keep(self, recorder, snap.scans);
        }
        Ok(found)
    }

    /// The first scan after `scan` on which the value of `slot` changed, `None` when it
    /// did not change up to the present.
    pub fn next_change(&self, slot: &Slot, scan: u64) -> Result<Option<u64>, RecordError> {
        let recorder = self.check_recorded(scan)?;
        let cells = self.cells_of(slot);
        let mut value = self.view_at(scan)?.read_slot(slot);
        let mut k = recorder.snapshots.partition_point(|s| s.scans <= scan).saturating_sub(1);
        while let Some(snap) = recorder.snapshots.get(k) {
            let next = recorder.snapshots.get(k + 1).map(|s| s.scans);
            let to = next.unwrap_or(self.scans);
            k += 1;
            if to <= scan {
                continue;
            }
            let complete = next.is_some();
            let known = self.known_changes(recorder, snap.scans, complete);
            if snap.scans >= scan
                && known.as_ref().is_some_and(|ch| !cells.iter().any(|&c| bit(ch, c)))
            {
                continue;
            }
            let mut hit = None;
            let mut stretch = Stretch::new(self.state_cells, complete && known.is_none());
            self.replay_from(recorder, snap, to, |r| {
                stretch.see(&r.machine.memory().cells);
                if r.scans <= scan || hit.is_some() {
                    return;
                }
                let v = r.read_slot(slot);
                if !same_value(&v, &value) {
                    hit = Some(r.scans);
                }
                value = v;
            })?;
            stretch.keep(self, recorder, snap.scans);
            if hit.is_some() {
                return Ok(hit);
            }
        }
        Ok(None)
    }

    fn cells_of(&self, slot: &Slot) -> Vec<usize> {
        let n = if slot.bit.is_some() { 1 } else { element_size(&self.exe, slot.ty).unwrap_or(1) };
        (slot.addr as usize..slot.addr as usize + n as usize).collect()
    }

    fn known_changes(&self, recorder: &Recorder, from: u64, complete: bool) -> Option<Box<[u64]>> {
        if !complete {
            return None;
        }
        recorder.changes.lock().ok()?.stretches.get(&from).cloned()
    }

    fn remember_changes(&self, recorder: &Recorder, from: u64, changed: Vec<u64>) {
        let Ok(mut index) = recorder.changes.lock() else { return };
        if index.bytes + 8 * changed.len() > limits::RECORD_BUDGET_BYTES / 8 {
            return;
        }
        index.bytes += 8 * changed.len();
        index.stretches.insert(from, changed.into());
    }
}

/// The cells that changed over one stretch of scans, gathered while it is replayed.
struct Stretch {
    on: bool,
    changed: Vec<u64>,
    previous: Option<Vec<u64>>,
    cells: usize,
}

impl Stretch {
    fn new(cells: usize, on: bool) -> Stretch {
        Stretch { on, changed: vec![0; cells / 64 + 1], previous: None, cells }
    }

    /// Memory at the end of the next scan of the stretch.
    fn see(&mut self, now: &[u64]) {
        if !self.on {
            return;
        }
        let now = &now[..self.cells.min(now.len())];
        match &mut self.previous {
            Some(prev) => {
                for (c, (a, b)) in prev.iter_mut().zip(now).enumerate() {
                    if *a != *b {
                        self.changed[c / 64] |= 1 << (c % 64);
                        *a = *b;
                    }
                }
            }
            None => self.previous = Some(now.to_vec()),
        }
    }

    /// Remembers what changed, when the whole stretch was seen.
    fn keep(self, sim: &Simulator, recorder: &Recorder, from: u64) {
        if self.on {
            sim.remember_changes(recorder, from, self.changed);
        }
    }
}

fn bit(set: &[u64], c: usize) -> bool {
    set.get(c / 64).is_some_and(|w| w & (1 << (c % 64)) != 0)
}
