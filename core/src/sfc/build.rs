//! Small constructors for the syntax tree the SFC lowering generates.
//!
//! Every generated node carries the span of the SFC element it comes from (a step, a
//! transition, an action), so diagnostics, the debug map and runtime faults point at the
//! user's chart and never at text that does not exist.

use crate::diagnostics::Span;
use crate::syntax::ast::*;

/// Builds nodes located at one span.
#[derive(Debug, Clone, Copy)]
pub(super) struct At(pub Span);

impl At {
    pub fn ident(self, name: &str) -> Ident {
        Ident { name: name.to_string(), span: self.0 }
    }

    fn expr(self, kind: ExprKind) -> Expr {
        Expr { kind, span: self.0 }
    }

    /// A variable by name.
    pub fn name(self, name: &str) -> Expr {
        self.expr(ExprKind::Name(self.ident(name)))
    }

    /// `var.field`
    pub fn field(self, var: &str, field: &str) -> Expr {
        self.expr(ExprKind::Member(Box::new(self.name(var)), self.ident(field)))
    }

    pub fn bool(self, value: bool) -> Expr {
        self.literal(LiteralValue::Bool(value))
    }

    pub fn time(self, ns: i64) -> Expr {
        self.literal(LiteralValue::Time(ns))
    }

    fn literal(self, value: LiteralValue) -> Expr {
        self.expr(ExprKind::Literal(Literal { value, type_prefix: None }))
    }

    pub fn not(self, e: Expr) -> Expr {
        self.expr(ExprKind::Unary(UnaryOp::Not, Box::new(e)))
    }

    pub fn bin(self, op: BinaryOp, a: Expr, b: Expr) -> Expr {
        self.expr(ExprKind::Binary(op, Box::new(a), Box::new(b)))
    }

    pub fn and(self, a: Expr, b: Expr) -> Expr {
        self.bin(BinaryOp::And, a, b)
    }

    pub fn or(self, a: Expr, b: Expr) -> Expr {
        self.bin(BinaryOp::Or, a, b)
    }

    /// The OR of `terms`; FALSE when there is none.
    pub fn any(self, terms: Vec<Expr>) -> Expr {
        self.balanced(terms, BinaryOp::Or).unwrap_or_else(|| self.bool(false))
    }

    /// The AND of `terms`; TRUE when there is none.
    pub fn all(self, terms: Vec<Expr>) -> Expr {
        self.balanced(terms, BinaryOp::And).unwrap_or_else(|| self.bool(true))
    }

    /// `terms` joined by `op` as a balanced tree: `(a op b) op (c op d)`. The terms are
    /// still evaluated left to right, and a chart joining thousands of steps gives a tree
    /// of logarithmic height, which the checker and the compiler walk without exhausting
    /// the stack (a chain `a op b op c …` would be one level per step).
    fn balanced(self, mut terms: Vec<Expr>, op: BinaryOp) -> Option<Expr> {
        while terms.len() > 1 {
            let mut paired = Vec::with_capacity(terms.len().div_ceil(2));
            let mut it = terms.into_iter();
            while let Some(a) = it.next() {
                paired.push(match it.next() {
                    Some(b) => self.bin(op, a, b),
                    None => a,
                });
            }
            terms = paired;
        }
        terms.pop()
    }

    fn stmt(self, kind: StmtKind) -> Stmt {
        Stmt { kind, span: self.0 }
    }

    pub fn assign(self, target: Expr, value: Expr) -> Stmt {
        self.stmt(StmtKind::Assign { target, value })
    }

    pub fn if_then(self, cond: Expr, body: Vec<Stmt>) -> Stmt {
        self.stmt(StmtKind::If { branches: vec![(cond, body)], else_body: None })
    }

    pub fn if_else(self, cond: Expr, body: Vec<Stmt>, else_body: Vec<Stmt>) -> Stmt {
        self.stmt(StmtKind::If { branches: vec![(cond, body)], else_body: Some(else_body) })
    }

    /// `IF c1 THEN b1 ELSIF c2 THEN b2 … END_IF` (nothing when `branches` is empty).
    pub fn if_chain(self, branches: Vec<(Expr, Vec<Stmt>)>) -> Option<Stmt> {
        (!branches.is_empty()).then(|| self.stmt(StmtKind::If { branches, else_body: None }))
    }

    /// A declaration `name : type [:= init];`.
    pub fn decl(self, name: &str, ty: &str, init: Option<Initializer>) -> VarDecl {
        VarDecl {
            names: vec![self.ident(name)],
            location: None,
            ty: TypeRef::Named(self.ident(ty)),
            init,
            comment: None,
            span: self.0,
        }
    }

    /// A structure type `name : STRUCT fields END_STRUCT`.
    pub fn struct_type(self, name: &str, fields: Vec<(String, &str)>) -> TypeDef {
        let fields = fields.iter().map(|(f, ty)| self.decl(f, ty, None)).collect();
        TypeDef {
            name: self.ident(name),
            ty: TypeRef::Struct { fields, span: self.0 },
            init: None,
            span: self.0,
        }
    }
}
