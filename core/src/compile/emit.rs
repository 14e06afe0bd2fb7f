//! The emitter: code buffer, temporaries, the debug map and the addressing of places.
//! Expressions are in `expr.rs`, statements in `stmt.rs`.

use super::error::{add, bad};
use super::{Code, CompileError, DebugEntry};
use crate::diagnostics::Span;
use crate::program::op::{DimInfo, ElemSite, Op, Reg};
use crate::program::Layouts;
use crate::semantic::ir::{BinOp, Expr, ExprKind, Place, Program, Stmt};
use crate::semantic::types::{dim_len, Elem, PouId, Type};
use crate::syntax::{PouKind, VarSection};
use crate::values::arith::identity_widening;

/// How a POU's frame is addressed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Frame {
    /// One frame at a fixed address (the main PROGRAM, a FUNCTION).
    Static,
    /// The instance passed by the caller (FUNCTION_BLOCK).
    Instance,
}

/// Where a value lives, as far as the compiler knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Addr {
    /// A register of the current frame.
    Frame(u32),
    /// An absolute address (only in frames without a fixed base).
    Abs(u32),
    /// The address in pointer register `.0` plus `.1`.
    Ptr(Reg, u32),
    /// An element of a one-dimensional array in the frame, selected by the value in
    /// register `idx` at the time of the access (`Op::LoadElem` and its kin check the bounds
    /// there); `site.start` already includes any offset into the element.
    Elem {
        /// The index register.
        idx: Reg,
        /// The access (not yet interned).
        site: ElemSite,
    },
}

impl Addr {
    /// The address `k` cells further.
    pub fn plus(self, k: u32) -> Addr {
        match self {
            Addr::Frame(o) => Addr::Frame(o.wrapping_add(k)),
            Addr::Abs(a) => Addr::Abs(a.wrapping_add(k)),
            Addr::Ptr(r, o) => Addr::Ptr(r, o.wrapping_add(k)),
            Addr::Elem { idx, site } => {
                Addr::Elem { idx, site: ElemSite { start: site.start.wrapping_add(k), ..site } }
            }
        }
    }
}

/// A point in the emitted code to go back to (see [`Emitter::checkpoint`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Checkpoint {
    code: usize,
    debug: usize,
    top: u32,
}

/// Targets to patch when a loop ends.
#[derive(Debug, Default)]
pub(crate) struct LoopCtx {
    pub exits: Vec<u32>,
    pub continues: Vec<u32>,
}

/// Compiles one POU body into `out`; returns the number of temporary cells it needs.
pub(crate) fn compile_pou(
    lay: &mut Layouts,
    p: &Program,
    q: PouId,
    out: &mut Code,
    frame: Frame,
) -> Result<u32, CompileError> {
    let pou = p.pous.get(q as usize).ok_or_else(|| bad("POU id"))?;
    let vars_size = lay.pou(p, q)?.vars_size;
    let base = match frame {
        Frame::Instance => None,
        Frame::Static if pou.kind == PouKind::Program => Some(lay.main_base),
        Frame::Static => Some(lay.frames.get(q as usize).copied().flatten().unwrap_or(0)),
    };
    let mut em = Emitter::new(lay, p, out, q, base, vars_size);
    em.mark(pou.span);
    if pou.vars.iter().any(|v| v.section == VarSection::Temp) {
        em.emit(Op::InitTemps { pou: q });
    }
    em.stmts(&pou.body)?;
    em.mark(pou.span);
    em.emit(Op::Ret);
    Ok(em.max - vars_size)
}

/// Compiles a breakpoint condition in the scope of the main program `main`, with
/// temporaries from frame offset `temp_base`; returns the temporaries it needs.
pub(crate) fn compile_condition(
    lay: &mut Layouts,
    p: &Program,
    main: PouId,
    out: &mut Code,
    temp_base: u32,
    cond: &Expr,
) -> Result<u32, CompileError> {
    let base = Some(lay.main_base);
    let mut em = Emitter::new(lay, p, out, main, base, temp_base);
    em.mark(cond.span);
    let r = em.expr(cond, None)?;
    em.emit(Op::Halt { a: r });
    Ok(em.max - temp_base)
}

/// The state of compiling one body.
pub(crate) struct Emitter<'a> {
    pub lay: &'a mut Layouts,
    pub p: &'a Program,
    pub out: &'a mut Code,
    pub pou: PouId,
    /// The fixed frame base, if the frame has one.
    pub base: Option<u32>,
    /// Next free temporary.
    pub top: u32,
    /// High-water mark of temporaries.
    pub max: u32,
    /// Enclosing loops, innermost last.
    pub loops: Vec<LoopCtx>,
    /// Array elements the last compare-and-branch loaded, with the registers holding them
    /// (see `fuse.rs`); empty except at the start of an IF branch.
    pub compared: Vec<(Place, Reg)>,
}

impl<'a> Emitter<'a> {
    fn new(
        lay: &'a mut Layouts,
        p: &'a Program,
        out: &'a mut Code,
        pou: PouId,
        base: Option<u32>,
        temp_base: u32,
    ) -> Self {
        Emitter {
            lay,
            p,
            out,
            pou,
            base,
            top: temp_base,
            max: temp_base,
            loops: Vec::new(),
            compared: Vec::new(),
        }
    }

    /// The index the next instruction gets.
    pub fn pc(&self) -> u32 {
        self.out.code.len() as u32
    }

    /// Appends an instruction; returns its index.
    pub fn emit(&mut self, op: Op) -> u32 {
        self.out.code.push(op);
        self.out.code.len() as u32 - 1
    }

    /// Sets the jump target of the instruction at `at`.
    pub fn patch(&mut self, at: u32, to: u32) {
        if let Some(
            Op::Jump { target }
            | Op::JumpIf { target, .. }
            | Op::JumpIfNot { target, .. }
            | Op::JumpLt(crate::program::op::Branch { target, .. })
            | Op::JumpLe(crate::program::op::Branch { target, .. })
            | Op::JumpGt(crate::program::op::Branch { target, .. })
            | Op::JumpGe(crate::program::op::Branch { target, .. })
            | Op::JumpEq(crate::program::op::Branch { target, .. })
            | Op::JumpNe(crate::program::op::Branch { target, .. })
            | Op::ForTest { target, .. }
            | Op::ForNext { target, .. }
            | Op::ForNext32 { target, .. }
            | Op::ForInc32 { target, .. },
        ) = self.out.code.get_mut(at as usize)
        {
            *target = to;
        }
    }

    /// The state to return to with [`Emitter::rollback`].
    pub fn checkpoint(&self) -> Checkpoint {
        Checkpoint { code: self.out.code.len(), debug: self.out.debug.len(), top: self.top }
    }

    /// Drops the code emitted since `cp` (tables keep any entries added meanwhile; unused
    /// entries are harmless).
    pub fn rollback(&mut self, cp: Checkpoint) {
        self.out.code.truncate(cp.code);
        self.out.debug.truncate(cp.debug);
        self.top = cp.top;
    }

    /// Code from here on belongs to the statement at `span`.
    pub fn mark(&mut self, span: Span) {
        let e = DebugEntry { pc: self.pc(), span, pou: self.pou };
        match self.out.debug.last_mut() {
            Some(last) if last.pc == e.pc => *last = e,
            _ => self.out.debug.push(e),
        }
    }

    /// Allocates `n` consecutive temporary cells.
    pub fn alloc(&mut self, n: u32) -> Result<Reg, CompileError> {
        let r = self.top;
        self.top = add(self.top, u64::from(n))?;
        self.max = self.max.max(self.top);
        Ok(r)
    }

    /// Compiles a list of statements.
    pub fn stmts(&mut self, list: &[Stmt]) -> Result<(), CompileError> {
        for s in list {
            self.stmt(s)?;
        }
        Ok(())
    }

    /// The address `a` (absolute) as seen from this frame.
    pub fn abs(&self, a: u32) -> Addr {
        match self.base {
            Some(b) => Addr::Frame(a.wrapping_sub(b)),
            None => Addr::Abs(a),
        }
    }

    /// The static frame of FUNCTION `q` (0 during a dry compile).
    pub fn frame_of(&self, q: PouId) -> u32 {
        self.lay.frames.get(q as usize).copied().flatten().unwrap_or(0)
    }

    /// The type of a place.
    pub fn place_type(&mut self, place: &Place) -> Result<Type, CompileError> {
        let p = self.p;
        Ok(match place {
            Place::Local(i) => {
                p.pou(self.pou).vars.get(*i as usize).ok_or_else(|| bad("local"))?.ty
            }
            Place::Global(i) => p.globals.get(*i as usize).ok_or_else(|| bad("global"))?.ty,
            Place::Field(b, i) => match self.place_type(b)? {
                Type::Struct(s) => {
                    let def = p.types.structs.get(s as usize).ok_or_else(|| bad("struct"))?;
                    def.fields.get(*i as usize).ok_or_else(|| bad("field"))?.ty
                }
                Type::Fb(q) => {
                    let pou = p.pous.get(q as usize).ok_or_else(|| bad("FB"))?;
                    pou.vars.get(*i as usize).ok_or_else(|| bad("FB variable"))?.ty
                }
                _ => return Err(bad("field base")),
            },
            Place::Element(_, a, _) => {
                p.types.arrays.get(*a as usize).ok_or_else(|| bad("array"))?.element
            }
            Place::Bit(..) => Type::BOOL,
            Place::Slice(_, _, elem) => Type::Elem(*elem),
            Place::Deref(r) => p.types.ref_target(r.ty).ok_or_else(|| bad("dereference"))?,
        })
    }

    /// The address of a (non-bit) place.
    pub fn place_addr(&mut self, place: &Place) -> Result<Addr, CompileError> {
        let p = self.p;
        match place {
            Place::Local(i) => {
                let v = p.pou(self.pou).vars.get(*i as usize).ok_or_else(|| bad("local"))?;
                let off = self.lay.var_offset(p, self.pou, *i)?;
                Ok(if v.section == VarSection::InOut {
                    Addr::Ptr(off, 0)
                } else {
                    Addr::Frame(off)
                })
            }
            Place::Global(i) => {
                let a = if self.lay.real {
                    *self.lay.globals.get(*i as usize).ok_or_else(|| bad("global"))?
                } else {
                    0
                };
                Ok(self.abs(a))
            }
            Place::Field(b, i) => {
                let ba = self.place_addr(b)?;
                match self.place_type(b)? {
                    Type::Struct(s) => Ok(ba.plus(self.lay.field_offset(p, s, *i)?)),
                    Type::Fb(q) => {
                        let v = p.pou(q).vars.get(*i as usize).ok_or_else(|| bad("FB variable"))?;
                        let a = ba.plus(self.lay.var_offset(p, q, *i)?);
                        if v.section == VarSection::InOut {
                            let t = self.alloc(1)?;
                            let r = self.load(a, Some(t))?;
                            return Ok(Addr::Ptr(r, 0));
                        }
                        Ok(a)
                    }
                    _ => Err(bad("field base")),
                }
            }
            Place::Element(b, arr, idx) => self.element_addr(b, *arr, idx),
            Place::Bit(..) | Place::Slice(..) => Err(bad("bit place used as an address")),
            Place::Deref(r) => self.deref_addr(r),
        }
    }

    /// The address a reference holds, checked against NULL when the code runs (its own
    /// function: places and expressions recurse into each other).
    #[inline(never)]
    fn deref_addr(&mut self, r: &Expr) -> Result<Addr, CompileError> {
        let a = self.expr(r, None)?;
        let dst = self.alloc(1)?;
        self.emit(Op::Deref { dst, a });
        Ok(Addr::Ptr(dst, 0))
    }

    fn element_addr(&mut self, b: &Place, arr: u32, idx: &[Expr]) -> Result<Addr, CompileError> {
        let p = self.p;
        let def = p.types.arrays.get(arr as usize).ok_or_else(|| bad("array"))?;
        if def.dims.len() != idx.len() {
            return Err(bad("index count"));
        }
        let esize = self.lay.size_of(p, def.element)?;
        // Strides, last dimension fastest.
        let mut strides = vec![0u32; def.dims.len()];
        let mut s = u64::from(esize);
        for (k, (lo, hi)) in def.dims.iter().enumerate().rev() {
            strides[k] = add(0, s)?;
            s = s.saturating_mul(dim_len(*lo, *hi));
        }
        let ba = self.place_addr(b)?;
        let consts: Option<Vec<i64>> = idx
            .iter()
            .map(|e| match e.kind {
                ExprKind::Const(bits) => Some(bits as i64),
                _ => None,
            })
            .collect();
        if let Some(cs) = consts {
            if cs.iter().zip(&def.dims).all(|(i, (lo, hi))| lo <= i && i <= hi) {
                let mut off = 0u64;
                for (k, i) in cs.iter().enumerate() {
                    off += (i - def.dims[k].0) as u64 * u64::from(strides[k]);
                }
                return Ok(ba.plus(add(0, off)?));
            }
        }
        let (low, high) = def.dims[0];
        let span = u32::try_from(high.wrapping_sub(low)).ok().filter(|_| low <= high);
        if let (Addr::Frame(start), [e], Some(span)) = (ba, idx, span) {
            let (r, add, shift, signed) = self.index_operand(e, (low, high))?;
            let site =
                ElemSite { shift, signed, ..ElemSite::new(add, low, span, start, strides[0]) };
            return Ok(Addr::Elem { idx: r, site });
        }
        let t = self.pointer(ba)?;
        for (k, e) in idx.iter().enumerate() {
            let r = self.expr_lint(e)?;
            let info = DimInfo { low: def.dims[k].0, high: def.dims[k].1, stride: strides[k] };
            let dim = match self.out.dims.iter().position(|d| *d == info) {
                Some(d) => d as u32,
                None => {
                    self.out.dims.push(info);
                    self.out.dims.len() as u32 - 1
                }
            };
            self.emit(Op::Index { ptr: t, idx: r, dim });
        }
        Ok(Addr::Ptr(t, 0))
    }

    /// Compiles an array index (a LINT expression) for an element site: the register to
    /// read and the constant added to it, with the wrapping of that sum. `j + 1` (and
    /// `j - 1`, `1 + j`) on an integer `j` keeps the addition in the site, wrapping in `j`'s
    /// type exactly as the separate addition and the (identity) widening to LINT would.
    /// Only when `bounds` lie inside `j`'s type (see [`ElemSite`]).
    fn index_operand(
        &mut self,
        e: &Expr,
        bounds: (i64, i64),
    ) -> Result<(Reg, i64, u8, bool), CompileError> {
        let mut inner = e;
        if let ExprKind::Convert(a) = &e.kind {
            if let (Some(from), Some(to)) = (a.ty.elem(), e.ty.elem()) {
                if identity_widening(from, to) {
                    inner = a;
                }
            }
        }
        if let (ExprKind::Binary(op, x, y), Some(elem)) = (&inner.kind, inner.ty.elem()) {
            let operand: Option<(&Expr, i64)> = match (op, &x.kind, &y.kind) {
                (BinOp::Add, _, ExprKind::Const(k)) => Some((x, *k as i64)),
                (BinOp::Add, ExprKind::Const(k), _) => Some((y, *k as i64)),
                (BinOp::Sub, _, ExprKind::Const(k)) => Some((x, (*k as i64).wrapping_neg())),
                _ => None,
            };
            let (lo, hi) = elem.int_range();
            let inside = lo <= i128::from(bounds.0) && i128::from(bounds.1) <= hi;
            let fits = |(x, _): &(&Expr, i64)| elem.is_int() && x.ty == inner.ty && inside;
            if let Some((x, add)) = operand.filter(fits) {
                let r = self.expr(x, None)?;
                let shift = (64 - elem.bits()) as u8;
                return Ok((r, add, shift, elem.is_signed_int()));
            }
        }
        Ok((self.expr_lint(e)?, 0, 0, true))
    }

    /// The index of `site` in the executable's site table (shared by equal accesses).
    pub fn intern_site(&mut self, site: ElemSite) -> u32 {
        if let Some(&k) = self.out.site_index.get(&site) {
            return k;
        }
        let k = self.out.sites.len() as u32;
        self.out.sites.push(site);
        self.out.site_index.insert(site, k);
        k
    }

    /// Turns an element address into a pointer now (bounds check included), so that the
    /// check happens before code emitted later; other addresses are returned unchanged.
    pub fn settle(&mut self, a: Addr) -> Result<Addr, CompileError> {
        match a {
            Addr::Elem { .. } => Ok(Addr::Ptr(self.pointer(a)?, 0)),
            other => Ok(other),
        }
    }

    /// Puts the absolute address `a` in a new pointer register.
    pub fn pointer(&mut self, a: Addr) -> Result<Reg, CompileError> {
        let t = self.alloc(1)?;
        let op = match a {
            Addr::Frame(off) => Op::AddrOf { dst: t, off },
            Addr::Abs(addr) => Op::Const { dst: t, bits: u64::from(addr) },
            Addr::Ptr(ptr, off) => Op::PtrAdd { dst: t, ptr, off },
            Addr::Elem { idx, site } => Op::ElemAddr { dst: t, idx, site: self.intern_site(site) },
        };
        self.emit(op);
        Ok(t)
    }

    /// Reads the scalar at `a`; into `hint` when given (else possibly the variable's own
    /// register).
    pub fn load(&mut self, a: Addr, hint: Option<Reg>) -> Result<Reg, CompileError> {
        match (a, hint) {
            (Addr::Frame(o), None) => Ok(o),
            (Addr::Frame(o), Some(h)) => {
                if h != o {
                    self.emit(Op::Move { dst: h, a: o });
                }
                Ok(h)
            }
            (Addr::Abs(addr), h) => {
                let dst = self.dst(h)?;
                self.emit(Op::LoadAbs { dst, addr });
                Ok(dst)
            }
            (Addr::Ptr(ptr, off), h) => {
                let dst = self.dst(h)?;
                self.emit(Op::LoadInd { dst, ptr, off });
                Ok(dst)
            }
            (Addr::Elem { idx, site }, h) => {
                let dst = self.dst(h)?;
                let site = self.intern_site(site);
                self.emit(Op::LoadElem { dst, idx, site });
                Ok(dst)
            }
        }
    }

    /// Writes the scalar in `v` to `a`.
    pub fn store(&mut self, a: Addr, v: Reg) {
        match a {
            Addr::Frame(o) => {
                if o != v {
                    self.emit(Op::Move { dst: o, a: v });
                }
            }
            Addr::Abs(addr) => {
                self.emit(Op::StoreAbs { addr, a: v });
            }
            Addr::Ptr(ptr, off) => {
                self.emit(Op::StoreInd { ptr, off, a: v });
            }
            Addr::Elem { idx, site } => {
                let site = self.intern_site(site);
                self.emit(Op::StoreElem { idx, site, a: v });
            }
        }
    }

    /// `hint`, or a new temporary.
    pub fn dst(&mut self, hint: Option<Reg>) -> Result<Reg, CompileError> {
        match hint {
            Some(h) => Ok(h),
            None => self.alloc(1),
        }
    }

    /// Reads a scalar place (bits included).
    pub fn load_place(&mut self, place: &Place, hint: Option<Reg>) -> Result<Reg, CompileError> {
        if let Place::Bit(b, n, _) = place {
            let a = self.place_addr(b)?;
            let v = self.load(a, None)?;
            let dst = self.dst(hint)?;
            self.emit(Op::GetBit { dst, a: v, n: *n });
            return Ok(dst);
        }
        if let Place::Slice(b, n, elem) = place {
            let a = self.place_addr(b)?;
            let v = self.load(a, None)?;
            let dst = self.dst(hint)?;
            let shift = u8::try_from(*n).map_err(|_| bad("image bit"))?;
            self.emit(Op::GetSlice { elem: *elem, shift, dst, a: v });
            return Ok(dst);
        }
        let a = self.place_addr(place)?;
        self.load(a, hint)
    }

    /// Writes the scalar in `v` to a place (bits and image slices by read-modify-write).
    pub fn store_place(&mut self, place: &Place, v: Reg) -> Result<(), CompileError> {
        type SetOp = fn(u8, Elem, Reg, Reg) -> Op;
        let (b, n, elem, op): (&Place, &u32, &Elem, SetOp) = match place {
            Place::Bit(b, n, e) => (b, n, e, |n, elem, dst, v| Op::SetBit { elem, n, dst, v }),
            Place::Slice(b, n, e) => {
                (b, n, e, |shift, elem, dst, v| Op::SetSlice { elem, shift, dst, v })
            }
            _ => {
                let a = self.place_addr(place)?;
                self.store(a, v);
                return Ok(());
            }
        };
        let n = u8::try_from(*n).map_err(|_| bad("bit number"))?;
        let a = self.place_addr(b)?;
        let a = self.settle(a)?;
        if let Addr::Frame(o) = a {
            self.emit(op(n, *elem, o, v));
        } else {
            let t = self.alloc(1)?;
            let cur = self.load(a, Some(t))?;
            self.emit(op(n, *elem, cur, v));
            self.store(a, cur);
        }
        Ok(())
    }

    /// Copies a non-scalar value of type `ty` from pointer `src` to pointer `dst`.
    pub fn copy_value(&mut self, ty: Type, dst: Reg, src: Reg) -> Result<(), CompileError> {
        if ty.is_string() {
            self.emit(Op::StrCopy { dst, src });
        } else {
            let n = self.lay.size_of(self.p, ty)?;
            self.emit(Op::Copy { dst, src, n });
        }
        Ok(())
    }

    /// Writes the value in `v` (a scalar, or a pointer for other types) of type `ty` to `a`.
    pub fn put(&mut self, a: Addr, ty: Type, v: Reg) -> Result<(), CompileError> {
        if ty.is_scalar() {
            self.store(a, v);
            Ok(())
        } else {
            let d = self.pointer(a)?;
            self.copy_value(ty, d, v)
        }
    }

    /// Reads the value of type `ty` at `a` into a fresh temporary (scalars) or a fresh
    /// temporary copy (others); returns the register (a pointer for non-scalars).
    pub fn take(&mut self, a: Addr, ty: Type, hint: Option<Reg>) -> Result<Reg, CompileError> {
        if ty.is_scalar() {
            let dst = self.dst(hint)?;
            return self.load(a, Some(dst));
        }
        let src = self.pointer(a)?;
        let dst = self.temp_value(ty, hint)?;
        self.copy_value(ty, dst, src)?;
        Ok(dst)
    }

    /// Allocates a temporary for a non-scalar value of type `ty`; returns a pointer to it.
    pub fn temp_value(&mut self, ty: Type, hint: Option<Reg>) -> Result<Reg, CompileError> {
        let n = self.lay.size_of(self.p, ty)?;
        let cells = self.alloc(n)?;
        if let Type::Str { wide, len } = ty {
            let cap = len * if wide { 2 } else { 1 };
            let bits = crate::program::memory::string_header(cap, 0);
            self.emit(Op::Const { dst: cells, bits });
        }
        let dst = self.dst(hint)?;
        self.emit(Op::AddrOf { dst, off: cells });
        Ok(dst)
    }

    /// The cell type used for values of `ty`.
    pub fn elem_of(&self, ty: Type) -> Result<Elem, CompileError> {
        match ty {
            Type::Elem(e) => Ok(e),
            Type::Enum(_) => Ok(Elem::LInt),
            // A reference is compared (`=`, `<>`) and moved as the bits of its cell.
            Type::Ref(_) => Ok(Elem::LWord),
            _ => Err(CompileError::Unsupported(Box::new(crate::msg!(
                CompileScalarNeeded,
                ty = self.p.types.display(ty).to_string()
            )))),
        }
    }
}
