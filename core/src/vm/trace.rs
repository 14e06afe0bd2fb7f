//! The VM's instrumented mode: a scan run with a [`Hook`] that sees every instruction
//! before and after it runs, so that [`Tracer`] can log every cell written, by which
//! instruction, in which frame, and every statement entered and call made. The simulator
//! replays one recorded scan this way to explain a value ("why is Motor TRUE?"); ordinary
//! scans run with [`NoHook`], whose calls the compiler removes, so the hot path pays
//! nothing for it.

use crate::program::op::{ElemSite, Op};
use crate::program::Executable;
use crate::semantic::types::PouId;

/// What the dispatch loops tell an observer. With `ON` false every call is compiled out.
pub(crate) trait Hook {
    /// Whether the loops call the hook at all.
    const ON: bool;
    /// Instruction `op` at `pc`, in the frame at `base`, is about to run on `cells`.
    fn before(&mut self, op: &Op, pc: usize, base: u32, cells: &[u64]);
    /// The instruction announced by the last [`Hook::before`] has run.
    fn after(&mut self, cells: &[u64]);
    /// The simulator wrote `value` to cell `addr` outside the program.
    fn external(&mut self, _addr: u32, _value: u64, _cause: Cause) {}
}

/// The hook of ordinary scans: nothing.
pub(crate) struct NoHook;

impl Hook for NoHook {
    const ON: bool = false;
    #[inline(always)]
    fn before(&mut self, _: &Op, _: usize, _: u32, _: &[u64]) {}
    #[inline(always)]
    fn after(&mut self, _: &[u64]) {}
}

/// Why the simulator wrote a cell outside the program.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// A held input, written before the scan.
    Held,
    /// A forced value, written before and after the scan.
    Forced,
    /// A value written from outside between the scans (the variable table, `--set`).
    Written,
    /// A copy from the cell at `from` (a plant's input or output, a task's connection, a
    /// `VAR_CONFIG` address).
    Link {
        /// The cell copied from.
        from: u32,
    },
}

/// One thing that happened during a traced scan, in the order it happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceEvent {
    /// Execution reached the first instruction `pc` of a debug-map entry (a statement, or
    /// the condition of an IF, CASE or loop) in the frame at `base`.
    Enter {
        /// The instruction.
        pc: u32,
        /// The frame.
        base: u32,
    },
    /// The instruction at `pc`, in the frame at `caller`, calls POU `pou`, whose frame is
    /// at `base`.
    Call {
        /// The calling instruction.
        pc: u32,
        /// The caller's frame.
        caller: u32,
        /// The callee.
        pou: PouId,
        /// The callee's frame (its instance, or a FUNCTION's static frame).
        base: u32,
    },
    /// The innermost call returned (or the program's body ended).
    Return,
    /// The instruction at `pc`, in the frame at `base`, wrote `value` to cell `addr`.
    Store {
        /// The cell.
        addr: u32,
        /// Its new bits.
        value: u64,
        /// The instruction.
        pc: u32,
        /// The frame.
        base: u32,
    },
    /// The simulator wrote `value` to cell `addr` outside the program.
    External {
        /// The cell.
        addr: u32,
        /// Its new bits.
        value: u64,
        /// Why.
        cause: Cause,
    },
}

/// The cells an announced instruction is going to write.
#[derive(Debug, Clone, Default)]
enum Pending {
    /// None (jumps, calls, comparisons into branches).
    #[default]
    Nothing,
    /// Up to two single cells.
    Cells([u32; 2], u8),
    /// A run of cells.
    Range(u32, u32),
    /// Unknown ahead (strings written through a pointer): memory as it was, to compare.
    Diff(Vec<u64>),
}

/// The [`Hook`] of a traced scan: logs [`TraceEvent`]s.
pub(crate) struct Tracer<'a> {
    exe: &'a Executable,
    /// Bit `pc` set: a debug-map entry starts at `pc`.
    starts: Vec<u64>,
    /// The events so far.
    pub events: Vec<TraceEvent>,
    pending: Pending,
    /// The instruction announced and not yet run (the inner loop may hand an instruction
    /// to the outer loop after announcing it: it is announced once).
    armed: Option<(usize, u32)>,
}

impl<'a> Tracer<'a> {
    /// A tracer for scans of `exe`.
    pub fn new(exe: &'a Executable) -> Tracer<'a> {
        let n = exe.out.code.len();
        let mut starts = vec![0u64; n / 64 + 1];
        for e in &exe.out.debug {
            let pc = e.pc as usize;
            if pc < n {
                starts[pc / 64] |= 1 << (pc % 64);
            }
        }
        Tracer { exe, starts, events: Vec::new(), pending: Pending::Nothing, armed: None }
    }

    fn cell(&mut self, addr: u64) {
        let Ok(a) = u32::try_from(addr) else { return };
        self.pending = match std::mem::take(&mut self.pending) {
            Pending::Cells([x, _], 1) => Pending::Cells([x, a], 2),
            _ => Pending::Cells([a, 0], 1),
        };
    }

    fn elem(&self, site: u32, idx: u32, base: u32, cells: &[u64]) -> Option<u64> {
        let s: &ElemSite = self.exe.out.sites.get(site as usize)?;
        let x = *cells.get(base.wrapping_add(idx) as usize)?;
        Some(u64::from(base.wrapping_add(s.start)) + s.offset(x).ok()?)
    }

    fn log_store(&mut self, addr: u32, cells: &[u64]) {
        let Some(&(pc, base)) = self.armed.as_ref() else { return };
        if let Some(&value) = cells.get(addr as usize) {
            self.events.push(TraceEvent::Store { addr, value, pc: pc as u32, base });
        }
    }
}

impl Hook for Tracer<'_> {
    const ON: bool = true;

    fn before(&mut self, op: &Op, pc: usize, base: u32, cells: &[u64]) {
        if self.armed == Some((pc, base)) {
            return;
        }
        self.armed = Some((pc, base));
        self.pending = Pending::Nothing;
        if self.starts.get(pc / 64).is_some_and(|w| w & (1 << (pc % 64)) != 0) {
            self.events.push(TraceEvent::Enter { pc: pc as u32, base });
        }
        let reg = |r: u32| u64::from(base.wrapping_add(r));
        let get = |r: u32| cells.get(base.wrapping_add(r) as usize).copied().unwrap_or(u64::MAX);
        match *op {
            Op::Const { dst, .. }
            | Op::Move { dst, .. }
            | Op::LoadAbs { dst, .. }
            | Op::LoadInd { dst, .. }
            | Op::AddrOf { dst, .. }
            | Op::Deref { dst, .. }
            | Op::PtrAdd { dst, .. }
            | Op::LoadElem { dst, .. }
            | Op::ElemAddr { dst, .. }
            | Op::Bin { dst, .. }
            | Op::Cmp { dst, .. }
            | Op::ScaleTime { dst, .. }
            | Op::Neg { dst, .. }
            | Op::Not { dst, .. }
            | Op::Conv { dst, .. }
            | Op::RealToDint { dst, .. }
            | Op::Trunc { dst, .. }
            | Op::GetBit { dst, .. }
            | Op::SetBit { dst, .. }
            | Op::GetSlice { dst, .. }
            | Op::SetSlice { dst, .. }
            | Op::Sys { dst, .. }
            | Op::StrCmp { dst, .. }
            | Op::Math { dst, .. }
            | Op::Select { dst, .. }
            | Op::MinMax { dst, .. }
            | Op::Limit { dst, .. }
            | Op::Mux { dst, .. }
            | Op::FromStr { dst, .. }
            | Op::Bcd { dst, .. } => self.cell(reg(dst)),
            Op::AddI64(r)
            | Op::SubI64(r)
            | Op::MulI64(r)
            | Op::AddI32(r)
            | Op::SubI32(r)
            | Op::MulI32(r)
            | Op::AddI16(r)
            | Op::SubI16(r)
            | Op::AddF64(r)
            | Op::SubF64(r)
            | Op::MulF64(r)
            | Op::DivF64(r)
            | Op::AddF32(r)
            | Op::SubF32(r)
            | Op::MulF32(r)
            | Op::DivF32(r)
            | Op::EqCell(r)
            | Op::NeCell(r)
            | Op::LtI64(r)
            | Op::LeI64(r)
            | Op::GtI64(r)
            | Op::GeI64(r)
            | Op::And(r)
            | Op::Or(r)
            | Op::Xor(r)
            | Op::AndNot(r)
            | Op::MulRealToDint(r) => self.cell(reg(r.dst)),
            Op::StoreAbs { addr, .. } => self.cell(u64::from(addr)),
            Op::StoreInd { ptr, off, .. } => self.cell(get(ptr).wrapping_add(u64::from(off))),
            Op::StoreElem { idx, site, .. } => {
                if let Some(a) = self.elem(site, idx, base, cells) {
                    self.cell(a);
                }
            }
            Op::MoveElem { didx, site, .. } => {
                if let Some(a) = self.elem(site, didx, base, cells) {
                    self.cell(a);
                }
            }
            Op::Index { ptr, .. } => self.cell(reg(ptr)),
            Op::ForNext { v, .. } | Op::ForNext32 { v, .. } | Op::ForInc32 { v, .. } => {
                self.cell(reg(v))
            }
            Op::ForStep { v, lim, .. } => {
                self.cell(reg(v));
                self.cell(reg(lim.wrapping_add(2)));
            }
            Op::Copy { dst, n, .. } => {
                if let Ok(start) = u32::try_from(get(dst)) {
                    self.pending = Pending::Range(start, n);
                }
            }
            Op::InitFrame { pou } => {
                if let Some(f) = self.exe.pous.get(pou as usize) {
                    self.pending = Pending::Range(f.frame.unwrap_or(u32::MAX), f.size);
                }
            }
            Op::InitTemps { .. } | Op::Str { .. } | Op::ToStr { .. } | Op::StrCopy { .. } => {
                self.pending = Pending::Diff(cells.to_vec())
            }
            Op::CallFb { pou, ptr } => {
                let callee = u32::try_from(get(ptr)).unwrap_or(u32::MAX);
                let call = TraceEvent::Call { pc: pc as u32, caller: base, pou, base: callee };
                self.events.push(call);
            }
            Op::CallFn { pou } => {
                let frame = self.exe.pous.get(pou as usize).and_then(|p| p.frame);
                let callee = frame.unwrap_or(u32::MAX);
                let call = TraceEvent::Call { pc: pc as u32, caller: base, pou, base: callee };
                self.events.push(call);
            }
            Op::Ret => self.events.push(TraceEvent::Return),
            Op::Jump { .. }
            | Op::JumpLt(_)
            | Op::JumpLe(_)
            | Op::JumpGt(_)
            | Op::JumpGe(_)
            | Op::JumpEq(_)
            | Op::JumpNe(_)
            | Op::JumpIf { .. }
            | Op::JumpIfNot { .. }
            | Op::ForStart { .. }
            | Op::ForTest { .. }
            | Op::Case { .. }
            | Op::Halt { .. } => {}
        }
    }

    fn after(&mut self, cells: &[u64]) {
        match std::mem::take(&mut self.pending) {
            Pending::Nothing => {}
            Pending::Cells(a, n) => {
                for &addr in &a[..usize::from(n)] {
                    self.log_store(addr, cells);
                }
            }
            Pending::Range(start, n) => {
                for addr in start..start.saturating_add(n) {
                    self.log_store(addr, cells);
                }
            }
            Pending::Diff(old) => {
                for (addr, (was, now)) in old.iter().zip(cells).enumerate() {
                    if was != now {
                        self.log_store(addr as u32, cells);
                    }
                }
            }
        }
        self.armed = None;
    }

    fn external(&mut self, addr: u32, value: u64, cause: Cause) {
        self.events.push(TraceEvent::External { addr, value, cause });
    }
}
