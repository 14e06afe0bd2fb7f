//! References (IEC 61131-3 ed. 3): `REF(x)`, `r^`, `NULL`, and the rules that let a
//! reference be assigned, compared and passed. A reference is one cell holding the address
//! of the referenced cell plus one (0 is NULL); only `REF()` makes one, so a reference of
//! type `REF_TO T` always points at a `T` or is NULL. Each function here is its own frame
//! (`#[inline(never)]`): `Checker::expr` recurses through deeply nested expressions.

use super::check::Checker;
use super::expr::Typed;
use super::ir::{BinOp, Cmp, Expr, ExprKind, Place};
use super::types::{Type, NULL_REF};
use crate::diagnostics::{Code, Span};
use crate::syntax as ast;

impl Checker<'_> {
    /// `NULL` as a value, when `id` is `NULL` and no variable of that name is in scope.
    #[inline(never)]
    pub(super) fn null_literal(&mut self, id: &ast::Ident, span: Span) -> Option<Typed> {
        if !id.name.eq_ignore_ascii_case("NULL") {
            return None;
        }
        let key = id.key();
        if self.local_var(self.body.pou as usize, &key).is_some()
            || self.global_index.contains_key(&key)
        {
            return None;
        }
        let e = Expr { kind: ExprKind::Const(0), ty: Type::Ref(NULL_REF), span };
        Some(Typed { e, flexible: false })
    }

    /// `base^`: the variable the reference `base` points to, and its type. `write` refuses
    /// it where nothing may be written (a breakpoint condition, a watch).
    #[inline(never)]
    pub(super) fn deref_place(
        &mut self,
        base: &ast::Expr,
        span: Span,
        write: bool,
    ) -> Option<(Place, Type)> {
        let t = self.expr(base, None)?;
        if write && self.body.read_only {
            self.error(Code::NotAssignable, span, crate::msg!(ConditionWrites));
            return None;
        }
        match self.types.ref_target(t.e.ty) {
            Some(target) => Some((Place::Deref(Box::new(t.e)), target)),
            None => {
                let msg = if t.e.ty == Type::Ref(NULL_REF) {
                    crate::msg!(NullCannotBeDereferenced)
                } else {
                    crate::msg!(DerefNeedsReference, ty = self.tname(t.e.ty))
                };
                self.error(Code::NotAReference, span, msg);
                None
            }
        }
    }

    /// `REF(x)`: a reference to the variable (element, field) `x`, of type `REF_TO` its type.
    /// `x` must be a variable this POU could assign (not a CONSTANT, not an FB's output
    /// from outside), and not a bit or a subrange variable, whose checks a write through
    /// the reference would bypass.
    #[inline(never)]
    pub(super) fn ref_call(&mut self, args: &[ast::Arg], span: Span) -> Option<Expr> {
        let [ast::Arg::Positional(arg) | ast::Arg::Input { value: arg, .. }] = args else {
            let msg = crate::msg!(RefTakesOneVariableArgument, args = (args.len()).to_string());
            self.error(Code::WrongArgumentCount, span, msg);
            return None;
        };
        if let ast::Arg::Input { name, .. } = &args[0] {
            if !name.name.eq_ignore_ascii_case("IN") {
                let msg = crate::msg!(RefHasOneParameterNot, name = name.name);
                self.error(Code::NoSuchParameter, name.span, msg);
                return None;
            }
        }
        let (place, ty) = self.place(arg, true)?;
        let refused = match &place {
            Place::Bit(..) => Some("a single bit has no address of its own"),
            Place::Slice(..) => Some("a located variable lives in the process image, which has no address of a value's own"),
            _ if self.place_range(&place).is_some() => {
                Some("a write through the reference would skip the subrange check")
            }
            _ => None,
        };
        if let Some(why) = refused {
            let msg = crate::msg!(RefNeedsWholeVariableElement, why = why);
            self.error(Code::RefNotAVariable, arg.span, msg);
            return None;
        }
        let ty = self.types.reference(ty);
        Some(Expr { kind: ExprKind::RefOf(place), ty, span })
    }

    /// `REF_TO X` where `X` is the named type being resolved right now (a field of struct
    /// `X` referring to `X`: a linked list): a reference type whose target is filled in
    /// when `X` is complete ([`Self::complete_pending_refs`]). `None` for any other target.
    pub(super) fn ref_to_resolving(&mut self, target: &ast::TypeRef) -> Option<Type> {
        let ast::TypeRef::Named(id) = target else { return None };
        let key = id.key();
        if !matches!(self.type_slots.get(&key), Some(super::check::TypeSlot::Resolving(_))) {
            return None;
        }
        if let Some((r, _)) = self.pending_refs.iter().find(|(_, k)| *k == key) {
            return Some(Type::Ref(*r));
        }
        self.types.refs.push(Type::Void);
        let r = self.types.refs.len() as u32 - 1;
        self.pending_refs.push((r, key));
        Some(Type::Ref(r))
    }

    /// Completes the reference types that wait for named type `key`, now resolved to `ty`
    /// (`None` when it failed). Only a struct may refer to itself: an alias or array that
    /// does (`TYPE P : REF_TO P;`) is E0108 at its `name`.
    pub(super) fn complete_pending_refs(&mut self, key: &str, ty: Option<Type>, name: &ast::Ident) {
        let mut still = Vec::new();
        for (r, k) in std::mem::take(&mut self.pending_refs) {
            if k != key {
                still.push((r, k));
                continue;
            }
            match ty {
                Some(t @ Type::Struct(_)) => {
                    if let Some(slot) = self.types.refs.get_mut(r as usize) {
                        *slot = t;
                    }
                }
                Some(_) => {
                    let msg = crate::msg!(TypeRefersItselfOnlyStruct, name = name.name);
                    self.error(Code::RecursiveType, name.span, msg);
                }
                None => {}
            }
        }
        self.pending_refs = still;
    }

    /// Whether `callee` names `REF` (and no variable or POU of the program is so named).
    #[inline(never)]
    pub(super) fn is_ref_call(&mut self, callee: &ast::Expr) -> bool {
        let ast::ExprKind::Name(id) = &callee.kind else { return false };
        if !id.name.eq_ignore_ascii_case("REF") {
            return false;
        }
        let key = id.key();
        !self.pou_index.contains_key(&key)
            && self.local_var(self.body.pou as usize, &key).is_none()
            && !self.global_index.contains_key(&key)
    }

    /// `e` (NULL's type) as a value of reference type `to`; other values unchanged.
    pub(super) fn null_as(&self, mut e: Expr, to: Type) -> Expr {
        if e.ty == Type::Ref(NULL_REF) && to.is_ref() {
            e.ty = to;
        }
        e
    }

    /// `a = b` or `a <> b` on two references of the same type, or NULL beside a
    /// reference; other comparisons of references are refused.
    #[inline(never)]
    pub(super) fn ref_compare(&mut self, op: BinOp, a: Expr, b: Expr, span: Span) -> Option<Typed> {
        let operand = match (a.ty, b.ty) {
            _ if !matches!(op, BinOp::Cmp(Cmp::Eq | Cmp::Ne)) => None,
            (Type::Ref(x), Type::Ref(y)) if x == y => Some(a.ty),
            (Type::Ref(NULL_REF), Type::Ref(_)) => Some(b.ty),
            (Type::Ref(_), Type::Ref(NULL_REF)) => Some(a.ty),
            _ => None,
        };
        let Some(operand) = operand else {
            let msg = crate::msg!(
                CannotCombine2,
                op_text = (super::expr::op_text(op)).to_string(),
                ty = (self.tname(a.ty)).to_string(),
                ty2 = (self.tname(b.ty)).to_string()
            );
            self.error(Code::OperatorTypeMismatch, span, msg);
            return None;
        };
        let (x, y) = (self.null_as(a, operand), self.null_as(b, operand));
        let kind = ExprKind::Binary(op, Box::new(x), Box::new(y));
        Some(Typed { e: Expr { kind, ty: Type::BOOL, span }, flexible: false })
    }
}
