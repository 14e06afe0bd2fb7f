//! Inputs that once crashed or hung the engine (issue 11), built at run time, each with
//! what must come out now: a located error, or a run that completes. The same list runs
//! natively on a thread with a 1 MiB stack (`tests/hostile.rs`) and in wasm32 under Node
//! (`tests/wasm_conformance.rs`), whose stack is 1 MiB too: the browser's stack is
//! small, and a debug build takes the most stack per level, so passing here leaves room.

use plc_core::open::open_text;
use plc_core::run::{run_project, run_source, RunOptions, RunReport, RunStatus};

/// What a hostile input must give.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The program is refused with this code at this 1-based line (any column).
    Error {
        /// The problem code.
        code: &'static str,
        /// The line it is reported on.
        line: u32,
    },
    /// The file is refused when opened, with a message containing this text.
    Refused(&'static str),
    /// The PLC stops with a FAULT at this 1-based line whose message contains the text.
    Faults {
        /// The line of the faulting statement.
        line: u32,
        /// Part of the message.
        text: &'static str,
    },
    /// The program runs and `var` ends with this JSON value.
    Runs {
        /// The variable.
        var: &'static str,
        /// Its value as `plc run --json` prints it.
        value: serde_json::Value,
    },
}

/// One input: a name, the text, and what it must give.
pub struct Hostile {
    /// What the input is.
    pub name: &'static str,
    /// The file's text (an ST program, a PLCopen XML or PNML document).
    pub text: String,
    /// What must come out.
    pub outcome: Outcome,
}

fn sum(terms: usize) -> String {
    let sum = vec!["1"; terms].join("+");
    format!("PROGRAM Main VAR x : DINT; END_VAR x := {sum}; END_PROGRAM")
}

fn nested_fbs(levels: usize) -> String {
    let mut s =
        String::from("FUNCTION_BLOCK F0 VAR x : INT; END_VAR x := x + 1; END_FUNCTION_BLOCK\n");
    for i in 1..levels {
        s += &format!("FUNCTION_BLOCK F{i} VAR f : F{}; END_VAR f(); END_FUNCTION_BLOCK\n", i - 1);
    }
    s + &format!("PROGRAM Main VAR top : F{}; END_VAR top(); END_PROGRAM\n", levels - 1)
}

/// Structs nested `levels` deep, the outermost declared first (so that resolving it
/// recurses through all the others) or last.
fn nested_structs(levels: usize, outermost_first: bool) -> String {
    let mut decls: Vec<String> =
        (1..levels).map(|i| format!("S{i} : STRUCT s : S{}; END_STRUCT;", i - 1)).collect();
    decls.insert(0, "S0 : STRUCT x : INT; END_STRUCT;".into());
    if outermost_first {
        decls.reverse();
    }
    format!(
        "TYPE\n{}\nEND_TYPE\nPROGRAM Main VAR top : S{}; END_VAR END_PROGRAM\n",
        decls.join("\n"),
        levels - 1
    )
}

/// An SFC whose start step fans out to `n` steps that all join again (an AND divergence and
/// convergence of `n` branches), then `n` alternative branches back.
fn wide_sfc(n: usize) -> String {
    let steps: Vec<String> = (0..n).map(|i| format!("S{i}")).collect();
    let list = steps.join(", ");
    let mut s =
        String::from("PROGRAM Main\nVAR finished : BOOL; END_VAR\nINITIAL_STEP Start : END_STEP\n");
    s += &format!("TRANSITION FROM Start TO ({list}) := TRUE; END_TRANSITION\n");
    for step in &steps {
        s += &format!("STEP {step} : END_STEP\n");
    }
    s += &format!("TRANSITION FROM ({list}) TO Done := TRUE; END_TRANSITION\n");
    s += "STEP Done : finished(N); END_STEP\n";
    for i in 0..n {
        s += &format!(
            "TRANSITION FROM Done TO X{i} := FALSE; END_TRANSITION\nSTEP X{i} : END_STEP\n"
        );
        s += &format!("TRANSITION FROM X{i} TO Start := TRUE; END_TRANSITION\n");
    }
    s + "END_PROGRAM\n"
}

/// A CASE of `n` labels 0, 2, 4, … and a last range overlapping the one before it.
fn wide_case(n: usize) -> String {
    let mut src = String::from("PROGRAM Main VAR x, y : DINT; END_VAR\nCASE x OF\n");
    for k in 0..n {
        src.push_str(&format!("{}: y := {k};\n", 2 * k));
    }
    src.push_str(&format!("{}..{}: y := 0;\nEND_CASE;\nEND_PROGRAM\n", 2 * n - 3, 2 * n - 1));
    src
}

fn deep_xml(depth: usize) -> String {
    format!(
        "<?xml version=\"1.0\"?><project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">{}{}</project>",
        "<a>".repeat(depth),
        "</a>".repeat(depth)
    )
}

/// An FBD program whose `n` NOT functions each feed the next: `Y := NOT(NOT(…(A)))`.
fn fbd_chain(n: usize) -> String {
    let mut body = String::from(
        r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>A</expression></inVariable>"#,
    );
    for k in 2..n + 2 {
        body.push_str(&format!(
            r#"<block localId="{k}" typeName="NOT"><position x="{k}" y="0"/><inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="{}"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#,
            k - 1
        ));
    }
    body.push_str(&format!(
        r#"<outVariable localId="{}"><position x="0" y="50"/><connectionPointIn><connection refLocalId="{}" formalParameter="OUT"/></connectionPointIn><expression>Y</expression></outVariable>"#,
        n + 2,
        n + 1
    ));
    format!(
        r#"<?xml version="1.0"?><project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="Main" pouType="program"><interface><localVars><variable name="A"><type><BOOL/></type></variable><variable name="Y"><type><BOOL/></type></variable></localVars></interface><body><FBD>{body}</FBD></body></pou></pous></types></project>"#
    )
}

fn deep_pnml(depth: usize) -> String {
    format!(
        "<?xml version=\"1.0\"?><pnml><net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/ptnet\">{}{}</net></pnml>",
        "<a>".repeat(depth),
        "</a>".repeat(depth)
    )
}

/// Every hostile input, with what it must give.
pub fn all() -> Vec<Hostile> {
    let error = |code, line| Outcome::Error { code, line };
    vec![
        Hostile { name: "a 20,000-term sum", text: sum(20_000), outcome: error("E0014", 1) },
        Hostile {
            name: "a 100-term sum (at the limit)",
            text: sum(100),
            outcome: Outcome::Runs { var: "x", value: 100.into() },
        },
        Hostile {
            name: "a 20,000-step member chain",
            text: format!(
                "TYPE S : STRUCT b : INT; END_STRUCT; END_TYPE\n\
                 PROGRAM Main VAR a : S; x : INT; END_VAR x := a{}; END_PROGRAM",
                ".b".repeat(20_000)
            ),
            outcome: error("E0014", 2),
        },
        Hostile {
            name: "a 20,000-step index chain",
            text: format!(
                "PROGRAM Main VAR a : ARRAY[0..1] OF INT; x : INT; END_VAR x := a{}; END_PROGRAM",
                "[0]".repeat(20_000)
            ),
            outcome: error("E0014", 1),
        },
        Hostile {
            name: "a 20,000-step dereference chain",
            text: format!(
                "PROGRAM Main VAR r : REF_TO INT; x : INT; END_VAR x := r{}; END_PROGRAM",
                "^".repeat(20_000)
            ),
            outcome: error("E0014", 1),
        },
        Hostile {
            name: "a reference type nested 20,000 deep",
            text: format!(
                "PROGRAM Main VAR r : {}INT; END_VAR END_PROGRAM",
                "REF_TO ".repeat(20_000)
            ),
            outcome: error("E0014", 1),
        },
        Hostile {
            name: "dereferences and REF() alternating 40 deep (at the limit)",
            text: format!(
                "PROGRAM Main VAR a : INT := 7; r : REF_TO INT; x : INT; END_VAR \
                 r := REF(a); x := {}r{}; END_PROGRAM",
                "REF(".repeat(40),
                ")^".repeat(40) + "^"
            ),
            outcome: Outcome::Runs { var: "x", value: 7.into() },
        },
        Hostile {
            name: "parentheses around a chain at the limit",
            text: format!(
                "PROGRAM Main VAR x : DINT; END_VAR x := {}{}{}; END_PROGRAM",
                "(".repeat(90),
                vec!["1"; 60].join("+"),
                ")".repeat(90)
            ),
            outcome: error("E0014", 1),
        },
        Hostile {
            name: "function blocks nested 3,000 deep",
            text: nested_fbs(3_000),
            outcome: error("E0014", 66),
        },
        Hostile {
            name: "structs nested 3,000 deep, innermost first",
            text: nested_structs(3_000, false),
            outcome: error("E0014", 3_003),
        },
        Hostile {
            name: "structs nested 3,000 deep, outermost first",
            text: nested_structs(3_000, true),
            outcome: error("E0014", 2_938),
        },
        Hostile {
            name: "an SFC joining 3,000 steps",
            text: wide_sfc(3_000),
            outcome: Outcome::Runs { var: "finished", value: true.into() },
        },
        Hostile {
            name: "an array whose size overflows 64 bits",
            text: "PROGRAM Main VAR a : ARRAY[-9223372036854775808..9223372036854775807] OF LINT;\n\
                   b : LINT; i : LINT; END_VAR a[i] := 7; END_PROGRAM"
                .to_string(),
            outcome: error("E0170", 1),
        },
        Hostile {
            name: "a CASE of 50,000 labels with one overlap at the end",
            text: wide_case(50_000),
            outcome: error("E0166", 50_003),
        },
        Hostile {
            name: "a loop of whole-array copies",
            text: "PROGRAM Main VAR a, b : ARRAY[1..262144] OF LINT; n : DINT; END_VAR\n\
                   WHILE TRUE DO a := b; n := n + 1; END_WHILE; END_PROGRAM"
                .to_string(),
            outcome: Outcome::Faults { line: 2, text: "watchdog" },
        },
        Hostile {
            name: "a loop of FIND on 60,000-character strings",
            text: format!(
                "PROGRAM Main VAR s : STRING[65535] := '{}';\n\
                 t : STRING[65535] := '{}b'; k : DINT; END_VAR\n\
                 WHILE TRUE DO k := FIND(s, t); END_WHILE; END_PROGRAM",
                "a".repeat(60_000),
                "a".repeat(30_000)
            ),
            outcome: Outcome::Faults { line: 3, text: "watchdog" },
        },
        Hostile {
            name: "a project file with a cycle time of 0 ms",
            text: r#"{"schema":1,"name":"p","source":"PROGRAM Main END_PROGRAM","settings":{"cycle_ms":0}}"#
                .to_string(),
            outcome: Outcome::Refused("1 to 60000 ms"),
        },
        Hostile {
            name: "a project file with a cycle time that overflows the clock",
            text: r#"{"schema":1,"name":"p","source":"PROGRAM Main END_PROGRAM","settings":{"cycle_ms":18446744073709551615}}"#
                .to_string(),
            outcome: Outcome::Refused("1 to 60000 ms"),
        },
        Hostile {
            name: "PLCopen XML nested 200,000 deep",
            text: deep_xml(200_000),
            outcome: Outcome::Refused("at line 1, column 672: elements nested more than 200 deep"),
        },
        Hostile {
            name: "an FBD network of 20,000 functions feeding each other in a row",
            text: fbd_chain(20_000),
            outcome: error("E0105", 0),
        },
        Hostile {
            name: "PNML nested 200,000 deep",
            text: deep_pnml(200_000),
            outcome: Outcome::Refused("nested more than 200 deep"),
        },
    ]
}

/// Opens `text` as the CLI does (`plc run FILE`) and runs it for 3 scans.
fn run(text: &str) -> Result<RunReport, String> {
    let options = RunOptions { cycles: 3, ..Default::default() };
    if text.starts_with("<?xml") || text.starts_with('{') {
        let opened = open_text("hostile", text).map_err(|e| e.to_string())?;
        return Ok(run_project(&opened.project, &options));
    }
    Ok(run_source(text, &options))
}

/// Runs every hostile input and returns what did not come out as it must.
pub fn check_all() -> Vec<String> {
    let mut failures = Vec::new();
    for h in all() {
        let got = run(&h.text);
        let ok = match (&h.outcome, &got) {
            (Outcome::Error { code, line }, Ok(r)) => {
                r.status == RunStatus::Error
                    && r.diagnostics.iter().any(|d| d.code == *code && d.line == *line)
            }
            (Outcome::Refused(text), Err(e)) => e.contains(text),
            (Outcome::Faults { line, text }, Ok(r)) => {
                r.status == RunStatus::Fault
                    && r.fault.as_ref().is_some_and(|f| f.line == *line && f.message.contains(text))
            }
            (Outcome::Runs { var, value }, Ok(r)) => {
                r.status == RunStatus::Ok && r.vars.get(*var) == Some(value)
            }
            _ => false,
        };
        if !ok {
            let got = match got {
                Ok(r) => {
                    let mut d: Vec<String> = r
                        .diagnostics
                        .iter()
                        .take(3)
                        .map(|d| format!("{}:{}: {} {}", d.line, d.column, d.code, d.message))
                        .collect();
                    d.truncate(3);
                    format!("{:?}, {}", r.status, d.join(" | "))
                }
                Err(e) => format!("refused: {e}"),
            };
            failures.push(format!("[{}] wanted {:?}, got {got}", h.name, h.outcome));
        }
    }
    failures
}
