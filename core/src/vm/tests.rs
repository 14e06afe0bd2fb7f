//! Built-in functions, strings, text conversion, values and JSON rendering.

use crate::compile::testkit::*;
use crate::semantic::ir::*;
use crate::semantic::types::*;
use crate::values::arith;
use crate::vm::*;
use serde_json::json;

fn s(len: u32) -> Type {
    Type::Str { wide: false, len }
}

/// Runs `r := expr` once (r of type `ty`); returns the result or the fault.
fn eval(expr: Expr) -> Result<Value, Fault> {
    let ty = expr.ty;
    let p = simple(vec![var("r", ty)], vec![set(Place::Local(0), expr, 1)]);
    let (m, exe, r) = run(&p, 1);
    r.map_err(|e| e.fault)?;
    Ok(value(&m, &exe, "r"))
}

fn st_val(x: &str) -> Value {
    Value::Str(x.as_bytes().to_vec())
}

fn int_val(v: i128, elem: Elem) -> Value {
    Value::Int(v, elem)
}

#[test]
fn string_functions() {
    let t = |x: &str| text(x, 20);
    let i = |v: i128| int(INT, v);
    let cases = [
        (builtin(Builtin::Str(StrFunc::Left), vec![t("hello"), i(2)], s(20)), st_val("he")),
        (builtin(Builtin::Str(StrFunc::Right), vec![t("hello"), i(3)], s(20)), st_val("llo")),
        (builtin(Builtin::Str(StrFunc::Mid), vec![t("hello"), i(3), i(2)], s(20)), st_val("ell")),
        (
            builtin(Builtin::Str(StrFunc::Concat), vec![t("ab"), t("cd"), t("e")], s(20)),
            st_val("abcde"),
        ),
        (builtin(Builtin::Str(StrFunc::Concat), vec![t("abc"), t("def")], s(4)), st_val("abcd")),
        (
            builtin(Builtin::Str(StrFunc::Insert), vec![t("ABC"), t("XY"), i(2)], s(20)),
            st_val("ABXYC"),
        ),
        (
            builtin(Builtin::Str(StrFunc::Insert), vec![t("ABC"), t("XY"), i(0)], s(20)),
            st_val("XYABC"),
        ),
        (
            builtin(Builtin::Str(StrFunc::Delete), vec![t("ABCDE"), i(2), i(2)], s(20)),
            st_val("ADE"),
        ),
        (
            builtin(Builtin::Str(StrFunc::Replace), vec![t("ABCDE"), t("xyz"), i(2), i(2)], s(20)),
            st_val("AxyzDE"),
        ),
    ];
    for (expr, want) in cases {
        assert_eq!(eval(expr.clone()), Ok(want), "{expr:?}");
    }
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Len), vec![t("hello")], INT)),
        Ok(int_val(5, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Find), vec![t("abcbc"), t("bc")], INT)),
        Ok(int_val(2, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Find), vec![t("abc"), t("x")], INT)),
        Ok(int_val(0, Elem::Int))
    );
}

#[test]
fn string_position_faults() {
    let t = |x: &str| text(x, 20);
    let i = |v: i128| int(INT, v);
    let fault = |f: &'static str, position: i64, length: usize| {
        Err(Fault::StringPosition { function: f, position, length })
    };
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Left), vec![t("abc"), i(4)], s(20))),
        fault("LEFT", 4, 3)
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Right), vec![t("abc"), i(-1)], s(20))),
        fault("RIGHT", -1, 3)
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Mid), vec![t("abc"), i(2), i(3)], s(20))),
        fault("MID", 3, 3)
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Mid), vec![t("abc"), i(1), i(0)], s(20))),
        fault("MID", 0, 3)
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Insert), vec![t("abc"), t("x"), i(4)], s(20))),
        fault("INSERT", 4, 3)
    );
    assert_eq!(
        eval(builtin(Builtin::Str(StrFunc::Delete), vec![t("abc"), i(5), i(1)], s(20))),
        fault("DELETE", 1, 3)
    );
}

#[test]
fn string_assignment_and_comparison() {
    // a := 'abcdef' (STRING[3]); b := a < 'abd'; c := a = 'abc'
    let body = vec![
        set(Place::Local(0), text("abcdef", 6), 1),
        set(Place::Local(1), bin(BinOp::Cmp(Cmp::Lt), local(0, s(3)), text("abd", 3)), 2),
        set(Place::Local(2), bin(BinOp::Cmp(Cmp::Eq), local(0, s(3)), text("abc", 3)), 3),
        set(Place::Local(3), local(0, s(3)), 4),
    ];
    let p = simple(vec![var("a", s(3)), var("b", BOOL), var("c", BOOL), var("d", s(10))], body);
    let (m, exe, r) = run(&p, 1);
    assert!(r.is_ok());
    assert_eq!(value(&m, &exe, "a"), st_val("abc"));
    assert_eq!(value(&m, &exe, "d"), st_val("abc"));
    assert_eq!((get(&m, &exe, "b"), get(&m, &exe, "c")), (1, 1));
}

#[test]
fn numeric_builtins() {
    let abs = builtin(Builtin::Math(MathFn::Abs), vec![int(SINT, -128)], SINT);
    assert_eq!(eval(abs), Ok(int_val(-128, Elem::SInt)));
    assert_eq!(
        eval(builtin(Builtin::Math(MathFn::Abs), vec![int(INT, -5)], INT)),
        Ok(int_val(5, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::Math(MathFn::Sqrt), vec![real(LREAL, 16.0)], LREAL)),
        Ok(Value::Real(4.0, Elem::LReal))
    );
    assert_eq!(
        eval(builtin(
            Builtin::Math(MathFn::Expt),
            vec![real(LREAL, 2.0), real(LREAL, 10.0)],
            LREAL
        )),
        Ok(Value::Real(1024.0, Elem::LReal))
    );
    assert_eq!(
        eval(builtin(Builtin::Math(MathFn::Rol), vec![int(BYTE, 0x81), int(INT, 1)], BYTE)),
        Ok(int_val(3, Elem::Byte))
    );
    assert_eq!(
        eval(builtin(Builtin::Math(MathFn::Shl), vec![int(BYTE, 0x81), int(LINT, 1)], BYTE)),
        Ok(int_val(2, Elem::Byte))
    );
    assert_eq!(
        eval(builtin(Builtin::Sel, vec![boolean(true), int(INT, 1), int(INT, 2)], INT)),
        Ok(int_val(2, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::Max, vec![int(INT, 1), int(INT, 7), int(INT, -2)], INT)),
        Ok(int_val(7, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::Min, vec![int(INT, 1), int(INT, 7), int(INT, -2)], INT)),
        Ok(int_val(-2, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::Limit, vec![int(INT, 0), int(INT, 12), int(INT, 10)], INT)),
        Ok(int_val(10, Elem::Int))
    );
    let mux =
        |k| builtin(Builtin::Mux, vec![int(INT, k), int(INT, 10), int(INT, 20), int(INT, 30)], INT);
    assert_eq!(eval(mux(2)), Ok(int_val(30, Elem::Int)));
    assert_eq!(eval(mux(3)), Err(Fault::IndexOutOfRange { index: 3, low: 0, high: 2 }));
    let sel_str = builtin(Builtin::Sel, vec![boolean(false), text("no", 2), text("yes", 3)], s(5));
    assert_eq!(eval(sel_str), Ok(st_val("no")));
}

#[test]
fn text_conversions_and_bcd() {
    let to_s = |x: Expr| builtin(Builtin::ToString, vec![x], s(40));
    assert_eq!(eval(to_s(int(INT, -42))), Ok(st_val("-42")));
    assert_eq!(eval(to_s(boolean(true))), Ok(st_val("TRUE")));
    assert_eq!(eval(to_s(real(REAL, 1.5))), Ok(st_val("1.5")));
    assert_eq!(eval(to_s(real(REAL, 0.1))), Ok(st_val("0.1")));
    assert_eq!(eval(to_s(int(TIME, 1_500_000_000))), Ok(st_val("T#1s500ms")));
    let from_s = |x: &str, ty: Type| builtin(Builtin::FromString, vec![text(x, 20)], ty);
    assert_eq!(eval(from_s(" 123 ", INT)), Ok(int_val(123, Elem::Int)));
    assert_eq!(eval(from_s("16#FF", INT)), Ok(int_val(255, Elem::Int)));
    assert_eq!(eval(from_s("T#1m2s", TIME)), Ok(Value::Time(62_000_000_000)));
    assert_eq!(
        eval(from_s("abc", INT)),
        Err(Fault::BadConversion { text: "abc".into(), target: "INT" })
    );
    assert_eq!(
        eval(from_s("40000", INT)),
        Err(Fault::BadConversion { text: "40000".into(), target: "INT" })
    );
    let word = Type::Elem(Elem::Word);
    assert_eq!(
        eval(builtin(Builtin::BcdToInt, vec![int(word, 0x1234)], INT)),
        Ok(int_val(1234, Elem::Int))
    );
    assert_eq!(
        eval(builtin(Builtin::IntToBcd, vec![int(INT, 1234)], word)),
        Ok(int_val(0x1234, Elem::Word))
    );
    assert!(matches!(
        eval(builtin(Builtin::BcdToInt, vec![int(word, 0x12A4)], INT)),
        Err(Fault::BadConversion { .. })
    ));
}

#[test]
fn time_arithmetic() {
    let t = |ms: i128| int(TIME, ms * 1_000_000);
    assert_eq!(eval(bin(BinOp::Add, t(1500), t(500))), Ok(Value::Time(2_000_000_000)));
    let scaled =
        e(ExprKind::Binary(BinOp::Mul, Box::new(t(100)), Box::new(real(LREAL, 2.5))), TIME);
    assert_eq!(eval(scaled), Ok(Value::Time(250_000_000)));
    let div = e(ExprKind::Binary(BinOp::Div, Box::new(t(100)), Box::new(int(LINT, 0))), TIME);
    assert_eq!(eval(div), Err(Fault::DivisionByZero));
}

#[test]
fn short_circuit_operators() {
    // r := FALSE AND_THEN (1 / 0 = 0): the right side never runs.
    let boom = bin(BinOp::Cmp(Cmp::Eq), bin(BinOp::Div, int(INT, 1), int(INT, 0)), int(INT, 0));
    assert_eq!(eval(bin(BinOp::AndThen, boolean(false), boom.clone())), Ok(Value::Bool(false)));
    assert_eq!(eval(bin(BinOp::OrElse, boolean(true), boom.clone())), Ok(Value::Bool(true)));
    assert_eq!(eval(bin(BinOp::And, boolean(false), boom)), Err(Fault::DivisionByZero));
}

#[test]
fn time_literals() {
    assert_eq!(format_time(0), "T#0s");
    assert_eq!(format_time(1_500_000_000), "T#1s500ms");
    assert_eq!(format_time(-14_000_000), "T#-14ms");
    assert_eq!(format_time(90_061_001_001_001), "T#1d1h1m1s1ms1us1ns");
    assert_eq!(format_time(25 * 3_600_000_000_000 + 15 * 60_000_000_000), "T#1d1h15m");
    assert_eq!(format_time(i64::MIN), "T#-106751d23h47m16s854ms775us808ns");
    assert_eq!(parse_time("T#1h_30m"), Some(5_400_000_000_000));
    assert_eq!(parse_time("t#-1.5s"), Some(-1_500_000_000));
    assert_eq!(parse_time("T#1.5s2ms"), None);
    // DATE and DT count microseconds, TOD nanoseconds.
    assert_eq!(format_date(days_from_civil(2006, 3, 20) * 86_400_000_000), "D#2006-03-20");
    assert_eq!(
        format_tod(((10 * 60 + 42) * 60 + 23) * 1_000_000_000 + 780_000_000),
        "TOD#10:42:23.78"
    );
    let dt = days_from_civil(2006, 3, 20) * 86_400_000_000
        + ((10 * 60 + 42) * 60 + 23) * 1_000_000
        + 780_000;
    assert_eq!(format_dt(dt), "DT#2006-03-20-10:42:23.78");
    assert_eq!(parse_text("DT#2006-03-20-10:42:23.78", Elem::Dt), Some(dt as u64));
    assert_eq!(civil_from_days(-1), (1969, 12, 31));
    // The ends of IEC's range, and the whole i64 of microseconds without a panic.
    let first = days_from_civil(1, 1, 1) * 86_400_000_000;
    assert_eq!(format_date(first), "D#0001-01-01");
    assert_eq!(parse_text("D#0001-01-01", Elem::Date), Some(first as u64));
    assert_eq!(parse_text("D#0000-12-31", Elem::Date), None);
    let last = days_from_civil(9999, 12, 31) * 86_400_000_000 + 86_399_999_999;
    assert_eq!(format_dt(last), "DT#9999-12-31-23:59:59.999999");
    assert!(format_dt(i64::MIN).starts_with("DT#-"));
    assert!(format_dt(i64::MAX).starts_with("DT#294247-"));
}

#[test]
fn json_rendering_of_every_kind() {
    let mut types = TypeTable::default();
    types
        .enums
        .push(EnumDef { name: "E".into(), values: vec![("Idle".into(), 0), ("Run".into(), 1)] });
    let j = |v: Value| to_json(&v);
    assert_eq!(j(Value::Bool(true)), json!(true));
    assert_eq!(j(int_val(-5, Elem::Int)), json!(-5));
    assert_eq!(j(int_val(u64::MAX as i128, Elem::ULInt)), json!(u64::MAX));
    assert_eq!(j(Value::Real(0.1f32 as f64, Elem::Real)), json!(0.1));
    assert_eq!(j(Value::Real(0.1, Elem::LReal)), json!(0.1));
    assert_eq!(j(Value::Real(f64::NAN, Elem::LReal)), json!(null));
    assert_eq!(j(Value::Real(f64::INFINITY, Elem::Real)), json!(null));
    assert_eq!(j(st_val("héllo")), json!("héllo"));
    assert_eq!(j(Value::Str(vec![b'a', 0xE9])), json!("aé"));
    assert_eq!(j(Value::WStr("wö".encode_utf16().collect())), json!("wö"));
    assert_eq!(j(Value::Time(1_500_000_000)), json!("T#1s500ms"));
    assert_eq!(j(Value::Date(0)), json!("D#1970-01-01"));
    assert_eq!(j(Value::Tod(3_600_000_000_000)), json!("TOD#01:00:00"));
    assert_eq!(j(Value::Dt(0)), json!("DT#1970-01-01-00:00:00"));
    assert_eq!(j(Value::from_bits(Type::Enum(0), 1, &types)), json!("Run"));
    assert_eq!(j(Value::from_bits(Type::Enum(0), 7, &types)), json!(7));
    let arr = Value::Array(vec![
        Value::Array(vec![Value::Bool(true)]),
        Value::Array(vec![Value::Bool(false)]),
    ]);
    assert_eq!(j(arr), json!([[true], [false]]));
    let st =
        Value::Struct(vec![("b".into(), Value::Bool(true)), ("a".into(), int_val(1, Elem::Int))]);
    assert_eq!(j(st), json!({"a": 1, "b": true}));
}

#[test]
fn write_and_read_values() {
    let mut types = TypeTable::default();
    types.arrays.push(ArrayDef {
        dims: vec![(0, 1), (0, 1)],
        element: INT,
        element_range: None,
        element_init: None,
    });
    let vars = vec![var("x", SINT), var("a", Type::Array(0)), var("t", s(3)), var("w", BYTE)];
    let p = program(types, vec![], vec![], vars, vec![]);
    let (mut m, exe, _) = run(&p, 1);
    let slot = exe.locate("x").expect("x");
    assert!(write(m.memory_mut(), &exe, &slot, &int_val(300, Elem::LInt)).is_err());
    write(m.memory_mut(), &exe, &slot, &int_val(-7, Elem::LInt)).expect("fits");
    assert_eq!(get(&m, &exe, "x"), -7);
    let a = exe.locate("a").expect("a");
    let nested = Value::Array(vec![
        Value::Array(vec![int_val(1, Elem::Int), int_val(2, Elem::Int)]),
        Value::Array(vec![int_val(3, Elem::Int), int_val(4, Elem::Int)]),
    ]);
    write(m.memory_mut(), &exe, &a, &nested).expect("writes");
    assert_eq!(read(m.memory(), &exe, &a), nested);
    assert_eq!(get(&m, &exe, "a[1,0]"), 3);
    let t = exe.locate("t").expect("t");
    write(m.memory_mut(), &exe, &t, &st_val("abcdef")).expect("writes");
    assert_eq!(value(&m, &exe, "t"), st_val("abc"));
    // A value of the wrong kind is refused both ways, a single cell and a composite one.
    let mismatch = |r| matches!(r, Err(WriteError::TypeMismatch { .. }));
    assert!(mismatch(write(m.memory_mut(), &exe, &slot, &st_val("1"))), "text into SINT");
    assert!(mismatch(write(m.memory_mut(), &exe, &t, &Value::Bool(true))), "BOOL into STRING");
    assert!(mismatch(write(m.memory_mut(), &exe, &a, &int_val(1, Elem::Int))), "INT into ARRAY");
    assert_eq!(value(&m, &exe, "t"), st_val("abc"));
    let bit = exe.locate("w.7").expect("bit");
    write(m.memory_mut(), &exe, &bit, &Value::Bool(true)).expect("writes");
    assert_eq!(get(&m, &exe, "w"), 128);
    write_init(m.memory_mut(), &exe, &t, &InitValue::Str(b"xy".to_vec())).expect("writes");
    assert_eq!(value(&m, &exe, "t"), st_val("xy"));
    assert_eq!(exe.locate("w.8"), None);
}

#[test]
fn wide_strings_convert_both_ways() {
    let w = |len| Type::Str { wide: true, len };
    let wide = conv(text("aé", 3), w(5));
    assert_eq!(eval(wide.clone()), Ok(Value::WStr(vec![97, 0xC3, 0xA9])));
    assert_eq!(eval(conv(wide, s(5))), Ok(Value::Str("aé".as_bytes().to_vec())));
    assert_eq!(
        eval(builtin(Builtin::ToString, vec![int(INT, 12)], w(4))),
        Ok(Value::WStr(vec![49, 50]))
    );
    let from = builtin(Builtin::FromString, vec![conv(text("77", 2), w(2))], INT);
    assert_eq!(eval(from), Ok(int_val(77, Elem::Int)));
    let len = builtin(Builtin::Str(StrFunc::Len), vec![conv(text("abc", 3), w(3))], INT);
    assert_eq!(eval(len), Ok(int_val(3, Elem::Int)));
}

#[test]
fn fast_real_to_dint_matches_arith() {
    let p = simple(vec![var("x", REAL), var("y", REAL), var("d", DINT), var("e", DINT)], {
        let prod = || bin(BinOp::Mul, local(0, REAL), local(1, REAL));
        vec![
            set(Place::Local(2), conv(prod(), DINT), 1),
            set(Place::Local(3), conv(local(0, REAL), DINT), 2),
        ]
    });
    let exe = crate::compile::compile(&p.0, p.1).expect("compiles");
    let mut m = Machine::new(&exe);
    let samples =
        [0.0, -0.0, 0.5, 1.5, 2.5, -2.5, -0.5, 1e9, -3e9, 4.5e15, 3e38, f64::NAN, f64::INFINITY];
    for &x in &samples {
        for &y in &[1.0, -1.0, 3.0, 0.1] {
            let slot = |n| exe.locate(n).expect("var");
            let put = |m: &mut Machine, n, v: f64| {
                write(m.memory_mut(), &exe, &slot(n), &Value::Real(v as f32 as f64, Elem::Real))
            };
            put(&mut m, "x", x).expect("x");
            put(&mut m, "y", y).expect("y");
            m.run_scan(&exe, SysState::default(), BUDGET).expect("runs");
            let xr = arith::from_f64(Elem::Real, x);
            let prod = arith::binary(BinOp::Mul, Elem::Real, xr, arith::from_f64(Elem::Real, y));
            let want = arith::convert(Elem::Real, Elem::DInt, prod.expect("mul"));
            assert_eq!(get(&m, &exe, "d"), arith::to_i128(Elem::DInt, want), "{x} * {y}");
            let want = arith::convert(Elem::Real, Elem::DInt, xr);
            assert_eq!(get(&m, &exe, "e"), arith::to_i128(Elem::DInt, want), "{x}");
        }
    }
}

#[test]
fn find_is_linear_and_agrees_with_a_plain_search() {
    // FIND (Knuth–Morris–Pratt) against the obvious search, on every pair of short strings
    // over a two-letter alphabet, for STRING and WSTRING characters.
    fn plain(hay: &[u8], needle: &[u8], unit: usize) -> i64 {
        if needle.is_empty() || needle.len() > hay.len() {
            return 0;
        }
        (0..=hay.len() - needle.len())
            .step_by(unit)
            .find(|&i| &hay[i..i + needle.len()] == needle)
            .map_or(0, |i| (i / unit) as i64 + 1)
    }
    let words: Vec<Vec<u8>> = (0..1u32 << 7)
        .flat_map(|bits| {
            (0..=7).map(move |len| (0..len).map(|k| b'a' + ((bits >> k) & 1) as u8).collect())
        })
        .collect();
    let mut table = Vec::new();
    for unit in [1usize, 2] {
        let widen = |w: &Vec<u8>| -> Vec<u8> {
            w.iter()
                .flat_map(|&c| std::iter::once(c).chain(std::iter::repeat_n(0, unit - 1)))
                .collect()
        };
        for h in words.iter().step_by(3) {
            for n in words.iter().step_by(5) {
                let (h, n) = (widen(h), widen(n));
                assert_eq!(
                    super::strings::find(&h, &n, unit, &mut table),
                    plain(&h, &n, unit),
                    "{h:?} {n:?}"
                );
            }
        }
    }
}
