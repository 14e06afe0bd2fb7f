//! Statements: assignments, FB calls, IF, CASE (jump table or binary search), the three
//! loops with EXIT/CONTINUE, RETURN. Every statement starts a debug-map entry.

use super::emit::{Addr, Emitter, LoopCtx};
use super::error::bad;
use super::CompileError;
use crate::program::op::{CaseTable, Op};
use crate::semantic::ir::{CallArg, Expr, ExprKind, Place, Stmt, StmtKind};
use crate::semantic::types::{Elem, PouId};
use crate::syntax::VarSection;

/// One CASE arm: its label ranges and body.
type Arm = (Vec<(i64, i64)>, Vec<Stmt>);

/// Dense CASE tables are used when the label span is at most this many entries.
const MAX_DENSE: i128 = 65536;

impl Emitter<'_> {
    /// Compiles one statement.
    pub fn stmt(&mut self, s: &Stmt) -> Result<(), CompileError> {
        // Loaded elements are reused only by an IF branch's leading statements.
        self.compared.clear();
        self.mark(s.span);
        let mark = self.top;
        match &s.kind {
            StmtKind::Assign(place, e) => self.assign(place, e)?,
            StmtKind::CallFb { instance, fb, args } => self.call_fb(instance, *fb, args)?,
            StmtKind::Eval(e) => {
                self.expr(e, None)?;
            }
            StmtKind::If { branches, else_body } => {
                let mut ends = Vec::new();
                for (k, (cond, body)) in branches.iter().enumerate() {
                    self.mark(s.span);
                    let j = self.jump_unless(cond)?;
                    // The comparison's registers stay allocated while its loaded elements
                    // are reused (see `reuse_compared`).
                    let reused = self.reuse_compared(body)?;
                    self.compared.clear();
                    self.top = mark;
                    self.stmts(&body[reused..])?;
                    // Every branch but the last (without ELSE) jumps over what follows,
                    // even an empty one.
                    if k + 1 < branches.len() || !else_body.is_empty() {
                        self.mark(s.span);
                        ends.push(self.emit(Op::Jump { target: 0 }));
                    }
                    let here = self.pc();
                    self.patch(j, here);
                }
                self.stmts(else_body)?;
                let end = self.pc();
                for j in ends {
                    self.patch(j, end);
                }
            }
            StmtKind::Case { selector, arms, else_body } => {
                self.case(s, selector, arms, else_body)?;
            }
            StmtKind::For { var, ty, from, to, by, body } => {
                self.for_loop(s, var, *ty, [from, to, by], body)?;
            }
            StmtKind::While { cond, body } => {
                let top = self.pc();
                let j = self.jump_unless(cond)?;
                self.top = mark;
                self.loops.push(LoopCtx::default());
                self.stmts(body)?;
                self.mark(s.span);
                self.emit(Op::Jump { target: top });
                let end = self.pc();
                self.patch(j, end);
                self.close_loop(top, end);
            }
            StmtKind::Repeat { body, until } => {
                let top = self.pc();
                self.loops.push(LoopCtx::default());
                self.stmts(body)?;
                self.mark(s.span);
                let cont = self.pc();
                let j = self.jump_unless(until)?;
                self.patch(j, top);
                let end = self.pc();
                self.close_loop(cont, end);
            }
            StmtKind::Exit => {
                let j = self.emit(Op::Jump { target: 0 });
                self.loops.last_mut().ok_or_else(|| bad("EXIT outside a loop"))?.exits.push(j);
            }
            StmtKind::Continue => {
                let j = self.emit(Op::Jump { target: 0 });
                let l = self.loops.last_mut().ok_or_else(|| bad("CONTINUE outside a loop"))?;
                l.continues.push(j);
            }
            StmtKind::Return => {
                self.emit(Op::Ret);
            }
        }
        self.top = mark;
        Ok(())
    }

    fn close_loop(&mut self, cont: u32, end: u32) {
        if let Some(l) = self.loops.pop() {
            for j in l.exits {
                self.patch(j, end);
            }
            for j in l.continues {
                self.patch(j, cont);
            }
        }
    }

    fn assign(&mut self, place: &Place, e: &Expr) -> Result<(), CompileError> {
        let ty = self.place_type(place)?;
        if let Place::Bit(..) | Place::Slice(..) = place {
            let v = self.expr(e, None)?;
            return self.store_place(place, v);
        }
        if ty.is_scalar() {
            match self.place_addr(place)? {
                Addr::Frame(o) => {
                    self.expr_to(e, o)?;
                }
                a @ Addr::Elem { .. } => self.assign_element(a, e)?,
                a => {
                    let v = self.expr(e, None)?;
                    self.store(a, v);
                }
            }
            return Ok(());
        }
        let a = self.place_addr(place)?;
        let d = self.pointer(a)?;
        let v = self.expr(e, None)?;
        self.copy_value(ty, d, v)
    }

    /// `arr[i] := e` with the element not yet bounds-checked. The check of the destination
    /// must come before anything in `e` that can fault or have an effect, as it always
    /// has: a value that cannot is computed first and stored with `StoreElem`; an element
    /// of another (or the same) frame array whose index cannot fault is copied with one
    /// `MoveElem` (destination checked first); anything else settles the address first.
    fn assign_element(&mut self, a: Addr, e: &Expr) -> Result<(), CompileError> {
        if self.is_pure(e) {
            let v = self.expr(e, None)?;
            self.store(a, v);
            return Ok(());
        }
        if let (ExprKind::Load(src @ Place::Element(_, _, idx)), true) = (&e.kind, e.ty.is_scalar())
        {
            if idx.iter().all(|i| self.is_pure(i)) {
                let saved = self.checkpoint();
                if let (Addr::Elem { idx: didx, site: ds }, Addr::Elem { idx: sidx, site: ss }) =
                    (a, self.place_addr(src)?)
                {
                    let site = self.out.sites.len() as u32;
                    self.out.sites.extend([ds, ss]);
                    self.emit(Op::MoveElem { didx, sidx, site });
                    return Ok(());
                }
                // The source is addressed another way: start again in the safe order.
                self.rollback(saved);
            }
        }
        let a = self.settle(a)?;
        let v = self.expr(e, None)?;
        self.store(a, v);
        Ok(())
    }

    fn call_fb(
        &mut self,
        instance: &Place,
        fb: PouId,
        args: &[CallArg],
    ) -> Result<(), CompileError> {
        let p = self.p;
        let pou = p.pous.get(fb as usize).ok_or_else(|| bad("FB"))?;
        let inst = self.place_addr(instance)?;
        let inst = self.settle(inst)?;
        for arg in args {
            match arg {
                CallArg::In(i, e) => {
                    let v = pou.vars.get(*i as usize).ok_or_else(|| bad("input"))?;
                    let a = inst.plus(self.lay.var_offset(p, fb, *i)?);
                    if v.ty.is_scalar() {
                        if let Addr::Frame(o) = a {
                            self.expr_to(e, o)?;
                            continue;
                        }
                    }
                    let r = self.expr(e, None)?;
                    self.put(a, v.ty, r)?;
                }
                CallArg::InOut(i, place) => {
                    let a = inst.plus(self.lay.var_offset(p, fb, *i)?);
                    let pa = self.place_addr(place)?;
                    let r = self.pointer(pa)?;
                    self.store(a, r);
                }
                CallArg::Out(..) => {}
            }
        }
        let ptr = self.pointer(inst)?;
        self.emit(Op::CallFb { pou: fb, ptr });
        self.outputs(args, fb, inst)
    }

    fn case(
        &mut self,
        s: &Stmt,
        selector: &Expr,
        arms: &[Arm],
        else_body: &[Stmt],
    ) -> Result<(), CompileError> {
        let elem = match self.elem_of(selector.ty)? {
            e if e.is_integral() || e == Elem::LInt => e,
            _ => Elem::LInt,
        };
        let sel = self.expr(selector, None)?;
        let table = self.out.cases.len() as u32;
        self.out.cases.push(CaseTable::Sparse { ranges: Vec::new(), default: 0 });
        self.emit(Op::Case { elem, sel, table });
        let mut ends = Vec::new();
        let mut ranges: Vec<(i64, i64, u32)> = Vec::new();
        let mut covered: i128 = 0;
        for (labels, body) in arms {
            let at = self.pc();
            for &(lo, hi) in labels {
                if lo <= hi {
                    // First matching arm wins: drop parts covered by earlier arms.
                    ranges.push((lo, hi, at));
                    covered += hi as i128 - lo as i128 + 1;
                }
            }
            self.stmts(body)?;
            self.mark(s.span);
            ends.push(self.emit(Op::Jump { target: 0 }));
        }
        let default = self.pc();
        self.stmts(else_body)?;
        let end = self.pc();
        for j in ends {
            self.patch(j, end);
        }
        let tab = build_table(ranges, covered, default);
        if let Some(t) = self.out.cases.get_mut(table as usize) {
            *t = tab;
        }
        Ok(())
    }

    fn for_loop(
        &mut self,
        s: &Stmt,
        var: &Place,
        elem: Elem,
        [from, to, by]: [&Expr; 3],
        body: &[Stmt],
    ) -> Result<(), CompileError> {
        let lim = self.alloc(3)?;
        let start = self.alloc(1)?;
        self.expr_to(from, start)?;
        self.expr_to(to, lim)?;
        self.expr_to(by, lim + 1)?;
        self.store_place(var, start)?;
        self.emit(Op::ForStart { lim });
        let direct = match var {
            Place::Local(i) => {
                let v = self.p.pou(self.pou).vars.get(*i as usize).ok_or_else(|| bad("local"))?;
                if v.section == VarSection::InOut {
                    None
                } else {
                    Some(self.lay.var_offset(self.p, self.pou, *i)?)
                }
            }
            Place::Global(_) if self.base.is_some() => match self.place_addr(var)? {
                Addr::Frame(o) => Some(o),
                _ => None,
            },
            _ => None,
        };
        let mark = self.top;
        let v = match direct {
            Some(o) => o,
            None => self.load_place(var, Some(start))?,
        };
        let test = self.emit(Op::ForTest { elem, v, lim, target: 0 });
        self.top = mark;
        let body_pc = self.pc();
        self.loops.push(LoopCtx::default());
        self.stmts(body)?;
        self.mark(s.span);
        let cont = self.pc();
        match direct {
            Some(o) if elem.is_int() && elem.bits() <= 32 => {
                let (bits, signed) = (elem.bits() as u8, elem.is_signed_int());
                if matches!(by.kind, ExprKind::Const(1)) {
                    self.emit(Op::ForInc32 { bits, signed, v: o, lim, target: body_pc });
                } else {
                    self.emit(Op::ForNext32 { bits, signed, v: o, lim, target: body_pc });
                }
            }
            Some(o) => {
                self.emit(Op::ForNext { elem, v: o, lim, target: body_pc });
            }
            None => {
                let t = self.load_place(var, Some(start))?;
                self.emit(Op::ForStep { elem, v: t, lim });
                self.store_place(var, t)?;
                self.emit(Op::JumpIf { c: lim + 2, target: body_pc });
            }
        }
        let end = self.pc();
        self.patch(test, end);
        self.close_loop(cont, end);
        Ok(())
    }
}

/// Chooses a jump table or a sorted range list for a CASE.
fn build_table(mut ranges: Vec<(i64, i64, u32)>, covered: i128, default: u32) -> CaseTable {
    let lo = ranges.iter().map(|r| r.0).min().unwrap_or(0);
    let hi = ranges.iter().map(|r| r.1).max().unwrap_or(-1);
    let span = hi as i128 - lo as i128 + 1;
    if !ranges.is_empty() && span <= MAX_DENSE && span <= 4 * covered.max(1) {
        let mut targets = vec![u32::MAX; span as usize];
        for &(a, b, t) in &ranges {
            for v in a..=b {
                if let Some(slot) = targets.get_mut((v as i128 - lo as i128) as usize) {
                    if *slot == u32::MAX {
                        *slot = t;
                    }
                }
            }
        }
        for t in &mut targets {
            if *t == u32::MAX {
                *t = default;
            }
        }
        return CaseTable::Dense { low: lo, targets, default };
    }
    // Sorted, overlaps resolved in favour of the earlier arm (smaller target).
    crate::order::sort_by_key(&mut ranges, |r| (r.0, r.2));
    let mut out: Vec<(i64, i64, u32)> = Vec::with_capacity(ranges.len());
    for (a, b, t) in ranges {
        match out.last() {
            Some(&(_, lb, _)) if a <= lb => {
                if b > lb {
                    out.push((lb + 1, b, t));
                }
            }
            _ => out.push((a, b, t)),
        }
    }
    CaseTable::Sparse { ranges: out, default }
}
