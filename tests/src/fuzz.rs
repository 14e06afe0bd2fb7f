//! The fuzz targets: one function per way user input enters the engine. Each takes any
//! bytes and must return without panicking, hanging past the watchdog or growing memory
//! without bound. `fuzz/` drives them with libFuzzer (`cargo fuzz run TARGET`, long runs,
//! figures in `docs/reliability.md`); `tests/fuzz_smoke.rs` drives them with proptest for a
//! fixed number of cases and replays the seed corpus in every `cargo test`.

use plc_core::run::{run_project, run_source, RunOptions};

/// A fuzz target: takes any bytes, must return.
pub type Target = fn(&[u8]);

/// The targets by name (the file names under `fuzz/fuzz_targets/` and the folders of
/// `fuzz/corpus/`).
pub const TARGETS: &[(&str, Target)] = &[
    ("st_text", st_text),
    ("st_program", st_program),
    ("project_json", project_json),
    ("share_link", share_link),
    ("plcopen_xml", plcopen_xml),
    ("pnml", pnml),
];

fn text(data: &[u8]) -> String {
    String::from_utf8_lossy(data).into_owned()
}

/// Any text through the lexer, parser and checker (what the editor does on every key),
/// and through the syntax highlighter.
pub fn st_text(data: &[u8]) {
    let src = text(data);
    let _ = plc_core::syntax::highlight_spans(&src);
    let _ = plc_core::semantic::analyze(&src);
}

/// A program built from the bytes by a small grammar (so that most inputs check and
/// run), compiled and run for a few scans: the compiler, the VM and the simulator.
pub fn st_program(data: &[u8]) {
    let src = program_from_bytes(data);
    let options = RunOptions { cycles: 3, ..Default::default() };
    let _ = run_source(&src, &options);
}

/// Any text as a project file, then built and run as `plc run` does.
pub fn project_json(data: &[u8]) {
    if let Ok(p) = plc_core::project::Project::from_file(&text(data)) {
        let _ = run_project(&p, &RunOptions { cycles: 2, ..Default::default() });
    }
}

/// Any text as a share link's fragment.
pub fn share_link(data: &[u8]) {
    if let Ok(p) = plc_core::project::decode_share(&text(data)) {
        let _ = plc_core::build::build_project(&p);
    }
}

/// Any text as a PLCopen XML document, then built (and its network POUs exported and read back).
pub fn plcopen_xml(data: &[u8]) {
    if let Ok(i) = plc_core::plcopen::import(&text(data)) {
        let _ = plc_core::build::build_project(&i.project);
        // Network POUs are written back element for element; what comes back imports.
        if !i.project.networks.is_empty() {
            let _ = plc_core::plcopen::import(&plc_core::plcopen::export(&i.project));
        }
    }
}

/// Any text as a PNML document, then analysed and compiled.
pub fn pnml(data: &[u8]) {
    if let Ok(pou) = plc_core::pnml::import(&text(data)) {
        let _ = plc_core::petri::compile(&pou);
    }
}

/// Reads bytes as choices of a tiny ST grammar: declarations of a few variables of varied
/// types, then statements (assignments of expressions, IF, CASE, FOR, WHILE with a bounded
/// counter, calls of standard functions and FBs). Every byte sequence gives a program; most
/// of them check, so the compiler and the VM get real work.
pub fn program_from_bytes(data: &[u8]) -> String {
    let mut g = Gen { data, at: 0 };
    let mut body = String::new();
    let statements = 1 + g.pick(12);
    for _ in 0..statements {
        g.statement(&mut body, 0);
    }
    format!(
        "PROGRAM Main\nVAR\n  i, j : INT; d : DINT := 7; l : LINT; u : UINT; b : BOOL; w : WORD;\n  \
         r : REAL := 1.5; lr : LREAL; t : TIME; s : STRING[20] := 'ab'; \
         a : ARRAY[1..4] OF INT; k : INT;\n  tm : TON; ct : CTU;\nEND_VAR\n{body}END_PROGRAM\n"
    )
}

struct Gen<'a> {
    data: &'a [u8],
    at: usize,
}

const INT_VARS: &[&str] = &["i", "j", "k", "a[1]", "a[ABS(k MOD 4) + 1]", "ct.CV"];
const REAL_VARS: &[&str] = &["lr", "REAL_TO_LREAL(r)"];

impl Gen<'_> {
    /// The next choice in `0..n` (0 once the bytes run out).
    fn pick(&mut self, n: usize) -> usize {
        let b = self.data.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        usize::from(b) % n.max(1)
    }

    fn one<'s>(&mut self, items: &[&'s str]) -> &'s str {
        items[self.pick(items.len())]
    }

    fn int_expr(&mut self, depth: usize) -> String {
        if depth > 3 {
            return self.int_atom();
        }
        match self.pick(8) {
            0..=2 => self.int_atom(),
            3 => {
                let op = self.one(&["+", "-", "*", "/", "MOD", "AND", "OR", "XOR"]);
                format!("({} {op} {})", self.int_expr(depth + 1), self.int_expr(depth + 1))
            }
            4 => {
                let f = self.one(&["ABS", "MIN", "MAX", "LIMIT", "SEL"]);
                match f {
                    "ABS" => format!("ABS({})", self.int_expr(depth + 1)),
                    "LIMIT" => format!("LIMIT(0, {}, 100)", self.int_expr(depth + 1)),
                    "SEL" => format!(
                        "SEL({}, {}, {})",
                        self.bool_expr(depth + 1),
                        self.int_expr(depth + 1),
                        self.int_expr(depth + 1)
                    ),
                    _ => format!("{f}({}, {})", self.int_expr(depth + 1), self.int_expr(depth + 1)),
                }
            }
            5 => format!("LEN({})", self.str_expr()),
            6 => format!("LREAL_TO_INT({})", self.real_expr(depth + 1)),
            _ => format!("-{}", self.int_atom()),
        }
    }

    fn int_atom(&mut self) -> String {
        match self.pick(3) {
            0 => self.one(INT_VARS).to_string(),
            1 => format!("{}", self.pick(256) as i32 - 128),
            _ => ["32767", "-32768", "0", "1", "16#7F"][self.pick(5)].to_string(),
        }
    }

    fn real_expr(&mut self, depth: usize) -> String {
        match self.pick(5) {
            0 => self.one(REAL_VARS).to_string(),
            1 => format!("{}.25", self.pick(100)),
            2 if depth < 3 => {
                let f = self.one(&["SQRT", "LN", "SIN", "EXP"]);
                format!("{f}({})", self.real_expr(depth + 1))
            }
            3 if depth < 3 => {
                let op = self.one(&["+", "-", "*", "/"]);
                format!("({} {op} {})", self.real_expr(depth + 1), self.real_expr(depth + 1))
            }
            _ => format!("INT_TO_LREAL({})", self.int_expr(depth + 1)),
        }
    }

    fn bool_expr(&mut self, depth: usize) -> String {
        match self.pick(5) {
            0 => "b".to_string(),
            1 => format!("NOT {}", if depth < 3 { self.bool_expr(depth + 1) } else { "b".into() }),
            2 => "tm.Q".to_string(),
            _ => {
                let op = self.one(&["=", "<>", "<", "<=", ">", ">="]);
                format!("({} {op} {})", self.int_expr(depth + 1), self.int_expr(depth + 1))
            }
        }
    }

    fn str_expr(&mut self) -> String {
        match self.pick(4) {
            0 => "s".to_string(),
            1 => "'xyz'".to_string(),
            2 => format!("CONCAT(s, '{}')", self.pick(10)),
            _ => format!("MID(s, {}, {})", self.pick(4), self.pick(4)),
        }
    }

    fn statement(&mut self, out: &mut String, depth: usize) {
        let indent = "  ".repeat(depth + 1);
        let choice = if depth >= 2 { self.pick(5) } else { self.pick(10) };
        match choice {
            0 => {
                let wide = self.one(&[
                    "d := INT_TO_DINT",
                    "l := INT_TO_LINT",
                    "u := INT_TO_UINT",
                    "w := INT_TO_WORD",
                ]);
                let e = self.int_expr(0);
                out.push_str(&format!("{indent}{wide}({e});\n"));
            }
            1 => {
                let v = self.one(&INT_VARS[..5]);
                let e = self.int_expr(0);
                out.push_str(&format!("{indent}{v} := {e};\n"));
            }
            2 => {
                let e = self.real_expr(0);
                match self.pick(2) {
                    0 => out.push_str(&format!("{indent}lr := {e};\n")),
                    _ => out.push_str(&format!("{indent}r := LREAL_TO_REAL({e});\n")),
                }
            }
            3 => out.push_str(&format!("{indent}b := {};\n", self.bool_expr(0))),
            4 => out.push_str(&format!("{indent}s := {};\n", self.str_expr())),
            5 => {
                out.push_str(&format!("{indent}IF {} THEN\n", self.bool_expr(0)));
                self.statement(out, depth + 1);
                out.push_str(&format!("{indent}ELSE\n"));
                self.statement(out, depth + 1);
                out.push_str(&format!("{indent}END_IF;\n"));
            }
            6 => {
                out.push_str(&format!("{indent}CASE {} OF\n", self.int_expr(0)));
                for label in 0..1 + self.pick(3) {
                    out.push_str(&format!(
                        "{indent}{}, {}..{}:\n",
                        label * 10,
                        label * 10 + 1,
                        label * 10 + 5
                    ));
                    self.statement(out, depth + 1);
                }
                out.push_str(&format!("{indent}END_CASE;\n"));
            }
            7 => {
                let to = self.int_expr(0);
                out.push_str(&format!("{indent}FOR k := 1 TO LIMIT(0, {to}, 50) DO\n"));
                self.statement(out, depth + 1);
                out.push_str(&format!("{indent}END_FOR;\n"));
            }
            8 => {
                out.push_str(&format!(
                    "{indent}j := 0;\n{indent}WHILE j < 20 AND {} DO\n",
                    self.bool_expr(0)
                ));
                out.push_str(&format!("{indent}  j := j + 1;\n"));
                self.statement(out, depth + 1);
                out.push_str(&format!("{indent}END_WHILE;\n"));
            }
            _ => {
                let e = self.bool_expr(0);
                out.push_str(&format!(
                    "{indent}tm(IN := {e}, PT := T#{}ms);\n{indent}ct(CU := b, PV := {});\n{indent}t := tm.ET;\n",
                    self.pick(100),
                    self.pick(10)
                ));
            }
        }
    }
}
