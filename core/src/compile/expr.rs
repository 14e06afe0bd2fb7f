//! Expressions: each compiles to a register holding the value (scalars) or a pointer to
//! it (strings, arrays, structs). A `hint` asks for the result in a given register; only
//! the last instruction of an expression writes it, so the hint may be a variable that
//! the expression itself reads.

use super::emit::{Addr, Emitter};
use super::error::bad;
use super::CompileError;
use crate::program::memory::{string_cells, string_header};
use crate::program::op::{MathFn, Op, Reg, StrFunc, R3};
use crate::semantic::ir::{BinOp, Builtin, CallArg, Cmp, Expr, ExprKind, UnOp};
use crate::semantic::types::{Elem, PouId, Type};
use crate::syntax::VarSection;
use crate::values::arith::identity_widening;

/// The typed instruction for `op` on `elem`, if there is one.
fn fast_op(op: BinOp, elem: Elem) -> Option<fn(R3) -> Op> {
    use Elem::*;
    let small_or_signed = !matches!(elem, ULInt | LWord | Real | LReal);
    Some(match (op, elem) {
        (BinOp::Add, LInt | Time | Date | Tod | Dt) => Op::AddI64,
        (BinOp::Sub, LInt | Time | Date | Tod | Dt) => Op::SubI64,
        (BinOp::Mul, LInt) => Op::MulI64,
        (BinOp::Add, DInt) => Op::AddI32,
        (BinOp::Sub, DInt) => Op::SubI32,
        (BinOp::Mul, DInt) => Op::MulI32,
        (BinOp::Add, Int) => Op::AddI16,
        (BinOp::Sub, Int) => Op::SubI16,
        (BinOp::Add, LReal) => Op::AddF64,
        (BinOp::Sub, LReal) => Op::SubF64,
        (BinOp::Mul, LReal) => Op::MulF64,
        (BinOp::Div, LReal) => Op::DivF64,
        (BinOp::Add, Real) => Op::AddF32,
        (BinOp::Sub, Real) => Op::SubF32,
        (BinOp::Mul, Real) => Op::MulF32,
        (BinOp::Div, Real) => Op::DivF32,
        (BinOp::Cmp(Cmp::Eq), e) if !e.is_real() => Op::EqCell,
        (BinOp::Cmp(Cmp::Ne), e) if !e.is_real() => Op::NeCell,
        (BinOp::Cmp(Cmp::Lt), _) if small_or_signed => Op::LtI64,
        (BinOp::Cmp(Cmp::Le), _) if small_or_signed => Op::LeI64,
        (BinOp::Cmp(Cmp::Gt), _) if small_or_signed => Op::GtI64,
        (BinOp::Cmp(Cmp::Ge), _) if small_or_signed => Op::GeI64,
        (BinOp::And, e) if !e.is_real() => Op::And,
        (BinOp::Or, e) if !e.is_real() => Op::Or,
        (BinOp::Xor, e) if !e.is_real() => Op::Xor,
        _ => return None,
    })
}

fn is_cmp(op: BinOp) -> bool {
    matches!(op, BinOp::Cmp(_))
}

impl Emitter<'_> {
    /// Compiles `e`; see the module comment.
    pub fn expr(&mut self, e: &Expr, hint: Option<Reg>) -> Result<Reg, CompileError> {
        match &e.kind {
            ExprKind::Const(bits) => {
                let dst = self.dst(hint)?;
                self.emit(Op::Const { dst, bits: *bits });
                Ok(dst)
            }
            ExprKind::ConstStr(bytes) => self.const_str(bytes, hint),
            ExprKind::Load(place) => {
                if e.ty.is_scalar()
                    || matches!(
                        place,
                        crate::semantic::ir::Place::Bit(..) | crate::semantic::ir::Place::Slice(..)
                    )
                {
                    self.load_place(place, hint)
                } else {
                    let a = self.place_addr(place)?;
                    let t = self.pointer(a)?;
                    self.finish(t, hint)
                }
            }
            ExprKind::Sys(var) => {
                let dst = self.dst(hint)?;
                self.emit(Op::Sys { var: *var, dst });
                Ok(dst)
            }
            ExprKind::Unary(op, a) => {
                let elem = self.elem_of(a.ty)?;
                let ra = self.expr(a, None)?;
                let dst = self.dst(hint)?;
                self.emit(match op {
                    UnOp::Neg => Op::Neg { elem, dst, a: ra },
                    UnOp::Not => Op::Not { elem, dst, a: ra },
                });
                Ok(dst)
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, hint),
            ExprKind::Convert(a) => self.convert(a, e.ty, hint),
            ExprKind::Trunc(a) => {
                let from = self.elem_of(a.ty)?;
                let to = self.elem_of(e.ty)?;
                let ra = self.expr(a, None)?;
                let dst = self.dst(hint)?;
                self.emit(Op::Trunc { from, to, dst, a: ra });
                Ok(dst)
            }
            ExprKind::Call { pou, args } => self.call_fn(*pou, args, hint),
            ExprKind::Builtin { func, args } => self.builtin(*func, args, e.ty, hint),
            ExprKind::RefOf(place) => self.ref_of(place, hint),
        }
    }

    /// `REF(place)`: the reference holds the address plus one, so that 0 stays NULL (its
    /// own function: `expr` recurses through deeply nested expressions).
    #[inline(never)]
    fn ref_of(
        &mut self,
        place: &crate::semantic::ir::Place,
        hint: Option<Reg>,
    ) -> Result<Reg, CompileError> {
        let a = self.place_addr(place)?;
        let t = self.pointer(a.plus(1))?;
        self.finish(t, hint)
    }

    /// Moves `r` into `hint` when one is given.
    fn finish(&mut self, r: Reg, hint: Option<Reg>) -> Result<Reg, CompileError> {
        match hint {
            Some(h) if h != r => {
                self.emit(Op::Move { dst: h, a: r });
                Ok(h)
            }
            _ => Ok(r),
        }
    }

    /// Compiles `e` into exactly register `dst`.
    pub fn expr_to(&mut self, e: &Expr, dst: Reg) -> Result<(), CompileError> {
        let r = self.expr(e, Some(dst))?;
        self.finish(r, Some(dst)).map(|_| ())
    }

    /// Compiles an integer expression converted to LINT.
    pub fn expr_lint(&mut self, e: &Expr) -> Result<Reg, CompileError> {
        let from = self.elem_of(e.ty)?;
        let r = self.expr(e, None)?;
        if identity_widening(from, Elem::LInt) {
            return Ok(r);
        }
        let dst = self.alloc(1)?;
        self.emit(Op::Conv { from, to: Elem::LInt, dst, a: r });
        Ok(dst)
    }

    fn expr_lint_to(&mut self, e: &Expr, dst: Reg) -> Result<(), CompileError> {
        let r = self.expr_lint(e)?;
        self.finish(r, Some(dst)).map(|_| ())
    }

    fn const_str(&mut self, bytes: &[u8], hint: Option<Reg>) -> Result<Reg, CompileError> {
        let addr = if self.lay.real {
            let at = self.out.init.len() as u32;
            let cap = bytes.len() as u32;
            let end = super::error::add(at, u64::from(string_cells(cap)))?;
            self.out.init.push(string_header(cap, cap));
            for chunk in bytes.chunks(8) {
                let mut b = [0u8; 8];
                b[..chunk.len()].copy_from_slice(chunk);
                self.out.init.push(u64::from_le_bytes(b));
            }
            self.out.init.resize(end as usize, 0);
            at
        } else {
            0
        };
        let dst = self.dst(hint)?;
        self.emit(Op::Const { dst, bits: u64::from(addr) });
        Ok(dst)
    }

    fn binary(
        &mut self,
        op: BinOp,
        a: &Expr,
        b: &Expr,
        hint: Option<Reg>,
    ) -> Result<Reg, CompileError> {
        if matches!(op, BinOp::AndThen | BinOp::OrElse) {
            let t = self.alloc(1)?;
            self.expr_to(a, t)?;
            let j = self.emit(if op == BinOp::AndThen {
                Op::JumpIfNot { c: t, target: 0 }
            } else {
                Op::JumpIf { c: t, target: 0 }
            });
            self.expr_to(b, t)?;
            let end = self.pc();
            self.patch(j, end);
            return self.finish(t, hint);
        }
        if a.ty.is_string() {
            let ra = self.expr(a, None)?;
            let rb = self.expr(b, None)?;
            let dst = self.dst(hint)?;
            if !is_cmp(op) {
                return Err(CompileError::Unsupported(Box::new(crate::msg!(
                    CompileOperatorOnStrings,
                    op = format!("{op:?}")
                ))));
            }
            self.emit(Op::StrCmp { op, dst, a: ra, b: rb });
            return Ok(dst);
        }
        let elem = self.elem_of(a.ty)?;
        if let Some(r) = self.logic_shortcut(op, elem, a, b, hint)? {
            return Ok(r);
        }
        let ra = self.expr(a, None)?;
        let rb = self.expr(b, None)?;
        let dst = self.dst(hint)?;
        if elem.is_temporal() && matches!(op, BinOp::Mul | BinOp::Div) && a.ty != b.ty {
            let real = b.ty == Type::Elem(Elem::LReal);
            self.emit(Op::ScaleTime { op, elem, real, dst, a: ra, b: rb });
        } else if let Some(f) = fast_op(op, elem) {
            self.emit(f(R3 { dst, a: ra, b: rb }));
        } else if is_cmp(op) {
            self.emit(Op::Cmp { op, elem, dst, a: ra, b: rb });
        } else {
            self.emit(Op::Bin { op, elem, dst, a: ra, b: rb });
        }
        Ok(dst)
    }

    /// The shapes ladder lowering writes on every contact: `TRUE AND x` and `FALSE OR x`
    /// are `x` (x is still evaluated: both sides of AND/OR always are), and `a AND NOT b`
    /// is one `AndNot`. `None` when `op` is none of them.
    fn logic_shortcut(
        &mut self,
        op: BinOp,
        elem: Elem,
        a: &Expr,
        b: &Expr,
        hint: Option<Reg>,
    ) -> Result<Option<Reg>, CompileError> {
        let neutral = match op {
            BinOp::And => 1,
            BinOp::Or => 0,
            _ => return Ok(None),
        };
        if elem == Elem::Bool {
            let is_neutral = |e: &Expr| matches!(e.kind, ExprKind::Const(k) if k == neutral);
            if is_neutral(a) {
                return self.expr(b, hint).map(Some);
            }
            if is_neutral(b) {
                return self.expr(a, hint).map(Some);
            }
        }
        if let (BinOp::And, ExprKind::Unary(UnOp::Not, nb)) = (op, &b.kind) {
            if nb.ty == a.ty && !elem.is_real() {
                let ra = self.expr(a, None)?;
                let rb = self.expr(nb, None)?;
                let dst = self.dst(hint)?;
                self.emit(Op::AndNot(R3 { dst, a: ra, b: rb }));
                return Ok(Some(dst));
            }
        }
        Ok(None)
    }

    fn convert(&mut self, a: &Expr, to_ty: Type, hint: Option<Reg>) -> Result<Reg, CompileError> {
        if let (Type::Str { wide: w1, .. }, Type::Str { wide: w2, .. }) = (a.ty, to_ty) {
            let r = self.expr(a, None)?;
            if w1 == w2 {
                return self.finish(r, hint);
            }
            return self.change_width(r, w2, to_ty, hint);
        }
        let from = self.elem_of(a.ty)?;
        let to = self.elem_of(to_ty)?;
        if identity_widening(from, to) {
            return self.expr(a, hint);
        }
        if let (Elem::Real, Elem::DInt, ExprKind::Binary(BinOp::Mul, x, y)) = (from, to, &a.kind) {
            if x.ty == a.ty && y.ty == a.ty {
                let (rx, ry) = (self.expr(x, None)?, self.expr(y, None)?);
                let dst = self.dst(hint)?;
                self.emit(Op::MulRealToDint(R3 { dst, a: rx, b: ry }));
                return Ok(dst);
            }
        }
        let ra = self.expr(a, None)?;
        let dst = self.dst(hint)?;
        if from == Elem::Real && to == Elem::DInt {
            self.emit(Op::RealToDint { dst, a: ra });
        } else {
            self.emit(Op::Conv { from, to, dst, a: ra });
        }
        Ok(dst)
    }

    /// A FUNCTION call: arguments first, then the frame reset, then the arguments are
    /// written, the body runs, the result and outputs are copied out.
    fn call_fn(
        &mut self,
        q: PouId,
        args: &[CallArg],
        hint: Option<Reg>,
    ) -> Result<Reg, CompileError> {
        let p = self.p;
        let f = p.pous.get(q as usize).ok_or_else(|| bad("function"))?;
        let mut vals = Vec::with_capacity(args.len());
        for arg in args {
            match arg {
                CallArg::In(i, e) => {
                    // A copy, so that nested calls of the same function cannot clobber it.
                    let r = if e.ty.is_scalar() {
                        let t = self.alloc(1)?;
                        self.expr_to(e, t)?;
                        t
                    } else {
                        self.expr(e, None)?
                    };
                    vals.push((*i, r, false));
                }
                CallArg::InOut(i, place) => {
                    let a = self.place_addr(place)?;
                    vals.push((*i, self.pointer(a)?, true));
                }
                CallArg::Out(..) => {}
            }
        }
        let frame = self.frame_of(q);
        self.emit(Op::InitFrame { pou: q });
        for (i, r, by_ref) in vals {
            let v = f.vars.get(i as usize).ok_or_else(|| bad("parameter"))?;
            let off = self.lay.var_offset(p, q, i)?;
            let a = self.abs(frame.wrapping_add(off));
            if by_ref || v.section == VarSection::InOut {
                self.store(a, r);
            } else {
                self.put(a, v.ty, r)?;
            }
        }
        self.emit(Op::CallFn { pou: q });
        let result = match f.result {
            Some(ri) => {
                let v = f.vars.get(ri as usize).ok_or_else(|| bad("result"))?;
                let off = self.lay.var_offset(p, q, ri)?;
                let a = self.abs(frame.wrapping_add(off));
                self.take(a, v.ty, hint)?
            }
            None => self.dst(hint)?,
        };
        self.outputs(args, q, Addr::Abs(frame))?;
        Ok(result)
    }

    /// Copies the `=>` outputs of a call of `q` whose frame is at `frame`.
    pub fn outputs(&mut self, args: &[CallArg], q: PouId, frame: Addr) -> Result<(), CompileError> {
        let p = self.p;
        for arg in args {
            if let CallArg::Out(i, place, negated) = arg {
                let v = p.pou(q).vars.get(*i as usize).ok_or_else(|| bad("output"))?;
                let off = self.lay.var_offset(p, q, *i)?;
                let src = match frame {
                    Addr::Abs(f) => self.abs(f.wrapping_add(off)),
                    other => other.plus(off),
                };
                if v.ty.is_scalar() {
                    let mut r = self.load(src, None)?;
                    if *negated {
                        let elem = self.elem_of(v.ty)?;
                        let t = self.alloc(1)?;
                        self.emit(Op::Not { elem, dst: t, a: r });
                        r = t;
                    }
                    self.store_place(place, r)?;
                } else {
                    let s = self.pointer(src)?;
                    let d = self.place_addr(place)?;
                    let d = self.pointer(d)?;
                    let ty = self.place_type(place)?;
                    self.copy_value(ty, d, s)?;
                }
            }
        }
        Ok(())
    }

    fn builtin(
        &mut self,
        func: Builtin,
        args: &[Expr],
        ty: Type,
        hint: Option<Reg>,
    ) -> Result<Reg, CompileError> {
        let arg = |k: usize| args.get(k).ok_or_else(|| bad("builtin argument count"));
        match func {
            Builtin::Math(MathFn::Expt) => {
                let elem = self.elem_of(ty)?;
                let block = self.alloc(2)?;
                for k in 0..2 {
                    let e = arg(k)?;
                    let from = self.elem_of(e.ty)?;
                    let r = self.expr(e, None)?;
                    self.emit(Op::Conv { from, to: elem, dst: block + k as u32, a: r });
                }
                let dst = self.dst(hint)?;
                self.emit(Op::Math { f: MathFn::Expt, elem, dst, a: block, b: block + 1 });
                Ok(dst)
            }
            Builtin::Math(f @ (MathFn::Shl | MathFn::Shr | MathFn::Rol | MathFn::Ror)) => {
                let elem = self.elem_of(arg(0)?.ty)?;
                let a = self.expr(arg(0)?, None)?;
                let b = self.expr_lint(arg(1)?)?;
                let dst = self.dst(hint)?;
                self.emit(Op::Math { f, elem, dst, a, b });
                Ok(dst)
            }
            Builtin::Math(f) => {
                let elem = self.elem_of(ty)?;
                let a = self.expr(arg(0)?, None)?;
                let dst = self.dst(hint)?;
                self.emit(Op::Math { f, elem, dst, a, b: a });
                Ok(dst)
            }
            Builtin::Sel => {
                let g = self.expr(arg(0)?, None)?;
                let block = self.alloc(2)?;
                self.expr_to(arg(1)?, block)?;
                self.expr_to(arg(2)?, block + 1)?;
                let dst = self.dst(hint)?;
                self.emit(Op::Select { dst, g, a: block });
                Ok(dst)
            }
            Builtin::Enabled => {
                // The default first; the call only when EN is TRUE (it may fault).
                let t = self.alloc(1)?;
                self.expr_to(arg(1)?, t)?;
                let en = self.expr(arg(0)?, None)?;
                let j = self.emit(Op::JumpIfNot { c: en, target: 0 });
                self.expr_to(arg(2)?, t)?;
                let end = self.pc();
                self.patch(j, end);
                self.finish(t, hint)
            }
            Builtin::Max | Builtin::Min | Builtin::Limit | Builtin::Subrange => {
                let elem = self.elem_of(ty)?;
                let n = u8::try_from(args.len()).map_err(|_| bad("argument count"))?;
                let block = self.alloc(u32::from(n))?;
                for (k, e) in args.iter().enumerate() {
                    self.expr_to(e, block + k as u32)?;
                }
                let dst = self.dst(hint)?;
                self.emit(match func {
                    Builtin::Limit if n == 3 => Op::Limit { elem, check: false, dst, args: block },
                    Builtin::Subrange if n == 3 => {
                        Op::Limit { elem, check: true, dst, args: block }
                    }
                    Builtin::Limit | Builtin::Subrange => return Err(bad("LIMIT arguments")),
                    _ => Op::MinMax { max: func == Builtin::Max, elem, n, dst, args: block },
                });
                Ok(dst)
            }
            Builtin::Mux => {
                let n = args.len().saturating_sub(1) as u32;
                let block = self.alloc(n + 1)?;
                self.expr_lint_to(arg(0)?, block)?;
                for (k, e) in args.iter().enumerate().skip(1) {
                    self.expr_to(e, block + k as u32)?;
                }
                let dst = self.dst(hint)?;
                self.emit(Op::Mux { n, dst, args: block });
                Ok(dst)
            }
            Builtin::Str(f) => self.string_fn(f, args, ty, hint),
            Builtin::ToString => {
                let a = self.expr(arg(0)?, None)?;
                let t = arg(0)?.ty;
                let idx = match self.out.types.iter().position(|x| *x == t) {
                    Some(i) => i as u32,
                    None => {
                        self.out.types.push(t);
                        self.out.types.len() as u32 - 1
                    }
                };
                let len = match ty {
                    Type::Str { len, .. } => len,
                    _ => return Err(bad("result of *_TO_STRING")),
                };
                let narrow = Type::Str { wide: false, len };
                let dst = self.temp_value(narrow, if ty == narrow { hint } else { None })?;
                self.emit(Op::ToStr { ty: idx, dst, a });
                if ty == narrow {
                    return Ok(dst);
                }
                self.change_width(dst, true, ty, hint)
            }
            Builtin::FromString => {
                let elem = self.elem_of(ty)?;
                let mut a = self.expr(arg(0)?, None)?;
                if let Type::Str { wide: true, len } = arg(0)?.ty {
                    a = self.change_width(a, false, Type::Str { wide: false, len }, None)?;
                }
                let dst = self.dst(hint)?;
                self.emit(Op::FromStr { elem, dst, a });
                Ok(dst)
            }
            Builtin::BcdToInt | Builtin::IntToBcd => {
                let from = self.elem_of(arg(0)?.ty)?;
                let to = self.elem_of(ty)?;
                let a = self.expr(arg(0)?, None)?;
                let dst = self.dst(hint)?;
                let encode = func == Builtin::IntToBcd;
                self.emit(Op::Bcd { encode, from, to, dst, a });
                Ok(dst)
            }
        }
    }

    /// Converts the string at pointer `r` to the other width (`to_wide`) in a new
    /// temporary of type `ty`.
    fn change_width(
        &mut self,
        r: Reg,
        to_wide: bool,
        ty: Type,
        hint: Option<Reg>,
    ) -> Result<Reg, CompileError> {
        let dst = self.temp_value(ty, hint)?;
        let f = if to_wide { StrFunc::Widen } else { StrFunc::Narrow };
        self.emit(Op::Str { f, n: 1, wide: to_wide, dst, args: r });
        Ok(dst)
    }

    fn string_fn(
        &mut self,
        f: StrFunc,
        args: &[Expr],
        ty: Type,
        hint: Option<Reg>,
    ) -> Result<Reg, CompileError> {
        let wide = matches!(args.first().map(|a| a.ty), Some(Type::Str { wide: true, .. }));
        let n = u8::try_from(args.len()).map_err(|_| bad("argument count"))?;
        let block = self.alloc(u32::from(n))?;
        for (k, e) in args.iter().enumerate() {
            if e.ty.is_string() {
                self.expr_to(e, block + k as u32)?;
            } else {
                self.expr_lint_to(e, block + k as u32)?;
            }
        }
        let dst = if ty.is_string() { self.temp_value(ty, hint)? } else { self.dst(hint)? };
        self.emit(Op::Str { f, n, wide, dst, args: block });
        if !ty.is_string() && ty != Type::Elem(Elem::LInt) {
            // LEN and FIND produce a LINT; convert to the declared result type.
            let to = self.elem_of(ty)?;
            self.emit(Op::Conv { from: Elem::LInt, to, dst, a: dst });
        }
        Ok(dst)
    }
}
