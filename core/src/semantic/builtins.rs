//! The standard functions: signatures, generic typing and conversion names.
//! Function blocks of the standard library are ST code in `prelude.rs`, not here.

use super::check::Checker;
use super::expr::Typed;
use super::ir::{Builtin, Expr, ExprKind, MathFn, StrFunc};
use super::types::{Elem, Type};
use crate::diagnostics::{Code, Span};
use crate::syntax::{self as ast};

/// Names of built-in functions other than conversions, with their parameter names in
/// order (for formal calls); `None` marks variadic functions.
const FIXED: &[(&str, &[&str])] = &[
    ("ABS", &["IN"]),
    ("SQRT", &["IN"]),
    ("LN", &["IN"]),
    ("LOG", &["IN"]),
    ("EXP", &["IN"]),
    ("SIN", &["IN"]),
    ("COS", &["IN"]),
    ("TAN", &["IN"]),
    ("ASIN", &["IN"]),
    ("ACOS", &["IN"]),
    ("ATAN", &["IN"]),
    ("EXPT", &["IN1", "IN2"]),
    ("SHL", &["IN", "N"]),
    ("SHR", &["IN", "N"]),
    ("ROL", &["IN", "N"]),
    ("ROR", &["IN", "N"]),
    ("SEL", &["G", "IN0", "IN1"]),
    ("LIMIT", &["MN", "IN", "MX"]),
    ("LEN", &["IN"]),
    ("LEFT", &["IN", "L"]),
    ("RIGHT", &["IN", "L"]),
    ("MID", &["IN", "L", "P"]),
    ("INSERT", &["IN1", "IN2", "P"]),
    ("DELETE", &["IN", "L", "P"]),
    ("REPLACE", &["IN1", "IN2", "L", "P"]),
    ("FIND", &["IN1", "IN2"]),
    ("TRUNC", &["IN"]),
    ("MOVE", &["IN"]),
    ("NOT", &["IN"]),
    ("SUB", &["IN1", "IN2"]),
    ("DIV", &["IN1", "IN2"]),
    ("MOD", &["IN1", "IN2"]),
    ("GT", &["IN1", "IN2"]),
    ("GE", &["IN1", "IN2"]),
    ("EQ", &["IN1", "IN2"]),
    ("NE", &["IN1", "IN2"]),
    ("LT", &["IN1", "IN2"]),
    ("LE", &["IN1", "IN2"]),
];

/// Variadic functions (at least two inputs, `IN1`, `IN2`, … or `K`, `IN0`, … for MUX).
const VARIADIC: &[&str] = &["MAX", "MIN", "MUX", "CONCAT", "ADD", "MUL", "AND", "OR", "XOR"];

/// A `FROM_TO_TO` conversion name, split.
fn conversion(key: &str) -> Option<(Option<Type>, ConvTarget)> {
    let (from, to) = match key.strip_prefix("TO_") {
        Some(to) => (None, to),
        None => {
            let i = key.find("_TO_")?;
            let from = &key[..i];
            (Some(type_by_name(from)?), &key[i + 4..])
        }
    };
    let target = match to {
        "BCD" => ConvTarget::Bcd,
        _ => ConvTarget::Type(type_by_name(to)?),
    };
    if from.is_none() && target == ConvTarget::Bcd {
        return None;
    }
    Some((from, target))
}

fn type_by_name(name: &str) -> Option<Type> {
    match name {
        "STRING" => Some(Type::Str { wide: false, len: 80 }),
        "WSTRING" => Some(Type::Str { wide: true, len: 80 }),
        "BCD" => Some(Type::Elem(Elem::LWord)),
        _ => Elem::from_name(name).map(Type::Elem),
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum ConvTarget {
    Type(Type),
    Bcd,
}

/// The names of the built-in functions, conversions included (for `did you mean`).
pub(super) fn builtin_names() -> Vec<String> {
    let types: Vec<&str> =
        Elem::ALL.iter().map(|e| e.name()).chain(["STRING", "WSTRING"]).collect();
    let mut names: Vec<String> = FIXED.iter().map(|(n, _)| n.to_string()).collect();
    names.extend(VARIADIC.iter().map(|n| n.to_string()));
    for from in &types {
        for to in &types {
            if from != to {
                names.push(format!("{from}_TO_{to}"));
            }
        }
    }
    names.extend(types.iter().map(|t| format!("TO_{t}")));
    names
}

/// True when `key` (upper case) names a built-in function.
pub fn is_builtin(key: &str) -> bool {
    FIXED.iter().any(|(n, _)| *n == key)
        || VARIADIC.contains(&key)
        || conversion(key).is_some()
        || key == "REF"
}

impl<'a> Checker<'a> {
    /// Orders the arguments of a built-in call positionally.
    fn builtin_args<'e>(
        &mut self,
        name: &ast::Ident,
        args: &'e [ast::Arg],
        span: Span,
    ) -> Option<Vec<&'e ast::Expr>> {
        let key = name.key();
        let params: Vec<String> = match FIXED.iter().find(|(n, _)| *n == key) {
            Some((_, p)) => p.iter().map(|s| s.to_string()).collect(),
            None if key == "MUX" => std::iter::once("K".to_string())
                .chain((0..args.len()).map(|i| format!("IN{i}")))
                .collect(),
            None if VARIADIC.contains(&key.as_str()) => {
                (1..=args.len()).map(|i| format!("IN{i}")).collect()
            }
            None => vec!["IN".to_string()],
        };
        let mut out: Vec<Option<&ast::Expr>> = vec![None; params.len().max(args.len())];
        for (k, arg) in args.iter().enumerate() {
            match arg {
                ast::Arg::Positional(e) => out[k] = Some(e),
                ast::Arg::Input { name: p, value } => {
                    match params.iter().position(|n| n.eq_ignore_ascii_case(&p.name)) {
                        Some(i) => out[i] = Some(value),
                        None => {
                            let msg = format!("`{}` has no input `{}`", name.name, p.name);
                            let inputs = params.clone();
                            self.error_suggesting(
                                Code::NoSuchParameter,
                                p.span,
                                msg,
                                &p.name,
                                inputs,
                            );
                            return None;
                        }
                    }
                }
                ast::Arg::Output { name: p, .. } => {
                    self.error(
                        Code::NotAnOutput,
                        p.span,
                        crate::msg!(HasNoOutputsUseResult, name = name.name),
                    );
                    return None;
                }
            }
        }
        let given: Vec<&ast::Expr> = out.iter().flatten().copied().collect();
        let variadic = VARIADIC.contains(&key.as_str());
        let wrong = if variadic {
            given.len() < 2
        } else {
            given.len() != params.len() || out.len() != params.len()
        };
        if wrong {
            let want = if variadic { "at least 2".to_string() } else { params.len().to_string() };
            let msg = crate::msg!(
                TakesArgumentSGiven,
                name = name.name,
                want = want,
                given = (given.len()).to_string()
            );
            self.error(Code::WrongArgumentCount, span, msg);
            return None;
        }
        Some(given)
    }

    fn builtin_expr(&self, func: Builtin, args: Vec<Expr>, ty: Type, span: Span) -> Expr {
        Expr { kind: ExprKind::Builtin { func, args }, ty, span }
    }

    /// The smallest type all `items` convert to, with each converted.
    fn unify(
        &mut self,
        items: Vec<Typed>,
        span: Span,
        what: &str,
        expected: Option<Type>,
    ) -> Option<(Type, Vec<Expr>)> {
        // Untyped literals only: take the type the context expects when every one fits.
        if let Some(Type::Elem(want)) = expected.filter(|_| items.iter().all(|t| t.flexible)) {
            if items.iter().all(|t| literal_fits(t, want)) {
                let ty = Type::Elem(want);
                let exprs = items.into_iter().map(|t| self.convert(t.e, ty)).collect();
                return Some((ty, exprs));
            }
        }
        let first = items.first()?.e.ty;
        let ty = match first {
            Type::Str { wide, .. } => {
                let mut len = 1;
                for t in &items {
                    match t.e.ty {
                        Type::Str { wide: w, len: l } if w == wide => len = len.max(l),
                        other => {
                            let msg = crate::msg!(
                                AllInputsMustStringsFound,
                                what = what,
                                other = (self.tname(other)).to_string()
                            );
                            self.error(Code::TypeMismatch, t.e.span, msg);
                            return None;
                        }
                    }
                }
                return Some((Type::Str { wide, len }, items.into_iter().map(|t| t.e).collect()));
            }
            Type::Elem(_) => {
                let mut acc = items[0].clone();
                for t in &items[1..] {
                    let el = match (acc.e.ty, t.e.ty) {
                        (Type::Elem(a), Type::Elem(b)) if a == b => Some(a),
                        (Type::Elem(_), Type::Elem(_)) => self.common_of(&acc, t),
                        _ => None,
                    };
                    let Some(el) = el else {
                        let msg = crate::msg!(
                            InputsTypesDoNotMix,
                            what = what,
                            ty = (self.tname(acc.e.ty)).to_string(),
                            ty2 = (self.tname(t.e.ty)).to_string()
                        );
                        self.error(Code::TypeMismatch, t.e.span, msg);
                        return None;
                    };
                    acc = Typed {
                        e: self.convert(acc.e, Type::Elem(el)),
                        flexible: acc.flexible && t.flexible,
                    };
                }
                acc.e.ty
            }
            other => {
                // NULL mixes with references of any one type (`MUX(k, REF(a), NULL)`).
                let null = Type::Ref(super::types::NULL_REF);
                let other = match items.iter().map(|t| t.e.ty).find(|t| *t != null) {
                    Some(r) if other == null && r.is_ref() => r,
                    _ => other,
                };
                let fits = |t: Type| t == other || (t == null && other.is_ref());
                if !items.iter().all(|t| fits(t.e.ty)) {
                    self.error(
                        Code::TypeMismatch,
                        span,
                        crate::msg!(AllInputsMustHaveSame, what = what),
                    );
                    return None;
                }
                other
            }
        };
        let exprs = items.into_iter().map(|t| self.convert(self.null_as(t.e, ty), ty)).collect();
        Some((ty, exprs))
    }

    fn common_of(&self, a: &Typed, b: &Typed) -> Option<Elem> {
        // The operator rules: an untyped literal adopts the other side's type, else the
        // first widening target of both.
        let (ae, be) = (a.e.ty.elem()?, b.e.ty.elem()?);
        if a.flexible && !b.flexible && be.is_num() {
            return Some(be);
        }
        if b.flexible && !a.flexible && ae.is_num() {
            return Some(ae);
        }
        super::expr::WIDENING_ORDER
            .into_iter()
            .find(|&t| super::expr::can_widen(ae, t) && super::expr::can_widen(be, t))
    }

    fn want(&mut self, e: &ast::Expr, ty: Type) -> Option<Expr> {
        let t = self.expr(e, Some(ty))?;
        self.coerce(t, ty, e.span)
    }

    fn want_int(&mut self, e: &ast::Expr) -> Option<Expr> {
        let t = self.expr(e, None)?;
        if !t.e.ty.elem().is_some_and(|el| el.is_integral()) {
            let msg = crate::msg!(ExpectedIntegerFound, ty = (self.tname(t.e.ty)).to_string());
            self.error(Code::TypeMismatch, e.span, msg);
            return None;
        }
        Some(self.convert(t.e, Type::Elem(Elem::LInt)))
    }

    fn want_string(&mut self, e: &ast::Expr) -> Option<Expr> {
        let t = self.expr(e, None)?;
        if !t.e.ty.is_string() {
            let msg = crate::msg!(ExpectedStringFound, ty = (self.tname(t.e.ty)).to_string());
            self.error(Code::TypeMismatch, e.span, msg);
            return None;
        }
        Some(t.e)
    }

    /// `t` in the type the call's result is expected to have, when `t` is an untyped
    /// literal (or a constant folded from literals) that fits it: the generic-literal rule.
    fn adapt(&mut self, t: Typed, want: Option<Type>) -> Typed {
        match want {
            Some(ty @ Type::Elem(w)) if t.flexible && literal_fits(&t, w) => {
                Typed { e: self.convert(t.e, ty), flexible: false }
            }
            _ => t,
        }
    }

    /// A REAL or LREAL argument (an integer is converted); `hint` types an untyped literal.
    fn want_real(&mut self, e: &ast::Expr, hint: Option<Type>) -> Option<Expr> {
        let t = self.expr(e, None)?;
        let t = self.adapt(t, hint);
        let target = match t.e.ty.elem() {
            Some(el) if el.is_real() => return Some(t.e),
            Some(el) if el.is_int() => {
                Type::Elem(if el.bits() <= 16 { Elem::Real } else { Elem::LReal })
            }
            _ => {
                let msg = crate::msg!(ExpectedNumberFound, ty = (self.tname(t.e.ty)).to_string());
                self.error(Code::TypeMismatch, e.span, msg);
                return None;
            }
        };
        Some(self.convert(t.e, target))
    }

    fn binary_ast(op: ast::BinaryOp, a: &ast::Expr, b: &ast::Expr, span: Span) -> ast::Expr {
        ast::Expr {
            kind: ast::ExprKind::Binary(op, Box::new(a.clone()), Box::new(b.clone())),
            span,
        }
    }

    /// Checks a call of a built-in function.
    pub fn builtin_call(
        &mut self,
        name: &ast::Ident,
        args: &[ast::Arg],
        span: Span,
        expected: Option<Type>,
    ) -> Option<Expr> {
        let key = name.key();
        let a = self.builtin_args(name, args, span)?;
        // The generic-literal rule (as CODESYS and matiec): an untyped literal argument of a
        // generic function takes the type the call's result is expected to have, when it
        // fits (`y := ABS(-3)` with `y : SINT`, `r := EXPT(3.0, 2)` with `r : REAL`).
        let hint = expected.filter(|t| t.elem().is_some());
        let num_hint = hint.filter(|t| t.elem().is_some_and(|e| e.is_num()));
        let real_hint = hint.filter(|t| t.elem().is_some_and(|e| e.is_real()));
        use ast::BinaryOp as B;
        let fold_ops = |c: &mut Self, op: B| {
            let mut acc = a[0].clone();
            for next in &a[1..] {
                acc = Self::binary_ast(op, &acc, next, span);
            }
            let t = c.expr(&acc, hint)?;
            Some(c.adapt(t, hint).e)
        };
        let simple = match key.as_str() {
            "ADD" => return fold_ops(self, B::Add),
            "MUL" => return fold_ops(self, B::Mul),
            "AND" => return fold_ops(self, B::And),
            "OR" => return fold_ops(self, B::Or),
            "XOR" => return fold_ops(self, B::Xor),
            "SUB" => Some(B::Sub),
            "DIV" => Some(B::Div),
            "MOD" => Some(B::Mod),
            name => ast::Cmp::from_function(name).map(B::Cmp),
        };
        if let Some(op) = simple {
            // A comparison's result is BOOL whatever its operands: no hint for them.
            let result = if matches!(op, B::Cmp(_)) { None } else { hint };
            let t = self.expr(&Self::binary_ast(op, a[0], a[1], span), None)?;
            return Some(self.adapt(t, result).e);
        }
        match key.as_str() {
            "MOVE" => {
                let t = self.expr(a[0], None)?;
                return Some(self.adapt(t, hint).e);
            }
            "NOT" => {
                let e = ast::Expr {
                    kind: ast::ExprKind::Unary(ast::UnaryOp::Not, Box::new(a[0].clone())),
                    span,
                };
                return self.expr(&e, None).map(|t| t.e);
            }
            _ => {}
        }
        let func = match key.as_str() {
            "ABS" => {
                let t = self.expr(a[0], None)?;
                let t = self.adapt(t, num_hint);
                if !t.e.ty.elem().is_some_and(|e| e.is_num()) {
                    let msg = crate::msg!(AbsNeedsNumberNot, ty = (self.tname(t.e.ty)).to_string());
                    self.error(Code::TypeMismatch, a[0].span, msg);
                    return None;
                }
                let ty = t.e.ty;
                return Some(self.builtin_expr(Builtin::Math(MathFn::Abs), vec![t.e], ty, span));
            }
            "SQRT" => Builtin::Math(MathFn::Sqrt),
            "LN" => Builtin::Math(MathFn::Ln),
            "LOG" => Builtin::Math(MathFn::Log),
            "EXP" => Builtin::Math(MathFn::Exp),
            "SIN" => Builtin::Math(MathFn::Sin),
            "COS" => Builtin::Math(MathFn::Cos),
            "TAN" => Builtin::Math(MathFn::Tan),
            "ASIN" => Builtin::Math(MathFn::Asin),
            "ACOS" => Builtin::Math(MathFn::Acos),
            "ATAN" => Builtin::Math(MathFn::Atan),
            "EXPT" => {
                let base = self.want_real(a[0], real_hint)?;
                let exp = self.want_real(a[1], None)?;
                let exp = self.convert(exp, Type::Elem(Elem::LReal));
                let ty = base.ty;
                return Some(self.builtin_expr(
                    Builtin::Math(MathFn::Expt),
                    vec![base, exp],
                    ty,
                    span,
                ));
            }
            "SHL" | "SHR" | "ROL" | "ROR" => {
                let t = self.expr(a[0], None)?;
                if !t.e.ty.elem().is_some_and(|e| e.is_integral()) {
                    let msg = crate::msg!(
                        NeedsBitStringIntegerNot,
                        key = key,
                        ty = (self.tname(t.e.ty)).to_string()
                    );
                    self.error(Code::TypeMismatch, a[0].span, msg);
                    return None;
                }
                let n = self.want_int(a[1])?;
                let f = match key.as_str() {
                    "SHL" => Builtin::Math(MathFn::Shl),
                    "SHR" => Builtin::Math(MathFn::Shr),
                    "ROL" => Builtin::Math(MathFn::Rol),
                    _ => Builtin::Math(MathFn::Ror),
                };
                let ty = t.e.ty;
                return Some(self.builtin_expr(f, vec![t.e, n], ty, span));
            }
            "SEL" => {
                let g = self.want(a[0], Type::BOOL)?;
                // The expected type reaches the inputs: a nested generic call of literals
                // (`SEL(g, SEL(h, 50, 100), 0)` for an INT) takes it too.
                let x = self.expr(a[1], hint)?;
                let y = self.expr(a[2], Some(x.e.ty))?;
                let (ty, mut rest) = self.unify(vec![x, y], span, "SEL", expected)?;
                rest.insert(0, g);
                return Some(self.builtin_expr(Builtin::Sel, rest, ty, span));
            }
            "MAX" | "MIN" | "LIMIT" => {
                let items = a.iter().map(|e| self.expr(e, hint)).collect::<Option<Vec<_>>>()?;
                if let Some(r) = items.iter().find(|t| t.e.ty.is_ref()) {
                    let msg = crate::msg!(ComparesInputsReferencesHaveNo, key = key);
                    self.error(Code::OperatorTypeMismatch, r.e.span, msg);
                    return None;
                }
                let (ty, args) = self.unify(items, span, &key, expected)?;
                let f = match key.as_str() {
                    "MAX" => Builtin::Max,
                    "MIN" => Builtin::Min,
                    _ => Builtin::Limit,
                };
                return Some(self.builtin_expr(f, args, ty, span));
            }
            "MUX" => {
                let k = self.want_int(a[0])?;
                let items =
                    a[1..].iter().map(|e| self.expr(e, hint)).collect::<Option<Vec<_>>>()?;
                let (ty, mut args) = self.unify(items, span, "MUX", expected)?;
                args.insert(0, k);
                return Some(self.builtin_expr(Builtin::Mux, args, ty, span));
            }
            "LEN" => {
                let s = self.want_string(a[0])?;
                return Some(self.builtin_expr(
                    Builtin::Str(StrFunc::Len),
                    vec![s],
                    Type::Elem(Elem::Int),
                    span,
                ));
            }
            "LEFT" | "RIGHT" => {
                let s = self.want_string(a[0])?;
                let n = self.want_int(a[1])?;
                let ty = s.ty;
                let f = if key == "LEFT" {
                    Builtin::Str(StrFunc::Left)
                } else {
                    Builtin::Str(StrFunc::Right)
                };
                return Some(self.builtin_expr(f, vec![s, n], ty, span));
            }
            "MID" | "DELETE" => {
                let s = self.want_string(a[0])?;
                let l = self.want_int(a[1])?;
                let p = self.want_int(a[2])?;
                let ty = s.ty;
                let f = if key == "MID" {
                    Builtin::Str(StrFunc::Mid)
                } else {
                    Builtin::Str(StrFunc::Delete)
                };
                return Some(self.builtin_expr(f, vec![s, l, p], ty, span));
            }
            "INSERT" | "REPLACE" => {
                let s1 = self.want_string(a[0])?;
                let s2 = self.want_string(a[1])?;
                let ty = sum_string(s1.ty, s2.ty);
                let mut args = vec![s1, s2];
                for e in &a[2..] {
                    args.push(self.want_int(e)?);
                }
                let f = if key == "INSERT" {
                    Builtin::Str(StrFunc::Insert)
                } else {
                    Builtin::Str(StrFunc::Replace)
                };
                return Some(self.builtin_expr(f, args, ty, span));
            }
            "FIND" => {
                let s1 = self.want_string(a[0])?;
                let s2 = self.want_string(a[1])?;
                return Some(self.builtin_expr(
                    Builtin::Str(StrFunc::Find),
                    vec![s1, s2],
                    Type::Elem(Elem::Int),
                    span,
                ));
            }
            "CONCAT" => {
                let items = a.iter().map(|e| self.want_string(e)).collect::<Option<Vec<_>>>()?;
                let mut ty = items[0].ty;
                for i in &items[1..] {
                    if !matches!((ty, i.ty), (Type::Str { wide: x, .. }, Type::Str { wide: y, .. }) if x == y)
                    {
                        self.error(
                            Code::TypeMismatch,
                            i.span,
                            crate::msg!(ConcatCannotMixStringWstring),
                        );
                        return None;
                    }
                    ty = sum_string(ty, i.ty);
                }
                return Some(self.builtin_expr(Builtin::Str(StrFunc::Concat), items, ty, span));
            }
            "TRUNC" => {
                let x = self.want_real(a[0], real_hint)?;
                return Some(Expr {
                    kind: ExprKind::Trunc(Box::new(x)),
                    ty: Type::Elem(Elem::DInt),
                    span,
                });
            }
            _ => return self.conversion_call(name, a[0], span),
        };
        let x = self.want_real(a[0], real_hint)?;
        let ty = x.ty;
        Some(self.builtin_expr(func, vec![x], ty, span))
    }

    fn conversion_call(&mut self, name: &ast::Ident, arg: &ast::Expr, span: Span) -> Option<Expr> {
        let key = name.key();
        let (from, to) = conversion(&key)?;
        let t = self.expr(arg, from)?;
        let value = match from {
            Some(Type::Elem(Elem::LWord)) if key.starts_with("BCD_TO_") => {
                if !t.e.ty.elem().is_some_and(|e| e.is_integral()) {
                    let msg = crate::msg!(
                        NeedsBitStringHoldingBcd,
                        name = name.name,
                        ty = (self.tname(t.e.ty)).to_string()
                    );
                    self.error(Code::TypeMismatch, arg.span, msg);
                    return None;
                }
                t.e
            }
            Some(f) => self.coerce(t, f, arg.span)?,
            None => t.e,
        };
        let from_ty = value.ty;
        if key.starts_with("BCD_TO_") {
            let ConvTarget::Type(to) = to else { return None };
            return Some(self.builtin_expr(Builtin::BcdToInt, vec![value], to, span));
        }
        match to {
            ConvTarget::Bcd => {
                let Some(el) = from_ty.elem().filter(|e| e.is_integral()) else {
                    self.error(
                        Code::TypeMismatch,
                        arg.span,
                        crate::msg!(BcdConversionNeedsInteger),
                    );
                    return None;
                };
                let out = match el.bits() {
                    8 => Elem::Byte,
                    16 => Elem::Word,
                    32 => Elem::DWord,
                    _ => Elem::LWord,
                };
                Some(self.builtin_expr(Builtin::IntToBcd, vec![value], Type::Elem(out), span))
            }
            ConvTarget::Type(to @ Type::Str { .. }) => match from_ty {
                Type::Str { .. } => Some(value),
                Type::Elem(_) | Type::Enum(_) => {
                    Some(self.builtin_expr(Builtin::ToString, vec![value], to, span))
                }
                other => {
                    let msg = crate::msg!(
                        CannotConvertValueType,
                        name = name.name,
                        other = (self.tname(other)).to_string()
                    );
                    self.error(Code::TypeMismatch, arg.span, msg);
                    None
                }
            },
            ConvTarget::Type(to) => match from_ty {
                Type::Str { .. } => {
                    Some(self.builtin_expr(Builtin::FromString, vec![value], to, span))
                }
                Type::Elem(_) => Some(self.convert(value, to)),
                Type::Enum(_) if to.elem().is_some_and(|e| e.is_integral()) => {
                    let as_int =
                        Expr { kind: value.kind, ty: Type::Elem(Elem::LInt), span: value.span };
                    Some(self.convert(as_int, to))
                }
                other => {
                    let msg = crate::msg!(
                        CannotConvertValueType,
                        name = name.name,
                        other = (self.tname(other)).to_string()
                    );
                    self.error(Code::TypeMismatch, arg.span, msg);
                    None
                }
            },
        }
    }
}

fn sum_string(a: Type, b: Type) -> Type {
    match (a, b) {
        (Type::Str { wide, len: x }, Type::Str { len: y, .. }) => {
            Type::Str { wide, len: (x + y).min(65_535) }
        }
        _ => a,
    }
}

/// Whether the untyped literal (or folded constant) `t` can take type `want`: an integer
/// within `want`'s range, or any number when `want` is real.
fn literal_fits(t: &Typed, want: Elem) -> bool {
    match (&t.e.kind, t.e.ty.elem()) {
        (ExprKind::Const(bits), Some(el)) if el.is_integral() && want.is_integral() => {
            let (lo, hi) = want.int_range();
            let v = crate::values::arith::to_i128(el, *bits);
            v >= lo && v <= hi
        }
        (ExprKind::Const(_), Some(el)) => el.is_num() && want.is_real(),
        _ => false,
    }
}
