//! Calls: FB instances, functions, in-outs, call depth, VAR_TEMP, compile errors.

use super::super::testkit::*;
use super::super::*;
use super::inc;
use crate::semantic::ir::*;
use crate::semantic::types::*;
use crate::syntax::{PouKind, VarSection};
use crate::vm::{Fault, Value};

/// FB Counter: VAR_INPUT inc: INT; VAR_IN_OUT total: INT; VAR_OUTPUT q: INT; VAR n: INT;
/// n := n + inc; total := total + inc; q := n;
fn counter_fb() -> Pou {
    let vars = vec![
        var_s("inc", INT, VarSection::Input),
        var_s("total", INT, VarSection::InOut),
        var_s("q", INT, VarSection::Output),
        var("n", INT),
    ];
    let body = vec![
        set(Place::Local(3), bin(BinOp::Add, local(3, INT), local(0, INT)), 100),
        set(Place::Local(1), bin(BinOp::Add, local(1, INT), local(0, INT)), 101),
        set(Place::Local(2), local(3, INT), 102),
    ];
    pou("Counter", PouKind::FunctionBlock, vars, body)
}

#[test]
fn fb_instances_in_an_array_keep_state_and_bind_in_outs() {
    let mut types = TypeTable::default();
    types.arrays.push(ArrayDef {
        dims: vec![(0, 2)],
        element: Type::Fb(0),
        element_range: None,
        element_init: None,
    });
    // FOR k := 0 TO 2 DO fbs[k](inc := k + 1, total := sum, q => last); END_FOR
    let inst = Place::Element(Box::new(Place::Local(0)), 0, vec![conv(local(1, INT), LINT)]);
    let call = st(
        StmtKind::CallFb {
            instance: inst,
            fb: 0,
            args: vec![
                CallArg::In(0, inc(1, INT, 1)),
                CallArg::InOut(1, Place::Local(2)),
                CallArg::Out(2, Place::Local(3), false),
            ],
        },
        2,
    );
    let body = vec![st(
        StmtKind::For {
            var: Place::Local(1),
            ty: Elem::Int,
            from: int(INT, 0),
            to: int(INT, 2),
            by: int(INT, 1),
            body: vec![call],
        },
        1,
    )];
    let vars = vec![var("fbs", Type::Array(0)), var("k", INT), var("sum", INT), var("last", INT)];
    let prog = program(types, vec![], vec![counter_fb()], vars, body);
    let (m, exe, r) = run(&prog, 3);
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(get(&m, &exe, "sum"), 18);
    assert_eq!(get(&m, &exe, "last"), 9);
    assert_eq!(get(&m, &exe, "fbs[1].n"), 6);
    assert_eq!(get(&m, &exe, "fbs[2].q"), 9);
    assert_eq!(
        crate::vm::to_json(&value(&m, &exe, "fbs[0]")),
        serde_json::json!({"inc": 1, "q": 3, "n": 3})
    );
}

/// FUNCTION Twice : INT  VAR_INPUT x: INT; VAR_OUTPUT o: INT;  Twice := x * 2; o := x + 1;
fn twice_fn(library: bool) -> Pou {
    let vars = vec![
        var_s("x", INT, VarSection::Input),
        var_s("o", INT, VarSection::Output),
        var("Twice", INT),
    ];
    let body = vec![
        set(Place::Local(2), bin(BinOp::Mul, local(0, INT), int(INT, 2)), 200),
        set(Place::Local(1), bin(BinOp::Div, int(INT, 100), local(0, INT)), 201),
    ];
    Pou { result: Some(2), library, ..pou("Twice", PouKind::Function, vars, body) }
}

fn call_twice(arg: Expr, out: Option<u32>) -> Expr {
    let mut args = vec![CallArg::In(0, arg)];
    if let Some(o) = out {
        args.push(CallArg::Out(1, Place::Local(o), false));
    }
    e(ExprKind::Call { pou: 0, args }, INT)
}

#[test]
fn function_calls_nest_and_copy_outputs() {
    // r := Twice(Twice(x) + Twice(3), o => o2)
    let inner = bin(BinOp::Add, call_twice(local(0, INT), None), call_twice(int(INT, 3), None));
    let body = vec![set(Place::Local(1), call_twice(inner, Some(2)), 1)];
    let vars = vec![var_init("x", INT, InitValue::Scalar(5)), var("r", INT), var("o2", INT)];
    let prog = program(TypeTable::default(), vec![], vec![twice_fn(false)], vars, body);
    let (m, exe, r) = run(&prog, 1);
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(get(&m, &exe, "r"), 32);
    assert_eq!(get(&m, &exe, "o2"), 6);
}

#[test]
fn a_fault_in_a_library_function_reports_the_calling_statement() {
    let body = vec![set(Place::Local(1), call_twice(local(0, INT), None), 42)];
    for (library, span, pou) in [(true, sp(42), 1), (false, sp(201), 0)] {
        let prog = program(
            TypeTable::default(),
            vec![],
            vec![twice_fn(library)],
            vec![var("x", INT), var("r", INT)],
            body.clone(),
        );
        let (_, _, r) = run(&prog, 1);
        let err = r.expect_err("division by zero");
        assert_eq!((err.fault, err.span, err.pou), (Fault::DivisionByZero, span, pou));
    }
}

#[test]
fn eval_statement_and_function_in_outs() {
    // FUNCTION Bump : BOOL  VAR_IN_OUT v: INT; s: STRING[8]  v := v + 1; s := 'bumped';
    let s8 = Type::Str { wide: false, len: 8 };
    let vars = vec![
        var_s("v", INT, VarSection::InOut),
        var_s("s", s8, VarSection::InOut),
        var("Bump", BOOL),
    ];
    let body = vec![
        set(Place::Local(0), inc(0, INT, 1), 300),
        set(Place::Local(1), text("bumped", 6), 301),
    ];
    let bump = Pou { result: Some(2), ..pou("Bump", PouKind::Function, vars, body) };
    let call = e(
        ExprKind::Call {
            pou: 0,
            args: vec![CallArg::InOut(0, Place::Local(0)), CallArg::InOut(1, Place::Local(1))],
        },
        BOOL,
    );
    let main_body = vec![st(StmtKind::Eval(call.clone()), 1), st(StmtKind::Eval(call), 2)];
    let s4 = Type::Str { wide: false, len: 4 };
    let prog = program(
        TypeTable::default(),
        vec![],
        vec![bump],
        vec![var("n", INT), var("t", s4)],
        main_body,
    );
    let (m, exe, r) = run(&prog, 1);
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(get(&m, &exe, "n"), 2);
    // Written through the reference, truncated to the actual variable's length.
    assert_eq!(value(&m, &exe, "t"), Value::Str(b"bump".to_vec()));
}

#[test]
fn calls_nested_too_deeply_fault() {
    // FB k contains an instance of FB k+1 and calls it; 70 levels.
    let depth = 70u32;
    let mut pous = Vec::new();
    for k in 0..depth {
        let (vars, body) = if k + 1 < depth {
            let call =
                st(StmtKind::CallFb { instance: Place::Local(0), fb: k + 1, args: vec![] }, 50);
            (vec![var("inner", Type::Fb(k + 1))], vec![call])
        } else {
            (vec![var("x", INT)], vec![set(Place::Local(0), int(INT, 1), 60)])
        };
        pous.push(pou(&format!("F{k}"), PouKind::FunctionBlock, vars, body));
    }
    let call = st(StmtKind::CallFb { instance: Place::Local(0), fb: 0, args: vec![] }, 7);
    let prog =
        program(TypeTable::default(), vec![], pous, vec![var("top", Type::Fb(0))], vec![call]);
    let (_, _, r) = run(&prog, 1);
    assert_eq!(r.expect_err("too deep").fault, Fault::CallDepth);
}

#[test]
fn var_temp_is_reinitialised_on_every_call() {
    // FB Acc: VAR_TEMP t: INT := 5; VAR_OUTPUT q: INT;  t := t + 1; q := t;
    let vars = vec![
        Var { init: Some(InitValue::Scalar(5)), ..var_s("t", INT, VarSection::Temp) },
        var_s("q", INT, VarSection::Output),
    ];
    let body =
        vec![set(Place::Local(0), inc(0, INT, 1), 10), set(Place::Local(1), local(0, INT), 11)];
    let acc = pou("Acc", PouKind::FunctionBlock, vars, body);
    let call = st(StmtKind::CallFb { instance: Place::Local(0), fb: 0, args: vec![] }, 1);
    let prog =
        program(TypeTable::default(), vec![], vec![acc], vec![var("a", Type::Fb(0))], vec![call]);
    let (m, exe, r) = run(&prog, 3);
    assert!(r.is_ok());
    assert_eq!(get(&m, &exe, "a.q"), 6);
}

#[test]
fn compile_errors_are_values() {
    let prog = simple(vec![], vec![]);
    assert_eq!(compile(&prog.0, 7).err(), Some(CompileError::NotAProgram(7)));
    let mut types = TypeTable::default();
    types.arrays.push(ArrayDef {
        dims: vec![(0, 99_999_999)],
        element: LINT,
        element_range: None,
        element_init: None,
    });
    let big = program(types, vec![], vec![], vec![var("huge", Type::Array(0))], vec![]);
    assert!(matches!(compile(&big.0, big.1), Err(CompileError::MemoryTooLarge { .. })));
}
