//! The simulator: a PLC's scan cycle on a virtual clock around the VM.
//!
//! One scan: write held inputs and forced values → run the program → write forced values
//! again (forcing wins over the program's writes) → advance the clock by the cycle time →
//! record the trace → evaluate breakpoints (a breakpoint pauses at the end of the scan on
//! which its condition became true). A runtime fault puts the PLC in FAULT until a restart.
//! The simulator never reads a wall clock: the caller decides how many scans to run and
//! when, so runs are reproducible natively and in the browser.

mod record;
mod tasks;
mod trace;

pub(crate) use record::same_value;
pub use record::{Readout, RecordError, Recording, ScanView, TracedScan};
pub use trace::{Trace, TraceSample};

use std::fmt;
use std::sync::Arc;

pub use crate::compile::CompileError;
use crate::compile::{self, ConditionId, Executable, Slot};
use crate::diagnostics::{Diagnostic, Span};
use crate::limits;
use crate::semantic::{self, InitValue, PouId, Program, Type};
use crate::syntax::VarSection;
use crate::vm::trace::{Hook, NoHook};
use crate::vm::{self, Cause, Fault, Machine, RuntimeError, SysState, Value};

pub use crate::limits::DEFAULT_WATCHDOG;

/// Why the PLC stopped in FAULT.
#[derive(Debug, Clone, PartialEq)]
pub struct FaultInfo {
    /// What went wrong.
    pub fault: Fault,
    /// The faulting statement in the source.
    pub span: Span,
    /// The POU it belongs to.
    pub pou: PouId,
    /// The scan on which it happened (1-based).
    pub scan: u64,
    /// The virtual time at the start of that scan, in nanoseconds.
    pub time_ns: i64,
}

/// Identifies a breakpoint.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BreakpointId(pub u32);

/// A compiled condition of [`Simulator::add_probe`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ProbeId(ConditionId);

/// What the simulator is doing.
#[derive(Debug, Clone, PartialEq)]
pub enum SimState {
    /// Ready to scan.
    Ready,
    /// Paused by a breakpoint (scanning again resumes).
    Paused(BreakpointId),
    /// Stopped by a runtime fault; only a restart leaves this state.
    Faulted(FaultInfo),
}

/// How a call to scan ended.
#[derive(Debug, Clone, PartialEq)]
pub enum ScanOutcome {
    /// Every requested scan ran.
    Completed,
    /// A breakpoint's condition became true at the end of a scan.
    Breakpoint(BreakpointId),
    /// A runtime fault stopped the PLC (now or earlier).
    Fault(FaultInfo),
}

/// Errors of simulator operations (never of the program itself: those are faults).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SimError {
    /// The program could not be compiled.
    Compile(CompileError),
    /// No variable has that name or path.
    UnknownVariable(String),
    /// The value text does not fit the variable.
    BadValue {
        /// The variable path.
        path: String,
        /// Why.
        message: String,
    },
    /// A breakpoint condition did not check.
    BadCondition(Vec<Diagnostic>),
    /// No breakpoint with that id.
    UnknownBreakpoint(BreakpointId),
    /// The plant cannot be run with this controller.
    Plant(Box<crate::diagnostics::Said>),
    /// The variable is an array, structure or FB instance: the timeline records single
    /// values.
    NotTraceable(String),
}

impl fmt::Display for SimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SimError::Compile(e) => write!(f, "{e}"),
            SimError::UnknownVariable(_) | SimError::Plant(_) | SimError::NotTraceable(_) => {
                f.write_str(&self.said().english)
            }
            SimError::BadValue { path, message } => write!(f, "`{path}`: {message}"),
            SimError::BadCondition(d) => {
                let first = d.first().map_or("invalid condition", |d| d.message.as_str());
                write!(f, "breakpoint condition: {first}")
            }
            SimError::UnknownBreakpoint(id) => write!(f, "no breakpoint #{}", id.0),
        }
    }
}

impl SimError {
    /// The error as a message, with its English text (what it displays as); an error still
    /// worded in English only is that text.
    pub fn said(&self) -> crate::diagnostics::Said {
        match self {
            SimError::Compile(e) => e.said(),
            SimError::UnknownVariable(p) => crate::msg!(NoVariable, name = p),
            SimError::Plant(m) => crate::msg!(PlantDetail, detail = **m),
            SimError::NotTraceable(p) => crate::msg!(NotSingleValue, name = p),
            _ => self.to_string().into(),
        }
    }
}

impl std::error::Error for SimError {}

/// A variable held at (or forced to) a value.
#[derive(Debug, Clone, PartialEq)]
struct Pinned {
    path: Arc<str>,
    slot: Slot,
    value: Value,
}

#[derive(Debug, Clone)]
struct Breakpoint {
    id: BreakpointId,
    source: String,
    condition: ConditionId,
    was_true: bool,
}

/// A simulated PLC running one PROGRAM.
///
/// With recording on ([`Simulator::set_recording`]) it keeps the recent history of the run,
/// so any recorded scan can be shown again ([`Simulator::view_at`]), replayed with every
/// write logged ([`Simulator::trace_scan`], behind `crate::why`) or made the present again
/// ([`Simulator::rewind_to`]); `record.rs` says how.
#[derive(Debug, Clone)]
pub struct Simulator {
    program: Arc<Program>,
    exe: Arc<Executable>,
    machine: Machine,
    cycle_ns: i64,
    time_ns: i64,
    scans: u64,
    first_scan: bool,
    state: SimState,
    held: Vec<Pinned>,
    forced: Vec<Pinned>,
    breakpoints: Vec<Breakpoint>,
    next_breakpoint: u32,
    trace: Trace,
    watchdog: u64,
    watches: Vec<Watch>,
    plant: Option<Plant>,
    /// The configuration's tasks, when the main program is a CONFIGURATION.
    schedule: Option<tasks::Schedule>,
    /// The cells of the program's own image (the state of a scan); breakpoint and watch
    /// conditions compiled later add scratch cells after them.
    state_cells: usize,
    /// The recent history, when recording is on.
    recorder: Option<Box<record::Recorder>>,
}

/// Copies each `(from, to)` pair of linked variables (one elementary type): the cell
/// itself, or through its value for a bit of a located variable. `hook` is told of each
/// cell written.
fn copy_links<H: Hook>(
    mem: &mut crate::program::memory::Memory,
    exe: &Executable,
    links: &[(Slot, Slot)],
    hook: &mut H,
) {
    for (from, to) in links {
        let cells = (from.addr as usize, to.addr as usize);
        match (from.bit, to.bit, mem.cells.get(cells.0).copied()) {
            (None, None, Some(bits)) if cells.1 < mem.cells.len() => mem.cells[cells.1] = bits,
            _ => {
                let v = vm::read(mem, exe, from);
                let _ = vm::write(mem, exe, to, &v);
            }
        }
        if H::ON {
            if let Some(&bits) = mem.cells.get(cells.1) {
                hook.external(to.addr, bits, Cause::Link { from: from.addr });
            }
        }
    }
}

/// A plant PROGRAM run after the controller on every scan (`docs/plants.md`): its inputs
/// are the controller's variables of the same names, copied in before it runs; its
/// outputs are copied to the controller's variables of the same names after it.
#[derive(Debug, Clone)]
struct Plant {
    /// Controller slot → plant input slot.
    inputs: Vec<(Slot, Slot)>,
    /// Plant output slot → controller slot.
    outputs: Vec<(Slot, Slot)>,
    /// The controller's variables the plant writes (its sensors), as declared.
    sensors: Vec<String>,
}

/// An expression the simulator evaluates after each run of scans (the network view's
/// function outputs, which have no variable of their own).
#[derive(Debug, Clone)]
struct Watch {
    source: String,
    condition: ConditionId,
    ty: semantic::Type,
    value: Option<Value>,
}

impl Simulator {
    /// Compiles PROGRAM `main` of a checked program and powers the PLC on (cold start).
    /// When `main` is a CONFIGURATION's PROGRAM ([`semantic::ir::Configuration::pou`]),
    /// its program instances run under their tasks (`tasks.rs`).
    pub fn new(program: Program, main: PouId) -> Result<Self, SimError> {
        let exe = compile::compile(&program, main).map_err(SimError::Compile)?;
        let machine = Machine::new(&exe);
        let schedule = tasks::Schedule::new(&program, &exe)?;
        let mut sim = Simulator::new_compiled(program, exe, machine);
        sim.schedule = schedule;
        Ok(sim)
    }

    /// Like [`Simulator::new`], with PROGRAM `plant` run after `main` on every scan, on the
    /// same virtual clock: each VAR_INPUT of the plant reads the controller's variable of
    /// its name, each VAR_OUTPUT is written to the controller's variable of its name (a
    /// sensor), matched case-insensitively and of the same elementary type. The plant's
    /// variables are read as `Plant.Name`.
    pub fn with_plant(program: Program, main: PouId, plant: PouId) -> Result<Self, SimError> {
        if plant == main {
            return Err(SimError::Plant(Box::new(crate::msg!(PlantIsProgramRun))));
        }
        let exe =
            compile::compile_with_programs(&program, main, &[plant]).map_err(SimError::Compile)?;
        let machine = Machine::new(&exe);
        let plant_pou = program.pou(plant);
        let main_pou = program.pou(main);
        let mut links = Plant { inputs: Vec::new(), outputs: Vec::new(), sensors: Vec::new() };
        for v in &plant_pou.vars {
            let into_plant = match v.section {
                VarSection::Input => true,
                VarSection::Output => false,
                _ => continue,
            };
            let Some(k) = main_pou.find_var(&v.name.to_ascii_uppercase()) else { continue };
            let c = &main_pou.vars[k as usize];
            if c.ty != v.ty || !matches!(v.ty, Type::Elem(_) | Type::Enum(_)) {
                return Err(SimError::Plant(Box::new(crate::msg!(
                    PlantControllerOneType,
                    name = &v.name,
                    plant = &plant_pou.name,
                    controller = &main_pou.name
                ))));
            }
            let ctrl =
                exe.locate(&c.name).ok_or_else(|| SimError::UnknownVariable(c.name.clone()))?;
            let path = format!("{}.{}", plant_pou.name, v.name);
            let own = exe.locate(&path).ok_or(SimError::UnknownVariable(path))?;
            if into_plant {
                links.inputs.push((ctrl, own));
            } else {
                links.outputs.push((own, ctrl));
                links.sensors.push(c.name.clone());
            }
        }
        // Conditions and watches compiled later (breakpoints, an exercise's expectations)
        // name the plant's variables as `Plant.Name`: the instance is known to their
        // checker as a global at its base (the image and the variable list are unchanged).
        let mut program = program;
        let mut exe = exe;
        if let Some(&(q, base)) = exe.instances.last() {
            let var = crate::semantic::ir::Var::program_instance(&program, q, VarSection::Global);
            program.globals.push(var);
            exe.lay.globals.push(base);
        }
        let schedule = tasks::Schedule::new(&program, &exe)?;
        let mut sim = Simulator::new_compiled(program, exe, machine);
        sim.plant = Some(links);
        sim.schedule = schedule;
        Ok(sim)
    }

    fn new_compiled(program: Program, exe: Executable, machine: Machine) -> Self {
        let state_cells = exe.out.init.len();
        Simulator {
            program: Arc::new(program),
            exe: Arc::new(exe),
            machine,
            cycle_ns: 10_000_000,
            time_ns: 0,
            scans: 0,
            first_scan: true,
            state: SimState::Ready,
            held: Vec::new(),
            forced: Vec::new(),
            breakpoints: Vec::new(),
            next_breakpoint: 0,
            trace: Trace::new(Vec::new(), 0),
            watchdog: DEFAULT_WATCHDOG,
            watches: Vec::new(),
            plant: None,
            schedule: None,
            state_cells,
            recorder: None,
        }
    }

    /// The name of the plant PROGRAM run after the controller, if any.
    pub fn plant_name(&self) -> Option<&str> {
        self.plant.as_ref()?;
        self.exe.instances.last().map(|(q, _)| self.program.pou(*q).name.as_str())
    }

    /// Whether the plant writes the controller's variable `name` on every scan (one of its
    /// sensors): a value written from outside lasts only until the plant's next scan.
    pub fn plant_drives(&self, name: &str) -> bool {
        self.plant.as_ref().is_some_and(|p| p.sensors.iter().any(|s| s.eq_ignore_ascii_case(name)))
    }

    /// Runs the plant after the controller: its inputs copied in, then its outputs out.
    fn run_plant<H: Hook>(&mut self, sys: SysState, hook: &mut H) -> Result<(), RuntimeError> {
        let Some(plant) = &self.plant else { return Ok(()) };
        copy_links(self.machine.memory_mut(), &self.exe, &plant.inputs, hook);
        let k = self.exe.instances.len().saturating_sub(1);
        self.machine.run_instance_hooked(&self.exe, k, sys, self.watchdog, hook)?;
        copy_links(self.machine.memory_mut(), &self.exe, &plant.outputs, hook);
        Ok(())
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

    /// The current state.
    pub fn state(&self) -> &SimState {
        &self.state
    }

    /// Virtual time since the last start, in nanoseconds.
    pub fn time_ns(&self) -> i64 {
        self.time_ns
    }

    /// Scans completed since the last start.
    pub fn scan_count(&self) -> u64 {
        self.scans
    }

    /// The cycle time in nanoseconds.
    pub fn cycle_ns(&self) -> i64 {
        self.cycle_ns
    }

    /// Sets the cycle time (at least 1 ns).
    pub fn set_cycle_ns(&mut self, ns: i64) {
        self.control(record::Control::Cycle(ns.max(1)));
    }

    /// Sets the watchdog: the most instructions one scan may run (at least 1).
    pub fn set_watchdog(&mut self, budget: u64) {
        self.control(record::Control::Watchdog(budget.max(1)));
    }

    /// The watchdog budget.
    pub fn watchdog(&self) -> u64 {
        self.watchdog
    }

    /// Runs one scan.
    pub fn scan(&mut self) -> ScanOutcome {
        let outcome = self.scan_once();
        self.refresh_watches();
        outcome
    }

    /// One scan of [`Simulator::run_scans`] and its kin, kept out of their loops: in the
    /// browser a loop that runs many scans in one call stays in the code it was entered
    /// with, and only what it calls gets the optimising compiler's code (BENCHMARKS.md, B5).
    #[inline(never)]
    fn scan_once(&mut self) -> ScanOutcome {
        if let Err(info) = self.scan_hooked(&mut NoHook) {
            return ScanOutcome::Fault(info);
        }
        if self.recorder.as_ref().is_some_and(|r| r.due(self.scans)) {
            self.take_snapshot();
        }
        self.record_trace();
        self.check_breakpoints()
    }

    /// The scan itself, with `hook` told of every write: held and forced values, the
    /// program (and the tasks' instances, and the plant), forced values again.
    #[cfg_attr(plc_speed, optimize(speed))]
    fn scan_hooked<H: Hook>(&mut self, hook: &mut H) -> Result<(), FaultInfo> {
        if let SimState::Faulted(info) = &self.state {
            return Err(info.clone());
        }
        self.state = SimState::Ready;
        self.apply_pinned(hook);
        let sys = SysState { first_scan: self.first_scan, time_ns: self.time_ns };
        if let Err(RuntimeError { fault, span, pou }) = self
            .machine
            .run_scan_hooked(&self.exe, sys, self.watchdog, hook)
            .and_then(|()| self.run_tasks(sys, hook))
            .and_then(|()| self.run_plant(sys, hook))
        {
            let info = FaultInfo { fault, span, pou, scan: self.scans + 1, time_ns: self.time_ns };
            self.state = SimState::Faulted(info.clone());
            return Err(info);
        }
        self.apply_forced(hook);
        self.scans += 1;
        self.first_scan = false;
        self.time_ns = self.time_ns.saturating_add(self.cycle_ns);
        Ok(())
    }

    /// Runs up to `n` scans, stopping early at a breakpoint or fault.
    pub fn run_scans(&mut self, n: u64) -> ScanOutcome {
        let mut outcome = ScanOutcome::Completed;
        for _ in 0..n {
            outcome = self.scan_once();
            if !matches!(outcome, ScanOutcome::Completed) {
                break;
            }
        }
        self.refresh_watches();
        outcome
    }

    /// Runs scans until the virtual clock reaches `time_ns` (or a breakpoint or fault).
    pub fn run_until(&mut self, time_ns: i64) -> ScanOutcome {
        let mut outcome = ScanOutcome::Completed;
        while self.time_ns < time_ns {
            outcome = self.scan_once();
            if !matches!(outcome, ScanOutcome::Completed) {
                break;
            }
        }
        self.refresh_watches();
        outcome
    }

    /// The paths (`Mixer1`, `Line.Mixer2`) of the instances of function block `fb` in the
    /// main program, nested ones too, in declaration order (arrays of instances are left
    /// out).
    pub fn instances_of(&self, fb: &str) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_instances(self.main_pou(), "", fb, 0, &mut out);
        out
    }

    fn collect_instances(
        &self,
        pou: PouId,
        prefix: &str,
        fb: &str,
        depth: usize,
        out: &mut Vec<String>,
    ) {
        if depth > 16 || out.len() > 1000 {
            return;
        }
        for v in &self.program.pou(pou).vars {
            let Type::Fb(id) = v.ty else { continue };
            let path = format!("{prefix}{}", v.name);
            if self.program.pou(id).name.eq_ignore_ascii_case(fb) {
                out.push(path.clone());
            }
            if !self.program.pou(id).library {
                self.collect_instances(id, &format!("{path}."), fb, depth + 1, out);
            }
        }
    }

    /// Watches `source`, an ST expression of one elementary value over the main program's
    /// variables that calls no FUNCTION of the program (`ADD(N, 5)`): from now on it is
    /// evaluated after every run of scans, and [`Simulator::watch`] gives its value. The
    /// same text is watched once.
    pub fn add_watch(&mut self, source: &str) -> Result<(), SimError> {
        if self.watches.iter().any(|w| w.source == source) {
            return Ok(());
        }
        let expr = semantic::check_watch(&self.program, self.main_pou(), source)
            .map_err(SimError::BadCondition)?;
        let condition = Arc::make_mut(&mut self.exe)
            .compile_condition(&self.program, &expr)
            .map_err(SimError::Compile)?;
        self.watches.push(Watch {
            source: source.to_string(),
            condition,
            ty: expr.ty,
            value: None,
        });
        self.refresh_watches();
        Ok(())
    }

    /// The value of the watched expression `source` after the last run of scans (`None`
    /// when it is not watched, or faulted: a division by zero).
    pub fn watch(&self, source: &str) -> Option<&Value> {
        self.watches.iter().find(|w| w.source == source).and_then(|w| w.value.as_ref())
    }

    fn refresh_watches(&mut self) {
        let sys = SysState { first_scan: false, time_ns: self.time_ns };
        for w in &mut self.watches {
            w.value = self
                .machine
                .eval_bits(&self.exe, w.condition, sys, self.watchdog)
                .ok()
                .map(|bits| Value::from_bits(w.ty, bits, &self.program.types));
        }
    }

    /// Cold restart: every variable back to its initial value, clock and scan count to 0,
    /// fault cleared. Held inputs and forcing stay.
    pub fn cold_restart(&mut self) {
        self.machine.cold_reset(&self.exe);
        self.restart_common();
    }

    /// Warm restart: like a cold restart, but RETAIN variables keep their values.
    pub fn warm_restart(&mut self) {
        self.machine.warm_reset(&self.exe);
        self.restart_common();
    }

    fn restart_common(&mut self) {
        self.time_ns = 0;
        self.scans = 0;
        self.first_scan = true;
        self.state = SimState::Ready;
        if let Some(schedule) = &mut self.schedule {
            schedule.reset();
        }
        for bp in &mut self.breakpoints {
            bp.was_true = false;
        }
        self.trace.clear();
        self.refresh_watches();
        // A restart begins a new history.
        if self.recorder.is_some() {
            self.start_recording();
        }
    }

    fn slot(&self, path: &str) -> Result<Slot, SimError> {
        self.exe.locate(path).ok_or_else(|| SimError::UnknownVariable(path.to_string()))
    }

    /// Parses `text` (an IEC literal) as a value for the variable at `path`.
    pub fn parse_value(&self, path: &str, text: &str) -> Result<(Slot, Value), SimError> {
        let slot = self.slot(path)?;
        let init = semantic::parse_value(&self.program, self.main_pou(), slot.ty, text)
            .map_err(|message| SimError::BadValue { path: path.to_string(), message })?;
        let value = match init {
            InitValue::Scalar(bits) => Value::from_bits(slot.ty, bits, self.exe.type_table()),
            InitValue::Str(bytes) => Value::Str(bytes),
            _ => {
                return Err(SimError::BadValue {
                    path: path.to_string(),
                    message: "only single values can be set".to_string(),
                })
            }
        };
        // A subrange variable takes only values inside its limits, from outside too.
        if let (Value::Int(v, _), Some((lo, hi))) =
            (&value, semantic::subrange_of(&self.program, self.main_pou(), path))
        {
            if *v < i128::from(lo) || *v > i128::from(hi) {
                return Err(SimError::BadValue {
                    path: path.to_string(),
                    message: format!("{v} is outside its subrange {lo}..{hi}"),
                });
            }
        }
        Ok((slot, value))
    }

    /// Writes a value now (the program may overwrite it on the next scan).
    pub fn write(&mut self, path: &str, text: &str) -> Result<(), SimError> {
        let (slot, value) = self.parse_value(path, text)?;
        self.write_slot(path, &slot, &value)?;
        self.record(record::Control::Write(Box::new((slot, value))));
        Ok(())
    }

    fn write_slot(&mut self, path: &str, slot: &Slot, value: &Value) -> Result<(), SimError> {
        vm::write(self.machine.memory_mut(), &self.exe, slot, value)
            .map_err(|f| SimError::BadValue { path: path.to_string(), message: f.to_string() })
    }

    /// Holds an input at a value: written before every scan until released.
    pub fn hold(&mut self, path: &str, text: &str) -> Result<(), SimError> {
        let (slot, value) = self.parse_value(path, text)?;
        self.write_slot(path, &slot, &value)?;
        self.control(record::Control::Hold(Box::new(Pinned { path: path.into(), slot, value })));
        Ok(())
    }

    /// Holds an input at an already typed value (no parsing: for plant models and
    /// benchmarks that set inputs every scan).
    pub fn hold_value(&mut self, path: &str, value: Value) -> Result<(), SimError> {
        let slot = self.slot(path)?;
        self.write_slot(path, &slot, &value)?;
        let held = self.held.iter().position(|p| p.path.eq_ignore_ascii_case(path));
        match held {
            // The same value held again changes nothing (and is not recorded).
            Some(k) if self.held[k].value == value => Ok(()),
            Some(k) if self.held[k].slot == slot => {
                // The common change, recorded small: a plant model holds a new value on
                // every scan.
                if self.recorder.is_some() {
                    let control = match record::scalar_bits(&slot, &value, &self.exe) {
                        Some(bits) => record::Control::Held { k: k as u32, bits },
                        None => {
                            let path = Arc::clone(&self.held[k].path);
                            let pin = Pinned { path, slot, value: value.clone() };
                            record::Control::HoldInPlace(Box::new(pin))
                        }
                    };
                    self.record(control);
                }
                self.held[k].value = value;
                Ok(())
            }
            _ => {
                let pin = Pinned { path: path.into(), slot, value };
                self.control(record::Control::HoldInPlace(Box::new(pin)));
                Ok(())
            }
        }
    }

    /// Stops holding an input (it keeps its last value).
    pub fn release(&mut self, path: &str) {
        if self.held.iter().any(|p| p.path.eq_ignore_ascii_case(path)) {
            self.control(record::Control::Release(Box::new(path.into())));
        }
    }

    /// Forces a variable: its value is written before and after every scan, whatever the
    /// program does, until unforced.
    pub fn force(&mut self, path: &str, text: &str) -> Result<(), SimError> {
        let (slot, value) = self.parse_value(path, text)?;
        self.write_slot(path, &slot, &value)?;
        self.control(record::Control::Force(Box::new(Pinned { path: path.into(), slot, value })));
        Ok(())
    }

    /// Removes forcing from a variable.
    pub fn unforce(&mut self, path: &str) {
        if self.forced.iter().any(|p| p.path.eq_ignore_ascii_case(path)) {
            self.control(record::Control::Unforce(Box::new(path.into())));
        }
    }

    /// The forced variables and their values.
    pub fn forced(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.forced.iter().map(|p| (&*p.path, &p.value))
    }

    /// The held inputs and their values.
    pub fn held(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.held.iter().map(|p| (&*p.path, &p.value))
    }

    fn apply_pinned<H: Hook>(&mut self, hook: &mut H) {
        let mem = self.machine.memory_mut();
        for (p, cause) in self
            .held
            .iter()
            .map(|p| (p, Cause::Held))
            .chain(self.forced.iter().map(|p| (p, Cause::Forced)))
        {
            // A pinned slot was checked when pinned; a failure here cannot happen for the
            // same executable, and is ignored rather than stopping the PLC.
            let _ = vm::write(mem, &self.exe, &p.slot, &p.value);
            if H::ON {
                record::log_slot(hook, mem, &self.exe, &p.slot, cause);
            }
        }
    }

    fn apply_forced<H: Hook>(&mut self, hook: &mut H) {
        let mem = self.machine.memory_mut();
        for p in &self.forced {
            let _ = vm::write(mem, &self.exe, &p.slot, &p.value);
            if H::ON {
                record::log_slot(hook, mem, &self.exe, &p.slot, Cause::Forced);
            }
        }
    }

    /// Where a variable lives, for reading it every scan with [`Simulator::read_slot`]
    /// without looking its name up each time.
    pub fn locate(&self, path: &str) -> Result<Slot, SimError> {
        self.slot(path)
    }

    /// The program's own memory now (without the scratch cells of breakpoint and watch
    /// conditions), as [`ScanView::state_memory`] gives it for a recorded scan.
    pub fn state_memory(&self) -> &[u64] {
        let cells = &self.machine.memory().cells;
        &cells[..self.state_cells.min(cells.len())]
    }

    /// Reads the variable at a slot from [`Simulator::locate`].
    pub fn read_slot(&self, slot: &Slot) -> Value {
        vm::read(self.machine.memory(), &self.exe, slot)
    }

    /// Reads a variable (`Name`, `Name.field`, `Arr[2]`, `Fb.Q`, `Word.3`).
    pub fn read(&self, path: &str) -> Result<Value, SimError> {
        let slot = self.slot(path)?;
        Ok(vm::read(self.machine.memory(), &self.exe, &slot))
    }

    /// Every variable of the main program (and the globals) as JSON, by declared name:
    /// the `vars` object of `plc run --json`.
    pub fn vars_json(&self) -> serde_json::Map<String, serde_json::Value> {
        vars_json_of(self.machine.memory(), &self.exe)
    }

    /// The first statement of the branch each CASE took on its last execution (CASEs whose
    /// selector matched no label and that have no ELSE are left out). The editor marks
    /// these lines while the program runs.
    pub fn active_case_branches(&self) -> Vec<Span> {
        case_branches(&self.machine, &self.exe)
    }

    /// Adds a breakpoint on an ST boolean condition over the program's variables.
    pub fn add_breakpoint(&mut self, condition: &str) -> Result<BreakpointId, SimError> {
        let expr = semantic::check_condition(&self.program, self.main_pou(), condition)
            .map_err(SimError::BadCondition)?;
        let id = Arc::make_mut(&mut self.exe)
            .compile_condition(&self.program, &expr)
            .map_err(SimError::Compile)?;
        let bp = BreakpointId(self.next_breakpoint);
        self.next_breakpoint += 1;
        self.breakpoints.push(Breakpoint {
            id: bp,
            source: condition.to_string(),
            condition: id,
            was_true: false,
        });
        Ok(bp)
    }

    /// Compiles an ST boolean condition over the program's variables (`Up AND Down`,
    /// `Level > 90`) into a probe that [`Simulator::probe`] evaluates between scans without
    /// pausing anything: the grader's expectations.
    pub fn add_probe(&mut self, condition: &str) -> Result<ProbeId, SimError> {
        let expr = semantic::check_condition(&self.program, self.main_pou(), condition)
            .map_err(SimError::BadCondition)?;
        let id = Arc::make_mut(&mut self.exe)
            .compile_condition(&self.program, &expr)
            .map_err(SimError::Compile)?;
        Ok(ProbeId(id))
    }

    /// The value of a probe now (a condition that faults, an index out of range, is false).
    pub fn probe(&mut self, id: ProbeId) -> bool {
        let sys = SysState { first_scan: false, time_ns: self.time_ns };
        self.machine.eval_condition(&self.exe, id.0, sys, self.watchdog).unwrap_or_default()
    }

    /// Removes a breakpoint.
    pub fn remove_breakpoint(&mut self, id: BreakpointId) -> Result<(), SimError> {
        let before = self.breakpoints.len();
        self.breakpoints.retain(|b| b.id != id);
        if self.breakpoints.len() == before {
            return Err(SimError::UnknownBreakpoint(id));
        }
        Ok(())
    }

    /// The condition text of a breakpoint.
    pub fn breakpoint_condition(&self, id: BreakpointId) -> Option<&str> {
        self.breakpoints.iter().find(|b| b.id == id).map(|b| b.source.as_str())
    }

    fn check_breakpoints(&mut self) -> ScanOutcome {
        let sys = SysState { first_scan: false, time_ns: self.time_ns };
        let mut hit = None;
        for i in 0..self.breakpoints.len() {
            let cond = self.breakpoints[i].condition;
            // A condition that faults (an index out of range) counts as not true.
            let now = self
                .machine
                .eval_condition(&self.exe, cond, sys, self.watchdog)
                .unwrap_or_default();
            let bp = &mut self.breakpoints[i];
            if now && !bp.was_true && hit.is_none() {
                hit = Some(bp.id);
            }
            bp.was_true = now;
        }
        match hit {
            Some(id) => {
                self.state = SimState::Paused(id);
                ScanOutcome::Breakpoint(id)
            }
            None => ScanOutcome::Completed,
        }
    }

    /// Starts recording `paths` after every scan, keeping the last `capacity` samples,
    /// or fewer when that many would take more than [`limits::TRACE_BUDGET_BYTES`].
    pub fn set_trace(&mut self, paths: &[&str], capacity: usize) -> Result<(), SimError> {
        let mut slots = Vec::new();
        let mut sample_bytes = 0usize;
        for p in paths {
            sample_bytes = sample_bytes.saturating_add(self.trace_cost(p)?);
            slots.push((p.to_string(), self.slot(p)?));
        }
        let affordable = limits::TRACE_BUDGET_BYTES / sample_bytes.max(1);
        self.trace = Trace::new(slots, capacity.min(affordable.max(1)));
        Ok(())
    }

    /// The bytes one recorded value of `path` is counted as, or why it cannot be recorded.
    pub fn trace_cost(&self, path: &str) -> Result<usize, SimError> {
        match self.slot(path)?.ty {
            Type::Elem(_) | Type::Enum(_) => Ok(16),
            Type::Str { wide, len } => Ok(16 + len as usize * if wide { 2 } else { 1 }),
            _ => Err(SimError::NotTraceable(path.to_string())),
        }
    }

    /// The trace recorded so far.
    pub fn trace(&self) -> &Trace {
        &self.trace
    }

    fn record_trace(&mut self) {
        if self.trace.is_enabled() {
            let values = self
                .trace
                .slots()
                .iter()
                .map(|(_, s)| vm::read(self.machine.memory(), &self.exe, s))
                .collect();
            self.trace.push(TraceSample { scan: self.scans, time_ns: self.time_ns, values });
        }
    }
}

/// Every variable of the main program (and the globals) in `mem` as JSON, by name.
fn vars_json_of(
    mem: &crate::program::memory::Memory,
    exe: &Executable,
) -> serde_json::Map<String, serde_json::Value> {
    let mut out = serde_json::Map::new();
    for entry in exe.main_vars() {
        if out.contains_key(&entry.var.name) {
            continue;
        }
        let value = vm::read(mem, exe, &entry.slot);
        out.insert(entry.var.name.clone(), vm::to_json(&value));
    }
    out
}

/// The first statement of the branch each CASE took on its last execution.
fn case_branches(machine: &Machine, exe: &Executable) -> Vec<Span> {
    let mut out: Vec<Span> = machine
        .case_hits()
        .filter_map(|(case_pc, target)| {
            let (case_span, _) = exe.statement_at(case_pc)?;
            let (arm, _) = exe.statement_at(target)?;
            let inside =
                arm.start >= case_span.start && arm.end <= case_span.end && arm != case_span;
            inside.then_some(arm)
        })
        .collect();
    crate::order::sort_by_key(&mut out, |s| s.start);
    out.dedup();
    out
}

#[cfg(test)]
mod tests;
