//! Hand-built IR for the compiler and VM tests (no parser involved).

use crate::compile::{compile, Executable};
use crate::diagnostics::Span;
use crate::semantic::ir::*;
use crate::semantic::types::*;
use crate::syntax::{PouKind, VarSection};
use crate::values::arith;
use crate::vm::{Machine, RuntimeError, SysState};

pub fn sp(n: u32) -> Span {
    Span { start: n, end: n + 1 }
}

pub fn var(name: &str, ty: Type) -> Var {
    Var {
        name: name.into(),
        ty,
        section: VarSection::Var,
        retain: false,
        constant: false,
        location: None,
        init: None,
        range: None,
        comment: None,
        span: sp(0),
    }
}

pub fn var_s(name: &str, ty: Type, section: VarSection) -> Var {
    Var { section, ..var(name, ty) }
}

pub fn var_init(name: &str, ty: Type, init: InitValue) -> Var {
    Var { init: Some(init), ..var(name, ty) }
}

pub const DINT: Type = Type::Elem(Elem::DInt);
pub const INT: Type = Type::Elem(Elem::Int);
pub const SINT: Type = Type::Elem(Elem::SInt);
pub const LINT: Type = Type::Elem(Elem::LInt);
pub const REAL: Type = Type::Elem(Elem::Real);
pub const LREAL: Type = Type::Elem(Elem::LReal);
pub const BOOL: Type = Type::BOOL;
pub const TIME: Type = Type::Elem(Elem::Time);
pub const BYTE: Type = Type::Elem(Elem::Byte);

pub fn e(kind: ExprKind, ty: Type) -> Expr {
    Expr { kind, ty, span: sp(0) }
}

pub fn int(ty: Type, v: i128) -> Expr {
    let elem = ty.elem().unwrap_or(Elem::LInt);
    e(ExprKind::Const(arith::norm(elem, v)), ty)
}

pub fn real(ty: Type, v: f64) -> Expr {
    let elem = ty.elem().unwrap_or(Elem::LReal);
    e(ExprKind::Const(arith::from_f64(elem, v)), ty)
}

pub fn boolean(b: bool) -> Expr {
    e(ExprKind::Const(u64::from(b)), BOOL)
}

pub fn text(s: &str, len: u32) -> Expr {
    e(ExprKind::ConstStr(s.as_bytes().to_vec()), Type::Str { wide: false, len })
}

pub fn load(p: Place, ty: Type) -> Expr {
    e(ExprKind::Load(p), ty)
}

pub fn local(i: u32, ty: Type) -> Expr {
    load(Place::Local(i), ty)
}

pub fn bin(op: BinOp, a: Expr, b: Expr) -> Expr {
    let ty = match op {
        BinOp::Cmp(_) => BOOL,
        _ => a.ty,
    };
    e(ExprKind::Binary(op, Box::new(a), Box::new(b)), ty)
}

pub fn conv(a: Expr, ty: Type) -> Expr {
    e(ExprKind::Convert(Box::new(a)), ty)
}

pub fn builtin(func: Builtin, args: Vec<Expr>, ty: Type) -> Expr {
    e(ExprKind::Builtin { func, args }, ty)
}

pub fn st(kind: StmtKind, span: u32) -> Stmt {
    Stmt { kind, span: sp(span) }
}

pub fn set(p: Place, v: Expr, span: u32) -> Stmt {
    st(StmtKind::Assign(p, v), span)
}

pub fn pou(name: &str, kind: PouKind, vars: Vec<Var>, body: Vec<Stmt>) -> Pou {
    Pou { name: name.into(), kind, vars, result: None, body, library: false, span: sp(0) }
}

/// A program whose only user POU is PROGRAM Main (last), after `others`.
pub fn program(
    types: TypeTable,
    globals: Vec<Var>,
    others: Vec<Pou>,
    vars: Vec<Var>,
    body: Vec<Stmt>,
) -> (Program, PouId) {
    let mut pous = others;
    pous.push(pou("Main", PouKind::Program, vars, body));
    let main = pous.len() as PouId - 1;
    (Program { types, globals, pous, library_pous: 0, config: None }, main)
}

pub fn simple(vars: Vec<Var>, body: Vec<Stmt>) -> (Program, PouId) {
    program(TypeTable::default(), Vec::new(), Vec::new(), vars, body)
}

pub const BUDGET: u64 = 1_000_000;

/// Compiles and runs `scans` scans; returns the machine, the executable and the result of
/// the last scan.
pub fn run(p: &(Program, PouId), scans: usize) -> (Machine, Executable, Result<(), RuntimeError>) {
    let exe = compile(&p.0, p.1).expect("compiles");
    let mut m = Machine::new(&exe);
    let mut r = Ok(());
    for k in 0..scans {
        r = m.run_scan(
            &exe,
            SysState { first_scan: k == 0, time_ns: k as i64 * 10_000_000 },
            BUDGET,
        );
        if r.is_err() {
            break;
        }
    }
    (m, exe, r)
}

/// The value of main variable `name` as i128 (scalars only).
pub fn get(m: &Machine, exe: &Executable, name: &str) -> i128 {
    let slot = exe.locate(name).expect("variable exists");
    match crate::vm::read(m.memory(), exe, &slot) {
        crate::vm::Value::Int(value, _) => value,
        crate::vm::Value::Bool(b) => i128::from(b),
        crate::vm::Value::Time(t) | crate::vm::Value::Enum { value: t, .. } => i128::from(t),
        other => panic!("not an integer: {other:?}"),
    }
}

/// The value of main variable `name` as a `Value`.
pub fn value(m: &Machine, exe: &Executable, name: &str) -> crate::vm::Value {
    let slot = exe.locate(name).expect("variable exists");
    crate::vm::read(m.memory(), exe, &slot)
}
