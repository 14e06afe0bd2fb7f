//! Statements, places, calls and layout, on hand-built IR.

use super::testkit::*;
use super::*;
use crate::program::op::{CaseTable, Op};
use crate::semantic::ir::*;
use crate::semantic::types::*;
use crate::vm::{Fault, Machine, SysState, Value};

mod calls;
mod fused;

fn inc(i: u32, ty: Type, by: i128) -> Expr {
    bin(BinOp::Add, local(i, ty), int(ty, by))
}

#[test]
fn instructions_are_16_bytes() {
    assert!(std::mem::size_of::<Op>() <= 16, "{}", std::mem::size_of::<Op>());
}

#[test]
fn real_product_to_dint() {
    // d := REAL_TO_DINT(a * b)
    let body =
        vec![set(Place::Local(2), conv(bin(BinOp::Mul, local(0, REAL), local(1, REAL)), DINT), 1)];
    let vars = vec![
        var_init("a", REAL, InitValue::Scalar(crate::values::arith::from_f64(Elem::Real, 2.5))),
        var_init("b", REAL, InitValue::Scalar(crate::values::arith::from_f64(Elem::Real, 1.0))),
        var("d", DINT),
    ];
    let (m, exe, r) = run(&simple(vars, body), 1);
    assert!(r.is_ok());
    assert_eq!(get(&m, &exe, "d"), 2); // 2.5 rounds half to even
}

#[test]
fn if_elsif_else() {
    let body = vec![st(
        StmtKind::If {
            branches: vec![
                (
                    bin(BinOp::Cmp(Cmp::Gt), local(0, INT), int(INT, 10)),
                    vec![set(Place::Local(1), int(INT, 1), 2)],
                ),
                (
                    bin(BinOp::Cmp(Cmp::Gt), local(0, INT), int(INT, 5)),
                    vec![set(Place::Local(1), int(INT, 2), 3)],
                ),
            ],
            else_body: vec![set(Place::Local(1), int(INT, 3), 4)],
        },
        1,
    )];
    for (x, want) in [(11, 1), (6, 2), (0, 3)] {
        let vars = vec![var_init("x", INT, InitValue::Scalar(x)), var("r", INT)];
        let (m, exe, _) = run(&simple(vars, body.clone()), 1);
        assert_eq!(get(&m, &exe, "r"), want, "x = {x}");
    }
}

fn case_prog(arms: Vec<(Vec<(i64, i64)>, i128)>, with_else: bool, sel: i128) -> i128 {
    let arms =
        arms.into_iter().map(|(l, v)| (l, vec![set(Place::Local(1), int(DINT, v), 2)])).collect();
    let else_body = if with_else { vec![set(Place::Local(1), int(DINT, -1), 3)] } else { vec![] };
    let body = vec![st(StmtKind::Case { selector: local(0, DINT), arms, else_body }, 1)];
    let vars = vec![
        var_init("s", DINT, InitValue::Scalar(sel as u64)),
        var_init("r", DINT, InitValue::Scalar(99)),
    ];
    let (m, exe, r) = run(&simple(vars, body), 1);
    assert!(r.is_ok());
    get(&m, &exe, "r")
}

#[test]
fn case_dense_and_sparse() {
    let dense = || vec![(vec![(1, 1)], 10), (vec![(2, 4), (6, 6)], 20), (vec![(5, 5)], 30)];
    assert_eq!(case_prog(dense(), true, 1), 10);
    assert_eq!(case_prog(dense(), true, 3), 20);
    assert_eq!(case_prog(dense(), true, 5), 30);
    assert_eq!(case_prog(dense(), true, 6), 20);
    assert_eq!(case_prog(dense(), true, 7), -1);
    assert_eq!(case_prog(dense(), false, 0), 99);
    let sparse = || {
        vec![
            (vec![(-1_000_000, -1_000_000)], 1),
            (vec![(5, 9), (100_000, 100_000)], 2),
            (vec![(7_000_000, 8_000_000)], 3),
        ]
    };
    assert_eq!(case_prog(sparse(), true, -1_000_000), 1);
    assert_eq!(case_prog(sparse(), true, 7), 2);
    assert_eq!(case_prog(sparse(), true, 100_000), 2);
    assert_eq!(case_prog(sparse(), true, 7_500_000), 3);
    assert_eq!(case_prog(sparse(), true, 10), -1);
    assert_eq!(case_prog(sparse(), false, 4), 99);
    let t = stmt_build_table_kind(sparse());
    assert!(matches!(t, CaseTable::Sparse { .. }));
    assert!(matches!(stmt_build_table_kind(dense()), CaseTable::Dense { .. }));
}

fn stmt_build_table_kind(arms: Vec<(Vec<(i64, i64)>, i128)>) -> CaseTable {
    let arms = arms.into_iter().map(|(l, _)| (l, vec![])).collect();
    let body = vec![st(StmtKind::Case { selector: local(0, DINT), arms, else_body: vec![] }, 1)];
    let p = simple(vec![var("s", DINT)], body);
    let exe = compile(&p.0, p.1).expect("compiles");
    exe.out.cases[0].clone()
}

fn for_prog(ty: Type, from: i128, to: i128, by: i128) -> (i128, i128) {
    // FOR i := from TO to BY by DO n := n + 1; END_FOR
    let body = vec![st(
        StmtKind::For {
            var: Place::Local(0),
            ty: ty.elem().expect("elem"),
            from: int(ty, from),
            to: int(ty, to),
            by: int(ty, by),
            body: vec![set(Place::Local(1), inc(1, DINT, 1), 2)],
        },
        1,
    )];
    let (m, exe, r) = run(&simple(vec![var("i", ty), var("n", DINT)], body), 1);
    assert!(r.is_ok(), "{r:?}");
    (get(&m, &exe, "i"), get(&m, &exe, "n"))
}

#[test]
fn for_loop_edges() {
    assert_eq!(for_prog(INT, 1, 3, 1), (4, 3));
    assert_eq!(for_prog(INT, 1, 0, -2), (-1, 1));
    assert_eq!(for_prog(INT, 1, 0, 1), (1, 0));
    assert_eq!(for_prog(INT, 10, 1, -3), (-2, 4));
    // The end is the type's maximum: no endless loop; the variable wraps.
    assert_eq!(for_prog(SINT, 120, 127, 1), (-128, 8));
    assert_eq!(for_prog(SINT, -120, -128, -1), (127, 9));
}

#[test]
fn for_step_zero_is_a_fault_at_the_statement() {
    let body = vec![
        set(Place::Local(2), int(INT, 7), 1),
        st(
            StmtKind::For {
                var: Place::Local(0),
                ty: Elem::Int,
                from: int(INT, 1),
                to: int(INT, 5),
                by: local(1, INT),
                body: vec![],
            },
            2,
        ),
    ];
    let (m, exe, r) = run(&simple(vec![var("i", INT), var("step", INT), var("x", INT)], body), 1);
    let err = r.expect_err("faults");
    assert_eq!(err.fault, Fault::ForStepZero);
    assert_eq!(err.span, sp(2));
    assert_eq!(get(&m, &exe, "x"), 7, "earlier writes stay");
}

#[test]
fn while_with_exit_and_continue_and_repeat() {
    // WHILE i < 10 DO i := i + 1; IF i = 3 THEN CONTINUE; END_IF; n := n + 1;
    //   IF i = 7 THEN EXIT; END_IF; END_WHILE;  REPEAT k := k + 2; UNTIL k >= 5 END_REPEAT;
    let body = vec![
        st(
            StmtKind::While {
                cond: bin(BinOp::Cmp(Cmp::Lt), local(0, INT), int(INT, 10)),
                body: vec![
                    set(Place::Local(0), inc(0, INT, 1), 2),
                    st(
                        StmtKind::If {
                            branches: vec![(
                                bin(BinOp::Cmp(Cmp::Eq), local(0, INT), int(INT, 3)),
                                vec![st(StmtKind::Continue, 4)],
                            )],
                            else_body: vec![],
                        },
                        3,
                    ),
                    set(Place::Local(1), inc(1, INT, 1), 5),
                    st(
                        StmtKind::If {
                            branches: vec![(
                                bin(BinOp::Cmp(Cmp::Eq), local(0, INT), int(INT, 7)),
                                vec![st(StmtKind::Exit, 7)],
                            )],
                            else_body: vec![],
                        },
                        6,
                    ),
                ],
            },
            1,
        ),
        st(
            StmtKind::Repeat {
                body: vec![set(Place::Local(2), inc(2, INT, 2), 9)],
                until: bin(BinOp::Cmp(Cmp::Ge), local(2, INT), int(INT, 5)),
            },
            8,
        ),
    ];
    let (m, exe, r) = run(&simple(vec![var("i", INT), var("n", INT), var("k", INT)], body), 1);
    assert!(r.is_ok());
    assert_eq!(get(&m, &exe, "i"), 7);
    assert_eq!(get(&m, &exe, "n"), 6);
    assert_eq!(get(&m, &exe, "k"), 6);
}

#[test]
fn return_leaves_the_pou() {
    let body = vec![
        set(Place::Local(0), int(INT, 1), 1),
        st(StmtKind::Return, 2),
        set(Place::Local(0), int(INT, 2), 3),
    ];
    let (m, exe, _) = run(&simple(vec![var("x", INT)], body), 1);
    assert_eq!(get(&m, &exe, "x"), 1);
}

#[test]
fn watchdog_stops_an_endless_loop() {
    let body = vec![st(StmtKind::While { cond: boolean(true), body: vec![] }, 5)];
    let (_, _, r) = run(&simple(vec![], body), 1);
    let err = r.expect_err("watchdog");
    assert_eq!(err.fault, Fault::Watchdog { budget: BUDGET });
    assert_eq!(err.span, sp(5));
}

#[test]
fn division_by_zero_keeps_earlier_writes() {
    let body = vec![
        set(Place::Local(0), int(DINT, 5), 1),
        set(Place::Local(1), bin(BinOp::Div, local(0, DINT), local(2, DINT)), 2),
        set(Place::Local(0), int(DINT, 6), 3),
    ];
    let (m, exe, r) = run(&simple(vec![var("a", DINT), var("b", DINT), var("z", DINT)], body), 1);
    let err = r.expect_err("faults");
    assert_eq!((err.fault, err.span, err.pou), (Fault::DivisionByZero, sp(2), 0));
    assert_eq!(get(&m, &exe, "a"), 5);
}

fn types_with_array_and_struct() -> TypeTable {
    let mut t = TypeTable::default();
    t.arrays.push(ArrayDef {
        dims: vec![(1, 5)],
        element: INT,
        element_range: None,
        element_init: None,
    });
    t.arrays.push(ArrayDef {
        dims: vec![(0, 1), (1, 3)],
        element: DINT,
        element_range: None,
        element_init: None,
    });
    t.structs.push(StructDef {
        name: "Pt".into(),
        fields: vec![
            FieldDef { name: "X".into(), ty: INT, init: Some(InitValue::Scalar(3)), range: None },
            FieldDef {
                name: "Name".into(),
                ty: Type::Str { wide: false, len: 4 },
                init: None,
                range: None,
            },
        ],
    });
    t
}

#[test]
fn places_global_field_element_bit() {
    let arr = |i: Expr| Place::Element(Box::new(Place::Local(0)), 0, vec![i]);
    let m2 = |a: i128, b: Expr| Place::Element(Box::new(Place::Local(1)), 1, vec![int(LINT, a), b]);
    let body = vec![
        // arr[i] := 7 for a dynamic i = 2; arr[5] := arr[2] + 1
        set(arr(conv(local(3, INT), LINT)), int(INT, 7), 1),
        set(arr(int(LINT, 5)), bin(BinOp::Add, load(arr(int(LINT, 2)), INT), int(INT, 1)), 2),
        set(m2(1, conv(local(3, INT), LINT)), int(DINT, 12), 3),
        set(Place::Global(0), load(Place::Field(Box::new(Place::Local(2)), 0), INT), 4),
        set(Place::Bit(Box::new(Place::Local(4)), 3, Elem::Byte), boolean(true), 5),
        set(Place::Local(5), load(Place::Bit(Box::new(Place::Local(4)), 3, Elem::Byte), BOOL), 6),
        set(Place::Field(Box::new(Place::Local(2)), 1), text("abcdef", 6), 7),
    ];
    let vars = vec![
        var("arr", Type::Array(0)),
        var("m", Type::Array(1)),
        var("p", Type::Struct(0)),
        var_init("i", INT, InitValue::Scalar(2)),
        var("b", BYTE),
        var("bit", BOOL),
    ];
    let prog = program(types_with_array_and_struct(), vec![var("g", INT)], vec![], vars, body);
    let (m, exe, r) = run(&prog, 1);
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(get(&m, &exe, "arr[2]"), 7);
    assert_eq!(get(&m, &exe, "ARR[5]"), 8);
    assert_eq!(get(&m, &exe, "m[1,2]"), 12);
    assert_eq!(get(&m, &exe, "g"), 3);
    assert_eq!(get(&m, &exe, "b"), 8);
    assert_eq!(get(&m, &exe, "b.3"), 1);
    assert_eq!(get(&m, &exe, "bit"), 1);
    assert_eq!(value(&m, &exe, "p.name"), Value::Str(b"abcd".to_vec()));
    assert_eq!(exe.locate("arr[6]"), None);
    assert_eq!(exe.locate("nope"), None);
}

#[test]
fn index_out_of_range_fault() {
    let arr = Place::Element(Box::new(Place::Local(0)), 0, vec![conv(local(1, INT), LINT)]);
    let body = vec![set(arr, int(INT, 1), 9)];
    let prog = program(
        types_with_array_and_struct(),
        vec![],
        vec![],
        vec![var("arr", Type::Array(0)), var_init("i", INT, InitValue::Scalar(6))],
        body,
    );
    let (_, _, r) = run(&prog, 1);
    let err = r.expect_err("faults");
    assert_eq!(err.fault, Fault::IndexOutOfRange { index: 6, low: 1, high: 5 });
    assert_eq!(err.span, sp(9));
}

#[test]
fn retain_survives_a_warm_restart_only() {
    let body =
        vec![set(Place::Local(0), inc(0, INT, 1), 1), set(Place::Local(1), inc(1, INT, 1), 2)];
    let vars = vec![
        Var { retain: true, ..var("kept", INT) },
        var_init("lost", INT, InitValue::Scalar(10)),
    ];
    let (mut m, exe, _) = run(&simple(vars, body), 3);
    assert_eq!((get(&m, &exe, "kept"), get(&m, &exe, "lost")), (3, 13));
    m.warm_reset(&exe);
    assert_eq!((get(&m, &exe, "kept"), get(&m, &exe, "lost")), (3, 10));
    m.cold_reset(&exe);
    assert_eq!((get(&m, &exe, "kept"), get(&m, &exe, "lost")), (0, 10));
    assert_eq!(exe.retained().len(), 1);
}

#[test]
fn initial_values_of_types() {
    let mut types = types_with_array_and_struct();
    types.enums.push(EnumDef {
        name: "Color".into(),
        values: vec![("Red".into(), 5), ("Green".into(), 6)],
    });
    types.arrays.push(ArrayDef {
        dims: vec![(1, 3)],
        element: INT,
        element_range: None,
        element_init: Some(InitValue::Scalar(4)),
    });
    let vars = vec![
        var("c", Type::Enum(0)),
        var("p", Type::Struct(0)),
        var_init("a", Type::Array(2), InitValue::Array(vec![InitValue::Scalar(1)])),
        Var { range: Some((3, 9)), ..var("r", INT) },
    ];
    let (m, exe, _) = run(&program(types, vec![], vec![], vars, vec![]), 1);
    assert_eq!(crate::vm::to_json(&value(&m, &exe, "c")), serde_json::json!("Red"));
    assert_eq!(get(&m, &exe, "p.x"), 3);
    assert_eq!(crate::vm::to_json(&value(&m, &exe, "a")), serde_json::json!([1, 4, 4]));
    assert_eq!(get(&m, &exe, "r"), 3);
}

#[test]
fn conditions_evaluate_in_the_main_scope() {
    let body = vec![set(Place::Local(0), inc(0, INT, 1), 1)];
    let prog = simple(vec![var("x", INT)], body);
    let mut exe = compile(&prog.0, prog.1).expect("compiles");
    let mut m = Machine::new(&exe);
    let c = exe
        .compile_condition(&prog.0, &bin(BinOp::Cmp(Cmp::Ge), local(0, INT), int(INT, 2)))
        .expect("condition compiles");
    let sys = SysState::default();
    let mut seen = vec![];
    for _ in 0..3 {
        m.run_scan(&exe, sys, BUDGET).expect("runs");
        seen.push(m.eval_condition(&exe, c, sys, BUDGET).expect("evaluates"));
    }
    assert_eq!(seen, [false, true, true]);
}

#[test]
fn system_variables() {
    let body = vec![
        set(Place::Local(0), e(ExprKind::Sys(SysVar::FirstScan), BOOL), 1),
        set(Place::Local(1), e(ExprKind::Sys(SysVar::T100ms), BOOL), 2),
        set(Place::Local(2), e(ExprKind::Sys(SysVar::Clock), TIME), 3),
    ];
    let prog = simple(vec![var("f", BOOL), var("t", BOOL), var("c", TIME)], body);
    let exe = compile(&prog.0, prog.1).expect("compiles");
    let mut m = Machine::new(&exe);
    m.run_scan(&exe, SysState { first_scan: true, time_ns: 40_000_000 }, BUDGET).expect("runs");
    assert_eq!((get(&m, &exe, "f"), get(&m, &exe, "t"), get(&m, &exe, "c")), (1, 1, 40_000_000));
    m.run_scan(&exe, SysState { first_scan: false, time_ns: 150_000_000 }, BUDGET).expect("runs");
    assert_eq!((get(&m, &exe, "f"), get(&m, &exe, "t")), (0, 0));
}

#[test]
fn statement_spans_and_debug_map() {
    let body = vec![set(Place::Local(0), int(INT, 1), 3), set(Place::Local(0), int(INT, 2), 7)];
    let prog = simple(vec![var("x", INT)], body);
    let exe = compile(&prog.0, prog.1).expect("compiles");
    let spans = exe.statement_spans(prog.1);
    assert!(spans.contains(&sp(3)) && spans.contains(&sp(7)));
}
