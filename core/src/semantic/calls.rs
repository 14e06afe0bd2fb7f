//! Calls of functions and function block instances: binding formal and informal arguments.

use super::check::Checker;
use super::ir::{CallArg, Expr, ExprKind, Place, StmtKind};
use super::types::{PouId, Type};
use crate::diagnostics::{Code, Span};
use crate::syntax::{self as ast, PouKind, VarSection};

/// What a callee expression names.
enum Callee {
    Instance(super::ir::Place, PouId),
    Function(PouId),
    Builtin,
}

impl<'a> Checker<'a> {
    /// What a body can call, in the order a hint prefers them: its function block
    /// instances, the FUNCTIONs, the standard functions.
    fn callable_names(&self) -> Vec<String> {
        let mut names = Vec::new();
        let own = self.pous.get(self.body.pou as usize).map(|p| p.vars.as_slice());
        for v in own.unwrap_or_default().iter().chain(&self.globals) {
            if matches!(v.ty, Type::Fb(_)) {
                names.push(v.name.clone());
            }
        }
        for p in &self.pous {
            if p.kind == PouKind::Function {
                names.push(p.name.clone());
            }
        }
        names.extend(super::builtins::builtin_names());
        names
    }

    fn callee(&mut self, callee: &ast::Expr, in_expression: bool) -> Option<Callee> {
        if let ast::ExprKind::Name(id) = &callee.kind {
            let key = id.key();
            let is_var =
                self.pous.get(self.body.pou as usize).is_some_and(|p| p.find_var(&key).is_some())
                    || self.global_index.contains_key(&key);
            if !is_var {
                if let Some(&pou) = self.pou_index.get(&key) {
                    return match self.pous[pou as usize].kind {
                        PouKind::Function => Some(Callee::Function(pou)),
                        PouKind::FunctionBlock => {
                            let msg = crate::msg!(FunctionBlockTypeDeclareInstance, name = id.name);
                            self.error(Code::UnknownFunction, callee.span, msg);
                            None
                        }
                        PouKind::Program => {
                            let msg = crate::msg!(ProgramProgramsAreRunPlc, name = id.name);
                            self.error(Code::ProgramCalled, callee.span, msg);
                            None
                        }
                    };
                }
                if super::builtins::is_builtin(&key) {
                    return Some(Callee::Builtin);
                }
                let msg = format!("`{}` is not a function or a function block instance", id.name);
                let callable = self.callable_names();
                self.error_suggesting(Code::UnknownFunction, callee.span, msg, &id.name, callable);
                return None;
            }
        }
        let (place, ty) = self.place(callee, false)?;
        match ty {
            Type::Fb(fb) => {
                if in_expression {
                    let msg = crate::msg!(FbCallIsStatement);
                    self.error(Code::FbCalledAsFunction, callee.span, msg);
                    return None;
                }
                Some(Callee::Instance(place, fb))
            }
            other => {
                let msg =
                    crate::msg!(ValueTypeCannotCalled, other = (self.tname(other)).to_string());
                self.error(Code::UnknownFunction, callee.span, msg);
                None
            }
        }
    }

    /// A call used inside an expression (a FUNCTION or a built-in).
    ///
    /// `expected` is the type the context wants; untyped literal arguments of generic
    /// functions (`i := MAX(3, 7)`) take it.
    pub fn call_expr(
        &mut self,
        callee: &ast::Expr,
        args: &[ast::Arg],
        span: Span,
        expected: Option<Type>,
    ) -> Option<Expr> {
        let en = args.iter().position(
            |a| matches!(a, ast::Arg::Input { name, .. } if name.name.eq_ignore_ascii_case("EN")),
        );
        if let Some(k) = en {
            return self.enabled_call(callee, args, k, span, expected);
        }
        match self.callee(callee, true)? {
            Callee::Instance(..) => None,
            Callee::Builtin => {
                let ast::ExprKind::Name(id) = &callee.kind else { return None };
                self.builtin_call(id, args, span, expected)
            }
            Callee::Function(pou) => {
                self.calls[self.body.pou as usize].insert(pou);
                let args = self.bind_args(pou, args, span)?;
                let ty = self.pous[pou as usize].result_type();
                if ty == Type::Void {
                    let name = self.pous[pou as usize].name.clone();
                    let msg = crate::msg!(HasNoResultTypeSo, name = name);
                    self.error(Code::NoReturnValue, span, msg);
                    return None;
                }
                Some(Expr { kind: ExprKind::Call { pou, args }, ty, span })
            }
        }
    }

    /// A function called with `EN := en` (argument `k`): the call when `en` is TRUE, else
    /// the default value of its result type, the call not made (IEC 61131-3 execution
    /// control; matiec returns the type's initial value, so an OpenPLC network's function
    /// with its EN off gives 0 to the block it feeds).
    #[inline(never)]
    fn enabled_call(
        &mut self,
        callee: &ast::Expr,
        args: &[ast::Arg],
        k: usize,
        span: Span,
        expected: Option<Type>,
    ) -> Option<Expr> {
        let ast::Arg::Input { value: en, .. } = &args[k] else { return None };
        let en = self.condition(en, "EN")?;
        let mut rest = args.to_vec();
        rest.remove(k);
        let call = self.call_expr(callee, &rest, span, expected)?;
        let ty = call.ty;
        if !matches!(ty, Type::Elem(_)) {
            let msg = crate::msg!(EnFunctionWhoseResultOnly, ty = (self.tname(ty)).to_string());
            self.error(Code::TypeMismatch, span, msg);
            return None;
        }
        let default = Expr { kind: ExprKind::Const(0), ty, span };
        let kind =
            ExprKind::Builtin { func: super::ir::Builtin::Enabled, args: vec![en, default, call] };
        Some(Expr { kind, ty, span })
    }

    /// A call used as a statement.
    pub fn call_stmt(
        &mut self,
        callee: &ast::Expr,
        args: &[ast::Arg],
        span: Span,
    ) -> Option<StmtKind> {
        match self.callee(callee, false)? {
            Callee::Instance(instance, fb) => {
                if let Some(calls) = self.calls.get_mut(self.body.pou as usize) {
                    calls.insert(fb);
                }
                let args = self.bind_args(fb, args, span)?;
                Some(StmtKind::CallFb { instance, fb, args })
            }
            Callee::Builtin => {
                let ast::ExprKind::Name(id) = &callee.kind else { return None };
                Some(StmtKind::Eval(self.builtin_call(id, args, span, None)?))
            }
            Callee::Function(pou) => {
                self.calls[self.body.pou as usize].insert(pou);
                let args = self.bind_args(pou, args, span)?;
                let ty = self.pous[pou as usize].result_type();
                Some(StmtKind::Eval(Expr { kind: ExprKind::Call { pou, args }, ty, span }))
            }
        }
    }

    /// Binds call arguments to the parameters of `pou`.
    fn bind_args(&mut self, pou: PouId, args: &[ast::Arg], span: Span) -> Option<Vec<CallArg>> {
        let callee = self.pous[pou as usize].clone();
        let params: Vec<u32> = (0..callee.vars.len() as u32)
            .filter(|&i| Some(i) != callee.result)
            .filter(|&i| {
                matches!(callee.vars[i as usize].section, VarSection::Input | VarSection::InOut)
            })
            .collect();
        let positional = args.iter().any(|a| matches!(a, ast::Arg::Positional(_)));
        let named = args.iter().any(|a| !matches!(a, ast::Arg::Positional(_)));
        if positional && named {
            self.error(Code::MixedArguments, span, crate::msg!(WriteEveryArgumentNameValue));
            return None;
        }
        let mut out = Vec::new();
        let mut given: Vec<u32> = Vec::new();
        let mut ok = true;
        let mut next_positional = 0usize;
        for arg in args {
            let (index, value_expr, output) = match arg {
                ast::Arg::Positional(e) => {
                    let Some(&i) = params.get(next_positional) else {
                        let msg = crate::msg!(
                            TakesArgumentSMoreWere,
                            name = callee.name,
                            params = (params.len()).to_string()
                        );
                        self.error(Code::WrongArgumentCount, e.span, msg);
                        return None;
                    };
                    next_positional += 1;
                    (i, e, None)
                }
                ast::Arg::Input { name, value } => {
                    let Some(i) = callee.find_var(&name.name).filter(|i| params.contains(i)) else {
                        let msg = format!("`{}` has no input `{}`", callee.name, name.name);
                        let inputs =
                            params.iter().map(|&i| callee.vars[i as usize].name.clone()).collect();
                        self.error_suggesting(
                            Code::NoSuchParameter,
                            name.span,
                            msg,
                            &name.name,
                            inputs,
                        );
                        ok = false;
                        continue;
                    };
                    (i, value, None)
                }
                ast::Arg::Output { name, target, negated } => {
                    let found = callee.find_var(&name.name).filter(|&i| Some(i) != callee.result);
                    let Some(i) = found else {
                        let msg = format!("`{}` has no output `{}`", callee.name, name.name);
                        let outputs = callee
                            .vars
                            .iter()
                            .filter(|v| v.section == VarSection::Output)
                            .map(|v| v.name.clone())
                            .collect();
                        self.error_suggesting(
                            Code::NoSuchParameter,
                            name.span,
                            msg,
                            &name.name,
                            outputs,
                        );
                        ok = false;
                        continue;
                    };
                    if callee.vars[i as usize].section != VarSection::Output {
                        let msg =
                            crate::msg!(NotOutputUseInputs, name = name.name, name2 = callee.name);
                        self.error(Code::NotAnOutput, name.span, msg);
                        ok = false;
                        continue;
                    }
                    (i, target, Some(*negated))
                }
            };
            if given.contains(&index) {
                let msg =
                    crate::msg!(GivenTwice, name = (callee.vars[index as usize].name).to_string());
                self.error(Code::DuplicateArgument, value_expr.span, msg);
                ok = false;
                continue;
            }
            given.push(index);
            let param = &callee.vars[index as usize];
            if let Some(negated) = output {
                let Some((place, ty)) = self.place(value_expr, true) else {
                    ok = false;
                    continue;
                };
                if matches!(place, Place::Bit(..) | Place::Slice(..)) {
                    let msg = crate::msg!(OutputWrittenWholeVariableNot, name = param.name);
                    self.error(Code::InOutNotVariable, value_expr.span, msg);
                    ok = false;
                    continue;
                }
                if ty != param.ty || (negated && !ty.is_bool()) {
                    let target = match place_text(value_expr) {
                        Some(text) => format!("`{text}`"),
                        None => "the variable it is written to".to_string(),
                    };
                    let msg = if ty != param.ty {
                        format!(
                            "the output `{}` is {}, but {target} is {}: an output is written to a variable of its own type",
                            param.name,
                            self.tname(param.ty),
                            self.tname(ty)
                        )
                    } else {
                        format!(
                            "`NOT {} =>` negates a BOOL output, but `{}` is {}",
                            param.name,
                            param.name,
                            self.tname(param.ty)
                        )
                    };
                    self.error(Code::TypeMismatch, value_expr.span, msg);
                    ok = false;
                    continue;
                }
                out.push(CallArg::Out(index, place, negated));
            } else if param.section == VarSection::InOut {
                let is_place = matches!(
                    value_expr.kind,
                    ast::ExprKind::Name(_)
                        | ast::ExprKind::Member(..)
                        | ast::ExprKind::Index(..)
                        | ast::ExprKind::Paren(_)
                        | ast::ExprKind::Deref(_)
                );
                if !is_place {
                    let msg = crate::msg!(VarOutPassVariableNot, name = param.name);
                    self.error(Code::InOutNotVariable, value_expr.span, msg);
                    ok = false;
                    continue;
                }
                let Some((place, ty)) = self.place(value_expr, true) else {
                    ok = false;
                    continue;
                };
                if matches!(place, Place::Bit(..) | Place::Slice(..)) {
                    let msg = crate::msg!(VarOutBitLocatedVariable, name = param.name);
                    self.error(Code::InOutNotVariable, value_expr.span, msg);
                    ok = false;
                    continue;
                }
                if ty != param.ty
                    && !matches!((ty, param.ty), (Type::Str { wide: a, .. }, Type::Str { wide: b, .. }) if a == b)
                {
                    let msg = crate::msg!(
                        VarOutNeedsVariableType,
                        name = param.name,
                        ty = (self.tname(param.ty)).to_string(),
                        ty2 = (self.tname(ty)).to_string()
                    );
                    self.error(Code::TypeMismatch, value_expr.span, msg);
                    ok = false;
                    continue;
                }
                out.push(CallArg::InOut(index, place));
            } else {
                let (pty, range) = (param.ty, param.range);
                let Some(t) = self.expr(value_expr, Some(pty)) else {
                    ok = false;
                    continue;
                };
                let Some(v) = self.coerce(t, pty, value_expr.span) else {
                    ok = false;
                    continue;
                };
                // An input declared with a subrange takes only values inside it.
                self.check_range(range, &v);
                out.push(CallArg::In(index, self.guard_range(range, v)));
            }
        }
        for &i in &params {
            let p = &callee.vars[i as usize];
            if p.section == VarSection::InOut && !given.contains(&i) {
                let msg = crate::msg!(VarOutMustGivenEvery, name = p.name, name2 = callee.name);
                self.error(Code::MissingInOut, span, msg);
                ok = false;
            }
        }
        ok.then_some(out)
    }
}

/// A place as written (`x`, `s.f`, `a[…]`, `w.3`, `r^`), for messages; `None` for
/// anything else.
fn place_text(e: &ast::Expr) -> Option<String> {
    use ast::ExprKind as K;
    Some(match &e.kind {
        K::Name(id) => id.name.clone(),
        K::Paren(inner) => return place_text(inner),
        K::Member(base, field) => format!("{}.{}", place_text(base)?, field.name),
        K::Bit(base, n) => format!("{}.{n}", place_text(base)?),
        K::Index(base, _) => format!("{}[…]", place_text(base)?),
        K::Deref(base) => format!("{}^", place_text(base)?),
        _ => return None,
    })
}
