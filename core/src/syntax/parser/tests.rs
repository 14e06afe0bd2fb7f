#![allow(clippy::unwrap_used)]
use super::*;

/// Parses and asserts there is no diagnostic.
fn parse_ok(src: &str) -> SourceFile {
    let (file, diags) = parse_source(src);
    assert!(diags.is_empty(), "unexpected diagnostics for\n{src}\n{diags:#?}");
    file
}

/// The codes and messages of the diagnostics of `src`.
fn errors(src: &str) -> Vec<(&'static str, String)> {
    parse_source(src).1.into_iter().map(|d| (d.code.as_str(), d.message)).collect()
}

fn program(body: &str) -> String {
    format!("PROGRAM Main\nVAR\n  x : INT;\nEND_VAR\n{body}\nEND_PROGRAM\n")
}

fn body_of(src: &str) -> Vec<Stmt> {
    match parse_ok(src).items.into_iter().last() {
        Some(Item::Pou(p)) => p.body,
        other => panic!("no POU: {other:?}"),
    }
}

fn stmts(body: &str) -> Vec<Stmt> {
    body_of(&program(body))
}

fn decls(src_decls: &str) -> Vec<VarDecl> {
    let src = format!("PROGRAM Main\nVAR\n{src_decls}\nEND_VAR\nEND_PROGRAM\n");
    match parse_ok(&src).items.into_iter().next() {
        Some(Item::Pou(p)) => p.var_blocks.into_iter().flat_map(|b| b.decls).collect(),
        other => panic!("no POU: {other:?}"),
    }
}

fn types(src_types: &str) -> Vec<TypeDef> {
    let src = format!("TYPE\n{src_types}\nEND_TYPE\n");
    match parse_ok(&src).items.into_iter().next() {
        Some(Item::Types(t)) => t,
        other => panic!("no TYPE: {other:?}"),
    }
}

/// A compact rendering of an expression for assertions.
fn sx(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Literal(l) => {
            let v = match &l.value {
                LiteralValue::Int(i) => i.to_string(),
                LiteralValue::Real(r) => format!("{r:?}"),
                LiteralValue::Bool(b) => b.to_string().to_uppercase(),
                LiteralValue::String(s) => format!("'{}'", String::from_utf8_lossy(s)),
                LiteralValue::WString(s) => format!("\"{}\"", String::from_utf16_lossy(s)),
                LiteralValue::Time(t) => format!("time:{t}"),
                LiteralValue::Date(t) => format!("date:{t}"),
                LiteralValue::TimeOfDay(t) => format!("tod:{t}"),
                LiteralValue::DateTime(t) => format!("dt:{t}"),
            };
            match &l.type_prefix {
                Some(p) => format!("{}#{v}", p.name),
                None => v,
            }
        }
        ExprKind::Name(n) => n.name.clone(),
        ExprKind::EnumValue { type_name, value } => format!("{}#{}", type_name.name, value.name),
        ExprKind::Member(b, m) => format!("{}.{}", sx(b), m.name),
        ExprKind::Bit(b, n) => format!("{}.bit{n}", sx(b)),
        ExprKind::Part { base, width, index } => format!("{}.part{width}:{index}", sx(base)),
        ExprKind::Index(b, ix) => {
            format!("{}[{}]", sx(b), ix.iter().map(sx).collect::<Vec<_>>().join(","))
        }
        ExprKind::Unary(op, x) => format!("({op:?} {})", sx(x)),
        ExprKind::Binary(BinaryOp::Cmp(c), a, b) => format!("({c:?} {} {})", sx(a), sx(b)),
        ExprKind::Binary(op, a, b) => format!("({op:?} {} {})", sx(a), sx(b)),
        ExprKind::Call { callee, args } => {
            let args: Vec<String> = args
                .iter()
                .map(|a| match a {
                    Arg::Positional(e) => sx(e),
                    Arg::Input { name, value } => format!("{}:={}", name.name, sx(value)),
                    Arg::Output { name, target, negated } => {
                        format!(
                            "{}{}=>{}",
                            if *negated { "NOT " } else { "" },
                            name.name,
                            sx(target)
                        )
                    }
                })
                .collect();
            format!("{}({})", sx(callee), args.join(","))
        }
        ExprKind::Direct(d) => format!("{}:{:?}{:?}{:?}", d.text, d.area, d.size, d.path),
        ExprKind::Paren(x) => format!("[{}]", sx(x)),
        ExprKind::Deref(x) => format!("{}^", sx(x)),
    }
}

fn ex(src: &str) -> String {
    match parse_single_expression(src) {
        Ok(e) => sx(&e),
        Err(d) => panic!("{src}: {d:#?}"),
    }
}

// ---------------------------------------------------------------- expressions

#[test]
fn precedence_follows_iec() {
    assert_eq!(ex("a OR b AND c"), "(Or a (And b c))");
    assert_eq!(ex("a XOR b OR c"), "(Or (Xor a b) c)");
    assert_eq!(ex("a OR b XOR c"), "(Or a (Xor b c))");
    assert_eq!(ex("a & b AND_THEN c OR_ELSE d"), "(OrElse (AndThen (And a b) c) d)");
    assert_eq!(ex("a = b AND c <> d"), "(And (Eq a b) (Ne c d))");
    assert_eq!(ex("a < b = c >= d"), "(Eq (Lt a b) (Ge c d))");
    assert_eq!(ex("a + b * c - d"), "(Sub (Add a (Mul b c)) d)");
    assert_eq!(ex("a - b - c"), "(Sub (Sub a b) c)");
    assert_eq!(ex("a MOD b / c"), "(Div (Mod a b) c)");
    assert_eq!(ex("a * b ** c"), "(Mul a (Pow b c))");
    assert_eq!(ex("a ** b ** c"), "(Pow (Pow a b) c)");
    assert_eq!(ex("-a ** 2"), "(Pow (Neg a) 2)");
    assert_eq!(ex("NOT a AND b"), "(And (Not a) b)");
    assert_eq!(ex("NOT NOT a"), "(Not (Not a))");
    assert_eq!(ex("+789 + -12"), "(Add (Plus 789) (Neg 12))");
    assert_eq!(ex("(a + b) * c"), "(Mul [(Add a b)] c)");
    assert_eq!(ex("2 ** -1"), "(Pow 2 (Neg 1))");
}

#[test]
fn postfix_calls_members_bits() {
    assert_eq!(ex("MAX(a, b)"), "MAX(a,b)");
    assert_eq!(ex("LIMIT(MN := 0, IN := x, MX := 10)"), "LIMIT(MN:=0,IN:=x,MX:=10)");
    assert_eq!(ex("REAL_TO_INT(x) + 1"), "(Add REAL_TO_INT(x) 1)");
    assert_eq!(ex("arr[i, j + 1]"), "arr[i,(Add j 1)]");
    assert_eq!(ex("arr[1].x"), "arr[1].x");
    assert_eq!(ex("s.a.b"), "s.a.b");
    assert_eq!(ex("w.3"), "w.bit3");
    assert_eq!(ex("s.w.15"), "s.w.bit15");
    assert_eq!(ex("w.%X7"), "w.bit7");
    assert_eq!(ex("w.%B1"), "w.part8:1");
    assert_eq!(ex("l.%W3"), "l.part16:3");
    assert_eq!(ex("l.%d1"), "l.part32:1");
    assert_eq!(ex("l.%L0"), "l.part64:0");
    assert_eq!(ex("timers[2].Q"), "timers[2].Q");
    assert_eq!(ex("F()"), "F()");
}

#[test]
fn dereference_is_a_postfix_operator() {
    assert_eq!(ex("r^"), "r^");
    assert_eq!(ex("r^.x"), "r^.x");
    assert_eq!(ex("r^[i]^"), "r^[i]^");
    assert_eq!(ex("a[1]^.b^"), "a[1]^.b^");
    assert_eq!(ex("-r^ + 1"), "(Add (Neg r^) 1)");
    assert_eq!(ex("REF(x)^"), "REF(x)^");
    assert_eq!(ex("r^ = NULL"), "(Eq r^ NULL)");
}

#[test]
fn reference_types() {
    let d = decls("r : REF_TO INT;\np : REF_TO ARRAY[1..2] OF REF_TO Pt;\nREF_TO : INT;");
    let TypeRef::Ref { target, .. } = &d[0].ty else { panic!("{:?}", d[0].ty) };
    assert!(matches!(&**target, TypeRef::Named(n) if n.name == "INT"));
    let TypeRef::Ref { target, .. } = &d[1].ty else { panic!("{:?}", d[1].ty) };
    let TypeRef::Array { element, .. } = &**target else { panic!("{target:?}") };
    assert!(matches!(&**element, TypeRef::Ref { .. }));
    // `REF_TO` alone stays a name.
    assert_eq!(d[2].names[0].name, "REF_TO");
    let t = types("PInt : REF_TO INT;");
    assert!(matches!(&t[0].ty, TypeRef::Ref { .. }));
}

#[test]
fn literals_in_expressions() {
    assert_eq!(ex("123_456"), "123456");
    assert_eq!(ex("2#1110_0000"), "224");
    assert_eq!(ex("8#377"), "255");
    assert_eq!(ex("16#e5"), "229");
    assert_eq!(ex("-12.0"), "(Neg 12.0)");
    assert_eq!(ex("1.234e-6"), "1.234e-6");
    assert_eq!(ex("TRUE"), "TRUE");
    assert_eq!(ex("false"), "FALSE");
    assert_eq!(ex("DINT#5"), "DINT#5");
    assert_eq!(ex("UINT#16#FE"), "UINT#254");
    assert_eq!(ex("INT#-5"), "INT#-5");
    assert_eq!(ex("LREAL#1"), "LREAL#1.0");
    assert_eq!(ex("REAL#1.5"), "REAL#1.5");
    assert_eq!(ex("BOOL#0"), "BOOL#FALSE");
    assert_eq!(ex("BOOL#TRUE"), "BOOL#TRUE");
    assert_eq!(ex("STRING#'OK'"), "STRING#'OK'");
    assert_eq!(ex("WSTRING#\"OK\""), "WSTRING#\"OK\"");
    assert_eq!(ex("'a$'b'"), "'a'b'");
    assert_eq!(ex("T#1s"), "time:1000000000");
    assert_eq!(ex("T#-14ms"), "time:-14000000");
    assert_eq!(ex("LTIME#1ms"), "time:1000000");
    assert_eq!(ex("D#1970-01-02"), "date:86400000000", "DATE counts microseconds");
    assert_eq!(ex("TOD#00:00:01"), "tod:1000000000");
    assert_eq!(ex("DT#1970-01-01-00:00:01.5"), "dt:1500000");
    assert_eq!(ex("Color#Red"), "Color#Red");
    assert_eq!(ex("%IX0.1"), "%IX0.1:InputBit[0, 1]");
    assert_eq!(ex("%QW4 + %MW6"), "(Add %QW4:OutputWord[4] %MW6:MemoryWord[6])");
    assert_eq!(ex("%I0.0"), "%I0.0:InputBit[0, 0]");
    assert_eq!(ex("x > t#3s"), "(Gt x time:3000000000)");
}

#[test]
fn spans_cover_the_expression() {
    let src = "  a + f(b)[2].c ";
    let e = parse_single_expression(src).unwrap();
    assert_eq!(&src[e.span.start as usize..e.span.end as usize], "a + f(b)[2].c");
    let e = parse_single_expression("(a)").unwrap();
    assert_eq!((e.span.start, e.span.end), (0, 3));
}

#[test]
fn single_expression_errors() {
    let d = parse_single_expression("a + b c").unwrap_err();
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].code.as_str(), "E0006");
    assert!(d[0].message.contains("`c`"), "{}", d[0].message);
    assert!(parse_single_expression("").is_err());
    assert!(parse_single_expression("a +").is_err());
    assert_eq!(parse_single_expression("INT#1.5").unwrap_err()[0].code.as_str(), "E0013");
    assert_eq!(parse_single_expression("T#1h75m").unwrap_err()[0].code.as_str(), "E0005");
    assert_eq!(parse_single_expression("%IZ1").unwrap_err()[0].code.as_str(), "E0009");
    assert_eq!(parse_single_expression("'$Q'").unwrap_err()[0].code.as_str(), "E0008");
}

// ---------------------------------------------------------------- statements

#[test]
fn assignments_and_calls() {
    let s = stmts(
        "x := 1;\n\
         Timer(IN := x, PT := T#1s, Q => done, NOT Q => notdone);\n\
         F(1, 2);\n\
         arr[i].t(IN := TRUE);\n\
         inst();\n\
         %QX0.0 := TRUE;\n\
         w.3 := FALSE;\n\
         ;",
    );
    assert_eq!(s.len(), 8);
    match &s[0].kind {
        StmtKind::Assign { target, value } => {
            assert_eq!((sx(target), sx(value)), ("x".into(), "1".into()))
        }
        k => panic!("{k:?}"),
    }
    let calls: Vec<String> = s[1..5]
        .iter()
        .map(|st| match &st.kind {
            StmtKind::Call(e) => sx(e),
            k => panic!("{k:?}"),
        })
        .collect();
    assert_eq!(
        calls,
        vec![
            "Timer(IN:=x,PT:=time:1000000000,Q=>done,NOT Q=>notdone)",
            "F(1,2)",
            "arr[i].t(IN:=TRUE)",
            "inst()"
        ]
    );
    assert!(
        matches!(&s[5].kind, StmtKind::Assign { target, .. } if matches!(target.kind, ExprKind::Direct(_)))
    );
    assert!(
        matches!(&s[6].kind, StmtKind::Assign { target, .. } if matches!(target.kind, ExprKind::Bit(_, 3)))
    );
    assert_eq!(s[7].kind, StmtKind::Empty);
}

#[test]
fn statement_spans_include_the_semicolon() {
    let src = program("x := 1 + 2;");
    let s = body_of(&src);
    assert_eq!(&src[s[0].span.start as usize..s[0].span.end as usize], "x := 1 + 2;");
}

#[test]
fn if_elsif_else() {
    let s = stmts("IF a THEN x := 1; ELSIF b THEN x := 2; ELSIF c THEN ; ELSE x := 3; END_IF;");
    match &s[0].kind {
        StmtKind::If { branches, else_body } => {
            assert_eq!(branches.len(), 3);
            assert_eq!(sx(&branches[1].0), "b");
            assert_eq!(else_body.as_ref().map(Vec::len), Some(1));
        }
        k => panic!("{k:?}"),
    }
    // `;` after END_IF is optional.
    assert_eq!(stmts("IF a THEN x := 1; END_IF x := 2;").len(), 2);
}

#[test]
fn case_with_lists_ranges_enums_and_else() {
    let s = stmts(
        "CASE p OF\n\
           1: x := 1; y := 2;\n\
           2, 3, 10..19: x := 2;\n\
           Red, Color#Green: ;\n\
           -1: x := 0;\n\
         ELSE\n\
           x := 9;\n\
         END_CASE;",
    );
    match &s[0].kind {
        StmtKind::Case { selector, arms, else_body } => {
            assert_eq!(sx(selector), "p");
            assert_eq!(arms.len(), 4);
            assert_eq!(arms[0].body.len(), 2);
            assert_eq!(arms[1].labels.len(), 3);
            assert!(
                matches!(&arms[1].labels[2], CaseLabel::Range(a, b) if sx(a) == "10" && sx(b) == "19")
            );
            assert!(matches!(&arms[2].labels[1], CaseLabel::Value(e) if sx(e) == "Color#Green"));
            assert!(matches!(&arms[3].labels[0], CaseLabel::Value(e) if sx(e) == "(Neg 1)"));
            assert_eq!(else_body.as_ref().map(Vec::len), Some(1));
        }
        k => panic!("{k:?}"),
    }
}

#[test]
fn loops_and_jumps() {
    let s = stmts(
        "FOR i := 1 TO 10 BY 2 DO IF i = 5 THEN EXIT; END_IF; CONTINUE; END_FOR;\n\
         FOR i := 10 TO 1 DO x := i; END_FOR;\n\
         WHILE x < 10 DO x := x + 1; END_WHILE;\n\
         REPEAT x := x - 1; UNTIL x <= 0 END_REPEAT;\n\
         RETURN;",
    );
    assert_eq!(s.len(), 5);
    match &s[0].kind {
        StmtKind::For { var, from, to, by, body } => {
            assert_eq!(var.name, "i");
            assert_eq!((sx(from), sx(to)), ("1".into(), "10".into()));
            assert_eq!(by.as_ref().map(sx), Some("2".into()));
            assert_eq!(body.len(), 2);
            assert!(matches!(body[1].kind, StmtKind::Continue));
        }
        k => panic!("{k:?}"),
    }
    assert!(matches!(&s[1].kind, StmtKind::For { by: None, .. }));
    assert!(matches!(&s[2].kind, StmtKind::While { body, .. } if body.len() == 1));
    assert!(matches!(&s[3].kind, StmtKind::Repeat { until, .. } if sx(until) == "(Le x 0)"));
    assert_eq!(s[4].kind, StmtKind::Return);
}

// ---------------------------------------------------------------- declarations

#[test]
fn declarations() {
    let d = decls(
        "a, b : INT := 5;\n\
         x AT %IX0.0 : BOOL;\n\
         arr : ARRAY[1..10, 0..2] OF INT := [1, 2, 3(0), 2()];\n\
         s : STRING[20] := 'abc';\n\
         s2 : STRING(20);\n\
         w : WSTRING;\n\
         st : MyStruct := (a := 1, b := (c := 2));\n\
         t : TON;\n\
         mode : (Auto, Manual) := Manual;\n\
         lvl : INT(0..100) := 50;\n\
         tbt : ARRAY [1..2][1..3] OF INT := [1, 2, 3(4), 6];\n\
         AT %QW4 : WORD;\n\
         neg : INT := -(5);",
    );
    assert_eq!(d.len(), 13);
    assert_eq!(d[0].names.iter().map(|n| n.name.as_str()).collect::<Vec<_>>(), vec!["a", "b"]);
    assert!(matches!(&d[0].init, Some(Initializer::Expr(e)) if sx(e) == "5"));
    let loc = d[1].location.as_ref().unwrap();
    assert_eq!(
        (loc.area, loc.size, loc.path.clone()),
        (AddressArea::Input, AddressSize::Bit, vec![0, 0])
    );
    match (&d[2].ty, &d[2].init) {
        (TypeRef::Array { ranges, element, .. }, Some(Initializer::Array { elements, .. })) => {
            assert_eq!(ranges.len(), 2);
            assert!(matches!(element.as_ref(), TypeRef::Named(n) if n.name == "INT"));
            assert_eq!(elements.len(), 4);
            assert!(
                matches!(&elements[2], ArrayInitElement::Repeat { count, value: Some(_), .. } if sx(count) == "3")
            );
            assert!(matches!(&elements[3], ArrayInitElement::Repeat { value: None, .. }));
        }
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(&d[3].ty, TypeRef::String { wide: false, length: Some(l), .. } if sx(l) == "20")
    );
    assert!(matches!(&d[4].ty, TypeRef::String { wide: false, length: Some(_), .. }));
    assert!(matches!(&d[5].ty, TypeRef::String { wide: true, length: None, .. }));
    match &d[6].init {
        Some(Initializer::Struct { fields, .. }) => {
            assert_eq!(fields[0].0.name, "a");
            assert!(
                matches!(&fields[1].1, Initializer::Struct { fields, .. } if fields[0].0.name == "c")
            );
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(&d[7].ty, TypeRef::Named(n) if n.name == "TON"));
    assert!(matches!(&d[8].ty, TypeRef::Enum { values, .. } if values.len() == 2));
    assert!(matches!(&d[9].ty, TypeRef::Subrange { base, low, high, .. }
        if base.name == "INT" && sx(low) == "0" && sx(high) == "100"));
    assert!(matches!(&d[10].ty, TypeRef::Array { ranges, .. } if ranges.len() == 2));
    assert!(d[11].names.is_empty() && d[11].location.is_some());
    assert!(matches!(&d[12].init, Some(Initializer::Expr(e)) if sx(e) == "(Neg [5])"));
}

#[test]
fn var_sections_and_qualifiers() {
    let src = "FUNCTION_BLOCK FB\n\
               VAR_INPUT a : BOOL; END_VAR\n\
               VAR_OUTPUT b : BOOL; END_VAR\n\
               VAR_IN_OUT c : INT; END_VAR\n\
               VAR_EXTERNAL g : INT; END_VAR\n\
               VAR_TEMP t : INT; END_VAR\n\
               VAR RETAIN r : INT; END_VAR\n\
               VAR CONSTANT PERSISTENT k : INT := 1; END_VAR\n\
               VAR NON_RETAIN n : INT; END_VAR\n\
               END_FUNCTION_BLOCK\n\
               VAR_GLOBAL CONSTANT gk : INT := 3; END_VAR\n\
               FUNCTION F : INT VAR_INPUT x : INT; END_VAR F := x; END_FUNCTION\n\
               FUNCTION NoResult x := 1; END_FUNCTION";
    let f = parse_ok(src);
    assert_eq!(f.items.len(), 4);
    let Item::Pou(fb) = &f.items[0] else { panic!() };
    assert_eq!(fb.kind, PouKind::FunctionBlock);
    let sections: Vec<_> =
        fb.var_blocks.iter().map(|b| (b.section, b.retain, b.constant)).collect();
    use VarSection::*;
    assert_eq!(
        sections,
        vec![
            (Input, false, false),
            (Output, false, false),
            (InOut, false, false),
            (External, false, false),
            (Temp, false, false),
            (Var, true, false),
            (Var, true, true),
            (Var, false, false)
        ]
    );
    assert!(matches!(&f.items[1], Item::Globals(b) if b.constant && b.section == Global));
    let Item::Pou(func) = &f.items[2] else { panic!() };
    assert_eq!(func.kind, PouKind::Function);
    assert!(matches!(&func.return_type, Some(TypeRef::Named(n)) if n.name == "INT"));
    assert_eq!(func.body.len(), 1);
    let Item::Pou(nr) = &f.items[3] else { panic!() };
    assert!(nr.return_type.is_none());
}

#[test]
fn declaration_comments_are_descriptions() {
    let d = decls(
        "Lim5 AT %IX27 : BOOL; (* Lim5 je 27. vstupní bit *)\n\
         Teplota AT %IW28 : INT; // Teplota\n\
         NoComment : INT;\n\
         (* a comment on its own line *)\n\
         Other : INT; /* block */",
    );
    let comments: Vec<Option<&str>> = d.iter().map(|v| v.comment.as_deref()).collect();
    assert_eq!(
        comments,
        vec![Some("Lim5 je 27. vstupní bit"), Some("Teplota"), None, Some("block")]
    );
}

#[test]
fn type_blocks() {
    let t = types(
        "Temp : REAL := 10.0;\n\
         Mode : (Rucni, Auto, Vyp) := Vyp;\n\
         Coded : (A := 1, B := 5);\n\
         Based : INT (X, Y);\n\
         Range : REAL(-1.0..+200.0);\n\
         Point : STRUCT\n  x : INT;\n  y : INT := 2;\nEND_STRUCT;\n\
         Temps : ARRAY [1..20] OF Temp := [10(-1.0), 10(1.0)];\n\
         Name : STRING[10] := 'ABCDEF';\n\
         Nested : STRUCT a : ARRAY[0..1] OF Point; END_STRUCT",
    );
    assert_eq!(t.len(), 9);
    assert!(matches!(&t[0].ty, TypeRef::Named(n) if n.name == "REAL"));
    assert!(matches!(&t[0].init, Some(Initializer::Expr(e)) if sx(e) == "10.0"));
    assert!(matches!(&t[1].ty, TypeRef::Enum { values, .. } if values.len() == 3));
    assert!(matches!(&t[1].init, Some(Initializer::Expr(e)) if sx(e) == "Vyp"));
    assert!(
        matches!(&t[2].ty, TypeRef::Enum { values, .. } if values[1].1.as_ref().map(sx) == Some("5".into()))
    );
    assert!(matches!(&t[3].ty, TypeRef::Enum { values, .. } if values.len() == 2));
    assert!(matches!(&t[4].ty, TypeRef::Subrange { low, high, .. }
        if sx(low) == "(Neg 1.0)" && sx(high) == "(Plus 200.0)"));
    assert!(
        matches!(&t[5].ty, TypeRef::Struct { fields, .. } if fields.len() == 2 && fields[1].init.is_some())
    );
    assert!(matches!(&t[6].init, Some(Initializer::Array { elements, .. }) if elements.len() == 2));
    assert!(matches!(&t[7].ty, TypeRef::String { length: Some(_), .. }));
    assert!(matches!(&t[8].ty, TypeRef::Struct { .. }));
}

#[test]
fn case_insensitive_keywords_keep_spelling() {
    let f = parse_ok("program Main var Motor : bool; end_var Motor := NOT motor; End_Program");
    let Item::Pou(p) = &f.items[0] else { panic!() };
    assert_eq!(p.name.name, "Main");
    assert_eq!(p.var_blocks[0].decls[0].names[0].name, "Motor");
    assert_eq!(p.body.len(), 1);
}

#[test]
fn pou_span_covers_the_whole_pou() {
    let src = "  PROGRAM P x := 1; END_PROGRAM  ";
    let f = parse_ok(src);
    let Item::Pou(p) = &f.items[0] else { panic!() };
    assert_eq!(&src[p.span.start as usize..p.span.end as usize], "PROGRAM P x := 1; END_PROGRAM");
}

// ---------------------------------------------------------------- errors and recovery

/// Exactly one diagnostic, with `code`; returns its message.
fn one_error(src: &str, code: &str) -> String {
    let e = errors(src);
    assert_eq!(e.len(), 1, "expected one error for\n{src}\ngot {e:#?}");
    assert_eq!(e[0].0, code, "{e:#?}");
    e[0].1.clone()
}

#[test]
fn one_bad_line_gives_one_error() {
    let good_before = "x := 1;\n";
    let good_after = "\nIF x > 0 THEN x := 2; END_IF;\nx := 3;";
    let cases: &[(&str, &str)] = &[
        ("x := ;", "E0006"),
        ("x := 5 +;", "E0006"),
        ("x := (1 + 2;", "E0006"),
        ("x = 5;", "E0006"),
        ("foo bar;", "E0006"),
        ("x := 5", "E0006"),
        ("x := 12abc;", "E0004"),
        ("x := 'abc;", "E0003"),
        ("x := '$Q';", "E0008"),
        ("x := T#1h75m;", "E0005"),
        ("x := D#2006-13-01;", "E0010"),
        ("x := %QZ1;", "E0009"),
        ("x := 1 ? 2;", "E0001"),
        ("x := INT#TRUE;", "E0013"),
        ("x := INT#;", "E0006"),
        ("x := Color#;", "E0006"),
        ("x := a.;", "E0006"),
        ("x := ?;", "E0001"),
        ("x := BOOL#5;", "E0013"),
        ("THEN x := 1;", "E0006"),
        ("IF x > THEN x := 1; END_IF;", "E0006"),
        ("IF x > 1 x := 1; END_IF;", "E0006"),
        ("FOR i := 1 TO DO x := 1; END_FOR;", "E0006"),
        ("WHILE x < 1 x := 1; END_WHILE;", "E0006"),
        ("CASE x OF 1 x := 1; END_CASE;", "E0006"),
        ("CASE x 1: x := 1; END_CASE;", "E0006"),
        ("x := F(1, ;", "E0006"),
        ("x := a[1;", "E0006"),
        ("my_var_ := 1;", "E0011"),
        ("END_IF;", "E0006"),
        ("x := 99999999999999999999999;", "E0012"),
    ];
    for (line, code) in cases {
        let src = program(&format!("{good_before}{line}{good_after}"));
        let msg = one_error(&src, code);
        assert!(!msg.is_empty());
    }
}

#[test]
fn one_bad_declaration_gives_one_error() {
    let cases: &[(&str, &str)] = &[
        ("y INT;", "E0006"),
        ("y : ;", "E0006"),
        ("y : INT := ;", "E0006"),
        ("y : INT", "E0006"),
        ("y : ARRAY[1..] OF INT;", "E0006"),
        ("y : ARRAY[1..2] INT;", "E0006"),
        ("y AT %QY1 : INT;", "E0009"),
        ("y : INT(0..100;", "E0006"),
        ("123 : INT;", "E0006"),
        ("y : STRING[10;", "E0006"),
    ];
    for (line, code) in cases {
        let src = format!(
            "PROGRAM Main\nVAR\n  a : INT;\n  {line}\n  b : BOOL;\nEND_VAR\nVAR c : INT; END_VAR\nb := TRUE;\nEND_PROGRAM"
        );
        one_error(&src, code);
    }
}

#[test]
fn messages_name_what_was_expected_and_found() {
    let m = one_error(&program("IF x > 0 THEN\n  x := 1\nEND_IF;"), "E0006");
    assert_eq!(m, "expected `;` after the statement, found `END_IF`");
    let m = one_error(&program("iF x > 0 THEN x := 1;"), "E0007");
    assert!(m.starts_with("`END_IF` is missing for this iF"), "{m}");
    let m = one_error(&program("x := ;"), "E0006");
    assert_eq!(m, "expected an expression, found `;`");
}

#[test]
fn missing_end_points_at_the_opening_keyword() {
    let src = program("x := 1;\nWHILE x < 5 DO\n  x := x + 1;\n");
    let (_, d) = parse_source(&src);
    assert_eq!(d.len(), 1, "{d:#?}");
    assert_eq!(d[0].code.as_str(), "E0007");
    assert_eq!(&src[d[0].span.start as usize..d[0].span.end as usize], "WHILE");

    let src = "PROGRAM Main\nx := 1;\n";
    let (_, d) = parse_source(src);
    assert_eq!(d.len(), 1, "{d:#?}");
    assert_eq!((d[0].code.as_str(), d[0].span.start), ("E0007", 0));

    for (src, kw) in [
        ("PROGRAM P VAR x : INT; x := 1; END_PROGRAM", "VAR"),
        ("PROGRAM P VAR x : INT; IF x THEN END_IF END_PROGRAM", "VAR"),
        ("TYPE A : INT; PROGRAM P END_PROGRAM", "TYPE"),
        ("TYPE S : STRUCT a : INT; END_TYPE", "STRUCT"),
        ("PROGRAM P REPEAT x := 1; END_PROGRAM", "REPEAT"),
        ("PROGRAM P CASE x OF 1: x := 1; END_PROGRAM", "CASE"),
        ("PROGRAM P FOR i := 1 TO 2 DO x := 1; END_PROGRAM", "FOR"),
    ] {
        let (_, d) = parse_source(src);
        assert_eq!(d.len(), 1, "{src}: {d:#?}");
        assert_eq!(d[0].code.as_str(), "E0007", "{src}");
        assert_eq!(&src[d[0].span.start as usize..d[0].span.end as usize], kw, "{src}");
    }
}

#[test]
fn recovery_keeps_the_rest_of_the_tree() {
    let (file, d) = parse_source(&program("x := ;\ny := 2;\nIF a THEN b := 1 END_IF;\nz := 3;"));
    assert_eq!(d.len(), 2, "{d:#?}");
    let Item::Pou(p) = &file.items[0] else { panic!() };
    assert_eq!(p.body.len(), 3);
}

#[test]
fn wrong_end_keyword_is_one_error() {
    one_error(&program("IF a THEN x := 1; END_WHILE;"), "E0006");
    one_error("PROGRAM P x := 1; END_FUNCTION_BLOCK", "E0006");
}

#[test]
fn configuration_with_resources_tasks_and_program_instances() {
    let src = "CONFIGURATION C VAR_GLOBAL g : INT; END_VAR RESOURCE R ON PLC TASK t(INTERVAL := T#10ms, PRIORITY := 2); TASK e (SINGLE := g); PROGRAM p WITH t : Main (i := g, o => g); PROGRAM q : Main; END_RESOURCE END_CONFIGURATION\nPROGRAM Main x := 1; END_PROGRAM";
    let (f, d) = parse_source(src);
    assert!(d.is_empty(), "{d:#?}");
    let [Item::Configuration(c), Item::Pou(_)] = &f.items[..] else { panic!("{:#?}", f.items) };
    assert_eq!(c.globals.len(), 1);
    let [r] = &c.resources[..] else { panic!() };
    assert_eq!((r.name.name.as_str(), r.on.as_ref().map(|o| o.name.as_str())), ("R", Some("PLC")));
    assert_eq!(r.tasks.len(), 2);
    assert!(r.tasks[0].interval.is_some() && r.tasks[0].priority.is_some());
    assert!(r.tasks[1].single.is_some() && r.tasks[1].interval.is_none());
    let names: Vec<_> = r
        .programs
        .iter()
        .map(|p| (p.name.name.as_str(), p.task.as_ref().map(|t| t.name.as_str())))
        .collect();
    assert_eq!(names, [("p", Some("t")), ("q", None)]);
    assert_eq!(
        r.programs[0].connections.iter().map(|c| c.output).collect::<Vec<_>>(),
        [false, true]
    );
}

#[test]
fn configuration_without_resource_forms_one() {
    let (f, d) = parse_source("CONFIGURATION C TASK t (INTERVAL := T#1s); PROGRAM p WITH t : Main; END_CONFIGURATION PROGRAM Main END_PROGRAM");
    assert!(d.is_empty(), "{d:#?}");
    let Item::Configuration(c) = &f.items[0] else { panic!() };
    assert_eq!(c.resources.len(), 1);
    assert_eq!(c.resources[0].name.name, "C");
}

#[test]
fn broken_configuration_lines_are_one_error_each() {
    let src = "CONFIGURATION C TASK t INTERVAL; PROGRAM p WITH : Main; PROGRAM q : Main; VAR_ACCESS a : q.x : INT READ_ONLY; END_VAR END_CONFIGURATION\nPROGRAM Main END_PROGRAM";
    let (f, d) = parse_source(src);
    let codes: Vec<_> = d.iter().map(|d| d.code.as_str()).collect();
    assert_eq!(codes, ["E0006", "E0006", "E0620"], "{d:#?}");
    let Item::Configuration(c) = &f.items[0] else { panic!() };
    assert_eq!(c.resources[0].programs.len(), 1);
    assert!(matches!(&f.items[1], Item::Pou(_)));
}

#[test]
fn resource_outside_a_configuration_is_skipped_with_an_error() {
    let (f, d) = parse_source(
        "RESOURCE R ON PLC TASK t (INTERVAL := T#1s); END_RESOURCE\nPROGRAM Main END_PROGRAM",
    );
    assert_eq!(d.len(), 1, "{d:#?}");
    assert!(matches!(&f.items[..], [Item::Pou(_)]));
}

#[test]
fn unclosed_configuration_stops_at_the_next_pou() {
    let (f, d) =
        parse_source("CONFIGURATION C PROGRAM p : Main;\nPROGRAM Main x := 1; END_PROGRAM");
    assert_eq!(d.iter().map(|d| d.code.as_str()).collect::<Vec<_>>(), ["E0007"], "{d:#?}");
    assert!(matches!(&f.items[..], [Item::Configuration(_), Item::Pou(_)]));
}

#[test]
fn garbage_at_top_level_is_one_error() {
    let (f, d) = parse_source("hello world 1 2 3;\nPROGRAM P END_PROGRAM\nVAR x : INT; END_VAR");
    assert_eq!(d.len(), 2, "{d:#?}");
    assert_eq!(f.items.len(), 1);
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    for open in ["(", "-", "NOT ", "F(", "a[", "[", "IF a THEN "] {
        let n = 5000;
        let src = program(&format!("x := {};", open.repeat(n)));
        let (_, d) = parse_source(&src);
        assert!(!d.is_empty());
    }
    let deep_ifs = format!("{}x := 1;{}", "IF a THEN ".repeat(3000), "END_IF; ".repeat(3000));
    let (_, d) = parse_source(&program(&deep_ifs));
    assert!(!d.is_empty());
    // Moderate nesting is fine.
    let ok = format!("x := {}1{};", "(".repeat(60), ")".repeat(60));
    parse_ok(&program(&ok));
}

const SAMPLE: &str = "TYPE\n  Mode : (Auto, Manual) := Manual;\n  Point : STRUCT x : INT; y : INT; END_STRUCT;\nEND_TYPE\n\
VAR_GLOBAL g AT %QX0.0 : BOOL; END_VAR\n\
FUNCTION_BLOCK Blink\nVAR_INPUT en : BOOL; END_VAR\nVAR_OUTPUT q : BOOL; END_VAR\nVAR t : TON; END_VAR\n\
t(IN := en AND NOT t.Q, PT := T#500ms);\nIF t.Q THEN q := NOT q; END_IF;\nEND_FUNCTION_BLOCK\n\
PROGRAM Main\nVAR p : INT := 0; arr : ARRAY[1..3] OF REAL := [3(1.5)]; s : STRING := 'a$Nb'; b : Blink; END_VAR\n\
CASE p OF 0: IF %IX0.0 THEN p := 10; END_IF; 10..19: p := p + 1; ELSE p := 0; END_CASE;\n\
FOR p := 1 TO 3 DO arr[p] := arr[p] * 2.0 ** 2; END_FOR;\n\
b(en := TRUE, q => g);\nWHILE p > 0 DO p := p - 1; END_WHILE;\nREPEAT p := p + 1; UNTIL p >= 3 END_REPEAT;\n\
END_PROGRAM\n";

#[test]
fn sample_program_parses() {
    let f = parse_ok(SAMPLE);
    assert_eq!(f.items.len(), 4);
}

/// A small deterministic generator (no dependencies).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 33
    }
}

#[test]
fn never_panics_on_truncated_or_random_input() {
    // Every prefix of a valid program (on character boundaries).
    for (i, _) in SAMPLE.char_indices() {
        let _ = parse_source(&SAMPLE[..i]);
        let _ = parse_single_expression(&SAMPLE[..i]);
    }
    // Random bytes, random tokens and shuffled pieces of the sample.
    let mut rng = Lcg(42);
    let pieces = [
        "IF",
        "THEN",
        "END_IF",
        "CASE",
        "OF",
        ":",
        ";",
        ":=",
        "(",
        ")",
        "[",
        "]",
        "x",
        "1",
        "..",
        "T#",
        "16#",
        "'",
        "\"",
        "$",
        "%IX",
        ".",
        ",",
        "=>",
        "NOT",
        "VAR",
        "END_VAR",
        "PROGRAM",
        "END_PROGRAM",
        "TYPE",
        "STRUCT",
        "ARRAY",
        "#",
        "(*",
        "*)",
        "{",
        "E",
        "-",
        "**",
        "FOR",
        "TO",
        "DO",
        "REPEAT",
        "UNTIL",
        "ELSE",
        "AT",
        "STRING",
        "\n",
        " ",
        "é",
        "\u{0}",
    ];
    for _ in 0..400 {
        let len = (rng.next() % 80) as usize;
        let bytes: Vec<u8> = (0..len).map(|_| (rng.next() % 256) as u8).collect();
        let text = String::from_utf8_lossy(&bytes);
        let _ = parse_source(&text);
        let tokens: String = (0..len)
            .map(|_| pieces[(rng.next() as usize) % pieces.len()])
            .collect::<Vec<_>>()
            .join(" ");
        let _ = parse_source(&tokens);
        let _ = parse_single_expression(&tokens);
        let glued: String =
            (0..len).map(|_| pieces[(rng.next() as usize) % pieces.len()]).collect();
        let _ = parse_source(&glued);
    }
}

// ---- textual SFC ----

use crate::syntax::ast::sfc::{Qualifier, TransitionCondition};

fn chart_of(src: &str) -> SfcBody {
    match parse_ok(src).items.into_iter().last() {
        Some(Item::Pou(p)) => {
            assert!(p.body.is_empty());
            p.sfc.expect("an SFC body")
        }
        other => panic!("no POU: {other:?}"),
    }
}

#[test]
fn parses_steps_with_qualifiers_durations_and_indicators() {
    let chart = chart_of(
        "PROGRAM Main\ninitial_step S1 : A1(N); A2(L, T#5s); A3(D, T#1s, Lamp); A4(); END_STEP\nSTEP S2: A5(P1, Ind1, Ind2); END_STEP;\nEND_PROGRAM",
    );
    let SfcElement::Step(s1) = &chart.elements[0] else { panic!() };
    assert!(s1.initial);
    assert_eq!(s1.name.name, "S1");
    let q: Vec<_> = s1.associations.iter().map(|a| (a.action.name.as_str(), a.qualifier)).collect();
    assert_eq!(
        q,
        [("A1", Qualifier::N), ("A2", Qualifier::L), ("A3", Qualifier::D), ("A4", Qualifier::N)]
    );
    assert_eq!(sx(s1.associations[1].duration.as_ref().unwrap()), "time:5000000000");
    assert_eq!(s1.associations[2].indicators[0].name, "Lamp");
    let SfcElement::Step(s2) = &chart.elements[1] else { panic!() };
    assert!(!s2.initial);
    let inds: Vec<_> = s2.associations[0].indicators.iter().map(|i| i.name.as_str()).collect();
    assert_eq!(inds, ["Ind1", "Ind2"]);
}

#[test]
fn parses_transitions_in_both_forms_with_priorities_and_step_lists() {
    let chart = chart_of(
        "PROGRAM Main
TRANSITION T1 (PRIORITY := 2) FROM (A, B) TO C := x > 1; END_TRANSITION
TRANSITION FROM C TO (A, B) := TRUE; END_TRANSITION
TRANSITION T3 FROM A TO B : T3 := x = 0; END_TRANSITION
ACTION Act : x := x + 1; END_ACTION
END_PROGRAM",
    );
    let SfcElement::Transition(t1) = &chart.elements[0] else { panic!() };
    assert_eq!(t1.name.as_ref().unwrap().name, "T1");
    assert_eq!(t1.priority.unwrap().0, 2);
    let names = |ids: &[Ident]| ids.iter().map(|i| i.name.clone()).collect::<Vec<_>>();
    assert_eq!((names(&t1.from), names(&t1.to)), (vec!["A".into(), "B".into()], vec!["C".into()]));
    let TransitionCondition::Expr(c) = &t1.condition else { panic!() };
    assert_eq!(sx(c), "(Gt x 1)");
    let SfcElement::Transition(t2) = &chart.elements[1] else { panic!() };
    assert!(t2.name.is_none() && t2.priority.is_none());
    assert_eq!(names(&t2.to), ["A", "B"]);
    let SfcElement::Transition(t3) = &chart.elements[2] else { panic!() };
    assert!(matches!(&t3.condition, TransitionCondition::Body(b) if b.len() == 1));
    let SfcElement::Action(a) = &chart.elements[3] else { panic!() };
    assert_eq!((a.name.name.as_str(), a.body.len()), ("Act", 1));
}

#[test]
fn sfc_syntax_errors_are_located() {
    let errs = errors("PROGRAM Main\nSTEP S1 : A1(N) END_STEP\nTRANSITION FROM S1 S2 := TRUE; END_TRANSITION\nEND_PROGRAM");
    let codes: Vec<_> = errs.iter().map(|(c, _)| *c).collect();
    assert_eq!(codes, ["E0006", "E0006"], "{errs:?}");
    assert!(errs[0].1.contains("expected `;`"), "{errs:?}");
    assert!(errs[1].1.contains("`TO`"), "{errs:?}");
}
