//! Walks over the statements of actions and transition bodies for the checks the checker
//! cannot make once the chart is lowered: writes to step flags and action controls,
//! `RETURN` inside an action, and transition bodies that never assign their name.

use std::collections::HashMap;

use crate::diagnostics::{Code, Diagnostic, Span};
use crate::syntax::ast::*;

/// Calls `f` on every statement of `stmts`, nested ones included.
pub(super) fn each_stmt<'a>(stmts: &'a [Stmt], f: &mut impl FnMut(&'a Stmt)) {
    for s in stmts {
        f(s);
        match &s.kind {
            StmtKind::If { branches, else_body } => {
                for (_, body) in branches {
                    each_stmt(body, f);
                }
                if let Some(body) = else_body {
                    each_stmt(body, f);
                }
            }
            StmtKind::Case { arms, else_body, .. } => {
                for arm in arms {
                    each_stmt(&arm.body, f);
                }
                if let Some(body) = else_body {
                    each_stmt(body, f);
                }
            }
            StmtKind::For { body, .. }
            | StmtKind::While { body, .. }
            | StmtKind::Repeat { body, .. } => each_stmt(body, f),
            _ => {}
        }
    }
}

/// The expressions written directly in statement `s` (not those of nested statements).
fn own_exprs(s: &Stmt) -> Vec<&Expr> {
    match &s.kind {
        StmtKind::Assign { target, value } => vec![target, value],
        StmtKind::Call(e) => vec![e],
        StmtKind::If { branches, .. } => branches.iter().map(|(c, _)| c).collect(),
        StmtKind::Case { selector, .. } => vec![selector],
        StmtKind::For { from, to, by, .. } => {
            let mut v = vec![from, to];
            v.extend(by);
            v
        }
        StmtKind::While { cond, .. } => vec![cond],
        StmtKind::Repeat { until, .. } => vec![until],
        _ => Vec::new(),
    }
}

/// Calls `f` on every call expression inside `e`.
fn each_call<'a>(e: &'a Expr, f: &mut impl FnMut(&'a [Arg])) {
    match &e.kind {
        ExprKind::Call { callee, args } => {
            f(args);
            each_call(callee, f);
            for a in args {
                match a {
                    Arg::Positional(v) | Arg::Input { value: v, .. } => each_call(v, f),
                    Arg::Output { target, .. } => each_call(target, f),
                }
            }
        }
        ExprKind::Member(b, _)
        | ExprKind::Bit(b, _)
        | ExprKind::Part { base: b, .. }
        | ExprKind::Unary(_, b) => each_call(b, f),
        ExprKind::Paren(b) => each_call(b, f),
        ExprKind::Index(b, ix) => {
            each_call(b, f);
            for i in ix {
                each_call(i, f);
            }
        }
        ExprKind::Binary(_, a, b) => {
            each_call(a, f);
            each_call(b, f);
        }
        _ => {}
    }
}

/// The variable an access path starts from: `S1` in `S1.X`, `a` in `a[1].b`.
pub(super) fn root(e: &Expr) -> Option<&Ident> {
    match &e.kind {
        ExprKind::Name(id) => Some(id),
        ExprKind::Member(b, _)
        | ExprKind::Bit(b, _)
        | ExprKind::Part { base: b, .. }
        | ExprKind::Index(b, _) => root(b),
        ExprKind::Paren(b) => root(b),
        _ => None,
    }
}

/// Reports every write (assignment or `=>` output) to a variable in `protected` (upper-case
/// name → what it is, e.g. "step"), since only the chart itself may change them.
pub(super) fn check_writes(
    stmts: &[Stmt],
    extra: &[&Expr],
    protected: &HashMap<String, &'static str>,
    diags: &mut Vec<Diagnostic>,
) {
    let mut report = |target: &Expr| {
        let Some(id) = root(target) else { return };
        if let Some(what) = protected.get(&id.key()) {
            let msg = if *what == "step" {
                crate::msg!(StepReadOnly, name = &id.name)
            } else {
                crate::msg!(ActionControlReadOnly, name = &id.name)
            };
            diags.push(Diagnostic::error(Code::SfcReadOnly, target.span, msg));
        }
    };
    let outputs = |e: &Expr, report: &mut dyn FnMut(&Expr)| {
        each_call(e, &mut |args| {
            for a in args {
                if let Arg::Output { target, .. } = a {
                    report(target);
                }
            }
        });
    };
    for e in extra {
        outputs(e, &mut report);
    }
    each_stmt(stmts, &mut |s| {
        if let StmtKind::Assign { target, .. } = &s.kind {
            report(target);
        }
        for e in own_exprs(s) {
            outputs(e, &mut report);
        }
    });
}

/// The first `RETURN` in `stmts`, if any.
pub(super) fn first_return(stmts: &[Stmt]) -> Option<Span> {
    let mut found = None;
    each_stmt(stmts, &mut |s| {
        if matches!(s.kind, StmtKind::Return) && found.is_none() {
            found = Some(s.span);
        }
    });
    found
}

/// True when `stmts` assign the plain variable `name` somewhere.
pub(super) fn assigns(stmts: &[Stmt], name: &Ident) -> bool {
    let mut found = false;
    each_stmt(stmts, &mut |s| {
        if let StmtKind::Assign { target, .. } = &s.kind {
            if let ExprKind::Name(id) = &target.kind {
                found |= id.key() == name.key();
            }
        }
    });
    found
}
