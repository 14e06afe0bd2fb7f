//! The Instruction List view of a ladder POU, beside the ST view: a rung of contacts and
//! coils (normal, negated, set, reset) reads as IL, `C := A AND NOT B;` as
//! `LD A` / `ANDN B` / `ST C`. It is made from the ST view's statements, so the two views
//! always say the same; a rung with blocks, edges, jumps or returns has no IL view and says
//! so. Nested OR/AND become deferred operations (`AND(` … `)`).

use super::model::LadderPou;
use super::st_view::view_statements;
use crate::syntax::ast::{BinaryOp, Expr, ExprKind, LiteralValue, StmtKind, UnaryOp};

/// The IL body of a ladder POU and a map from its 1-based lines to 0-based rungs. Rungs
/// without an IL form appear as a comment saying so.
pub fn il_view(pou: &LadderPou) -> (String, Vec<(u32, usize)>) {
    let (lines, _) = view_statements(pou);
    let mut out: Vec<(String, Option<usize>)> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let Some(rung) = lines[i].1 else {
            i += 1;
            continue;
        };
        let mut end = i;
        while end < lines.len() && lines[end].1 == Some(rung) {
            end += 1;
        }
        let rung_lines = &lines[i..end];
        match rung_il(rung_lines) {
            Some(il) => out.extend(il.into_iter().map(|l| (l, Some(rung)))),
            None => out.push((
                format!("(* rung {}: no IL view (it holds blocks, edges or jumps) *)", rung + 1),
                Some(rung),
            )),
        }
        i = end;
    }
    let mut text = String::new();
    let mut map = Vec::new();
    for (n, (line, rung)) in out.iter().enumerate() {
        text.push_str(line);
        text.push('\n');
        if let Some(r) = rung {
            map.push((n as u32 + 1, *r));
        }
    }
    (text, map)
}

/// Whether every rung of `pou` has an IL form (the view then is a complete IL body).
pub fn has_il_view(pou: &LadderPou) -> bool {
    !il_view(pou).0.contains("no IL view")
}

/// The IL lines of one rung's ST view lines, or `None` when one is not a coil statement.
fn rung_il(lines: &[(String, Option<usize>)]) -> Option<Vec<String>> {
    let mut out = Vec::new();
    for (line, _) in lines {
        let t = line.trim();
        if t.starts_with("(*") {
            out.push(t.to_string());
            continue;
        }
        let wrapped = format!("PROGRAM P\n{t}\nEND_PROGRAM\n");
        let (file, diags) = crate::syntax::parse(&wrapped);
        if !diags.is_empty() {
            return None;
        }
        let Some(crate::syntax::ast::Item::Pou(p)) = file.items.first() else { return None };
        let [stmt] = p.body.as_slice() else { return None };
        match &stmt.kind {
            StmtKind::Assign { target, value } => {
                let target = place(&wrapped, target)?;
                match &value.kind {
                    ExprKind::Unary(UnaryOp::Not, inner) if !is_atom(inner) => {
                        load(&wrapped, inner, &mut out, 0)?;
                        out.push(format!("STN {target}"));
                    }
                    _ => {
                        load(&wrapped, value, &mut out, 0)?;
                        out.push(format!("ST {target}"));
                    }
                }
            }
            StmtKind::If { branches, else_body: None } => {
                let [(cond, body)] = branches.as_slice() else { return None };
                let [write] = body.as_slice() else { return None };
                let StmtKind::Assign { target, value } = &write.kind else { return None };
                let ExprKind::Literal(lit) = &value.kind else { return None };
                let LiteralValue::Bool(set) = lit.value else { return None };
                let target = place(&wrapped, target)?;
                load(&wrapped, cond, &mut out, 0)?;
                out.push(format!("{} {target}", if set { "S" } else { "R" }));
            }
            _ => return None,
        }
    }
    Some(out)
}

/// The text of a variable, member or address operand.
fn place(src: &str, e: &Expr) -> Option<String> {
    is_atom(e).then(|| text(src, e))
}

fn text(src: &str, e: &Expr) -> String {
    src.get(e.span.start as usize..e.span.end as usize).unwrap_or("").to_string()
}

fn is_atom(e: &Expr) -> bool {
    matches!(
        e.kind,
        ExprKind::Name(_)
            | ExprKind::Member(..)
            | ExprKind::Direct(_)
            | ExprKind::Bit(..)
            | ExprKind::Index(..)
    ) || matches!(&e.kind, ExprKind::Literal(l) if matches!(l.value, LiteralValue::Bool(_)))
}

/// Deepest nesting of parentheses the view writes.
const MAX_DEPTH: usize = 32;

/// Appends the instructions that load `e` into the CR.
fn load(src: &str, e: &Expr, out: &mut Vec<String>, depth: usize) -> Option<()> {
    if depth > MAX_DEPTH {
        return None;
    }
    match &e.kind {
        ExprKind::Paren(inner) => load(src, inner, out, depth + 1),
        ExprKind::Unary(UnaryOp::Not, inner) if is_atom(inner) => {
            out.push(format!("LDN {}", text(src, inner)));
            Some(())
        }
        ExprKind::Binary(op @ (BinaryOp::And | BinaryOp::Or), l, r) => {
            load(src, l, out, depth + 1)?;
            operate(src, *op, r, out, depth + 1)
        }
        _ if is_atom(e) => {
            out.push(format!("LD {}", text(src, e)));
            Some(())
        }
        _ => None,
    }
}

/// Appends `op r` on the CR: `AND x`, `ANDN x`, or `AND(` … `)` for a compound `r`.
fn operate(src: &str, op: BinaryOp, r: &Expr, out: &mut Vec<String>, depth: usize) -> Option<()> {
    let name = if op == BinaryOp::And { "AND" } else { "OR" };
    let mut r = r;
    while let ExprKind::Paren(inner) = &r.kind {
        r = inner;
    }
    match &r.kind {
        _ if is_atom(r) => out.push(format!("{name} {}", text(src, r))),
        ExprKind::Unary(UnaryOp::Not, inner) if is_atom(inner) => {
            out.push(format!("{name}N {}", text(src, inner)));
        }
        ExprKind::Unary(UnaryOp::Not, inner) => {
            let start = out.len();
            load(src, inner, out, depth + 1)?;
            nest(out, start, &format!("{name}N("));
        }
        _ => {
            let start = out.len();
            load(src, r, out, depth + 1)?;
            nest(out, start, &format!("{name}("));
        }
    }
    Some(())
}

/// Turns the instructions from `start` into a deferred operation: the first load joins the
/// opening (`AND( x`), the rest is indented, and `)` closes it.
fn nest(out: &mut Vec<String>, start: usize, open: &str) {
    let body: Vec<String> = out.drain(start..).collect();
    let mut it = body.into_iter();
    match it.next() {
        Some(first) => match first.strip_prefix("LD ") {
            Some(x) => out.push(format!("{open} {x}")),
            None => {
                out.push(open.to_string());
                out.push(format!("    {first}"));
            }
        },
        None => out.push(open.to_string()),
    }
    out.extend(it.map(|l| format!("    {l}")));
    out.push(")".to_string());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lecture_rungs_read_as_the_lecture_il() {
        let text = include_str!("../../../examples/lecture-ld-il-st.plcproj.json");
        let project = crate::project::Project::from_file(text).expect("opens");
        let pou = &project.ladder[0];
        let (il, map) = il_view(pou);
        assert!(il.contains("LD A\nANDN B\nST C\n"), "{il}");
        assert!(il.contains("LD Start\nOR Motor\nANDN Stop\nST Motor\n"), "{il}");
        assert!(map.iter().any(|&(_, r)| r == 1));
        assert!(has_il_view(pou));
    }

    /// Each ST view statement's IL, run as an IL body, gives what the statement gives, for
    /// every value of A, B, C, D and every start value of Y.
    #[test]
    fn coil_statements_and_their_il_agree_for_all_inputs() {
        let statements = [
            "Y := A AND NOT B;",
            "Y := NOT (A OR B);",
            "IF A AND NOT B THEN Y := TRUE; END_IF;",
            "IF (A OR C) AND D THEN Y := FALSE; END_IF;",
            "Y := A AND (B OR NOT C) AND D;",
            "Y := (A AND B OR C AND NOT D) AND NOT (B OR D);",
            "Y := A OR B AND (C OR D);",
        ];
        let decl = "VAR_INPUT A, B, C, D : BOOL; END_VAR VAR_IN_OUT Y : BOOL; END_VAR";
        for st in statements {
            let il = rung_il(&[(st.to_string(), Some(0))]).unwrap_or_else(|| panic!("{st}"));
            let il = il.join("\n");
            let src = format!(
                "FUNCTION_BLOCK S {decl}\n{st}\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK I {decl}\n{il}\nEND_FUNCTION_BLOCK\n\
                 PROGRAM Main VAR s : S; i : I; ys, yi : BOOL; k : INT; bad : INT; END_VAR\n\
                 FOR k := 0 TO 31 DO ys := (k / 16) MOD 2 = 1; yi := ys;\n\
                 s(A := k MOD 2 = 1, B := (k / 2) MOD 2 = 1, C := (k / 4) MOD 2 = 1, D := (k / 8) MOD 2 = 1, Y := ys);\n\
                 i(A := k MOD 2 = 1, B := (k / 2) MOD 2 = 1, C := (k / 4) MOD 2 = 1, D := (k / 8) MOD 2 = 1, Y := yi);\n\
                 IF ys <> yi THEN bad := bad + 1; END_IF; END_FOR;\nEND_PROGRAM\n"
            );
            let report = crate::run::run_source(&src, &crate::run::RunOptions::default());
            assert_eq!(
                report.vars.get("bad"),
                Some(&serde_json::json!(0)),
                "{st} vs\n{il}\n{:?}",
                report.diagnostics
            );
        }
    }

    #[test]
    fn other_statements_have_no_il_view() {
        for st in ["LdEdge_0(CLK := A);", "Y := A + 1 > 2;", "IF A THEN RETURN; END_IF;", "x"] {
            assert!(rung_il(&[(st.to_string(), Some(0))]).is_none(), "{st}");
        }
    }
}
