//! What every problem code means, how to fix it, and a wrong and a right example: what
//! `plc explain CODE` prints and what `docs/problems.md` (and the site's `problems.html`,
//! which the problem list links to) are generated from. A test runs every ST example
//! through the checker: the wrong one must give its code, the right one must not.

use super::Code;

/// An example of a problem, or of its fix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Example {
    /// An ST program, run as `plc run` runs it (`program` chooses the PROGRAM, `set` is one
    /// `--set VAR=VALUE`).
    St {
        /// The source.
        source: &'static str,
        /// `--program`.
        program: Option<&'static str>,
        /// One `--set VAR=VALUE`.
        set: Option<(&'static str, &'static str)>,
    },
    /// A ladder rung or a Petri net, described in words and rung pictures (their checks
    /// have their own tests, on models).
    Drawn(&'static str),
}

/// The explanation of one code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Explanation {
    /// The code.
    pub code: Code,
    /// What it means and how to fix it.
    pub text: &'static str,
    /// Something that gives the code.
    pub wrong: Example,
    /// The same, fixed.
    pub right: Example,
}

const fn st(source: &'static str) -> Example {
    Example::St { source, program: None, set: None }
}

const fn drawn(text: &'static str) -> Example {
    Example::Drawn(text)
}

macro_rules! explanations {
    ($( $code:ident : $text:literal, $wrong:expr, $right:expr; )*) => {
        /// Every explanation, in the order of the code table.
        pub const EXPLANATIONS: &[Explanation] = &[
            $( Explanation { code: Code::$code, text: $text, wrong: $wrong, right: $right }, )*
        ];
    };
}

impl Code {
    /// The explanation of this code, with its examples.
    pub fn explanation(self) -> Option<&'static Explanation> {
        EXPLANATIONS.iter().find(|e| e.code == self)
    }
}

explanations! {
    UnexpectedCharacter: "The text holds a character that no ST token starts with, such as `$`, `?` or `\"` outside a string. Remove it, or put it inside a comment or a string.",
        st("PROGRAM Main VAR x : INT; END_VAR x := 1 ? 2; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := 1 + 2; END_PROGRAM");
    UnterminatedComment: "A `(*` comment (or `/*`) runs to the end of the text: its closing `*)` is missing.",
        st("PROGRAM Main VAR x : INT; END_VAR (* count x := 1; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR (* count *) x := 1; END_PROGRAM");
    UnterminatedString: "A string literal has no closing quote on its line. Close it with the same quote it opened with (`'` for STRING, `\"` for WSTRING).",
        st("PROGRAM Main VAR s : STRING; END_VAR s := 'hello;\nEND_PROGRAM"),
        st("PROGRAM Main VAR s : STRING; END_VAR s := 'hello';\nEND_PROGRAM");
    InvalidNumber: "A number is written in a way ST does not accept: a base other than 2, 8 or 16, digits that do not belong to the base, or an exponent without digits.",
        st("PROGRAM Main VAR x : INT; END_VAR x := 2#102; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := 2#101; END_PROGRAM");
    InvalidTimeLiteral: "A duration after `T#` (or `TIME#`) is malformed. Write units from days to milliseconds: `T#1h30m`, `T#2s`, `T#250ms`.",
        st("PROGRAM Main VAR t : TIME; END_VAR t := T#2x; END_PROGRAM"),
        st("PROGRAM Main VAR t : TIME; END_VAR t := T#2s; END_PROGRAM");
    UnexpectedToken: "The parser found something that cannot stand here: often a missing `;`, `THEN`, `DO` or `:=`, or `=` written for an assignment. The message says what was expected.",
        st("PROGRAM Main VAR x : INT; END_VAR IF x > 1 x := 0; END_IF; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR IF x > 1 THEN x := 0; END_IF; END_PROGRAM");
    MissingEnd: "A block is opened and never closed: `IF` needs `END_IF`, `CASE` `END_CASE`, `FOR` `END_FOR`, `VAR` `END_VAR`, `PROGRAM` `END_PROGRAM`.",
        st("PROGRAM Main VAR x : INT; END_VAR IF x > 1 THEN x := 0; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR IF x > 1 THEN x := 0; END_IF; END_PROGRAM");
    InvalidEscape: "In a string, `$` starts an escape: `$$`, `$'`, `$L`, `$N`, `$P`, `$R`, `$T` or two hex digits. Any other letter after `$` is an error; write `$$` for a dollar sign.",
        st("PROGRAM Main VAR s : STRING; END_VAR s := 'cost: 5$Q'; END_PROGRAM"),
        st("PROGRAM Main VAR s : STRING; END_VAR s := 'cost: 5$$'; END_PROGRAM");
    InvalidDirectAddress: "A directly represented variable is malformed. It is `%` + `I`, `Q` or `M` + a size (`X` bit, `B`, `W`, `D`, `L`; none means bit) + numbers: `%IX0.3`, `%QW2`, `%MD10`.",
        st("PROGRAM Main VAR b AT %IZ0.1 : BOOL; x : BOOL; END_VAR x := b; END_PROGRAM"),
        st("PROGRAM Main VAR b AT %IX0.1 : BOOL; x : BOOL; END_VAR x := b; END_PROGRAM");
    InvalidDateLiteral: "A date or time-of-day literal is malformed or out of range: `D#2024-02-30` is not a date. Write `D#YYYY-MM-DD`, `TOD#hh:mm:ss`, `DT#YYYY-MM-DD-hh:mm:ss`.",
        st("PROGRAM Main VAR d : DATE; END_VAR d := D#2024-02-30; END_PROGRAM"),
        st("PROGRAM Main VAR d : DATE; END_VAR d := D#2024-02-29; END_PROGRAM");
    InvalidIdentifier: "IEC 61131-3 names may not end with `_` or hold two `_` in a row.",
        st("PROGRAM Main VAR motor__on : BOOL; END_VAR motor__on := TRUE; END_PROGRAM"),
        st("PROGRAM Main VAR motor_on : BOOL; END_VAR motor_on := TRUE; END_PROGRAM");
    IntegerLiteralTooLarge: "An integer literal is larger than the largest integer type (ULINT, 18446744073709551615).",
        st("PROGRAM Main VAR x : ULINT; END_VAR x := 99999999999999999999; END_PROGRAM"),
        st("PROGRAM Main VAR x : ULINT; END_VAR x := 9999999999999999999; END_PROGRAM");
    InvalidTypedLiteral: "A type prefix does not fit its literal: `BOOL#5`, `INT#1.5`, `REAL#TRUE`. Use the prefix of a type that can hold the value.",
        st("PROGRAM Main VAR x : INT; END_VAR x := INT#1.5; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := INT#15; END_PROGRAM");
    TooComplex: "The program nests or chains further than the trainer allows (100 levels of nesting, 100 operators or steps in one expression, 64 levels of types inside types; XML files 200 elements deep). Split the expression over several statements, or flatten the types.",
        st("PROGRAM Main VAR x : INT; END_VAR x := ((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((1)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))); END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := (((1))); END_PROGRAM");
    UndeclaredName: "The name is not declared where it is used: declare it in a VAR block of the POU (or as VAR_GLOBAL), or check its spelling. When a declared name is one or two letters away, the message asks `did you mean NAME?` and the problem list offers `Replace with NAME`; `Declare NAME` adds the declaration to the POU that uses the name (an input when the POU only reads it, an output when it writes it) with the type its use implies (BOOL when nothing tells).",
        st("PROGRAM Main VAR_INPUT Start : BOOL; END_VAR VAR_OUTPUT Motor : BOOL; END_VAR Motr := Start; END_PROGRAM"),
        st("PROGRAM Main VAR_INPUT Start : BOOL; END_VAR VAR_OUTPUT Motor : BOOL; END_VAR Motor := Start; END_PROGRAM");
    DuplicateDeclaration: "The same name is declared twice in one scope (names are case-insensitive: `Motor` and `MOTOR` are one name). Rename or remove one.",
        st("PROGRAM Main VAR x : INT; X : BOOL; END_VAR x := 1; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; y : BOOL; END_VAR x := 1; y := TRUE; END_PROGRAM");
    UnknownType: "A variable is declared with a type that is neither elementary nor declared in a TYPE block or as a FUNCTION_BLOCK. A type name one or two letters away is named in the message (`did you mean BOOL?`).",
        st("PROGRAM Main VAR x : INTEGER; END_VAR x := 1; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := 1; END_PROGRAM");
    NotAVariable: "A name that is a type, a POU or an enumerator is used where a variable is needed.",
        st("PROGRAM Main VAR x : INT; END_VAR x := TON; END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; x : TIME; END_VAR t(IN := TRUE, PT := T#1s); x := t.ET; END_PROGRAM");
    NoSuchMember: "A struct has no field, or a function block no input or output, of that name. The message names the closest member (`did you mean ET?`) or lists the members there are.",
        st("PROGRAM Main VAR t : TON; b : BOOL; END_VAR t(IN := TRUE, PT := T#1s); b := t.Done; END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; b : BOOL; END_VAR t(IN := TRUE, PT := T#1s); b := t.Q; END_PROGRAM");
    NoProgram: "There is nothing to run: the source holds FUNCTIONs or FUNCTION_BLOCKs but no PROGRAM (or the project has errors, listed first).",
        st("FUNCTION_BLOCK Blink VAR_OUTPUT q : BOOL; END_VAR q := NOT q; END_FUNCTION_BLOCK"),
        st("FUNCTION_BLOCK Blink VAR_OUTPUT q : BOOL; END_VAR q := NOT q; END_FUNCTION_BLOCK PROGRAM Main VAR b : Blink; END_VAR b(); END_PROGRAM");
    UnknownProgram: "The PROGRAM chosen to run (`plc run --program NAME`, or the project's setting) is not in the source.",
        Example::St { source: "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM", program: Some("Mian"), set: None },
        Example::St { source: "PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM", program: Some("Main"), set: None };
    RecursiveCall: "A POU calls itself, directly or through others. PLC code does not recurse (every POU has one static frame): use a loop instead.",
        st("FUNCTION Ping : INT VAR_INPUT n : INT; END_VAR Ping := Pong(n - 1); END_FUNCTION FUNCTION Pong : INT VAR_INPUT n : INT; END_VAR Pong := Ping(n - 1); END_FUNCTION PROGRAM Main VAR x : INT; END_VAR x := Ping(5); END_PROGRAM"),
        st("FUNCTION Fact : DINT VAR_INPUT n : DINT; END_VAR VAR i : DINT; END_VAR Fact := 1; FOR i := 2 TO n DO Fact := Fact * i; END_FOR; END_FUNCTION PROGRAM Main VAR x : DINT; END_VAR x := Fact(5); END_PROGRAM");
    RecursiveType: "A type contains itself, directly or through other types, so it would be infinitely large.",
        st("TYPE Node : STRUCT value : INT; next : Node; END_STRUCT; END_TYPE PROGRAM Main VAR n : Node; END_VAR n.value := 1; END_PROGRAM"),
        st("TYPE Node : STRUCT value : INT; next : INT; END_STRUCT; END_TYPE PROGRAM Main VAR n : Node; END_VAR n.value := 1; END_PROGRAM");
    ExternalWithoutGlobal: "A VAR_EXTERNAL names a variable that no VAR_GLOBAL declares. Declare it in a VAR_GLOBAL block with the same type.",
        st("PROGRAM Main VAR_EXTERNAL count : INT; END_VAR count := count + 1; END_PROGRAM"),
        st("VAR_GLOBAL count : INT; END_VAR PROGRAM Main VAR_EXTERNAL count : INT; END_VAR count := count + 1; END_PROGRAM");
    InvalidLocation: "An AT location does not fit the variable: a bit address (`%IX`) needs a BOOL, a word address (`%IW`) a 16-bit type, and so on.",
        st("PROGRAM Main VAR level AT %IX0.1 : INT; x : INT; END_VAR x := level; END_PROGRAM"),
        st("PROGRAM Main VAR level AT %IW1 : INT; x : INT; END_VAR x := level; END_PROGRAM");
    DuplicateEnumerator: "One enumeration type lists the same value twice.",
        st("TYPE Mode : (Off, Run, Off); END_TYPE PROGRAM Main VAR m : Mode; END_VAR m := Run; END_PROGRAM"),
        st("TYPE Mode : (Off, Run, Fault); END_TYPE PROGRAM Main VAR m : Mode; END_VAR m := Run; END_PROGRAM");
    SectionNotAllowed: "A VAR_GLOBAL block stands in a FUNCTION or a FUNCTION_BLOCK. Global variables are declared at the top level of the file or in a PROGRAM; a FUNCTION_BLOCK that uses one names it in a VAR_EXTERNAL block.",
        st("FUNCTION_BLOCK Counter VAR_GLOBAL total : INT; END_VAR total := total + 1; END_FUNCTION_BLOCK PROGRAM Main VAR c : Counter; END_VAR c(); END_PROGRAM"),
        st("VAR_GLOBAL total : INT; END_VAR FUNCTION_BLOCK Counter VAR_EXTERNAL total : INT; END_VAR total := total + 1; END_FUNCTION_BLOCK PROGRAM Main VAR c : Counter; END_VAR c(); END_PROGRAM");
    TypeMismatch: "A value of one type is used where another is needed and ST does not convert it by itself: only conversions that cannot lose anything are implicit (SINT to INT, INT to REAL). Between two number types the message names the conversion function to write (`REAL does not convert to INT without possible loss: convert it explicitly with REAL_TO_INT(…)`).",
        st("PROGRAM Main VAR i : INT; r : REAL := 2.5; END_VAR i := r; END_PROGRAM"),
        st("PROGRAM Main VAR i : INT; r : REAL := 2.5; END_VAR i := REAL_TO_INT(r); END_PROGRAM");
    NotAssignable: "The left side of `:=` is not a variable: a literal, an expression, a function call or a constant enumerator cannot be written.",
        st("PROGRAM Main VAR t : TON; END_VAR t.Q := TRUE; END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; END_VAR t(IN := TRUE, PT := T#1s); END_PROGRAM");
    AssignToConstant: "The target is read-only: a VAR CONSTANT or a system variable such as `FST_SCN`.",
        st("PROGRAM Main VAR CONSTANT limit : INT := 10; END_VAR limit := 20; END_PROGRAM"),
        st("PROGRAM Main VAR limit : INT := 10; END_VAR limit := 20; END_PROGRAM");
    OperatorTypeMismatch: "The operator does not accept these operand types: arithmetic needs numbers (or TIME), `AND`/`OR` need BOOL or bit strings, both sides must have the same type family.",
        st("PROGRAM Main VAR b : BOOL; x : INT; END_VAR x := b + 1; END_PROGRAM"),
        st("PROGRAM Main VAR b : BOOL; x : INT; END_VAR x := BOOL_TO_INT(b) + 1; END_PROGRAM");
    ConditionNotBool: "The condition of IF, ELSIF, WHILE or UNTIL must be BOOL. Compare the value explicitly: `IF x <> 0 THEN`.",
        st("PROGRAM Main VAR x : INT; END_VAR IF x THEN x := 0; END_IF; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR IF x <> 0 THEN x := 0; END_IF; END_PROGRAM");
    NotAnArray: "`[ ]` is applied to something that is not an array.",
        st("PROGRAM Main VAR x : INT; y : INT; END_VAR y := x[1]; END_PROGRAM"),
        st("PROGRAM Main VAR x : ARRAY[1..3] OF INT; y : INT; END_VAR y := x[1]; END_PROGRAM");
    WrongIndexCount: "An array is indexed with a different number of subscripts than it has dimensions: `a[i, j]` for a two-dimensional array.",
        st("PROGRAM Main VAR a : ARRAY[1..3, 1..3] OF INT; y : INT; END_VAR y := a[1]; END_PROGRAM"),
        st("PROGRAM Main VAR a : ARRAY[1..3, 1..3] OF INT; y : INT; END_VAR y := a[1, 2]; END_PROGRAM");
    NotAStruct: "`.member` is applied to something without members (an elementary value). For one bit of an integer write `.3`.",
        st("PROGRAM Main VAR x : INT; y : INT; END_VAR y := x.value; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; y : BOOL; END_VAR y := x.3; END_PROGRAM");
    BitOutOfRange: "The bit number is beyond the width of the value: a BYTE has bits 0 to 7, a WORD 0 to 15.",
        st("PROGRAM Main VAR w : BYTE; b : BOOL; END_VAR b := w.9; END_PROGRAM"),
        st("PROGRAM Main VAR w : BYTE; b : BOOL; END_VAR b := w.7; END_PROGRAM");
    NotConstant: "A value that must be known before the program runs (an array bound, a string length, a CASE label, an initial value) uses a variable.",
        st("PROGRAM Main VAR n : INT := 3; x : INT; END_VAR CASE x OF n: x := 0; END_CASE; END_PROGRAM"),
        st("PROGRAM Main VAR CONSTANT n : INT := 3; END_VAR VAR x : INT; END_VAR CASE x OF n: x := 0; END_CASE; END_PROGRAM");
    ConstantOutOfRange: "A constant does not fit the type it is stored in: INT holds -32768 to 32767, SINT -128 to 127, BYTE 0 to 255.",
        st("PROGRAM Main VAR x : SINT; END_VAR x := 200; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := 200; END_PROGRAM");
    ConstantIndexOutOfRange: "A constant index lies outside the array's declared bounds (which need not start at 0).",
        st("PROGRAM Main VAR a : ARRAY[1..3] OF INT; END_VAR a[0] := 5; END_PROGRAM"),
        st("PROGRAM Main VAR a : ARRAY[1..3] OF INT; END_VAR a[1] := 5; END_PROGRAM");
    DivisionByZeroConstant: "A division or MOD by a constant zero would fault on every scan.",
        st("PROGRAM Main VAR x : INT := 10; END_VAR x := x / 0; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT := 10; END_VAR x := x / 2; END_PROGRAM");
    ZeroForStep: "A FOR loop with `BY 0` never ends.",
        st("PROGRAM Main VAR i, s : INT; END_VAR FOR i := 1 TO 10 BY 0 DO s := s + i; END_FOR; END_PROGRAM"),
        st("PROGRAM Main VAR i, s : INT; END_VAR FOR i := 1 TO 10 BY 2 DO s := s + i; END_FOR; END_PROGRAM");
    ForVariableNotInteger: "The control variable of FOR must be a variable of an integer type (not REAL, not an element or a member).",
        st("PROGRAM Main VAR r : REAL; s : REAL; END_VAR FOR r := 1 TO 10 DO s := s + r; END_FOR; END_PROGRAM"),
        st("PROGRAM Main VAR i : INT; s : REAL; END_VAR FOR i := 1 TO 10 DO s := s + INT_TO_REAL(i); END_FOR; END_PROGRAM");
    CaseLabelType: "A CASE label has a different type from the selector: an INT selector takes integer labels, an enumeration selector its values.",
        st("TYPE Mode : (Off, Run); END_TYPE PROGRAM Main VAR x : INT; END_VAR CASE x OF Run: x := 0; END_CASE; END_PROGRAM"),
        st("TYPE Mode : (Off, Run); END_TYPE PROGRAM Main VAR m : Mode; x : INT; END_VAR CASE m OF Run: x := 0; END_CASE; END_PROGRAM");
    DuplicateCaseLabel: "A CASE label (or range) overlaps an earlier one, so its branch can never be chosen for those values.",
        st("PROGRAM Main VAR x, y : INT; END_VAR CASE x OF 1..5: y := 1; 3: y := 2; END_CASE; END_PROGRAM"),
        st("PROGRAM Main VAR x, y : INT; END_VAR CASE x OF 1..5: y := 1; 6: y := 2; END_CASE; END_PROGRAM");
    InvalidRange: "A range's lower limit is above its upper limit: `ARRAY[5..1]`, `INT(10..0)`, a CASE label `9..2`.",
        st("PROGRAM Main VAR a : ARRAY[5..1] OF INT; END_VAR a[3] := 1; END_PROGRAM"),
        st("PROGRAM Main VAR a : ARRAY[1..5] OF INT; END_VAR a[3] := 1; END_PROGRAM");
    ExitOutsideLoop: "EXIT and CONTINUE only work inside FOR, WHILE or REPEAT. To leave a POU early, use RETURN.",
        st("PROGRAM Main VAR x : INT; END_VAR IF x > 3 THEN EXIT; END_IF; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR IF x > 3 THEN RETURN; END_IF; END_PROGRAM");
    SubrangeViolation: "A constant lies outside the subrange declared for the variable (`INT(0..100)`).",
        st("PROGRAM Main VAR pct : INT(0..100); END_VAR pct := 150; END_PROGRAM"),
        st("PROGRAM Main VAR pct : INT(0..100); END_VAR pct := 100; END_PROGRAM");
    InvalidArraySize: "An array or string is too large for the simulator (more than 4,194,304 elements, or STRING longer than 65,535), or its bounds are not usable.",
        st("PROGRAM Main VAR s : STRING[100000]; END_VAR s := 'x'; END_PROGRAM"),
        st("PROGRAM Main VAR s : STRING[1000]; END_VAR s := 'x'; END_PROGRAM");
    TooManyInitializers: "An array's initial value lists more elements than the array has.",
        st("PROGRAM Main VAR a : ARRAY[1..3] OF INT := [1, 2, 3, 4]; END_VAR a[1] := 0; END_PROGRAM"),
        st("PROGRAM Main VAR a : ARRAY[1..3] OF INT := [1, 2, 3]; END_VAR a[1] := 0; END_PROGRAM");
    NotAReference: "`r^` reads or writes the variable the reference `r` points to, so `r` must be declared `REF_TO` a type; NULL points nowhere. A NULL reference met while the program runs is a FAULT at that statement.",
        st("PROGRAM Main VAR x : INT; y : INT; END_VAR y := x^; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; r : REF_TO INT; y : INT; END_VAR r := REF(x); y := r^; END_PROGRAM");
    RefNotAVariable: "`REF(x)` takes a whole variable, an array element or a struct field. A single bit has no address of its own, and a write through a reference to a subrange variable would skip its range check. As a reference's initial value (`r : REF_TO INT := REF(x);`), `x` must also have one place for the whole run, known before it runs: a variable of the same POU or a global, with constant indexes; not a VAR_TEMP or a FUNCTION's variable (they exist only while their POU runs), a VAR_IN_OUT, an element chosen by a variable index, or `r^`.",
        st("PROGRAM Main VAR w : WORD; r : REF_TO BOOL; END_VAR r := REF(w.3); END_PROGRAM"),
        st("PROGRAM Main VAR w : WORD; r : REF_TO WORD; END_VAR r := REF(w); END_PROGRAM");
    UnknownFunction: "The name called is neither a standard function, a FUNCTION, nor a function block instance. A close name is suggested (`did you mean SQRT?`).",
        st("PROGRAM Main VAR x : REAL; END_VAR x := SQUARE(2.0); END_PROGRAM"),
        st("PROGRAM Main VAR x : REAL; END_VAR x := EXPT(2.0, 2.0); END_PROGRAM");
    WrongArgumentCount: "A call gives more or fewer arguments than the function takes.",
        st("PROGRAM Main VAR x : INT; END_VAR x := LIMIT(0, x); END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := LIMIT(0, x, 100); END_PROGRAM");
    NoSuchParameter: "A formal argument names a parameter the function or function block does not have.",
        st("PROGRAM Main VAR t : TON; END_VAR t(IN := TRUE, TIME := T#1s); END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; END_VAR t(IN := TRUE, PT := T#1s); END_PROGRAM");
    DuplicateArgument: "One call gives the same parameter twice.",
        st("PROGRAM Main VAR t : TON; END_VAR t(IN := TRUE, IN := FALSE, PT := T#1s); END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; END_VAR t(IN := TRUE, PT := T#1s); END_PROGRAM");
    MixedArguments: "A call mixes positional (informal) arguments with `name :=` (formal) ones. Use one style per call.",
        st("FUNCTION Add2 : INT VAR_INPUT a, b : INT; END_VAR Add2 := a + b; END_FUNCTION PROGRAM Main VAR x : INT; END_VAR x := Add2(1, b := 2); END_PROGRAM"),
        st("FUNCTION Add2 : INT VAR_INPUT a, b : INT; END_VAR Add2 := a + b; END_FUNCTION PROGRAM Main VAR x : INT; END_VAR x := Add2(a := 1, b := 2); END_PROGRAM");
    NotAnOutput: "`=>` takes an output of the callee into a variable; this parameter is an input (use `:=`).",
        st("PROGRAM Main VAR t : TON; b : BOOL; END_VAR t(IN => b, PT := T#1s); END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; b : BOOL; END_VAR t(IN := TRUE, PT := T#1s, Q => b); END_PROGRAM");
    InOutNotVariable: "A VAR_IN_OUT parameter is passed by reference, so its argument must be a variable, not an expression or a literal.",
        st("FUNCTION Inc : BOOL VAR_IN_OUT v : INT; END_VAR v := v + 1; Inc := TRUE; END_FUNCTION PROGRAM Main VAR x : INT; ok : BOOL; END_VAR ok := Inc(v := x + 1); END_PROGRAM"),
        st("FUNCTION Inc : BOOL VAR_IN_OUT v : INT; END_VAR v := v + 1; Inc := TRUE; END_FUNCTION PROGRAM Main VAR x : INT; ok : BOOL; END_VAR ok := Inc(v := x); END_PROGRAM");
    MissingInOut: "Every VAR_IN_OUT parameter must be given in a call: there is no value to fall back on.",
        st("FUNCTION_BLOCK Acc VAR_IN_OUT total : INT; END_VAR total := total + 1; END_FUNCTION_BLOCK PROGRAM Main VAR a : Acc; END_VAR a(); END_PROGRAM"),
        st("FUNCTION_BLOCK Acc VAR_IN_OUT total : INT; END_VAR total := total + 1; END_FUNCTION_BLOCK PROGRAM Main VAR a : Acc; n : INT; END_VAR a(total := n); END_PROGRAM");
    FbCalledAsFunction: "A function block instance is called as a statement and has no value: call it, then read its outputs (`t(IN := s); q := t.Q;`).",
        st("PROGRAM Main VAR t : TON; q : BOOL; END_VAR q := t(IN := TRUE, PT := T#1s); END_PROGRAM"),
        st("PROGRAM Main VAR t : TON; q : BOOL; END_VAR t(IN := TRUE, PT := T#1s); q := t.Q; END_PROGRAM");
    FunctionBlockInFunction: "A FUNCTION has no memory between calls, so it cannot hold a function block instance (a timer, a counter). Make it a FUNCTION_BLOCK.",
        st("FUNCTION Delay : BOOL VAR t : TON; END_VAR t(IN := TRUE, PT := T#1s); Delay := t.Q; END_FUNCTION PROGRAM Main VAR q : BOOL; END_VAR q := Delay(); END_PROGRAM"),
        st("FUNCTION_BLOCK Delay VAR_OUTPUT q : BOOL; END_VAR VAR t : TON; END_VAR t(IN := TRUE, PT := T#1s); q := t.Q; END_FUNCTION_BLOCK PROGRAM Main VAR d : Delay; q : BOOL; END_VAR d(); q := d.q; END_PROGRAM");
    ProgramCalled: "A PROGRAM is not called from other code: the simulator runs it every scan. Make the called code a FUNCTION_BLOCK.",
        st("PROGRAM Pump VAR on : BOOL; END_VAR on := TRUE; END_PROGRAM PROGRAM Main VAR x : INT; END_VAR Pump(); END_PROGRAM"),
        st("FUNCTION_BLOCK Pump VAR on : BOOL; END_VAR on := TRUE; END_FUNCTION_BLOCK PROGRAM Main VAR p : Pump; END_VAR p(); END_PROGRAM");
    NoReturnValue: "A FUNCTION declared without a result type returns nothing, so it cannot stand in an expression; call it as a statement.",
        st("FUNCTION Beep VAR_INPUT on : BOOL; END_VAR END_FUNCTION PROGRAM Main VAR x : BOOL; END_VAR x := Beep(TRUE); END_PROGRAM"),
        st("FUNCTION Beep VAR_INPUT on : BOOL; END_VAR END_FUNCTION PROGRAM Main VAR x : BOOL; END_VAR Beep(TRUE); END_PROGRAM");
    UnknownSetVariable: "`plc run --set NAME=VALUE` or `--set-at SCAN:NAME=VALUE` (or an input set in the page) names a variable the program does not have, or `plc run --trace NAME` names one it does not have or that is not a single value (a whole array or structure cannot be recorded: name its elements). Names are those of the main PROGRAM, then the globals; members and elements are written `Tank.Level`, `Arr[2]`.",
        Example::St { source: "PROGRAM Main VAR start : BOOL; END_VAR END_PROGRAM", program: None, set: Some(("strat", "TRUE")) },
        Example::St { source: "PROGRAM Main VAR start : BOOL; END_VAR END_PROGRAM", program: None, set: Some(("start", "TRUE")) };
    BadSetValue: "The value given with `--set` or `--set-at` does not fit the variable: write it as an IEC literal of the variable's type (`TRUE`, `42`, `T#2s`, `'text'`).",
        Example::St { source: "PROGRAM Main VAR level : INT; END_VAR END_PROGRAM", program: None, set: Some(("level", "high")) },
        Example::St { source: "PROGRAM Main VAR level : INT; END_VAR END_PROGRAM", program: None, set: Some(("level", "75")) };
    ProgramTooLarge: "The program needs more memory cells than the simulator provides (16 M cells of 64 bits). Make the arrays smaller.",
        st("PROGRAM Main VAR a, b, c, d, e : ARRAY[1..4000000] OF LINT; END_VAR a[1] := 1; END_PROGRAM"),
        st("PROGRAM Main VAR a : ARRAY[1..4000000] OF LINT; END_VAR a[1] := 1; END_PROGRAM");
    BadCycleTime: "The virtual clock advances by the scan cycle after every scan; it is a whole number of milliseconds from 1 to 60000 (a project's `cycle_ms`, `plc run --cycle-ms`, the page's cycle time).",
        drawn("`plc run --cycle-ms 0 main.st`, or `\"cycle_ms\": 18446744073709551615` in a project file"),
        drawn("`plc run --cycle-ms 10 main.st`");
    FileNotOpened: "The file given to `plc run` or `plc check` could not be opened: it cannot be read, it is not well-formed (XML, JSON), or it is XML but not a PLCopen project. The report says where in the file the problem is when it can.",
        drawn("`plc run plc.xml` on a file cut off in the middle of an element"),
        drawn("The complete file, as OpenPLC Editor or Beremiz saved it");
    ProgramSkipped: "The PROGRAM named with `--program` is in the file, but the import had to leave it out (its body is in a language the trainer does not import yet, such as IL in PLCopen XML). The message says why; run another PROGRAM of the file, or rewrite this one in ST or LD.",
        drawn("`plc run --program Traffic plc.xml` where `Traffic` is an IL body"),
        drawn("`plc run --program Main plc.xml` where `Main` is an ST or LD body");
    PlantMismatch: "The project's settings name a plant PROGRAM that runs after the controller on every scan; each of its VAR_INPUTs reads the controller's variable of the same name and each VAR_OUTPUT writes one, so both must have one elementary type (BOOL, INT, REAL…). Declare them alike, or rename one of them.",
        drawn("`\"plant\": \"Tank\"` with `Level : REAL` in PROGRAM Tank and `Level : INT` in the controller"),
        drawn("`Level : INT` in both PROGRAMs");
    LadderOpenCircuit: "An element of the rung cannot carry power: no path from the left rail reaches it, or it leads nowhere (no coil after it).",
        drawn("A contact `Start` on row 1, column 3, with empty cells before it: `|-    -| Start |--( Motor )-`."),
        drawn("Wire the gap: `|-------| Start |--( Motor )-`.");
    LadderShortCircuit: "A coil is wired straight to the rail, with no condition before it: it would be on in every scan. Add the contact that should switch it.",
        drawn("`|------------( Motor )-`"),
        drawn("`|--| Start |--( Motor )-`");
    LadderAmbiguousBranch: "A parallel branch opens or closes inside another branch in a way that is not a series-parallel circuit, so the power flow has no single reading. Close inner branches before outer ones.",
        drawn("Two vertical links that cross: a branch from column 1 to column 3 and another from column 2 to column 4 on the same rows."),
        drawn("Nested branches: one from column 1 to column 4, and inside it one from column 2 to column 3.");
    LadderMissingOperand: "A contact, coil or block pin has no variable.",
        drawn("`|--|   |--( Motor )-` (a contact without an operand)"),
        drawn("`|--| Start |--( Motor )-`");
    LadderBadOperand: "An operand must be a variable, a member (`Tank.Full`), an element (`Valves[2]`) or a direct address (`%IX0.1`), not an expression.",
        drawn("A contact with the operand `Start AND Ready`."),
        drawn("Two contacts in series: `Start` then `Ready`.");
    LadderUnknownBlock: "A block's type is neither a standard block (TON, CTU, ADD, GT, …) nor a FUNCTION or FUNCTION_BLOCK of the project.",
        drawn("A block of type `TIMER`."),
        drawn("A block of type `TON`.");
    LadderMissingInstance: "A function block in a rung needs an instance variable to keep its state between scans (`T1 : TON`).",
        drawn("A `TON` block without an instance name."),
        drawn("A `TON` block with instance `T1`, declared `T1 : TON;`.");
    LadderEdgeCoilShared: "A rising or falling edge coil must be the only coil of its rung: it detects the edge of the rung's power, which other coils would share.",
        drawn("`|--| Start |--+--(P Pulse )-` with a second branch `+--( Lamp )-` on the same rung."),
        drawn("The edge coil alone in its rung, `Lamp` in a rung of its own.");
    LadderAfterCoil: "Nothing may follow a coil, a jump or a return in the same row: power ends there.",
        drawn("`|--| Start |--( Motor )--| Ready |--`"),
        drawn("`|--| Start |--| Ready |--( Motor )-`");
    LadderStrayCovered: "A cell marked as covered by a block has no block above it (a damaged file). Clear the cell.",
        drawn("A `covered` cell in row 2 under an empty cell."),
        drawn("The cell emptied, or a block of height 2 placed above it.");
    LadderBadJump: "A jump names a label that no rung has, or a rung above it: jumps go forward only, so the scan always ends.",
        drawn("A jump to `Skip` when no rung is labelled `Skip`."),
        drawn("A later rung labelled `Skip`.");
    LadderBadGrid: "The rung's rows have different lengths, or a block reaches past the grid's last row.",
        drawn("A `CTU` block of height 3 anchored on the last row."),
        drawn("The block anchored three rows above the bottom.");
    LadderUnknownPin: "A block names a pin its type does not have, names one twice, or binds its power input as an ordinary pin.",
        drawn("A `TON` block with a pin `TIME` bound to `T#2s`."),
        drawn("The pin `PT` bound to `T#2s`.");
    LadderPinType: "The operand of a block pin does not have the pin's type: `PT` of a timer needs a TIME, `PV` of a counter an INT.",
        drawn("`PT` of a `TON` bound to `2000`."),
        drawn("`PT` bound to `T#2s`.");
    LadderMissingPin: "A block input or VAR_IN_OUT that the block needs is not given.",
        drawn("A `TON` block with no `PT`."),
        drawn("`PT` bound to `T#2s`.");
    LadderBadWiredPin: "A block input wired to a contact network must be BOOL, lie on one of the block's own rows, have its own row, and not also have an operand.",
        drawn("The reset `R` of a `CTU` wired from a row below the block."),
        drawn("`R` wired from the block's second row.");
    LadderBadPowerPin: "The pins chosen to carry the rung's power through a block must be BOOL, and `ENO` needs `EN`.",
        drawn("An `ADD` block taking power at `IN1`."),
        drawn("The `ADD` block taking power at `EN`.");
    LadderInstanceType: "A block's instance is declared with another type than the block's, or a FUNCTION block was given an instance.",
        drawn("A `TON` block with instance `C1` declared `C1 : CTU;`."),
        drawn("Instance `T1` declared `T1 : TON;`.");
    LadderUndeclaredOperand: "An operand names a variable that the POU does not declare. Declare it (the problem list offers `Declare NAME` with the type the use implies: a contact's operand is a BOOL input, a coil's a BOOL output), or, when the message asks `did you mean NAME?`, take `Replace with NAME`.",
        drawn("A contact `Start` in a POU whose declarations have no `Start`."),
        drawn("`Start : BOOL;` added to the declarations.");
    NetworkNotRunnable: "An LD or FBD network from another tool (kept as it was drawn, not as rungs) has an element the trainer cannot run: a wire from an element that does not exist, functions wired in a loop with no function block to hold a value, a jump or return outside the rung grid, an input of a function left unwired. The message names the element by its `localId`; the file's tool shows the same number.",
        drawn("An FBD network where ADD feeds MUL and MUL feeds ADD, with no function block between them"),
        drawn("The same network with the loop through a variable (an output variable written and an input variable read): it reads the previous scan's value");
    PetriDuplicateId: "Two places or transitions of the net have the same id.",
        drawn("Two places both with id `P1`."),
        drawn("Ids `P1` and `P2`.");
    PetriBadArc: "An arc must go from a place to a transition or from a transition to a place, with a weight of at least 1.",
        drawn("An arc from place `P1` to place `P2`."),
        drawn("`P1` → transition `T1` → `P2`.");
    PetriDuplicateArc: "Two arcs join the same place and transition in the same direction; give one arc a larger weight instead.",
        drawn("Two arcs `P1` → `T1`."),
        drawn("One arc `P1` → `T1`.");
    PetriBadGuard: "A transition's guard (or an emergency condition) must be one ST expression of type BOOL.",
        drawn("Guard `Start;`"),
        drawn("Guard `Start AND NOT Stop`");
    PetriBadActions: "A place's actions, the prologue and the epilogue must be ST statements.",
        drawn("Actions `Motor = TRUE`"),
        drawn("Actions `Motor := TRUE;`");
    PetriNotCovered: "CASE OF code gives every process (state-machine component) one CASE variable; places that no component covers cannot be coded that way. Add the places that close each cycle.",
        drawn("A transition that puts a token in `P2` and one in `P3` from `P1`, with no way back to `P1` from `P3`."),
        drawn("A transition from `P3` back to `P1`, so `P1`, `P3` form a component.");
    PetriProcessTokens: "A process is one sequence: exactly one of its places holds a token at the start.",
        drawn("A cycle `P1` → `P2` → `P1` with a token in both."),
        drawn("A token in `P1` only.");
    PetriDuplicateLabel: "Two places of one process have the same CASE label.",
        drawn("`P1` and `P2` of one process both labelled 10."),
        drawn("Labels 10 and 20.");
    PetriBadProcess: "A process declared for the net is not a state-machine component (every transition of it takes one token from it and gives one back).",
        drawn("A process `{P1, P3}` where `P1` → `T1` → `P2`."),
        drawn("The process `{P1, P2}`.");
    PetriBadEmergency: "The emergency place named in the net's settings is not one of its places.",
        drawn("Emergency place `Stop` in a net without `Stop`."),
        drawn("Emergency place `P9`, a place of the net.");
    PetriBadMacroPlace: "A macro-place lists a place that does not exist, or a place is inside two macro-places.",
        drawn("Macro-places `Fill = {P1, P2}` and `Drain = {P2, P3}`."),
        drawn("`Fill = {P1, P2}`, `Drain = {P3}`.");
    PetriArcWeight: "Arcs that touch the places of a process have weight 1: a process holds one token.",
        drawn("An arc of weight 2 from `P1`, a place of a process."),
        drawn("Weight 1.");
    PetriLabelRange: "A CASE label must fit an INT (-32768 to 32767).",
        drawn("A place labelled 40000."),
        drawn("A place labelled 400.");
    PetriFlagsAmbiguous: "Flag-style code (one BOOL per place) cannot tell apart two transitions that share this place and fire together; use CASE OF code for the process.",
        drawn("Two transitions leaving `P1` in flag style, both enabled by the same guard."),
        drawn("The same net coded CASE OF.");
    PetriSourceTransition: "A transition without input places could fire in every scan; give it an input place.",
        drawn("A transition `T1` with only an output arc to `P1`."),
        drawn("An arc from `P0` to `T1`.");
    PetriBadName: "The POU, process and step variable names become ST identifiers, so they must be valid names.",
        drawn("A process named `Fill tank`."),
        drawn("A process named `FillTank`.");
    PnmlInvalid: "The PNML file cannot be read as a place/transition net: not XML, not PNML, or missing its ids. The message gives the line and column.",
        drawn("A `<place>` element without an `id`."),
        drawn("`<place id=\"P1\">`.");
    PetriEmptyNet: "A Petri net POU without places generates no code.",
        drawn("A new net with no place."),
        drawn("A net with a place `P1` holding the initial token.");
    SfcUnknownStep: "A transition's FROM or TO list names a step that is not declared.",
        st("PROGRAM Main INITIAL_STEP Idle : END_STEP TRANSITION FROM Idle TO Runing := TRUE; END_TRANSITION STEP Running : END_STEP END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP Idle : END_STEP TRANSITION FROM Idle TO Running := TRUE; END_TRANSITION STEP Running : END_STEP END_PROGRAM");
    SfcDuplicateName: "Steps, transitions, actions and variables of a POU share one set of names.",
        st("PROGRAM Main VAR Idle : BOOL; END_VAR INITIAL_STEP Idle : END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR ready : BOOL; END_VAR INITIAL_STEP Idle : END_STEP END_PROGRAM");
    SfcSecondInitialStep: "An SFC network has exactly one INITIAL_STEP.",
        st("PROGRAM Main INITIAL_STEP A : END_STEP INITIAL_STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION END_PROGRAM");
    SfcNoInitialStep: "An SFC network needs an INITIAL_STEP to start from.",
        st("PROGRAM Main STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION END_PROGRAM");
    SfcUnknownAction: "A step's action association names neither an ACTION of the POU nor a BOOL variable.",
        st("PROGRAM Main INITIAL_STEP A : Fill(N); END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(N); END_STEP END_PROGRAM");
    SfcMissingDuration: "The timed qualifiers L, D, SD, DS and SL need a duration: `Fill(L, T#5s)`.",
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(L); END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(L, T#5s); END_STEP END_PROGRAM");
    SfcUnexpectedDuration: "The qualifiers N, R, S, P, P1 and P0 take no duration.",
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(N, T#5s); END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(N); END_STEP END_PROGRAM");
    SfcUnknownQualifier: "An action qualifier is one of N, R, S, P, P1, P0, L, D, SD, DS, SL.",
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(X); END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(S); END_STEP END_PROGRAM");
    SfcConditionNotBool: "A transition condition must be BOOL.",
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := n; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := n > 3; END_TRANSITION END_PROGRAM");
    SfcDurationNotTime: "An action's duration must be a TIME: `T#5s`, not `5`.",
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(L, 5); END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(L, T#5s); END_STEP END_PROGRAM");
    SfcReadOnly: "Step flags (`S.X`, `S.T`) and an action's `Q` and `A` are set by the SFC itself; code may read them, not write them.",
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION ACTION Go : B.X := TRUE; END_ACTION END_PROGRAM"),
        st("PROGRAM Main VAR seen : BOOL; END_VAR INITIAL_STEP A : Go(N); END_STEP STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION ACTION Go : seen := B.X; END_ACTION END_PROGRAM");
    SfcNotAllowedHere: "SFC bodies belong to PROGRAMs and FUNCTION_BLOCKs (a FUNCTION has no memory for steps), and a body is either steps and transitions or statements, not both.",
        st("FUNCTION F : BOOL INITIAL_STEP A : END_STEP END_FUNCTION PROGRAM Main VAR b : BOOL; END_VAR b := F(); END_PROGRAM"),
        st("FUNCTION_BLOCK F INITIAL_STEP A : END_STEP END_FUNCTION_BLOCK PROGRAM Main VAR f : F; END_VAR f(); END_PROGRAM");
    SfcReservedName: "`SFC_STEP` is the type of the SFC runtime's step flags; a type or POU of that name would clash with it.",
        st("TYPE SFC_STEP : INT; END_TYPE PROGRAM Main INITIAL_STEP A : END_STEP END_PROGRAM"),
        st("TYPE StepNo : INT; END_TYPE PROGRAM Main INITIAL_STEP A : END_STEP END_PROGRAM");
    SfcUnnamedTransitionBody: "A transition written with statements (`TRANSITION … : … END_TRANSITION`) assigns its own name, so it needs one.",
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B : n := n + 1; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION Go FROM A TO B : Go := n > 3; END_TRANSITION END_PROGRAM");
    SfcStepListedTwice: "A step appears twice in one FROM or TO list.",
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO (B, B) := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION END_PROGRAM");
    SfcBooleanActionNotBool: "A step may name a variable instead of an ACTION (a boolean action); that variable must be BOOL.",
        st("PROGRAM Main VAR Fill : INT; END_VAR INITIAL_STEP A : Fill(N); END_STEP END_PROGRAM"),
        st("PROGRAM Main VAR Fill : BOOL; END_VAR INITIAL_STEP A : Fill(N); END_STEP END_PROGRAM");
    SfcReturnInAction: "RETURN would leave the whole POU from inside an action or a transition body; end the action normally instead.",
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : Go(N); END_STEP ACTION Go : IF n > 3 THEN RETURN; END_IF; n := n + 1; END_ACTION END_PROGRAM"),
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : Go(N); END_STEP ACTION Go : IF n <= 3 THEN n := n + 1; END_IF; END_ACTION END_PROGRAM");
    IlUnknownOperator: "An IL line begins with a word that is neither an IL operator (LD, ST, S, R, AND, OR, XOR, NOT, ADD … MOD, GT … LE, JMP, CAL, RET with their N, C and ( modifiers, or an input operator such as S1, CU, PT) nor the name of a function. Check the spelling: `LDN` loads the negation, there is no `LDX`.",
        st("PROGRAM Main VAR a, b : BOOL; END_VAR\nLD a\nLDX b\nST a\nEND_PROGRAM"),
        st("PROGRAM Main VAR a, b : BOOL; END_VAR\nLD a\nANDN b\nST a\nEND_PROGRAM");
    IlBadInstruction: "An IL instruction has the wrong operands or modifiers: an operand is missing (`LD` alone), more than one value stands where one is expected (`LD a b`), an operand is an expression (`LD a AND b`: write `LD a` then `AND b`), a `)` has no `(`, a `(` is never closed, or a store, jump or call stands inside parentheses.",
        st("PROGRAM Main VAR a, b : BOOL; END_VAR\nLD a AND b\nST a\nEND_PROGRAM"),
        st("PROGRAM Main VAR a, b : BOOL; END_VAR\nLD a\nAND b\nST a\nEND_PROGRAM");
    IlUndefinedLabel: "A JMP, JMPC or JMPCN names a label that no line of the body defines (`Label:` at the start of a line), or a label is defined twice. Labels are case-insensitive.",
        st("PROGRAM Main VAR a : BOOL; n : INT; END_VAR\nLD a\nJMPC Skip\nLD 1\nST n\nEND_PROGRAM"),
        st("PROGRAM Main VAR a : BOOL; n : INT; END_VAR\nLD a\nJMPC Skip\nLD 1\nST n\nSkip: RET\nEND_PROGRAM");
    IlNoCurrentResult: "The instruction works on the current result, but nothing has been loaded yet: at the start of the body, after an unconditional JMP or RET, or at a label that is reached without one. Load a value with LD first.",
        st("PROGRAM Main VAR a : BOOL; END_VAR\nST a\nEND_PROGRAM"),
        st("PROGRAM Main VAR a : BOOL; END_VAR\nLD TRUE\nST a\nEND_PROGRAM");
    IlResultType: "The current result must be kept here (across a store, a call or a label), but it is not an elementary value, or it reaches a label as one type on one way in and as another type on another.",
        st("PROGRAM Main VAR a : BOOL; n : INT; END_VAR\nLD a\nJMPC L\nLD n\nL: ST n\nEND_PROGRAM"),
        st("PROGRAM Main VAR a : BOOL; n : INT; END_VAR\nLD a\nJMPC L\nLD 1\nST n\nL: RET\nEND_PROGRAM");
    UnusedVariable: "A declared variable is never read or written. Remove it, or use it. (Reserved: the checker does not report it yet.)",
        drawn("`VAR x, spare : INT; END_VAR x := x + 1;` (`spare` is never used)"),
        drawn("`VAR x : INT; END_VAR x := x + 1;`");
    UnreachableCode: "A statement follows RETURN, EXIT or CONTINUE in the same list, so it never runs.",
        st("PROGRAM Main VAR x : INT; END_VAR RETURN; x := 1; END_PROGRAM"),
        st("PROGRAM Main VAR x : INT; END_VAR x := 1; RETURN; END_PROGRAM");
    ImplicitNarrowing: "A value is stored where it may not fit (a DINT into an INT through an output): it would wrap. (Reserved: the checker reports such stores as errors, E0150, today.)",
        drawn("`c(CU := TRUE, PV := 5, CV => n);` with `n : SINT` (today an error, E0150)"),
        drawn("`n : INT`, the type of `CV`");
    CaseWithoutMatch: "A CASE label lies outside every value the selector's type can have (a negative label for a USINT), so its branch never runs.",
        st("PROGRAM Main VAR x : USINT; y : INT; END_VAR CASE x OF -1: y := 1; 1: y := 2; END_CASE; END_PROGRAM"),
        st("PROGRAM Main VAR x : USINT; y : INT; END_VAR CASE x OF 0: y := 1; 1: y := 2; END_CASE; END_PROGRAM");
    LadderEnableFromRail: "A block's enable is tied straight to the left rail, so it runs on every scan; if that is meant, the block needs no enable.",
        drawn("`|--[ ADD EN ]--` with EN wired to the rail."),
        drawn("`|--| Run |--[ ADD EN ]--`");
    LadderDuplicateCoil: "Two coils write the same variable; the last one in the scan wins, which hides the first. Combine their conditions in one rung.",
        drawn("Rung 1 `( Motor )` after `Start`, rung 3 `( Motor )` after `Jog`."),
        drawn("One rung: `Start` and `Jog` in parallel, then `( Motor )`.");
    LadderPinFromRail: "A wired block input is tied straight to the rail, so it is always TRUE; bind the pin to TRUE or wire the condition meant.",
        drawn("The `R` of a `CTU` wired from the rail."),
        drawn("`R` wired through a `Reset` contact.");
    PetriGuardConflict: "Transitions leaving one place have the same priority and guards that may hold together, so which one fires is up to the order in the net. Make the guards exclusive or give priorities.",
        drawn("`T1: Level > 50` and `T2: Level > 80` leaving `P1`, same priority."),
        drawn("`T2: Level > 80` with priority 1, `T1: Level > 50 AND Level <= 80`.");
    PetriDeadlock: "Some reachable marking enables no transition (guards ignored): the sequence can get stuck there. The analysis gives the firing sequence that reaches it.",
        drawn("`P1` → `T1` → `P2` and nothing leaving `P2`."),
        drawn("`T2` from `P2` back to `P1`.");
    PetriDeadTransition: "A transition can never fire in any reachable marking (guards ignored).",
        drawn("`T3` needs tokens in `P1` and `P2`, which never hold tokens together."),
        drawn("`T3` from `P2` alone.");
    PetriAnalysisIncomplete: "The net has more reachable markings than the analysis explores; its results hold for the part explored.",
        drawn("A net with 40 independent two-place cycles (2^40 markings)."),
        drawn("The cycles grouped into a few processes.");
    PetriPriorityIgnored: "Transitions compete for one token but belong to different processes, where the generated code decides each process on its own, so their priorities cannot choose between them.",
        drawn("`T1` (process A) and `T2` (process B) both taking the token of shared place `R`, with priorities 1 and 2."),
        drawn("The shared place guarded so only one can be enabled at a time.");
    SfcUnreachableStep: "No sequence of transitions from the initial step reaches this step.",
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION TRANSITION FROM B TO C := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM");
    SfcUnsafe: "A transition can activate a step that is already active (two tokens in one step: an unsafe SFC).",
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION FROM A TO (B, C) := TRUE; END_TRANSITION TRANSITION FROM B TO A := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION FROM A TO (B, C) := TRUE; END_TRANSITION TRANSITION FROM (B, C) TO A := TRUE; END_TRANSITION END_PROGRAM");
    SfcDeadTransition: "A transition's source steps are never active together, so it never fires.",
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION TRANSITION FROM B TO C := TRUE; END_TRANSITION TRANSITION FROM (B, C) TO A := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION FROM A TO B := TRUE; END_TRANSITION TRANSITION FROM B TO C := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM");
    SfcUnusedAction: "An ACTION is declared but no step uses it.",
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP ACTION Count : n := n + 1; END_ACTION END_PROGRAM"),
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : Count(N); END_STEP ACTION Count : n := n + 1; END_ACTION END_PROGRAM");
    SfcTransitionNotAssigned: "A transition body never assigns the transition's name, so it is always FALSE.",
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION Go FROM A TO B : n := n + 1; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main VAR n : INT; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP TRANSITION Go FROM A TO B : n := n + 1; Go := n > 3; END_TRANSITION END_PROGRAM");
    SfcSamePriority: "Transitions leaving one step have the same PRIORITY, so the order they are written in decides which fires.",
        st("PROGRAM Main VAR x : BOOL; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION T1 (PRIORITY := 1) FROM A TO B := x; END_TRANSITION TRANSITION T2 (PRIORITY := 1) FROM A TO C := NOT x; END_TRANSITION TRANSITION FROM B TO A := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM"),
        st("PROGRAM Main VAR x : BOOL; END_VAR INITIAL_STEP A : END_STEP STEP B : END_STEP STEP C : END_STEP TRANSITION T1 (PRIORITY := 1) FROM A TO B := x; END_TRANSITION TRANSITION T2 (PRIORITY := 2) FROM A TO C := NOT x; END_TRANSITION TRANSITION FROM B TO A := TRUE; END_TRANSITION TRANSITION FROM C TO A := TRUE; END_TRANSITION END_PROGRAM");
    ImportChanged: "Opening a file from another tool skipped or changed part of it to fit the trainer: a POU in a language not imported yet, an element that is not connected, a block input read from a variable that became a contact. The program runs without it, or with the change; the message names the element and its place in the file.",
        drawn("An OpenPLC `plc.xml` with a comment box outside any rung, or an FBD POU beside the LD program"),
        drawn("The same project with every element wired into a network and its POUs in ST or LD");
    FunctionInputWritten: "A FUNCTION assigns to one of its VAR_INPUTs. The input is the function's own copy of the argument: the assignment changes that copy for the rest of the call, and the caller's variable stays as it was. CODESYS, OpenPLC and Beremiz accept this (files from them do it); write the value to a local variable to make the code clear.",
        st("FUNCTION Twice : INT VAR_INPUT a : INT; END_VAR a := a * 2; Twice := a; END_FUNCTION PROGRAM Main VAR x : INT; END_VAR x := Twice(3); END_PROGRAM"),
        st("FUNCTION Twice : INT VAR_INPUT a : INT; END_VAR VAR d : INT; END_VAR d := a * 2; Twice := d; END_FUNCTION PROGRAM Main VAR x : INT; END_VAR x := Twice(3); END_PROGRAM");
    UnsupportedConfiguration: "A program has one CONFIGURATION, and `VAR_ACCESS` blocks (access paths for other devices on a network) are not supported. Declare the variables in the configuration's VAR_GLOBAL, and put every resource in one configuration.",
        st("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM CONFIGURATION C VAR_ACCESS A : P1.x : INT READ_ONLY; END_VAR PROGRAM P1 : P; END_CONFIGURATION"),
        st("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM CONFIGURATION C PROGRAM P1 : P; END_CONFIGURATION");
    UnknownTask: "A program instance runs `WITH` a task that its resource does not declare. Declare the task (`TASK Fast (INTERVAL := T#10ms, PRIORITY := 1);`) in the same resource, or fix the name.",
        st("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM CONFIGURATION C RESOURCE R ON PLC TASK Fast (INTERVAL := T#10ms, PRIORITY := 1); PROGRAM P1 WITH Fats : P; END_RESOURCE END_CONFIGURATION"),
        st("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM CONFIGURATION C RESOURCE R ON PLC TASK Fast (INTERVAL := T#10ms, PRIORITY := 1); PROGRAM P1 WITH Fast : P; END_RESOURCE END_CONFIGURATION");
    NotAProgramType: "A program instance (`PROGRAM Name WITH Task : Type;`) must name a PROGRAM; a FUNCTION_BLOCK is instantiated inside a PROGRAM instead.",
        st("FUNCTION_BLOCK F VAR x : INT; END_VAR x := x + 1; END_FUNCTION_BLOCK CONFIGURATION C PROGRAM P1 : F; END_CONFIGURATION"),
        st("FUNCTION_BLOCK F VAR x : INT; END_VAR x := x + 1; END_FUNCTION_BLOCK PROGRAM P VAR f : F; END_VAR f(); END_PROGRAM CONFIGURATION C PROGRAM P1 : P; END_CONFIGURATION");
    BadTaskSetting: "A task's INTERVAL must be a constant TIME above zero, its PRIORITY a constant from 0 (most urgent) to 9999, and its SINGLE a BOOL variable of the configuration whose rising edge starts the task.",
        st("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM CONFIGURATION C TASK T (INTERVAL := T#0ms, PRIORITY := 1); PROGRAM P1 WITH T : P; END_CONFIGURATION"),
        st("PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM CONFIGURATION C TASK T (INTERVAL := T#20ms, PRIORITY := 1); PROGRAM P1 WITH T : P; END_CONFIGURATION");
    BadProgramConnection: "A connection of a program instance joins one of the program's VAR_INPUTs (`In := Variable`) or VAR_OUTPUTs (`Out => Variable`) to a global variable of the same type.",
        st("PROGRAM P VAR_INPUT i : INT; END_VAR VAR x : INT; END_VAR x := i; END_PROGRAM CONFIGURATION C VAR_GLOBAL g : BOOL; END_VAR PROGRAM P1 : P (i := g); END_CONFIGURATION"),
        st("PROGRAM P VAR_INPUT i : INT; END_VAR VAR x : INT; END_VAR x := i; END_PROGRAM CONFIGURATION C VAR_GLOBAL g : INT; END_VAR PROGRAM P1 : P (i := g); END_CONFIGURATION");
    BadConfigVar: "A `VAR_CONFIG` entry configures a variable of one instance: the path starts at a program instance of the configuration and goes through instance names to the variable, and the type is the variable's own. With `AT`, the entry gives an address to a variable declared at an incomplete address (`Out AT %Q* : BOOL;`): complete, of the same area and size. With `:= value`, it gives the variable its initial value in that instance; a VAR_TEMP, VAR_IN_OUT, VAR_EXTERNAL, CONSTANT or a variable at a complete address cannot take one, and one entry per variable gives it.",
        st("FUNCTION_BLOCK Valve VAR_OUTPUT Open AT %Q* : BOOL; END_VAR Open := TRUE; END_FUNCTION_BLOCK PROGRAM P VAR V1 : Valve; END_VAR V1(); END_PROGRAM CONFIGURATION C PROGRAM P1 : P; VAR_CONFIG P1.V1.Open AT %IX0.0 : BOOL; END_VAR END_CONFIGURATION"),
        st("FUNCTION_BLOCK Valve VAR_OUTPUT Open AT %Q* : BOOL; END_VAR Open := TRUE; END_FUNCTION_BLOCK PROGRAM P VAR V1 : Valve; END_VAR V1(); END_PROGRAM CONFIGURATION C PROGRAM P1 : P; VAR_CONFIG P1.V1.Open AT %QX0.0 : BOOL; END_VAR END_CONFIGURATION");
    SceneUnknownVariable: "A widget of the project's scene (the Plant panel, `docs/plants.md`) is bound to a variable that neither the PROGRAM that runs nor its plant has, so it shows no value (and a button writes nothing). Names are the controller's variables and globals, and the plant's as `Plant.Name`; fix the widget's `var` (or `alarm`, `at`, `yellow`, `green`), or declare the variable.",
        drawn("a tank widget with `\"var\": \"TankPlant.Volme\"` in a project whose plant TankPlant declares `Volume`"),
        drawn("the same widget with `\"var\": \"TankPlant.Volume\"`");
    VariableShadowsEnumValue: "A name is both a variable and a value of the enumeration expected here; it is read as the enumeration value (as CODESYS does). Rename the variable to make the code clear.",
        st("TYPE Mode : (Off, Hand, Auto); END_TYPE PROGRAM Main VAR m : Mode; Hand : BOOL; END_VAR m := Hand; END_PROGRAM"),
        st("TYPE Mode : (Off, Hand, Auto); END_TYPE PROGRAM Main VAR m : Mode; HandSwitch : BOOL; END_VAR m := Hand; END_PROGRAM");
}

/// The heading of a code's section: `E0150: a value of one type where another is needed`.
fn heading(code: Code) -> String {
    format!("{}: {}", code.as_str(), code.title())
}

fn example_text(e: &Example) -> String {
    match e {
        Example::St { source, program, set } => {
            let mut s = source.to_string();
            if let Some(p) = program {
                s.push_str(&format!("\n(* plc run --program {p} *)"));
            }
            if let Some((var, value)) = set {
                s.push_str(&format!("\n(* plc run --set {var}={value} *)"));
            }
            s
        }
        Example::Drawn(text) => text.to_string(),
    }
}

/// What `plc explain CODE` prints.
pub fn explain_text(code: Code) -> String {
    let mut out = heading(code);
    if let Some(e) = code.explanation() {
        out.push_str(&format!(
            "\n\n{}\n\nWrong:\n{}\n\nRight:\n{}\n",
            e.text,
            indent(&example_text(&e.wrong)),
            indent(&example_text(&e.right))
        ));
    }
    out
}

fn indent(text: &str) -> String {
    text.lines().map(|l| format!("    {l}")).collect::<Vec<_>>().join("\n")
}

const PAGE_INTRO: &str =
    "Every problem the trainer reports has a stable code. Errors (E) stop the program from \
running; warnings (W) let it run but point at something that is probably not meant. `plc \
explain CODE` prints the same text. A name one or two letters away from a declared one gets \
`did you mean NAME?` at the end of its message, and the page's problem list offers the fix \
with one click (`Replace with NAME`, `Declare NAME`).";

/// `docs/problems.md`: every code with its explanation and examples. Generated; a test
/// keeps the file current (`cargo run -p plc-core --bin plc -- explain --markdown >
/// docs/problems.md`).
pub fn problems_markdown() -> String {
    let mut out = format!("# Problem codes\n\n<!-- Generated by `plc explain --markdown` from core/src/diagnostics/explain.rs: do not edit. -->\n\n{PAGE_INTRO}\n");
    for code in Code::all() {
        out.push_str(&format!("\n## {}\n", heading(*code)));
        if let Some(e) = code.explanation() {
            out.push_str(&format!("\n{}\n", e.text));
            for (label, ex) in [("Wrong", &e.wrong), ("Right", &e.right)] {
                match ex {
                    Example::St { .. } => {
                        out.push_str(&format!("\n{label}:\n\n```st\n{}\n```\n", example_text(ex)))
                    }
                    Example::Drawn(t) => out.push_str(&format!("\n{label}: {t}\n")),
                }
            }
        }
    }
    out
}

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// Inline `code` spans of a text as HTML.
fn html_inline(s: &str) -> String {
    let mut out = String::new();
    for (k, part) in html_escape(s).split('`').enumerate() {
        if k % 2 == 1 {
            out.push_str(&format!("<code>{part}</code>"));
        } else {
            out.push_str(part);
        }
    }
    out
}

/// `problems.html` of the site (copied into `dist/` by trunk): the same page as HTML, one
/// section per code with the code as its id, so the problem list links to
/// `problems.html#E0150`. Static, so it costs nothing until opened; dark when the system is
/// (it has no script to read the app's Theme switch).
pub fn problems_html() -> String {
    let mut out = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>Problem codes · PLC trainer</title>\n\
         <style>body{font:16px/1.5 system-ui,sans-serif;max-width:50rem;margin:2rem auto;padding:0 1rem;color:#1b1f24}\
         h2{font-size:1.1rem;margin-top:2rem;border-top:1px solid #d0d7de;padding-top:1rem}\
         pre{background:#f6f8fa;padding:.6rem .8rem;overflow-x:auto;white-space:pre-wrap;overflow-wrap:anywhere}\
         code{background:#f6f8fa;padding:0 .2rem}:target{outline:3px solid #f0b400;outline-offset:.4rem}\
         :root{color-scheme:light dark}@media (prefers-color-scheme:dark){body{background:#0f1419;color:#e2e8ef}\
         h2{border-color:#3a4654}pre,code{background:#222c37}}</style>\n\
         </head>\n<body>\n<main>\n<h1>Problem codes</h1>\n",
    );
    out.push_str(&format!("<p>{}</p>\n", html_inline(PAGE_INTRO)));
    for code in Code::all() {
        out.push_str(&format!(
            "<section id=\"{}\">\n<h2>{}</h2>\n",
            code.as_str(),
            html_inline(&heading(*code))
        ));
        if let Some(e) = code.explanation() {
            out.push_str(&format!("<p>{}</p>\n", html_inline(e.text)));
            for (label, ex) in [("Wrong", &e.wrong), ("Right", &e.right)] {
                match ex {
                    Example::St { .. } => out.push_str(&format!(
                        "<p>{label}:</p>\n<pre><code>{}</code></pre>\n",
                        html_escape(&example_text(ex))
                    )),
                    Example::Drawn(t) => {
                        out.push_str(&format!("<p>{label}: {}</p>\n", html_inline(t)))
                    }
                }
            }
        }
        out.push_str("</section>\n");
    }
    out.push_str("</main>\n</body>\n</html>\n");
    out
}
