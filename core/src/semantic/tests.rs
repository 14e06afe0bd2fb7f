#![allow(clippy::unwrap_used)]

use super::*;
use crate::diagnostics::{Code, LineIndex};

/// Checks `src` and returns its errors as (code, line, column).
fn errors(src: &str) -> Vec<(Code, u32, u32)> {
    let index = LineIndex::new(src);
    analyze(src)
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let l = index.location(d.span.start);
            (d.code, l.line, l.column)
        })
        .collect()
}

/// Every diagnostic of an analysis of `src` (warnings too) as (code, line, column).
fn located(src: &str, a: &Analysis) -> Vec<(Code, u32, u32)> {
    let index = LineIndex::new(src);
    a.diagnostics
        .iter()
        .map(|d| {
            let l = index.location(d.span.start);
            (d.code, l.line, l.column)
        })
        .collect()
}

fn program(body: &str) -> String {
    format!(
        "PROGRAM P\nVAR i : INT; s : SINT; d : DINT; r : REAL; b : BOOL; w : WORD; t : TON; str : STRING[5]; END_VAR\n{body}\nEND_PROGRAM\n"
    )
}

#[test]
fn the_prelude_checks_clean() {
    let a = analyze("PROGRAM P END_PROGRAM");
    assert!(a.diagnostics.is_empty(), "{:?}", a.diagnostics);
    let p = a.program.unwrap();
    for fb in ["TON", "TOF", "TP", "RTO", "CTU", "CTD", "CTUD", "R_TRIG", "F_TRIG", "SR", "RS"] {
        assert!(p.find_pou(fb).is_some(), "{fb}");
    }
}

#[test]
fn names_are_case_insensitive() {
    assert_eq!(errors(&program("I := 1; STR := 'ab'; T(in := B, pt := t#1s); b := T.q;")), vec![]);
}

#[test]
fn each_error_is_located() {
    assert_eq!(errors(&program("i := d;")), vec![(Code::TypeMismatch, 3, 6)]);
    assert_eq!(errors(&program("s := 300;")), vec![(Code::ConstantOutOfRange, 3, 6)]);
    assert_eq!(errors(&program("x := 1;")), vec![(Code::UndeclaredName, 3, 1)]);
    assert_eq!(errors(&program("IF i THEN END_IF;")), vec![(Code::ConditionNotBool, 3, 4)]);
    assert_eq!(errors(&program("EXIT;")), vec![(Code::ExitOutsideLoop, 3, 1)]);
    assert_eq!(errors(&program("i := NOPE(1);")), vec![(Code::UnknownFunction, 3, 6)]);
    assert_eq!(errors(&program("i := i / 0;")), vec![(Code::DivisionByZeroConstant, 3, 10)]);
    assert_eq!(
        errors(&program("FOR i := 1 TO 5 BY 0 DO END_FOR;")),
        vec![(Code::ZeroForStep, 3, 20)]
    );
    assert_eq!(errors(&program("b := w.16;")), vec![(Code::BitOutOfRange, 3, 6)]);
    assert_eq!(errors(&program("t.Q := TRUE;")), vec![(Code::NotAssignable, 3, 1)]);
    assert_eq!(errors(&program("i := t(IN := TRUE);")), vec![(Code::FbCalledAsFunction, 3, 6)]);
    assert_eq!(
        errors(&program("CASE i OF 1: ; 1..3: ; END_CASE;")),
        vec![(Code::DuplicateCaseLabel, 3, 16)]
    );
    assert_eq!(errors(&program("FST_SCN := TRUE;")), vec![(Code::AssignToConstant, 3, 1)]);
}

#[test]
fn widening_is_implicit_and_narrowing_is_not() {
    assert_eq!(errors(&program("d := i; d := s; r := i; w := 255; i := s * 2;")), vec![]);
    assert_eq!(errors(&program("i := r;")), vec![(Code::TypeMismatch, 3, 6)]);
    assert_eq!(errors(&program("r := i * 1.5;")), vec![], "an untyped real literal adapts to REAL");
    assert_eq!(errors(&program("i := REAL_TO_INT(r); s := INT_TO_SINT(i);")), vec![]);
}

#[test]
fn literals_adapt_to_their_context() {
    assert_eq!(errors(&program("s := -128; w := 16#FFFF; i := 2#0111_1111_1111_1111;")), vec![]);
    assert_eq!(errors(&program("w := 16#10000;")), vec![(Code::ConstantOutOfRange, 3, 6)]);
    assert_eq!(errors(&program("i := INT#40000;")), vec![(Code::ConstantOutOfRange, 3, 6)]);
}

#[test]
fn declarations_are_checked() {
    let src = "TYPE A : STRUCT x : B; END_STRUCT; B : STRUCT y : A; END_STRUCT; END_TYPE
PROGRAM P VAR a : A; END_VAR END_PROGRAM";
    assert!(errors(src).iter().any(|e| e.0 == Code::RecursiveType), "{:?}", errors(src));
    let src =
        "PROGRAM P VAR x : Nope; y : ARRAY[5..1] OF INT; x2 AT %IX0.0 : INT; END_VAR END_PROGRAM";
    let codes: Vec<Code> = errors(src).into_iter().map(|e| e.0).collect();
    assert_eq!(codes, vec![Code::UnknownType, Code::InvalidRange, Code::InvalidLocation]);
    let src = "FUNCTION F : INT VAR_INPUT a : INT; END_VAR F := G(a); END_FUNCTION
FUNCTION G : INT VAR_INPUT a : INT; END_VAR G := F(a); END_FUNCTION
PROGRAM P END_PROGRAM";
    assert!(errors(src).iter().any(|e| e.0 == Code::RecursiveCall));
    let src = "PROGRAM P VAR CONSTANT N : INT := 3; END_VAR VAR a : ARRAY[1..N] OF INT; END_VAR a[N] := 1; a[4] := 2; END_PROGRAM";
    assert_eq!(errors(src), vec![(Code::ConstantIndexOutOfRange, 1, 95)]);
}

#[test]
fn calls_bind_formal_and_informal_arguments() {
    let src = "FUNCTION F : INT VAR_INPUT a : INT; b : INT := 10; END_VAR F := a - b; END_FUNCTION
PROGRAM P VAR x : INT; q : BOOL; t : TON; END_VAR
x := F(1, 2); x := F(b := 1, a := 2); x := F(a := 1);
t(IN := TRUE, PT := T#1s, Q => q);
END_PROGRAM";
    assert_eq!(errors(src), vec![]);
    let bad = "FUNCTION F : INT VAR_INPUT a : INT; END_VAR F := a; END_FUNCTION
PROGRAM P VAR x : INT; t : TON; END_VAR
x := F(1, 2);
x := F(1, a := 2);
x := F(c := 1);
t(IN := TRUE, ET := T#1s);
END_PROGRAM";
    let codes: Vec<Code> = errors(bad).into_iter().map(|e| e.0).collect();
    assert_eq!(
        codes,
        vec![
            Code::WrongArgumentCount,
            Code::MixedArguments,
            Code::NoSuchParameter,
            Code::NoSuchParameter
        ]
    );
}

#[test]
fn conditions_and_values_check_in_a_program_scope() {
    let a = analyze(&program(""));
    let p = a.program.unwrap();
    let main = p.find_pou("P").unwrap();
    assert!(check_condition(&p, main, "i > 80 AND b").is_ok());
    assert!(check_condition(&p, main, "i + 1").is_err());
    assert_eq!(
        parse_value(&p, main, Type::Elem(Elem::Int), "-42"),
        Ok(InitValue::Scalar(-42i64 as u64))
    );
    assert_eq!(
        parse_value(&p, main, Type::Elem(Elem::Time), "T#1s"),
        Ok(InitValue::Scalar(1_000_000_000))
    );
    assert!(parse_value(&p, main, Type::Elem(Elem::Int), "i").is_err());
    assert!(parse_value(&p, main, Type::Elem(Elem::SInt), "300").is_err());
}

#[test]
fn a_name_declared_twice_is_found_in_any_case_across_blocks() {
    // The duplicate in a later block (other case) is reported where it is written, and the
    // body's names resolve to the first declaration (INT, so 40000 does not fit).
    let src = "PROGRAM P\nVAR_INPUT Level : INT; END_VAR\nVAR level : REAL; x : INT; X : BOOL; END_VAR\nLEVEL := 40000;\nEND_PROGRAM\n";
    let errs = errors(src);
    assert!(errs.contains(&(Code::DuplicateDeclaration, 3, 5)), "{errs:?}");
    assert!(errs.contains(&(Code::DuplicateDeclaration, 3, 28)), "{errs:?}");
    assert!(errs.contains(&(Code::ConstantOutOfRange, 4, 10)), "{errs:?}");
}

#[test]
fn an_enum_value_expected_wins_over_a_variable_of_another_type() {
    let src = "TYPE Mode_t : (HAND, AUTO); END_TYPE\nPROGRAM P\nVAR_INPUT Hand : BOOL; END_VAR\nVAR m : Mode_t := AUTO; b : BOOL; END_VAR\nm := HAND;\nb := hand;\nEND_PROGRAM\n";
    let a = analyze(src);
    assert!(a.program.is_some(), "{:?}", a.diagnostics);
    let warned = located(src, &a);
    // Only where a Mode_t is expected; `b := hand` reads the BOOL input.
    assert_eq!(warned, vec![(Code::VariableShadowsEnumValue, 5, 6)]);
    let mut sim = crate::sim::Simulator::new(
        a.program.clone().unwrap(),
        a.program.as_ref().unwrap().find_pou("P").unwrap(),
    )
    .unwrap();
    sim.hold("Hand", "TRUE").unwrap();
    sim.scan();
    assert_eq!(crate::export::value_text(&sim.read("m").unwrap()), "HAND");
    assert_eq!(sim.read("b").unwrap(), crate::vm::Value::Bool(true));
}

#[test]
fn the_first_statement_after_return_exit_or_continue_is_unreachable() {
    let src = "PROGRAM P\nVAR i : INT; n : INT; END_VAR\nFOR i := 1 TO 3 DO\n    IF i = 2 THEN CONTINUE; n := 0; END_IF;\n    EXIT;\n    n := n + 1;\nEND_FOR;\nRETURN;\nn := 5;\nn := 6;\nEND_PROGRAM\n";
    let a = analyze(src);
    assert!(a.program.is_some(), "{:?}", a.diagnostics);
    let found = located(src, &a);
    // One warning per list, at its first unreachable statement; a CONTINUE inside an IF
    // does not make what follows the IF unreachable.
    assert_eq!(
        found,
        vec![
            (Code::UnreachableCode, 4, 29),
            (Code::UnreachableCode, 6, 5),
            (Code::UnreachableCode, 9, 1)
        ]
    );
}

#[test]
fn a_case_of_200000_labels_checks_and_still_finds_overlaps() {
    // Issue 11: the overlap test compared every label with every earlier one (quadratic:
    // minutes for 200,000 labels). Labels 0, 2, 4, … with one range overlapping near the end.
    let mut src = String::from("PROGRAM Main VAR x, y : DINT; END_VAR\nCASE x OF\n");
    for k in 0..200_000 {
        src.push_str(&format!("{}: y := {k};\n", 2 * k));
    }
    src.push_str("399997..399999: y := 0;\nEND_CASE;\nEND_PROGRAM\n");
    let errs = errors(&src);
    assert_eq!(errs, vec![(Code::DuplicateCaseLabel, 200_003, 1)]);
}

#[test]
fn a_function_writing_its_input_is_a_warning_and_constants_stay_errors() {
    let src = "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nVAR CONSTANT k : INT := 1; END_VAR\na := 2;\nk := 3;\nF := a;\nEND_FUNCTION\n";
    let a = analyze(src);
    assert_eq!(
        located(src, &a),
        vec![(Code::FunctionInputWritten, 4, 1), (Code::AssignToConstant, 5, 1)]
    );
}

#[test]
fn zero_and_one_are_bool_literals_beside_a_bool() {
    assert_eq!(
        errors(&program("b := b = 1; b := 0 <> b; b := b AND 1; b := 1; b := b OR 0;")),
        vec![]
    );
    assert_eq!(errors(&program("b := b = 2;")), vec![(Code::OperatorTypeMismatch, 3, 6)]);
    assert_eq!(errors(&program("b := i = 1;")), vec![], "an INT compared with 1 stays an INT");
}

#[test]
fn il_carries_a_current_result_of_every_elementary_type() {
    // The IL lowering (on the text floor, below the types) keeps its own list of names.
    let names: Vec<&str> = super::Elem::ALL.iter().map(|e| e.name()).collect();
    assert_eq!(crate::il::ELEMENTARY.to_vec(), names);
}

/// The first error of `src`: its message, suggestion and implied type.
fn first_error(src: &str) -> crate::diagnostics::Diagnostic {
    analyze(src).diagnostics.into_iter().find(|d| d.is_error()).expect("an error")
}

#[test]
fn a_narrowing_says_what_does_not_convert_and_how_to_convert_it() {
    let d = first_error(&program("i := r;"));
    assert_eq!(d.code, Code::TypeMismatch);
    assert_eq!(
        d.message,
        "REAL does not convert to INT without possible loss: convert it explicitly with REAL_TO_INT(…)"
    );
    let d = first_error(&program("s := i;"));
    assert_eq!(
        d.message,
        "INT does not convert to SINT without possible loss: convert it explicitly with INT_TO_SINT(…)"
    );
    // Not two numbers: only what was expected and found.
    assert_eq!(
        first_error(&program("i := b;")).message,
        "expected a value of type INT, found BOOL"
    );
}

#[test]
fn an_unknown_name_close_to_a_declared_one_gets_did_you_mean() {
    let d = first_error(&program("Bb := TRUE; strr := 'x';"));
    // Two letters: no hint (every short name is one edit from many).
    assert_eq!(d.message, "`Bb` is not declared");
    assert_eq!(d.suggestion, None);
    let src =
        "PROGRAM Main\nVAR_INPUT Start, Stop : BOOL; END_VAR\nVAR_OUTPUT Motor : BOOL; END_VAR\n\
               Motr := (Start OR Motor) AND NOT Stop;\nEND_PROGRAM\n";
    let d = first_error(src);
    assert_eq!(d.message, "`Motr` is not declared; did you mean Motor?");
    assert_eq!(d.suggestion.as_deref(), Some("Motor"));
    assert_eq!(&src[d.span.start as usize..d.span.end as usize], "Motr", "the span is the name");
    assert_eq!(d.implied_type.as_deref(), Some("BOOL"), "the value stored tells the type");
    // Case-insensitive, spelled as declared; the first declared wins a tie.
    let d =
        first_error("PROGRAM P\nVAR Lamp1, Lamp2 : BOOL; END_VAR\nlamp := TRUE;\nEND_PROGRAM\n");
    assert_eq!(d.suggestion.as_deref(), Some("Lamp1"));
    // Globals, enumeration values and system variables are in scope too.
    let d =
        first_error("VAR_GLOBAL Counter : INT; END_VAR\nPROGRAM P\nCountr := 1;\nEND_PROGRAM\n");
    assert_eq!(d.suggestion.as_deref(), Some("Counter"));
    assert_eq!(d.implied_type.as_deref(), Some("INT"), "an untyped integer is an INT");
    let d = first_error(
        "TYPE Mode : (Idle, Running); END_TYPE\nPROGRAM P\nVAR m : Mode; END_VAR\nm := Runing;\nEND_PROGRAM\n",
    );
    assert_eq!(d.suggestion.as_deref(), Some("Running"));
    assert_eq!(d.implied_type.as_deref(), Some("Mode"));
    let d = first_error("PROGRAM P\nVAR b : BOOL; END_VAR\nb := FST_SCAN;\nEND_PROGRAM\n");
    assert_eq!(d.suggestion.as_deref(), Some("FST_SCN"));
    // Nothing close: the message alone.
    let d = first_error(&program("i := Pressure;"));
    assert_eq!((d.message.as_str(), d.suggestion), ("`Pressure` is not declared", None));
    assert_eq!(d.implied_type.as_deref(), Some("INT"), "the target's type");
}

#[test]
fn a_condition_implies_bool_and_nothing_is_implied_where_nothing_is_known() {
    let d = first_error(&program("IF Ready THEN i := 1; END_IF;"));
    assert_eq!(d.implied_type.as_deref(), Some("BOOL"));
    let d = first_error(&program("r := Gain * 2.5;"));
    assert_eq!(d.implied_type.as_deref(), Some("REAL"));
    let d = first_error(&program("Limit := 2.5;"));
    assert_eq!(d.implied_type.as_deref(), Some("REAL"));
    let d = first_error(&program("Big := 100000;"));
    assert_eq!(d.implied_type.as_deref(), Some("DINT"), "as large as the value needs");
}

#[test]
fn members_parameters_functions_and_types_get_did_you_mean() {
    let d = first_error(&program("t(IN := b, PT := T#1s); i := TIME_TO_INT(t.EET);"));
    assert_eq!(d.code, Code::NoSuchMember);
    assert_eq!(d.message, "`TON` has no member `EET`; did you mean ET?");
    let d = first_error(&program("t(IN := b, PT := T#1s); b := t.Done;"));
    assert_eq!(d.message, "`TON` has no member `Done`; it has IN, PT, Q, ET");
    let d = first_error(&program("t(IN := b, PTT := T#1s);"));
    assert_eq!((d.code, d.suggestion.as_deref()), (Code::NoSuchParameter, Some("PT")));
    let d = first_error(&program("r := SQTR(r);"));
    assert_eq!((d.code, d.suggestion.as_deref()), (Code::UnknownFunction, Some("SQRT")));
    let d = first_error(&program("i := REAL_TO_IN(r);"));
    assert_eq!(d.suggestion.as_deref(), Some("REAL_TO_INT"));
    let d = first_error("PROGRAM P\nVAR x : BOLL; END_VAR\nEND_PROGRAM\n");
    assert_eq!(
        (d.code, d.message.as_str()),
        (Code::UnknownType, "unknown type `BOLL`; did you mean BOOL?")
    );
    let d = first_error(
        "TYPE Valve : STRUCT open : BOOL; END_STRUCT; END_TYPE\nPROGRAM P\nVAR v : Vlave; END_VAR\nEND_PROGRAM\n",
    );
    assert_eq!(d.suggestion.as_deref(), Some("Valve"));
    let d = first_error(
        "TYPE Mode : (Idle, Running); END_TYPE\nPROGRAM P\nVAR m : Mode; END_VAR\nm := Mode#Runing;\nEND_PROGRAM\n",
    );
    assert_eq!(d.message, "`Mode` has no value `Runing`; did you mean Running?");
}

#[test]
fn var_config_paths_get_did_you_mean() {
    let src = "FUNCTION_BLOCK Valve\nVAR_OUTPUT Open AT %Q* : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n\
               PROGRAM Cell\nVAR Inlet : Valve; END_VAR\nInlet();\nEND_PROGRAM\n\
               CONFIGURATION Plant\nPROGRAM Line : Cell;\nVAR_CONFIG\n\
               Line.Inlte.Open AT %QX0.0 : BOOL;\nEND_VAR\nEND_CONFIGURATION\n";
    let d = first_error(src);
    assert_eq!(
        (d.code, d.message.as_str()),
        (Code::BadConfigVar, "`Cell` has no `Inlte`; did you mean Inlet?")
    );
    assert_eq!(d.suggestion.as_deref(), Some("Inlet"));
    let d = first_error(&src.replace("Line.Inlte", "Lien.Inlet"));
    assert_eq!(d.suggestion.as_deref(), Some("Line"));
}

#[test]
fn sfc_steps_actions_and_guards_get_did_you_mean() {
    let src =
        "PROGRAM P\nVAR go : BOOL; Pump : BOOL; END_VAR\nINITIAL_STEP Idle : Pmup(N); END_STEP\n\
               TRANSITION FROM Idle TO Filing := go; END_TRANSITION\nSTEP Filling : END_STEP\n\
               TRANSITION FROM Filling TO Idle := goo; END_TRANSITION\nEND_PROGRAM\n";
    let errs: Vec<(Code, String)> = analyze(src)
        .diagnostics
        .into_iter()
        .filter(|d| d.is_error())
        .map(|d| (d.code, d.message))
        .collect();
    assert!(
        errs.contains(&(
            Code::SfcUnknownAction,
            "`Pmup` is neither an ACTION of this chart nor a variable; did you mean Pump?".into()
        )),
        "{errs:?}"
    );
    assert!(
        errs.contains(&(
            Code::SfcUnknownStep,
            "there is no step `Filing` in this chart; did you mean Filling?".into()
        )),
        "{errs:?}"
    );
}

#[test]
fn an_output_written_to_the_wrong_place_names_the_output_and_the_target() {
    // Was "output `ET` is TIME but `the target` is INT".
    let d = first_error(&program("t(IN := b, PT := T#1s, ET => i);"));
    assert_eq!(d.code, Code::TypeMismatch);
    assert_eq!(d.message, "the output `ET` is TIME, but `i` is INT: an output is written to a variable of its own type");
    let d = first_error(&program("t(IN := b, PT := T#1s, NOT ET => r);"));
    assert_eq!(d.message, "the output `ET` is TIME, but `r` is REAL: an output is written to a variable of its own type");
    // Was "`Q` is VAR_IN_OUT: …" though Q is an output.
    let d = first_error(&program("t(IN := b, PT := T#1s, Q => w.3);"));
    assert_eq!(d.code, Code::InOutNotVariable);
    assert_eq!(
        d.message,
        "the output `Q` is written to a whole variable, not to a bit or a located variable (a part of the process image): write it to a variable, then copy that"
    );
}
