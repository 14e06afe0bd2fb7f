//! The tasks of a CONFIGURATION on the simulator's one virtual clock.
//!
//! A scan is one tick of the base clock (the cycle time). On each tick, every task that is
//! due runs its program instances, most urgent PRIORITY first (0 before 1; equal
//! priorities in source order), then the instances with no task run:
//! - a cyclic task (INTERVAL) is due on the first tick and then on each tick whose start
//!   time has reached its next multiple of the interval, so a task of T#20ms on a 10 ms
//!   clock runs on every second scan, and one slower than the clock never runs twice in one
//!   scan (IEC 61131-3 §2.7.2; an interval that is no multiple of the clock runs on the
//!   first tick at or after each multiple);
//! - an event task (SINGLE) is due on the tick where its BOOL global has turned TRUE since
//!   the last tick (a rising edge); with an INTERVAL too, it also runs cyclically while the
//!   global is FALSE;
//! - a task with neither runs on every tick.
//!
//! Each instance's input connections are copied in from their globals before it runs, and
//! its output connections copied out after. Variables that `VAR_CONFIG` gives an address
//! (declared at `%I*`, `%Q*`, `%M*`) keep their own cells: inputs are copied from the
//! process image when the tick starts, outputs and memory to it when the tick ends, as a
//! PLC's I/O mapping does.

use super::{copy_links, Simulator};
use crate::compile::{Executable, Slot};
use crate::semantic::Program;
use crate::syntax::VarSection;
use crate::vm::trace::Hook;
use crate::vm::{self, Machine, RuntimeError, SysState};

/// The configuration's tasks and instances, ready to run.
#[derive(Debug, Clone)]
pub(super) struct Schedule {
    tasks: Vec<TaskState>,
    /// Per instance, in source order: its index in the executable's instances, its task
    /// and its connections.
    instances: Vec<InstanceRun>,
    /// The tasks in the order they run when due together.
    order: Vec<usize>,
    /// `VAR_CONFIG`: (image slot, variable slot) of inputs, copied before the tasks run.
    inputs: Vec<(Slot, Slot)>,
    /// (variable slot, image slot) of outputs and memory, copied after.
    outputs: Vec<(Slot, Slot)>,
}

#[derive(Debug, Clone)]
struct TaskState {
    interval_ns: i64,
    single: Option<Slot>,
    /// The SINGLE global's value on the last tick.
    was_set: bool,
    /// The start time from which the cyclic task is due again.
    next_due_ns: i64,
    /// How many times the task has run since the last restart.
    runs: u64,
}

#[derive(Debug, Clone)]
struct InstanceRun {
    task: Option<usize>,
    inputs: Vec<(Slot, Slot)>,
    outputs: Vec<(Slot, Slot)>,
}

/// Why a schedule cannot be built: a path the checker accepted that the executable lacks.
pub(super) fn missing(path: &str) -> super::SimError {
    super::SimError::UnknownVariable(path.to_string())
}

impl Schedule {
    /// The schedule of `program`'s configuration, compiled in `exe` (whose first
    /// instances are the configuration's, in order).
    pub fn new(program: &Program, exe: &Executable) -> Result<Option<Schedule>, super::SimError> {
        let Some(config) = &program.config else { return Ok(None) };
        if exe.main != config.pou {
            return Ok(None);
        }
        let locate = |path: &str| exe.locate(path).ok_or_else(|| missing(path));
        let mut tasks = Vec::with_capacity(config.tasks.len());
        for t in &config.tasks {
            let single = t.single.as_deref().map(locate).transpose()?;
            tasks.push(TaskState {
                interval_ns: t.interval_ns,
                single,
                was_set: false,
                next_due_ns: 0,
                runs: 0,
            });
        }
        let mut instances = Vec::with_capacity(config.instances.len());
        for i in &config.instances {
            let mut run = InstanceRun {
                task: i.task.map(|t| t as usize),
                inputs: Vec::new(),
                outputs: Vec::new(),
            };
            for (param, global) in &i.inputs {
                run.inputs.push((locate(global)?, locate(&format!("{}.{param}", i.name))?));
            }
            for (param, global) in &i.outputs {
                run.outputs.push((locate(&format!("{}.{param}", i.name))?, locate(global)?));
            }
            instances.push(run);
        }
        let mut order: Vec<usize> = (0..tasks.len()).collect();
        order.sort_by_key(|&k| (config.tasks[k].priority, k));
        let (mut inputs, mut outputs) = (Vec::new(), Vec::new());
        for (path, loc) in &config.io {
            let var = locate(path)?;
            let image = crate::program::locate::image_slot_at(exe, loc, var.ty)
                .ok_or_else(|| missing(&loc.text))?;
            if loc.area == crate::syntax::AddressArea::Input {
                inputs.push((image, var));
            } else {
                outputs.push((var, image));
            }
        }
        Ok(Some(Schedule { tasks, instances, order, inputs, outputs }))
    }

    /// Back to power-on: every task due on the first tick, no edge seen.
    pub fn reset(&mut self) {
        for t in &mut self.tasks {
            t.was_set = false;
            t.next_due_ns = 0;
            t.runs = 0;
        }
    }

    /// How many times task `k` (in source order) has run since the last restart.
    pub fn runs(&self, k: usize) -> u64 {
        self.tasks.get(k).map_or(0, |t| t.runs)
    }

    /// Which tasks are due on the tick starting at `now_ns`, in the order they run; marks
    /// them run.
    fn due(&mut self, machine: &Machine, exe: &Executable, now_ns: i64) -> Vec<usize> {
        let mut due = Vec::new();
        for &k in &self.order {
            let t = &mut self.tasks[k];
            let set = t
                .single
                .as_ref()
                .is_some_and(|s| vm::read(machine.memory(), exe, s) == vm::Value::Bool(true));
            let edge = set && !t.was_set;
            t.was_set = set;
            let cyclic = t.interval_ns > 0 && !set && now_ns >= t.next_due_ns;
            let every_tick = t.interval_ns == 0 && t.single.is_none();
            if edge || cyclic || every_tick {
                if t.interval_ns > 0 {
                    t.next_due_ns =
                        (now_ns / t.interval_ns).saturating_add(1).saturating_mul(t.interval_ns);
                }
                t.runs += 1;
                due.push(k);
            }
        }
        due
    }
}

impl Simulator {
    /// Runs the configuration's due tasks, then its instances without a task.
    pub(super) fn run_tasks<H: Hook>(
        &mut self,
        sys: SysState,
        hook: &mut H,
    ) -> Result<(), RuntimeError> {
        let Some(mut schedule) = self.schedule.take() else { return Ok(()) };
        copy_links(self.machine.memory_mut(), &self.exe, &schedule.inputs, hook);
        let due = schedule.due(&self.machine, &self.exe, sys.time_ns);
        let result = due
            .iter()
            .map(|&k| Some(k))
            .chain(std::iter::once(None))
            .try_for_each(|task| self.run_task_instances(&schedule, task, sys, hook));
        copy_links(self.machine.memory_mut(), &self.exe, &schedule.outputs, hook);
        self.schedule = Some(schedule);
        result
    }

    fn run_task_instances<H: Hook>(
        &mut self,
        schedule: &Schedule,
        task: Option<usize>,
        sys: SysState,
        hook: &mut H,
    ) -> Result<(), RuntimeError> {
        for (k, inst) in schedule.instances.iter().enumerate() {
            if inst.task != task {
                continue;
            }
            copy_links(self.machine.memory_mut(), &self.exe, &inst.inputs, hook);
            self.machine.run_instance_hooked(&self.exe, k, sys, self.watchdog, hook)?;
            copy_links(self.machine.memory_mut(), &self.exe, &inst.outputs, hook);
        }
        Ok(())
    }

    /// How many times the configuration's task `name` has run since the last restart
    /// (`None`: no such task, or no configuration running).
    pub fn task_runs(&self, name: &str) -> Option<u64> {
        let config = self.program.config.as_ref()?;
        let k = config.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(name))?;
        Some(self.schedule.as_ref()?.runs(k))
    }
}

impl Simulator {
    /// The CONFIGURATION being run, when the main program is one.
    pub fn configuration(&self) -> Option<&crate::semantic::ir::Configuration> {
        self.schedule.as_ref()?;
        self.program.config.as_ref()
    }

    /// The variables the I/O panel and the timeline offer, with their paths: the main
    /// program's and the globals (as [`Executable::main_vars`]); when a configuration runs,
    /// each program instance's own variables instead of the instance, as `Instance.Name`
    /// (its VAR_EXTERNALs are the globals, listed once; inputs connected to a global are
    /// left out: the global drives them).
    pub fn listed_vars(&self) -> Vec<(String, &crate::semantic::ir::Var)> {
        let instances: Vec<&crate::semantic::ir::ProgramInstance> =
            self.configuration().map(|c| c.instances.iter().collect()).unwrap_or_default();
        let mut out = Vec::new();
        for e in self.exe.main_vars() {
            let instance =
                instances.iter().find(|i| !e.global && i.name.eq_ignore_ascii_case(&e.var.name));
            match (e.var.ty, instance) {
                (crate::semantic::Type::Fb(q), Some(inst)) => {
                    for v in &self.program.pou(q).vars {
                        // Inputs connected to a global are driven by it: the global is listed.
                        let connected =
                            inst.inputs.iter().any(|(p, _)| p.eq_ignore_ascii_case(&v.name));
                        let own = !matches!(v.section, VarSection::External | VarSection::InOut);
                        if own && !connected {
                            out.push((format!("{}.{}", e.var.name, v.name), v));
                        }
                    }
                }
                _ => out.push((e.var.name.clone(), &e.var)),
            }
        }
        out
    }
}
