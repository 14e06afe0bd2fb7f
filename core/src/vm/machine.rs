//! The machine: memory plus the dispatch loop that runs one scan of the main program (or a
//! breakpoint condition).
//!
//! The loop hands the simple instructions to the inner loop (`fast`) and runs the rest
//! itself, one `match` over the 16-byte [`Op`]s; registers are cells addressed relative to
//! the current frame base. It never allocates during a scan except for string temporaries
//! (reused scratch buffers) and never panics (every memory and code index is checked, a bad
//! one is `Fault::Internal`, except in code `program::verify` accepted, whose register
//! operands were checked once). The watchdog budget counts every instruction run here and,
//! in the inner loop, every pass of a loop at the number of instructions it jumps back
//! over.

use super::builtins;
use super::fast;
use super::strings::Scratch;
use super::trace::{Hook, NoHook};
use crate::diagnostics::Span;
use crate::limits::{WATCHDOG_BYTES_PER_UNIT, WATCHDOG_CELLS_PER_UNIT};
use crate::program::memory::{copy_cells, copy_str, str_header, Memory};
use crate::program::op::{builtin_ops, Op};
use crate::program::{ConditionId, Executable};
use crate::semantic::ir::SysVar;
use crate::semantic::types::PouId;
use crate::values::arith;
use crate::values::Fault;

pub use crate::limits::MAX_CALL_DEPTH;

/// The system state the simulator passes to each scan.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SysState {
    /// TRUE on the first scan after a cold or warm start.
    pub first_scan: bool,
    /// The virtual clock in nanoseconds since the start.
    pub time_ns: i64,
}

/// A runtime fault with the statement that caused it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RuntimeError {
    /// What went wrong.
    pub fault: Fault,
    /// The innermost statement of user code being executed.
    pub span: Span,
    /// The POU of that statement.
    pub pou: PouId,
}

impl std::fmt::Display for RuntimeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.fault.fmt(f)
    }
}

impl std::error::Error for RuntimeError {}

#[derive(Debug, Clone, Copy)]
struct CallFrame {
    ret: u32,
    base: u32,
    /// The caller's code may run in the inner loop without operand checks.
    trusted: bool,
}

/// A PLC: memory and the state needed to run scans.
#[derive(Debug, Clone)]
pub struct Machine {
    mem: Memory,
    stack: Vec<CallFrame>,
    scratch: Scratch,
    /// Per CASE table: (instruction of the CASE, branch target) of its last execution.
    case_hits: Vec<(u32, u32)>,
}

const BAD: Fault = Fault::Internal("register address out of range");

impl Machine {
    /// A machine whose memory is the executable's initial image.
    pub fn new(exe: &Executable) -> Machine {
        Machine {
            mem: Memory { cells: exe.out.init.clone() },
            stack: Vec::with_capacity(MAX_CALL_DEPTH),
            scratch: Scratch::default(),
            case_hits: vec![(u32::MAX, u32::MAX); exe.out.cases.len()],
        }
    }

    /// For every CASE statement that has run: the instruction of the CASE and the
    /// instruction its last execution jumped to (the active branch, or the end of the
    /// CASE when no label matched). The debug map turns both into source spans.
    pub fn case_hits(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.case_hits.iter().filter(|h| h.0 != u32::MAX).map(|&(c, t)| (c as usize, t as usize))
    }

    /// Per CASE table: (instruction of the CASE, branch target) of its last execution,
    /// `u32::MAX` when it has not run: what a recording keeps of the machine besides memory.
    pub(crate) fn case_state(&self) -> &[(u32, u32)] {
        &self.case_hits
    }

    /// Puts back a state kept by a recording: the first cells of memory and the CASE
    /// branches taken.
    pub(crate) fn restore(&mut self, cells: &[u64], case_hits: &[(u32, u32)]) {
        let n = cells.len().min(self.mem.cells.len());
        self.mem.cells[..n].copy_from_slice(&cells[..n]);
        let k = case_hits.len().min(self.case_hits.len());
        self.case_hits[..k].copy_from_slice(&case_hits[..k]);
    }

    /// The memory.
    pub fn memory(&self) -> &Memory {
        &self.mem
    }

    /// The memory, for writing inputs and forced values.
    pub fn memory_mut(&mut self) -> &mut Memory {
        &mut self.mem
    }

    /// Cold restart: every cell back to its initial value.
    pub fn cold_reset(&mut self, exe: &Executable) {
        self.mem.cells.clear();
        self.mem.cells.extend_from_slice(&exe.out.init);
        self.case_hits.iter_mut().for_each(|h| *h = (u32::MAX, u32::MAX));
    }

    /// Warm restart: as [`Machine::cold_reset`], but RETAIN variables keep their values.
    pub fn warm_reset(&mut self, exe: &Executable) {
        let old = std::mem::take(&mut self.mem.cells);
        self.cold_reset(exe);
        for &(s, n) in &exe.retained {
            let (s, e) = (s as usize, s as usize + n as usize);
            if let (Some(dst), Some(src)) = (self.mem.cells.get_mut(s..e), old.get(s..e)) {
                dst.copy_from_slice(src);
            }
        }
    }

    /// Runs one scan of the main program with at most `budget` instructions.
    pub fn run_scan(
        &mut self,
        exe: &Executable,
        sys: SysState,
        budget: u64,
    ) -> Result<(), RuntimeError> {
        self.run_scan_hooked(exe, sys, budget, &mut NoHook)
    }

    /// [`Machine::run_scan`] with `hook` seeing every instruction.
    pub(crate) fn run_scan_hooked<H: Hook>(
        &mut self,
        exe: &Executable,
        sys: SysState,
        budget: u64,
        hook: &mut H,
    ) -> Result<(), RuntimeError> {
        let main = exe.pous.get(exe.main as usize);
        let entry = main.map_or(u32::MAX, |p| p.entry);
        let trusted = main.is_some_and(|p| p.trusted);
        self.run(exe, (entry, trusted), exe.main_base, sys, budget, hook).map(|_| ())
    }

    /// Runs the body of further PROGRAM instance `k` of the executable (a plant, after the
    /// main program in the same scan).
    pub fn run_instance(
        &mut self,
        exe: &Executable,
        k: usize,
        sys: SysState,
        budget: u64,
    ) -> Result<(), RuntimeError> {
        self.run_instance_hooked(exe, k, sys, budget, &mut NoHook)
    }

    /// [`Machine::run_instance`] with `hook` seeing every instruction.
    pub(crate) fn run_instance_hooked<H: Hook>(
        &mut self,
        exe: &Executable,
        k: usize,
        sys: SysState,
        budget: u64,
        hook: &mut H,
    ) -> Result<(), RuntimeError> {
        let Some(&(pou, base)) = exe.instances.get(k) else { return Ok(()) };
        let code = exe.pous.get(pou as usize);
        let entry = code.map_or(u32::MAX, |p| p.entry);
        let trusted = code.is_some_and(|p| p.trusted);
        self.run(exe, (entry, trusted), base, sys, budget, hook).map(|_| ())
    }

    /// Evaluates a breakpoint condition (in the main program's scope) with at most
    /// `budget` instructions.
    pub fn eval_condition(
        &mut self,
        exe: &Executable,
        id: ConditionId,
        sys: SysState,
        budget: u64,
    ) -> Result<bool, RuntimeError> {
        self.eval_bits(exe, id, sys, budget).map(|v| v != 0)
    }

    /// Evaluates a compiled expression (see [`Executable::compile_condition`]) to its
    /// value's cell bits.
    pub fn eval_bits(
        &mut self,
        exe: &Executable,
        id: ConditionId,
        sys: SysState,
        budget: u64,
    ) -> Result<u64, RuntimeError> {
        let entry = exe.conditions.get(id.0 as usize).copied().unwrap_or(u32::MAX);
        let trusted = exe.condition_trusted.get(id.0 as usize).copied().unwrap_or(false);
        self.run(exe, (entry, trusted), exe.main_base, sys, budget, &mut NoHook)
    }

    fn run<H: Hook>(
        &mut self,
        exe: &Executable,
        (entry, trusted): (u32, bool),
        base: u32,
        sys: SysState,
        budget: u64,
        hook: &mut H,
    ) -> Result<u64, RuntimeError> {
        // Conditions compiled after this machine was made may have grown the image.
        if self.mem.cells.len() < exe.out.init.len() {
            let n = self.mem.cells.len();
            self.mem.cells.extend_from_slice(&exe.out.init[n..]);
        }
        self.stack.clear();
        let mut pc = entry as usize;
        match self.exec(exe, &mut pc, (base, trusted), sys, budget, hook) {
            Ok(v) => Ok(v),
            Err(fault) => Err(self.locate_fault(exe, fault, pc)),
        }
    }

    /// Finds the statement to report: the innermost one in user code.
    #[cold]
    #[inline(never)]
    fn locate_fault(&self, exe: &Executable, fault: Fault, pc: usize) -> RuntimeError {
        let user = |pc: usize| {
            let (span, pou) = exe.statement_at(pc)?;
            let lib = exe.pous.get(pou as usize).is_some_and(|p| p.library);
            (!lib).then_some((span, pou))
        };
        let found = user(pc.saturating_sub(1))
            .or_else(|| {
                self.stack.iter().rev().find_map(|f| user((f.ret as usize).saturating_sub(1)))
            })
            .or_else(|| exe.statement_at(pc.saturating_sub(1)));
        let (span, pou) = found.unwrap_or((Span::default(), exe.main));
        RuntimeError { fault, span, pou }
    }

    #[cfg_attr(plc_speed, optimize(speed))]
    fn exec<H: Hook>(
        &mut self,
        exe: &Executable,
        pc: &mut usize,
        (mut base, mut trusted): (u32, bool),
        sys: SysState,
        budget: u64,
        hook: &mut H,
    ) -> Result<u64, Fault> {
        let code = &exe.out.code[..];
        let cells: &mut [u64] = &mut self.mem.cells;
        // Trusted regions of static frames rely on memory being at least the image.
        trusted &= cells.len() >= exe.out.init.len();
        let mut fuel = budget;
        macro_rules! r {
            ($x:expr) => {
                *cells.get(base.wrapping_add($x) as usize).ok_or(BAD)?
            };
        }
        macro_rules! w {
            ($x:expr, $v:expr) => {{
                let v = $v;
                *cells.get_mut(base.wrapping_add($x) as usize).ok_or(BAD)? = v;
            }};
        }
        let tables = fast::Tables { code, sites: &exe.out.sites, dims: &exe.out.dims };
        loop {
            let exit = if trusted {
                fast::run::<true, H>(tables, cells, base, pc, &mut fuel, hook)
            } else {
                fast::run::<false, H>(tables, cells, base, pc, &mut fuel, hook)
            };
            if exit == fast::Exit::Fault {
                let op = code.get(*pc).ok_or(BAD)?;
                *pc += 1;
                return Err(fast::diagnose(op, tables, cells, base));
            }
            let op = code.get(*pc).ok_or(Fault::Internal("jump outside the code"))?;
            *pc += 1;
            if fuel == 0 {
                return Err(Fault::Watchdog { budget });
            }
            fuel -= 1;
            if H::ON {
                hook.before(op, *pc - 1, base, cells);
            }
            match *op {
                Op::Case { elem, sel, table } => {
                    let t = exe.out.cases.get(table as usize).ok_or(BAD)?;
                    let target = t.target(arith::to_i128(elem, r!(sel)));
                    if let Some(hit) = self.case_hits.get_mut(table as usize) {
                        *hit = ((*pc).saturating_sub(1) as u32, target);
                    }
                    *pc = target as usize;
                }
                Op::CallFb { pou, ptr } => {
                    let callee = exe.pous.get(pou as usize).ok_or(BAD)?;
                    if self.stack.len() >= MAX_CALL_DEPTH {
                        return Err(Fault::CallDepth);
                    }
                    self.stack.push(CallFrame { ret: *pc as u32, base, trusted });
                    base = u32::try_from(r!(ptr)).map_err(|_| BAD)?;
                    // The instance must lie inside memory for its code to run unchecked.
                    let end = base as usize + callee.size as usize;
                    trusted = callee.trusted && end <= cells.len();
                    *pc = callee.entry as usize;
                }
                Op::CallFn { pou } => {
                    let callee = exe.pous.get(pou as usize).ok_or(BAD)?;
                    if self.stack.len() >= MAX_CALL_DEPTH {
                        return Err(Fault::CallDepth);
                    }
                    self.stack.push(CallFrame { ret: *pc as u32, base, trusted });
                    base = callee.frame.ok_or(BAD)?;
                    trusted = callee.trusted && cells.len() >= exe.out.init.len();
                    *pc = callee.entry as usize;
                }
                Op::InitFrame { pou } => {
                    let f = exe.pous.get(pou as usize).ok_or(BAD)?;
                    let start = f.frame.ok_or(BAD)? as usize;
                    let end = start + f.size as usize;
                    let src = exe.out.init.get(start..end).ok_or(BAD)?;
                    cells.get_mut(start..end).ok_or(BAD)?.copy_from_slice(src);
                }
                Op::InitTemps { pou } => {
                    let f = exe.pous.get(pou as usize).ok_or(BAD)?;
                    for &(off, n) in &f.temps {
                        let (s, e) = (off as usize, off as usize + n as usize);
                        let src = f.template.get(s..e).ok_or(BAD)?;
                        let d = base as usize + s;
                        cells.get_mut(d..d + (e - s)).ok_or(BAD)?.copy_from_slice(src);
                    }
                    // A reference into the instance: its offset plus one, moved to `base`.
                    for &off in &f.relocs {
                        let c = cells.get_mut(base as usize + off as usize).ok_or(BAD)?;
                        if *c != 0 {
                            *c = c.wrapping_add(u64::from(base));
                        }
                    }
                }
                Op::Ret => match self.stack.pop() {
                    Some(f) => {
                        *pc = f.ret as usize;
                        base = f.base;
                        trusted = f.trusted;
                    }
                    None => return Ok(0),
                },
                Op::Halt { a } => return Ok(r!(a)),
                Op::Sys { var, dst } => w!(dst, sys_var(var, sys)),
                // The rest (generic operators, FOR of wide types, strings, copies,
                // built-ins) out of line: this loop stays small enough for the browser's
                // optimising compiler to compile it early (BENCHMARKS.md, B5).
                _ => {
                    let spent = rare_op(*op, cells, base, pc, exe, &mut self.scratch)?;
                    fuel = fuel.saturating_sub(spent);
                }
            }
            if H::ON {
                hook.after(cells);
            }
        }
    }
}

/// The instructions of the outer loop that few programs run on every scan: generic
/// operators, FOR loops over types the inner loop does not step, references, copies,
/// strings and built-ins. Returns the extra watchdog units the instruction costs (work that
/// grows with its operands); a jump sets `*pc`.
#[inline(never)]
fn rare_op(
    op: Op,
    cells: &mut [u64],
    base: u32,
    pc: &mut usize,
    exe: &Executable,
    scratch: &mut Scratch,
) -> Result<u64, Fault> {
    macro_rules! r {
        ($x:expr) => {
            *cells.get(base.wrapping_add($x) as usize).ok_or(BAD)?
        };
    }
    macro_rules! w {
        ($x:expr, $v:expr) => {{
            let v = $v;
            *cells.get_mut(base.wrapping_add($x) as usize).ok_or(BAD)? = v;
        }};
    }
    match op {
        Op::Bin { op, elem, dst, a, b } => w!(dst, arith::binary(op, elem, r!(a), r!(b))?),
        Op::Cmp { op, elem, dst, a, b } => {
            w!(dst, u64::from(arith::compare(op, elem, r!(a), r!(b))))
        }
        Op::ScaleTime { op, elem, real, dst, a, b } => {
            w!(dst, arith::scale_time(op, elem, r!(a), r!(b), real)?)
        }
        Op::Conv { from, to, dst, a } => w!(dst, arith::convert(from, to, r!(a))),
        Op::Trunc { from, to, dst, a } => w!(dst, arith::trunc(from, to, r!(a))),
        Op::SetBit { elem, n, dst, v } => {
            w!(dst, arith::set_bit(elem, r!(dst), u32::from(n), r!(v) != 0))
        }
        Op::GetSlice { elem, shift, dst, a } => {
            w!(dst, arith::get_slice(r!(a), u32::from(shift), elem))
        }
        Op::SetSlice { elem, shift, dst, v } => {
            w!(dst, arith::set_slice(r!(dst), u32::from(shift), elem, r!(v)))
        }
        Op::Deref { dst, a } => {
            let addr = r!(a).checked_sub(1).ok_or(Fault::NullReference)?;
            if addr >= cells.len() as u64 {
                return Err(Fault::Internal("a reference points outside memory"));
            }
            w!(dst, addr);
        }
        Op::ForStart { lim } => {
            if r!(lim.wrapping_add(1)) == 0 {
                return Err(Fault::ForStepZero);
            }
        }
        Op::ForTest { elem, v, lim, target } => {
            let x = arith::to_i128(elem, r!(v));
            let end = arith::to_i128(elem, r!(lim));
            let step = arith::to_i128(elem, r!(lim.wrapping_add(1)));
            if !(if step > 0 { x <= end } else { x >= end }) {
                *pc = target as usize;
            }
        }
        Op::ForNext { elem, v, lim, target } => {
            let step = arith::to_i128(elem, r!(lim.wrapping_add(1)));
            let next = arith::to_i128(elem, r!(v)) + step;
            w!(v, arith::norm(elem, next));
            let end = arith::to_i128(elem, r!(lim));
            if if step > 0 { next <= end } else { next >= end } {
                *pc = target as usize;
            }
        }
        Op::ForStep { elem, v, lim } => {
            let end = arith::to_i128(elem, r!(lim));
            let step = arith::to_i128(elem, r!(lim.wrapping_add(1)));
            let next = arith::to_i128(elem, r!(v)) + step;
            w!(v, arith::norm(elem, next));
            w!(lim.wrapping_add(2), u64::from(if step > 0 { next <= end } else { next >= end }));
        }
        // Work that grows with the operands is charged by size (`limits`).
        Op::Copy { dst, src, n } => {
            copy_cells(cells, r!(dst) as usize, r!(src) as usize, n as usize)?;
            return Ok(u64::from(n) / WATCHDOG_CELLS_PER_UNIT);
        }
        Op::StrCopy { dst, src } => {
            let (_, len) = str_header(cells, r!(src) as usize)?;
            copy_str(cells, r!(dst) as usize, r!(src) as usize)?;
            return Ok(u64::from(len) / WATCHDOG_BYTES_PER_UNIT);
        }
        builtin_ops!() => {
            let bytes = builtins::exec(op, cells, base, exe, scratch)?;
            return Ok(bytes / WATCHDOG_BYTES_PER_UNIT);
        }
        // The inner loop's instructions never get here.
        _ => return Err(Fault::Internal("instruction left by the inner loop")),
    }
    Ok(0)
}

/// The value of a system variable.
fn sys_var(var: SysVar, sys: SysState) -> u64 {
    match var {
        SysVar::FirstScan => u64::from(sys.first_scan),
        SysVar::AlwaysOn => 1,
        SysVar::AlwaysOff => 0,
        SysVar::Clock => sys.time_ns as u64,
        other => {
            let period = other.period_ns().unwrap_or(1).max(1);
            u64::from(sys.time_ns.rem_euclid(period) < period / 2)
        }
    }
}
