//! Expressions: names and places, literals, operators, implicit conversions, folding.

use super::check::Checker;
use super::ir::{BinOp, Builtin, Cmp, Expr, ExprKind, InitValue, MathFn, Place, SysVar, UnOp, Var};
use super::types::{Elem, Type};
use crate::diagnostics::{Code, Diagnostic, Span};
use crate::msg;
use crate::syntax::{self as ast, AddressArea, AddressSize, LiteralValue, VarSection};
use crate::values::arith;

/// A checked expression, and whether it is an untyped literal whose type may still adapt
/// to its context (`x + 1` with `x : INT` makes the `1` an INT).
#[derive(Debug, Clone)]
pub(super) struct Typed {
    pub e: Expr,
    pub flexible: bool,
}

impl Typed {
    fn fixed(e: Expr) -> Self {
        Typed { e, flexible: false }
    }
}

/// What a name in a body refers to.
enum NameRef {
    Var { place: Place, var: Box<Var> },
    Enumerator(Type, i64),
    Sys(SysVar),
    Pou,
}

/// The candidate types for implicit widening, smallest first.
pub(super) const WIDENING_ORDER: [Elem; 14] = [
    Elem::SInt,
    Elem::USInt,
    Elem::Byte,
    Elem::Int,
    Elem::UInt,
    Elem::Word,
    Elem::DInt,
    Elem::UDInt,
    Elem::DWord,
    Elem::LInt,
    Elem::ULInt,
    Elem::LWord,
    Elem::Real,
    Elem::LReal,
];

/// True when a value of `from` converts to `to` implicitly without loss (or, for integers
/// into REAL, the way CODESYS allows).
pub(crate) fn can_widen(from: Elem, to: Elem) -> bool {
    if from == to {
        return true;
    }
    let (fb, tb) = (from.bits(), to.bits());
    match (from, to) {
        _ if from.is_signed_int() && to.is_signed_int() => tb > fb,
        _ if from.is_unsigned_int() && to.is_unsigned_int() => tb > fb,
        _ if from.is_unsigned_int() && to.is_signed_int() => tb > fb,
        _ if from.is_bitstring() && to.is_bitstring() => tb > fb,
        _ if from.is_bitstring() && to.is_unsigned_int() => tb >= fb,
        _ if from.is_bitstring() && to.is_signed_int() => tb > fb,
        _ if from.is_int() && to.is_bitstring() => tb >= fb,
        _ if from.is_int() && to.is_real() => true,
        (Elem::Real, Elem::LReal) => true,
        _ => false,
    }
}

fn smallest_int_type(v: i128) -> Option<Elem> {
    [Elem::DInt, Elem::LInt, Elem::ULInt].into_iter().find(|e| {
        let (lo, hi) = e.int_range();
        v >= lo && v <= hi
    })
}

fn fits(elem: Elem, v: i128) -> bool {
    let (lo, hi) = elem.int_range();
    v >= lo && v <= hi
}

/// The operator as written, for messages.
pub(super) fn op_text(op: BinOp) -> &'static str {
    match op {
        BinOp::Add => "+",
        BinOp::Sub => "-",
        BinOp::Mul => "*",
        BinOp::Div => "/",
        BinOp::Mod => "MOD",
        BinOp::Pow => "**",
        BinOp::And => "AND",
        BinOp::Or => "OR",
        BinOp::Xor => "XOR",
        BinOp::AndThen => "AND_THEN",
        BinOp::OrElse => "OR_ELSE",
        BinOp::Cmp(c) => c.symbol(),
    }
}

fn is_comparison(op: BinOp) -> bool {
    matches!(op, BinOp::Cmp(_))
}

/// Normalises a direct address text: upper case, with the `X` of bit addresses written.
pub(super) fn normalize_address(a: &ast::DirectAddress) -> String {
    let area = match a.area {
        AddressArea::Input => 'I',
        AddressArea::Output => 'Q',
        AddressArea::Memory => 'M',
    };
    let size = match a.size {
        AddressSize::Bit => 'X',
        AddressSize::Byte => 'B',
        AddressSize::Word => 'W',
        AddressSize::DWord => 'D',
        AddressSize::LWord => 'L',
    };
    let path: Vec<String> = a.path.iter().map(u32::to_string).collect();
    format!("%{area}{size}{}", path.join("."))
}

impl<'a> Checker<'a> {
    fn const_expr(&self, bits: u64, ty: Type, span: Span) -> Expr {
        Expr { kind: ExprKind::Const(bits), ty, span }
    }

    /// Checks an expression. `expected` is a hint (enumerators, literals); the caller still
    /// converts with [`Checker::coerce`].
    pub fn expr(&mut self, e: &ast::Expr, expected: Option<Type>) -> Option<Typed> {
        use ast::ExprKind as K;
        let span = e.span;
        match &e.kind {
            K::Literal(lit) => self.literal(lit, span),
            K::Paren(inner) => {
                let mut t = self.expr(inner, expected)?;
                t.e.span = span;
                Some(t)
            }
            K::Name(id) => self.name_expr(id, expected, span),
            K::EnumValue { type_name, value } => self.enum_value(type_name, value, span),
            K::Member(..) | K::Bit(..) | K::Index(..) | K::Direct(_) | K::Deref(_) => {
                let (place, ty) = self.place(e, false)?;
                Some(Typed::fixed(Expr { kind: ExprKind::Load(place), ty, span }))
            }
            K::Part { base, width, index } => self.part_expr(base, *width, *index, span),
            K::Unary(op, operand) => self.unary(*op, operand, span, expected),
            K::Binary(op, l, r) => self.binary(*op, l, r, span, expected),
            K::Call { callee, args } if self.is_ref_call(callee) => {
                self.ref_call(args, span).map(Typed::fixed)
            }
            K::Call { callee, args } => {
                self.call_expr(callee, args, span, expected).map(Typed::fixed)
            }
        }
    }

    /// A name read as a value (its own function: `expr` recurses through deeply nested
    /// expressions, so its frame stays small).
    #[inline(never)]
    fn name_expr(&mut self, id: &ast::Ident, expected: Option<Type>, span: Span) -> Option<Typed> {
        if let Some(null) = self.null_literal(id, span) {
            return Some(null);
        }
        match self.lookup(id, expected)? {
            NameRef::Var { place, var } => {
                if var.constant {
                    if let Some(InitValue::Scalar(bits)) = var.init {
                        return Some(Typed::fixed(self.const_expr(bits, var.ty, span)));
                    }
                    if let Some(InitValue::Str(s)) = &var.init {
                        let e = Expr { kind: ExprKind::ConstStr(s.clone()), ty: var.ty, span };
                        return Some(Typed::fixed(e));
                    }
                }
                self.check_readable(&var, span)?;
                Some(Typed::fixed(Expr { kind: ExprKind::Load(place), ty: var.ty, span }))
            }
            NameRef::Enumerator(ty, v) => Some(Typed::fixed(self.const_expr(v as u64, ty, span))),
            NameRef::Sys(s) => {
                Some(Typed::fixed(Expr { kind: ExprKind::Sys(s), ty: s.ty(), span }))
            }
            NameRef::Pou => {
                self.error(Code::NotAVariable, span, crate::msg!(PouNotValueCall, name = id.name));
                None
            }
        }
    }

    /// Reads a partial access `base.%B1` (its own function: `expr` recurses through deeply
    /// nested expressions, so its frame stays small).
    #[inline(never)]
    fn part_expr(&mut self, base: &ast::Expr, width: u32, index: u32, span: Span) -> Option<Typed> {
        let b = self.expr(base, None)?.e;
        let part = self.part_of(b.ty, width, index, span)?;
        Some(Typed::fixed(self.read_part(b, part, index, span)))
    }

    /// The type of part `index`, `width` bits wide, of a value of type `base` (a bit
    /// string wide enough), or the error.
    pub(super) fn part_of(
        &mut self,
        base: Type,
        width: u32,
        index: u32,
        span: Span,
    ) -> Option<Elem> {
        let part = match width {
            8 => Elem::Byte,
            16 => Elem::Word,
            32 => Elem::DWord,
            _ => Elem::LWord,
        };
        let Some(el) = base
            .elem()
            .filter(|e| matches!(e, Elem::Byte | Elem::Word | Elem::DWord | Elem::LWord))
        else {
            let msg = crate::msg!(
                PartialAccessNeedsBitString,
                part_letter = (part_letter(part)).to_string(),
                index = index,
                base = (self.tname(base)).to_string()
            );
            self.error(Code::NotAStruct, span, msg);
            return None;
        };
        if u64::from(width) * (u64::from(index) + 1) > u64::from(el.bits()) {
            let count = el.bits() / width;
            let msg = if count == 0 {
                format!("{} has no {} (it is narrower)", el.name(), part.name())
            } else {
                format!(
                    "{} has {}s 0..{}; there is no {} {index}",
                    el.name(),
                    part.name(),
                    count - 1,
                    part.name()
                )
            };
            self.error(Code::BitOutOfRange, span, msg);
            return None;
        }
        Some(part)
    }

    /// `(b SHR (width × index)) AND mask`, as the part's type.
    pub(super) fn read_part(&self, b: Expr, part: Elem, index: u32, span: Span) -> Expr {
        let ty = b.ty;
        let shift = part.bits() * index;
        let shifted = if shift == 0 {
            b
        } else {
            let n = self.const_expr(u64::from(shift), Type::Elem(Elem::LInt), span);
            Expr {
                kind: ExprKind::Builtin { func: Builtin::Math(MathFn::Shr), args: vec![b, n] },
                ty,
                span,
            }
        };
        let mask = part_mask(part);
        let masked = if ty.elem().is_some_and(|e| e.bits() == part.bits()) {
            shifted
        } else {
            let m = self.const_expr(mask, ty, span);
            Expr { kind: ExprKind::Binary(BinOp::And, Box::new(shifted), Box::new(m)), ty, span }
        };
        self.convert(masked, Type::Elem(part))
    }

    /// `b` with part `index` replaced by `v` (already of the part's type):
    /// `(b AND NOT (mask SHL shift)) OR (v SHL shift)`.
    pub(super) fn write_part(&self, b: Expr, part: Elem, index: u32, v: Expr, span: Span) -> Expr {
        let ty = b.ty;
        let shift = part.bits() * index;
        let keep = !(part_mask(part) << shift);
        let keep = self.const_expr(keep & type_mask(ty), ty, span);
        let kept =
            Expr { kind: ExprKind::Binary(BinOp::And, Box::new(b), Box::new(keep)), ty, span };
        let wide = self.convert(v, ty);
        let placed = if shift == 0 {
            wide
        } else {
            let n = self.const_expr(u64::from(shift), Type::Elem(Elem::LInt), span);
            Expr {
                kind: ExprKind::Builtin { func: Builtin::Math(MathFn::Shl), args: vec![wide, n] },
                ty,
                span,
            }
        };
        Expr { kind: ExprKind::Binary(BinOp::Or, Box::new(kept), Box::new(placed)), ty, span }
    }

    fn check_readable(&mut self, var: &Var, span: Span) -> Option<()> {
        if let Type::Fb(_) = var.ty {
            self.error(
                Code::TypeMismatch,
                span,
                crate::msg!(FunctionBlockInstanceUseOne, name = var.name),
            );
            return None;
        }
        Some(())
    }

    fn literal(&mut self, lit: &ast::Literal, span: Span) -> Option<Typed> {
        let prefix = lit.type_prefix.as_ref();
        let prefix_elem = match prefix {
            None => None,
            Some(p) => {
                let key = p.key();
                match Elem::from_name(&key) {
                    Some(e) => Some(e),
                    None if key == "STRING" || key == "WSTRING" => None,
                    None => {
                        self.error(
                            Code::InvalidTypedLiteral,
                            p.span,
                            crate::msg!(UnknownTypePrefix, name = p.name),
                        );
                        return None;
                    }
                }
            }
        };
        let bad_prefix = |c: &mut Self| {
            if let Some(p) = prefix {
                c.error(
                    Code::InvalidTypedLiteral,
                    span,
                    crate::msg!(DoesNotFitLiteral, name = p.name),
                );
            }
        };
        let fixed = |c: &Self, bits, ty| Some(Typed::fixed(c.const_expr(bits, ty, span)));
        match &lit.value {
            LiteralValue::Int(v) => match prefix_elem {
                None if prefix.is_some() => {
                    bad_prefix(self);
                    None
                }
                None => {
                    let Some(ty) = smallest_int_type(*v) else {
                        self.error(
                            Code::IntegerLiteralTooLarge,
                            span,
                            crate::msg!(TooLargeAnyIntegerType, v = v),
                        );
                        return None;
                    };
                    let e = self.const_expr(arith::norm(ty, *v), Type::Elem(ty), span);
                    Some(Typed { e, flexible: true })
                }
                Some(el) if el.is_real() => {
                    fixed(self, arith::from_f64(el, *v as f64), Type::Elem(el))
                }
                Some(el) if el.is_integral() || el == Elem::Bool => {
                    if !fits(el, *v) {
                        let (lo, hi) = el.int_range();
                        self.error(
                            Code::ConstantOutOfRange,
                            span,
                            crate::msg!(
                                DoesNotFit,
                                v = v,
                                name = (el.name()).to_string(),
                                lo = lo,
                                hi = hi
                            ),
                        );
                        return None;
                    }
                    fixed(self, arith::norm(el, *v), Type::Elem(el))
                }
                Some(_) => {
                    bad_prefix(self);
                    None
                }
            },
            LiteralValue::Real(f) => match prefix_elem {
                None if prefix.is_some() => {
                    bad_prefix(self);
                    None
                }
                None => {
                    let e = self.const_expr(f.to_bits(), Type::Elem(Elem::LReal), span);
                    Some(Typed { e, flexible: true })
                }
                Some(el) if el.is_real() => fixed(self, arith::from_f64(el, *f), Type::Elem(el)),
                Some(_) => {
                    bad_prefix(self);
                    None
                }
            },
            LiteralValue::Bool(b) => match prefix_elem {
                None | Some(Elem::Bool) => fixed(self, u64::from(*b), Type::BOOL),
                Some(el) if el.is_integral() => fixed(self, u64::from(*b), Type::Elem(el)),
                Some(_) => {
                    bad_prefix(self);
                    None
                }
            },
            LiteralValue::String(bytes) => {
                let len = bytes.len().max(1) as u32;
                let e = Expr {
                    kind: ExprKind::ConstStr(bytes.clone()),
                    ty: Type::Str { wide: false, len },
                    span,
                };
                Some(Typed { e, flexible: true })
            }
            LiteralValue::WString(units) => {
                let bytes: Vec<u8> = units.iter().flat_map(|u| u.to_le_bytes()).collect();
                let len = units.len().max(1) as u32;
                let e = Expr {
                    kind: ExprKind::ConstStr(bytes),
                    ty: Type::Str { wide: true, len },
                    span,
                };
                Some(Typed { e, flexible: true })
            }
            LiteralValue::Time(ns) => fixed(self, *ns as u64, Type::Elem(Elem::Time)),
            LiteralValue::Date(ns) => fixed(self, *ns as u64, Type::Elem(Elem::Date)),
            LiteralValue::TimeOfDay(ns) => fixed(self, *ns as u64, Type::Elem(Elem::Tod)),
            LiteralValue::DateTime(ns) => fixed(self, *ns as u64, Type::Elem(Elem::Dt)),
        }
    }

    fn enum_value(
        &mut self,
        type_name: &ast::Ident,
        value: &ast::Ident,
        span: Span,
    ) -> Option<Typed> {
        let resolved = self.resolve_type(&ast::TypeRef::Named(type_name.clone()), "")?;
        let Type::Enum(id) = resolved.ty else {
            self.error(
                Code::TypeMismatch,
                type_name.span,
                crate::msg!(NotEnumeration, name = type_name.name),
            );
            return None;
        };
        let def = &self.types.enums[id as usize];
        match def.values.iter().find(|(n, _)| n.eq_ignore_ascii_case(&value.name)) {
            Some((_, v)) => Some(Typed::fixed(self.const_expr(*v as u64, resolved.ty, span))),
            None => {
                let msg = msg!(NoEnumValue, ty = &def.name, value = &value.name);
                let values: Vec<String> = def.values.iter().map(|(n, _)| n.clone()).collect();
                self.error_suggesting(Code::UndeclaredName, value.span, msg, &value.name, values);
                None
            }
        }
    }

    /// Where a value of enumeration `expected` is wanted and `id` names both a variable of
    /// another type and a value of that enumeration (OpenPLC files have an input `Mode_Local`
    /// next to the value `MODE_LOCAL`, and names are case-insensitive): the value, as matiec
    /// and CODESYS resolve it by the expected type, with warning W0030.
    fn enum_value_over_variable(
        &mut self,
        id: &ast::Ident,
        var: &Var,
        expected: Option<Type>,
    ) -> Option<NameRef> {
        let Some(Type::Enum(eid)) = expected else { return None };
        if var.ty == Type::Enum(eid) {
            return None;
        }
        let def = &self.types.enums[eid as usize];
        let &(_, value) = def.values.iter().find(|(n, _)| n.eq_ignore_ascii_case(&id.name))?;
        let message = crate::msg!(
            BothVariableValueReadValue,
            name = id.name,
            name2 = var.name,
            ty = (self.tname(var.ty)).to_string(),
            name3 = def.name
        );
        self.warning(Code::VariableShadowsEnumValue, id.span, message);
        Some(NameRef::Enumerator(Type::Enum(eid), value))
    }

    /// Resolves a name used in a body.
    fn lookup(&mut self, id: &ast::Ident, expected: Option<Type>) -> Option<NameRef> {
        let key = id.key();
        let pou = self.body.pou as usize;
        if let Some(i) = self.local_var(pou, &key) {
            let var = self.pous[pou].vars[i as usize].clone();
            if let Some(enumerator) = self.enum_value_over_variable(id, &var, expected) {
                return Some(enumerator);
            }
            if var.section == VarSection::External {
                if let Some(&g) = self.global_index.get(&key) {
                    let var = self.globals[g as usize].clone();
                    let place = self.image_place(&var).unwrap_or(Place::Global(g));
                    return Some(NameRef::Var { place, var: Box::new(var) });
                }
                return None;
            }
            let place = self.image_place(&var).unwrap_or(Place::Local(i));
            return Some(NameRef::Var { place, var: Box::new(var) });
        }
        if let Some(&g) = self.global_index.get(&key) {
            let var = self.globals[g as usize].clone();
            let place = self.image_place(&var).unwrap_or(Place::Global(g));
            return Some(NameRef::Var { place, var: Box::new(var) });
        }
        if let Some(Type::Enum(eid)) = expected {
            if let Some((_, v)) = self.types.enums[eid as usize]
                .values
                .iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(&key))
            {
                return Some(NameRef::Enumerator(Type::Enum(eid), *v));
            }
        }
        let matches: Vec<(u32, i64)> = self
            .types
            .enums
            .iter()
            .enumerate()
            .filter_map(|(i, e)| {
                e.values
                    .iter()
                    .find(|(n, _)| n.eq_ignore_ascii_case(&key))
                    .map(|(_, v)| (i as u32, *v))
            })
            .collect();
        match matches.as_slice() {
            [(eid, v)] => return Some(NameRef::Enumerator(Type::Enum(*eid), *v)),
            [(first, _), (second, _), ..] => {
                let (a, b) = (
                    self.types.enums[*first as usize].name.clone(),
                    self.types.enums[*second as usize].name.clone(),
                );
                self.error(
                    Code::UndeclaredName,
                    id.span,
                    crate::msg!(ValueBothWrite, name = id.name, a = a, b = b),
                );
                return None;
            }
            [] => {}
        }
        if let Some(s) = SysVar::from_name(&key) {
            return Some(NameRef::Sys(s));
        }
        if self.pou_index.contains_key(&key) {
            return Some(NameRef::Pou);
        }
        self.undeclared(id, expected);
        None
    }

    /// E0100 for `id`, with `did you mean NAME?` when a name in scope is close to it and
    /// the type `expected` there (when it is one a declaration can name) as the type its
    /// use implies.
    #[inline(never)]
    fn undeclared(&mut self, id: &ast::Ident, expected: Option<Type>) {
        let candidates = self.names_in_scope();
        let suggestion =
            crate::diagnostics::suggest::closest(&id.name, candidates.iter().map(String::as_str));
        let mut d =
            Diagnostic::error(Code::UndeclaredName, id.span, msg!(NotDeclared, name = &id.name))
                .suggesting(suggestion);
        d.implied_type = expected.and_then(|t| self.declarable(t));
        self.diags.push(d);
    }

    /// The names a body can read, in the order a hint prefers them: the POU's variables as
    /// declared, the globals, the enumeration values, the system variables.
    fn names_in_scope(&self) -> Vec<String> {
        let mut names = Vec::new();
        if let Some(p) = self.pous.get(self.body.pou as usize) {
            names.extend(p.vars.iter().map(|v| v.name.clone()));
        }
        names.extend(self.globals.iter().map(|g| g.name.clone()));
        for e in &self.types.enums {
            names.extend(e.values.iter().map(|(n, _)| n.clone()));
        }
        names.extend(SysVar::NAMES.iter().map(|n| n.to_string()));
        names
    }

    /// The name of `ty` as a declaration writes it, for the types a `Declare NAME` fix
    /// can declare (elementary types, strings, named enumerations and structures).
    pub(super) fn declarable(&self, ty: Type) -> Option<String> {
        let name = self.tname(ty);
        match ty {
            Type::Elem(_) | Type::Str { .. } => Some(name),
            // Only a type declared by name (an enumeration written inside a declaration has
            // no name to repeat).
            Type::Enum(_) | Type::Struct(_)
                if self.type_slots.contains_key(&name.to_ascii_uppercase()) =>
            {
                Some(name)
            }
            _ => None,
        }
    }

    /// The type a value `t` implies for a variable it is stored into: its own, or for an
    /// untyped literal the type a declaration would give it (INT, DINT or LINT for an
    /// integer, as large as it needs; REAL for a real number).
    pub(super) fn implied_by(&self, t: &Typed) -> Option<String> {
        let el = t.e.ty.elem();
        if t.flexible {
            if let (Some(el), ExprKind::Const(bits)) = (el, &t.e.kind) {
                if el.is_integral() {
                    let v = arith::to_i128(el, *bits);
                    let fit = [Elem::Int, Elem::DInt, Elem::LInt].into_iter().find(|&e| fits(e, v));
                    return fit.map(|e| e.name().to_string());
                }
                if el.is_real() {
                    return Some(Elem::Real.name().to_string());
                }
            }
        }
        self.declarable(t.e.ty)
    }

    /// Resolves an expression that denotes memory. `write` checks it may be assigned.
    pub fn place(&mut self, e: &ast::Expr, write: bool) -> Option<(Place, Type)> {
        use ast::ExprKind as K;
        match &e.kind {
            K::Paren(inner) => self.place(inner, write),
            K::Name(id) => match self.lookup(id, None)? {
                NameRef::Var { place, var } => {
                    if write {
                        self.check_writable(&var, e.span)?;
                    }
                    Some((place, var.ty))
                }
                NameRef::Sys(_) => {
                    if write {
                        self.error(
                            Code::AssignToConstant,
                            e.span,
                            msg!(SystemVariableWritten, name = &id.name),
                        );
                        return None;
                    }
                    self.error(
                        Code::NotAVariable,
                        e.span,
                        crate::msg!(SystemVariableNotPlaceMemory, name = id.name),
                    );
                    None
                }
                NameRef::Enumerator(..) | NameRef::Pou => {
                    self.error(Code::NotAssignable, e.span, msg!(NotAVariable, name = &id.name));
                    None
                }
            },
            K::Member(base, field) => {
                let (bp, bty) = self.place(base, false)?;
                match bty {
                    Type::Struct(sid) => {
                        let def = &self.types.structs[sid as usize];
                        match def
                            .fields
                            .iter()
                            .position(|f| f.name.eq_ignore_ascii_case(&field.name))
                        {
                            Some(i) => {
                                let ty = def.fields[i].ty;
                                if write {
                                    self.check_writable_root(base, e.span)?;
                                }
                                Some((Place::Field(Box::new(bp), i as u32), ty))
                            }
                            None => {
                                let fields = def.fields.iter().map(|f| f.name.clone()).collect();
                                let owner = def.name.clone();
                                self.no_member(field, &owner, true, fields);
                                None
                            }
                        }
                    }
                    Type::Fb(fb) => {
                        let pou = &self.pous[fb as usize];
                        let Some(i) = pou.find_var(&field.name) else {
                            let owner = pou.name.clone();
                            let members = super::check::interface_names(pou);
                            self.no_member(field, &owner, false, members);
                            return None;
                        };
                        let var = &pou.vars[i as usize];
                        let ty = var.ty;
                        if write && !matches!(var.section, VarSection::Input) {
                            let msg = crate::msg!(
                                NotInputOnlyInputsMay,
                                name = field.name,
                                name2 = pou.name
                            );
                            self.error(Code::NotAssignable, e.span, msg);
                            return None;
                        }
                        Some((Place::Field(Box::new(bp), i), ty))
                    }
                    other => {
                        let msg = crate::msg!(
                            ValueTypeHasNoMembers,
                            name = field.name,
                            other = (self.tname(other)).to_string()
                        );
                        self.error(Code::NotAStruct, field.span, msg);
                        None
                    }
                }
            }
            K::Bit(base, n) => {
                let (bp, bty) = self.place(base, write)?;
                let Some(el) = bty.elem().filter(|e| e.is_integral()) else {
                    let msg = crate::msg!(
                        BitAccessNeedsIntegerBit,
                        n = n,
                        bty = (self.tname(bty)).to_string()
                    );
                    self.error(Code::NotAStruct, e.span, msg);
                    return None;
                };
                if *n >= el.bits() {
                    let msg = crate::msg!(
                        HasBits0ThereNo,
                        name = (el.name()).to_string(),
                        bits = (el.bits() - 1).to_string(),
                        n = n
                    );
                    self.error(Code::BitOutOfRange, e.span, msg);
                    return None;
                }
                Some((Place::Bit(Box::new(bp), *n, el), Type::BOOL))
            }
            K::Index(base, indices) => {
                let (bp, bty) = self.place(base, write)?;
                let Type::Array(aid) = bty else {
                    self.error(
                        Code::NotAnArray,
                        e.span,
                        crate::msg!(ValueTypeCannotIndexed, bty = (self.tname(bty)).to_string()),
                    );
                    return None;
                };
                let def = self.types.arrays[aid as usize].clone();
                if def.dims.len() != indices.len() {
                    let msg = crate::msg!(
                        ArrayHasDimensionSBut,
                        dims = (def.dims.len()).to_string(),
                        indices = (indices.len()).to_string()
                    );
                    self.error(Code::WrongIndexCount, e.span, msg);
                    return None;
                }
                let mut out = Vec::new();
                for (ix, (lo, hi)) in indices.iter().zip(&def.dims) {
                    let t = self.expr(ix, None)?;
                    if !t.e.ty.elem().is_some_and(|el| el.is_integral()) {
                        let msg = crate::msg!(
                            ArrayIndexMustIntegerNot,
                            ty = (self.tname(t.e.ty)).to_string()
                        );
                        self.error(Code::TypeMismatch, ix.span, msg);
                        return None;
                    }
                    if let Some(v) = super::consts::int_value(&t.e) {
                        if v < *lo || v > *hi {
                            let msg = crate::msg!(IndexOutsideArrayBounds, v = v, lo = lo, hi = hi);
                            self.error(Code::ConstantIndexOutOfRange, ix.span, msg);
                            return None;
                        }
                    }
                    out.push(self.convert(t.e, Type::Elem(Elem::LInt)));
                }
                Some((Place::Element(Box::new(bp), aid, out), def.element))
            }
            K::Direct(addr) => Some(self.direct_place(addr)),
            K::Deref(base) => self.deref_place(base, e.span, write),
            _ => {
                let what = if write { "assigned to" } else { "used here" };
                self.error(
                    Code::NotAssignable,
                    e.span,
                    crate::msg!(ExpressionCannotNotVariable, what = what),
                );
                None
            }
        }
    }

    /// E0104 for `.field` of `owner` (a structure's field when `of_struct`, else a function
    /// block's member): `did you mean NAME?` when a member is close to it, else the members
    /// there are (the first ten).
    pub(super) fn no_member(
        &mut self,
        field: &ast::Ident,
        owner: &str,
        of_struct: bool,
        members: Vec<String>,
    ) {
        let suggestion =
            crate::diagnostics::suggest::closest(&field.name, members.iter().map(String::as_str));
        let listed = match members.len() {
            _ if suggestion.is_some() => None,
            0 => None,
            1..=10 => Some(members.join(", ")),
            _ => Some(format!("{}, …", members[..10].join(", "))),
        };
        let name = &field.name;
        let msg = match (of_struct, listed) {
            (true, None) => msg!(HasNoField, owner = owner, name = name),
            (true, Some(list)) => msg!(HasNoFieldItHas, owner = owner, name = name, list = list),
            (false, None) => msg!(HasNoMember, owner = owner, name = name),
            (false, Some(list)) => msg!(HasNoMemberItHas, owner = owner, name = name, list = list),
        };
        let d = Diagnostic::error(Code::NoSuchMember, field.span, msg).suggesting(suggestion);
        self.diags.push(d);
    }

    fn check_writable(&mut self, var: &Var, span: Span) -> Option<()> {
        let pou_kind = self.pous.get(self.body.pou as usize).map(|p| p.kind);
        if self.body.read_only {
            self.error(Code::NotAssignable, span, msg!(ConditionWrites));
            return None;
        }
        if var.constant {
            self.error(Code::AssignToConstant, span, msg!(ConstantWritten, name = &var.name));
            return None;
        }
        if pou_kind == Some(crate::syntax::PouKind::Function) && var.section == VarSection::Input {
            self.warning(
                Code::FunctionInputWritten,
                span,
                msg!(FunctionInputWritten, name = &var.name),
            );
        }
        Some(())
    }

    fn check_writable_root(&mut self, base: &ast::Expr, span: Span) -> Option<()> {
        // Re-resolve the root name to apply CONSTANT checks to struct members.
        let mut root = base;
        loop {
            match &root.kind {
                ast::ExprKind::Member(b, _)
                | ast::ExprKind::Index(b, _)
                | ast::ExprKind::Bit(b, _)
                | ast::ExprKind::Part { base: b, .. } => root = b,
                ast::ExprKind::Paren(b) => root = b,
                _ => break,
            }
        }
        if let ast::ExprKind::Name(id) = &root.kind {
            if let Some(NameRef::Var { var, .. }) = self.lookup(id, None) {
                return self.check_writable(&var, span);
            }
        }
        Some(())
    }

    /// The variable a direct address refers to: a declared variable located there, or an
    /// implicit global of the address's size.
    fn direct_place(&mut self, addr: &ast::DirectAddress) -> (Place, Type) {
        let text = normalize_address(addr);
        let located = |v: &Var| v.location.as_ref().is_some_and(|l| normalize_address(l) == text);
        if let Some(p) = self.pous.get(self.body.pou as usize) {
            if let Some(i) = p.vars.iter().position(located) {
                let var = p.vars[i].clone();
                return (self.image_place(&var).unwrap_or(Place::Local(i as u32)), var.ty);
            }
        }
        if let Some(g) = self.globals.iter().position(|v| located(v) || v.name == text) {
            let var = self.globals[g].clone();
            return (self.image_place(&var).unwrap_or(Place::Global(g as u32)), var.ty);
        }
        let elem = match addr.size {
            AddressSize::Bit => Elem::Bool,
            AddressSize::Byte => Elem::Byte,
            AddressSize::Word => Elem::Word,
            AddressSize::DWord => Elem::DWord,
            AddressSize::LWord => Elem::LWord,
        };
        let g = self.globals.len() as u32;
        self.global_index.insert(text.clone(), g);
        let var = Var {
            name: text,
            ty: Type::Elem(elem),
            section: VarSection::Global,
            retain: false,
            constant: false,
            location: Some(addr.clone()),
            init: None,
            range: None,
            comment: None,
            span: addr.span,
        };
        self.globals.push(var.clone());
        (self.image_place(&var).unwrap_or(Place::Global(g)), Type::Elem(elem))
    }

    fn unary(
        &mut self,
        op: ast::UnaryOp,
        operand: &ast::Expr,
        span: Span,
        expected: Option<Type>,
    ) -> Option<Typed> {
        let t = self.expr(operand, expected)?;
        let ty = t.e.ty;
        match op {
            ast::UnaryOp::Plus => {
                if !ty.elem().is_some_and(|e| e.is_num() || e == Elem::Time) {
                    self.error(
                        Code::OperatorTypeMismatch,
                        span,
                        crate::msg!(UnaryNeedsNumberNot, ty = (self.tname(ty)).to_string()),
                    );
                    return None;
                }
                let mut t = t;
                t.e.span = span;
                Some(t)
            }
            ast::UnaryOp::Neg => {
                let Some(el) = ty.elem().filter(|e| e.is_num() || *e == Elem::Time) else {
                    self.error(
                        Code::OperatorTypeMismatch,
                        span,
                        crate::msg!(NeedsNumberTimeNot, ty = (self.tname(ty)).to_string()),
                    );
                    return None;
                };
                if let ExprKind::Const(bits) = t.e.kind {
                    if t.flexible && el.is_integral() {
                        let v = -arith::to_i128(el, bits);
                        let nt = smallest_int_type(v)?;
                        let e = self.const_expr(arith::norm(nt, v), Type::Elem(nt), span);
                        return Some(Typed { e, flexible: true });
                    }
                    let e = self.const_expr(arith::negate(el, bits), ty, span);
                    return Some(Typed { e, flexible: t.flexible });
                }
                Some(Typed::fixed(Expr {
                    kind: ExprKind::Unary(UnOp::Neg, Box::new(t.e)),
                    ty,
                    span,
                }))
            }
            ast::UnaryOp::Not => {
                let Some(el) = ty.elem().filter(|e| *e == Elem::Bool || e.is_integral()) else {
                    self.error(
                        Code::OperatorTypeMismatch,
                        span,
                        crate::msg!(NotNeedsBoolBitString, ty = (self.tname(ty)).to_string()),
                    );
                    return None;
                };
                if let ExprKind::Const(bits) = t.e.kind {
                    let e = self.const_expr(arith::complement(el, bits), ty, span);
                    return Some(Typed::fixed(e));
                }
                Some(Typed::fixed(Expr {
                    kind: ExprKind::Unary(UnOp::Not, Box::new(t.e)),
                    ty,
                    span,
                }))
            }
        }
    }

    /// The common type two numeric operands convert to, if any.
    fn common_elem(&self, a: &Typed, b: &Typed) -> Option<Elem> {
        let (ae, be) = (a.e.ty.elem()?, b.e.ty.elem()?);
        if ae == be {
            return Some(ae);
        }
        // An untyped literal adopts the other side's type when its value fits.
        for (lit, other) in [(a, be), (b, ae)] {
            if lit.flexible && !(if std::ptr::eq(lit, a) { b.flexible } else { a.flexible }) {
                if let ExprKind::Const(bits) = lit.e.kind {
                    let le = lit.e.ty.elem()?;
                    if le.is_integral()
                        && (other.is_integral() && fits(other, arith::to_i128(le, bits))
                            || other.is_real())
                    {
                        return Some(other);
                    }
                    if le.is_real() && other.is_real() {
                        return Some(other);
                    }
                }
            }
        }
        WIDENING_ORDER.into_iter().find(|&t| can_widen(ae, t) && can_widen(be, t))
    }

    /// Converts `e` to `to` (which must be reachable), folding constants.
    pub fn convert(&self, e: Expr, to: Type) -> Expr {
        if e.ty == to {
            return e;
        }
        if let (ExprKind::Const(bits), Some(from), Some(t)) = (&e.kind, e.ty.elem(), to.elem()) {
            return self.const_expr(arith::convert(from, t, *bits), to, e.span);
        }
        let span = e.span;
        Expr { kind: ExprKind::Convert(Box::new(e)), ty: to, span }
    }

    /// Converts a checked value for storing into (or passing as) `target`; reports a
    /// mismatch.
    pub fn coerce(&mut self, t: Typed, target: Type, span: Span) -> Option<Expr> {
        let from = t.e.ty;
        if from == target {
            return Some(t.e);
        }
        match (from, target) {
            (Type::Elem(fe), Type::Elem(te)) => {
                if let (true, ExprKind::Const(bits)) = (t.flexible, &t.e.kind) {
                    if fe.is_integral() {
                        let v = arith::to_i128(fe, *bits);
                        if (te.is_integral() || te == Elem::Bool) && fits(te, v) {
                            return Some(self.const_expr(arith::norm(te, v), target, t.e.span));
                        }
                        if te.is_real() {
                            return Some(self.const_expr(
                                arith::from_f64(te, v as f64),
                                target,
                                t.e.span,
                            ));
                        }
                        if te.is_integral() {
                            let (lo, hi) = te.int_range();
                            self.error(
                                Code::ConstantOutOfRange,
                                span,
                                crate::msg!(
                                    DoesNotFit,
                                    v = v,
                                    name = (te.name()).to_string(),
                                    lo = lo,
                                    hi = hi
                                ),
                            );
                            return None;
                        }
                    }
                    if fe.is_real() && te.is_real() {
                        return Some(self.const_expr(
                            arith::from_f64(te, f64::from_bits(*bits)),
                            target,
                            t.e.span,
                        ));
                    }
                }
                if t.flexible && fe.is_real() && te.is_real() {
                    return Some(self.convert(t.e, target));
                }
                if can_widen(fe, te) {
                    return Some(self.convert(t.e, target));
                }
                let (f, to) = (fe.name(), te.name());
                let message = if fe.is_num() && te.is_num() || fe.is_integral() && te.is_integral()
                {
                    // Both are numbers: the value would fit only sometimes.
                    msg!(LossyConversion, from = f, to = to)
                } else {
                    msg!(ExpectedType, to = to, from = f)
                };
                self.error(Code::TypeMismatch, span, message);
                None
            }
            (Type::Ref(super::types::NULL_REF), Type::Ref(_)) => Some(self.null_as(t.e, target)),
            (Type::Str { wide: a, .. }, Type::Str { wide: b, .. }) if a == b => {
                let mut e = t.e;
                if let ExprKind::ConstStr(_) = e.kind {
                    e.ty = target;
                }
                Some(e)
            }
            _ => {
                let (f, to) = (self.tname(from), self.tname(target));
                self.error(Code::TypeMismatch, span, msg!(ExpectedType, to = to, from = f));
                None
            }
        }
    }

    /// The operands of a comparison or a logical operator, an untyped `0` or `1` beside a
    /// BOOL read as FALSE or TRUE. Kept out of [`Self::binary`]'s frame: expressions nest
    /// as deep as the limit on a 1 MiB stack.
    #[inline(never)]
    fn bool_literals(&self, op: BinOp, a: Typed, b: Typed) -> (Typed, Typed) {
        if !(is_comparison(op) || matches!(op, BinOp::And | BinOp::Or | BinOp::Xor)) {
            return (a, b);
        }
        let (at, bt) = (a.e.ty, b.e.ty);
        (self.bool_literal(a, bt), self.bool_literal(b, at))
    }

    /// An untyped `0` or `1` beside a BOOL operand is the BOOL literal FALSE or TRUE
    /// (IEC 61131-3 Table 5; `IF Done = 1`, as matiec and OpenPLC accept).
    pub(super) fn bool_literal(&self, t: Typed, other: Type) -> Typed {
        match (&t.e.kind, t.e.ty.elem()) {
            (ExprKind::Const(bits), Some(el)) if t.flexible && other.is_bool() && el.is_int() => {
                match arith::to_i128(el, *bits) {
                    v @ (0 | 1) => Typed::fixed(self.const_expr(
                        arith::norm(Elem::Bool, v),
                        Type::BOOL,
                        t.e.span,
                    )),
                    _ => t,
                }
            }
            _ => t,
        }
    }

    fn binary(
        &mut self,
        op: BinOp,
        l: &ast::Expr,
        r: &ast::Expr,
        span: Span,
        expected: Option<Type>,
    ) -> Option<Typed> {
        let hint = if is_comparison(op) { None } else { expected };
        let a = self.expr(l, hint);
        let b = match &a {
            Some(a) if is_comparison(op) => self.expr(r, Some(a.e.ty)),
            _ => self.expr(r, hint),
        };
        let (a, b) = self.bool_literals(op, a?, b?);
        let (at, bt) = (a.e.ty, b.e.ty);
        let mismatch = |c: &mut Self| {
            let msg = crate::msg!(
                CannotCombine,
                op_text = (op_text(op)).to_string(),
                tname = (c.tname(at)).to_string(),
                tname2 = (c.tname(bt)).to_string()
            );
            c.error(Code::OperatorTypeMismatch, span, msg);
            None
        };
        let make = |c: &Self, ty: Type, x: Expr, y: Expr| {
            let e = Expr { kind: ExprKind::Binary(op, Box::new(x), Box::new(y)), ty, span };
            c.fold(e)
        };
        match op {
            BinOp::AndThen | BinOp::OrElse => {
                let x = self.coerce(a, Type::BOOL, l.span)?;
                let y = self.coerce(b, Type::BOOL, r.span)?;
                return Some(Typed::fixed(make(self, Type::BOOL, x, y)?));
            }
            BinOp::And | BinOp::Or | BinOp::Xor => {
                if at.is_bool() && bt.is_bool() {
                    return Some(Typed::fixed(make(self, Type::BOOL, a.e, b.e)?));
                }
                let ok = |t: Type| t.elem().is_some_and(|e| e.is_integral());
                if !ok(at) || !ok(bt) {
                    return mismatch(self);
                }
                let flexible = a.flexible && b.flexible;
                let el = self.common_elem(&a, &b).filter(|e| e.is_integral());
                let Some(el) = el else { return mismatch(self) };
                let ty = Type::Elem(el);
                let (x, y) = (self.convert(a.e, ty), self.convert(b.e, ty));
                return Some(Typed { e: make(self, ty, x, y)?, flexible });
            }
            _ => {}
        }
        if is_comparison(op) {
            let operand = match (at, bt) {
                (Type::Str { wide: x, .. }, Type::Str { wide: y, .. }) if x == y => {
                    return Some(Typed::fixed(make(self, Type::BOOL, a.e, b.e)?));
                }
                (Type::Enum(x), Type::Enum(y)) if x == y => at,
                (Type::Ref(_), Type::Ref(_)) => return self.ref_compare(op, a.e, b.e, span),
                (Type::Elem(x), Type::Elem(y)) if x == y => at,
                (Type::Elem(_), Type::Elem(_)) => match self.common_elem(&a, &b) {
                    Some(el) => Type::Elem(el),
                    None => return mismatch(self),
                },
                _ => return mismatch(self),
            };
            if matches!(op, BinOp::Cmp(Cmp::Lt | Cmp::Le | Cmp::Gt | Cmp::Ge)) && operand.is_bool()
            {
                // Allowed (FALSE < TRUE), as in IEC.
            }
            let (x, y) = (self.convert(a.e, operand), self.convert(b.e, operand));
            return Some(Typed::fixed(make(self, Type::BOOL, x, y)?));
        }
        // Arithmetic.
        let (ae, be) = match (at.elem(), bt.elem()) {
            (Some(x), Some(y)) => (x, y),
            _ => return mismatch(self),
        };
        if ae.is_temporal() || be.is_temporal() {
            return self.temporal_arith(op, a, b, span, mismatch);
        }
        // Bit strings take part in arithmetic and wrap in their width, as in CODESYS.
        let arithmetic = |e: Elem| e.is_num() || e.is_bitstring();
        if !arithmetic(ae) || !arithmetic(be) {
            return mismatch(self);
        }
        // `i * 1.5` with an integer `i` stays assignable to REAL: the untyped real literal
        // lends its flexibility to the result.
        let real_literal = |t: &Typed, other: Elem| {
            t.flexible && t.e.ty.elem().is_some_and(Elem::is_real) && other.is_int()
        };
        let flexible = (a.flexible && b.flexible) || real_literal(&a, be) || real_literal(&b, ae);
        if flexible && ae.is_integral() && be.is_integral() && op != BinOp::Pow {
            // Fold untyped integer literals exactly, then pick the smallest type.
            if let (ExprKind::Const(x), ExprKind::Const(y)) = (&a.e.kind, &b.e.kind) {
                let (x, y) = (arith::to_i128(ae, *x), arith::to_i128(be, *y));
                let v = match op {
                    BinOp::Add => x.checked_add(y),
                    BinOp::Sub => x.checked_sub(y),
                    BinOp::Mul => x.checked_mul(y),
                    BinOp::Div if y == 0 => {
                        self.error(Code::DivisionByZeroConstant, span, crate::msg!(DivisionZero));
                        return None;
                    }
                    BinOp::Div => Some(x / y),
                    BinOp::Mod => Some(if y == 0 { 0 } else { x % y }),
                    _ => None,
                };
                if let Some(ty) = v.and_then(smallest_int_type) {
                    let v = v.unwrap_or_default();
                    let e = self.const_expr(arith::norm(ty, v), Type::Elem(ty), span);
                    return Some(Typed { e, flexible: true });
                }
            }
        }
        let el = if op == BinOp::Pow {
            if ae.is_bitstring() || be.is_bitstring() {
                return mismatch(self);
            }
            if ae == Elem::Real && (be == Elem::Real || b.flexible) {
                Elem::Real
            } else {
                Elem::LReal
            }
        } else {
            match self.common_elem(&a, &b) {
                Some(el) => el,
                None => return mismatch(self),
            }
        };
        if op == BinOp::Mod && !el.is_integral() {
            let msg = crate::msg!(ModNeedsIntegersNot, name = (el.name()).to_string());
            self.error(Code::OperatorTypeMismatch, span, msg);
            return None;
        }
        let ty = Type::Elem(el);
        let (x, y) = (self.convert(a.e, ty), self.convert(b.e, ty));
        if op == BinOp::Div && el.is_integral() && matches!(y.kind, ExprKind::Const(0)) {
            self.error(Code::DivisionByZeroConstant, r.span, crate::msg!(DivisionConstantZero));
            return None;
        }
        Some(Typed { e: make(self, ty, x, y)?, flexible })
    }

    fn temporal_arith(
        &mut self,
        op: BinOp,
        a: Typed,
        b: Typed,
        span: Span,
        mismatch: impl Fn(&mut Self) -> Option<Typed>,
    ) -> Option<Typed> {
        use Elem::*;
        let (ae, be) = (a.e.ty.elem()?, b.e.ty.elem()?);
        let make = |c: &Self, ty: Elem, x: Expr, y: Expr| {
            let e = Expr {
                kind: ExprKind::Binary(op, Box::new(x), Box::new(y)),
                ty: Type::Elem(ty),
                span,
            };
            c.fold(e).map(Typed::fixed)
        };
        let result = match (op, ae, be) {
            (BinOp::Add | BinOp::Sub, Time, Time) => Time,
            (BinOp::Add | BinOp::Sub, Tod, Time) => Tod,
            // DT counts microseconds, TIME nanoseconds: the TIME is converted first (its
            // part below a microsecond dropped), the difference of two DT or DATE after.
            (BinOp::Add | BinOp::Sub, Dt, Time) => {
                let y = self.convert(b.e, Type::Elem(Dt));
                return make(self, Dt, a.e, y);
            }
            (BinOp::Sub, Dt, Dt) | (BinOp::Sub, Date, Date) => {
                let diff = make(self, ae, a.e, b.e)?;
                return Some(Typed::fixed(self.convert(diff.e, Type::Elem(Time))));
            }
            (BinOp::Sub, Tod, Tod) => Time,
            (BinOp::Mul | BinOp::Div, t, n) if t.is_temporal() && t == Time && n.is_num() => {
                let f = if n.is_real() { LReal } else { LInt };
                let y = self.convert(b.e, Type::Elem(f));
                return make(self, t, a.e, y);
            }
            (BinOp::Mul, n, Time) if n.is_num() => {
                let f = if n.is_real() { LReal } else { LInt };
                let x = self.convert(a.e, Type::Elem(f));
                let e = Expr {
                    kind: ExprKind::Binary(op, Box::new(b.e), Box::new(x)),
                    ty: Type::Elem(Time),
                    span,
                };
                return self.fold(e).map(Typed::fixed);
            }
            _ => return mismatch(self),
        };
        make(self, result, a.e, b.e)
    }

    /// Folds a binary node whose operands are constants; reports constant faults.
    fn fold(&self, e: Expr) -> Option<Expr> {
        let ExprKind::Binary(op, x, y) = &e.kind else { return Some(e) };
        let (ExprKind::Const(a), ExprKind::Const(b)) = (&x.kind, &y.kind) else { return Some(e) };
        let Some(xe) = x.ty.elem() else {
            if let (Type::Enum(_), true) = (x.ty, is_comparison(*op)) {
                let r = arith::compare(*op, Elem::LInt, *a, *b);
                return Some(self.const_expr(u64::from(r), Type::BOOL, e.span));
            }
            return Some(e);
        };
        let bits = if is_comparison(*op) {
            u64::from(arith::compare(*op, xe, *a, *b))
        } else if matches!(op, BinOp::AndThen) {
            a & b
        } else if matches!(op, BinOp::OrElse) {
            a | b
        } else if xe.is_temporal() && matches!(op, BinOp::Mul | BinOp::Div) {
            let real = y.ty == Type::Elem(Elem::LReal);
            match arith::scale_time(*op, xe, *a, *b, real) {
                Ok(v) => v,
                Err(_) => return Some(e),
            }
        } else {
            match arith::binary(*op, xe, *a, *b) {
                Ok(v) => v,
                Err(_) => return Some(e),
            }
        };
        Some(self.const_expr(bits, e.ty, e.span))
    }
}

/// The letter of a part's size in `.%B1`.
fn part_letter(part: Elem) -> char {
    match part {
        Elem::Byte => 'B',
        Elem::Word => 'W',
        Elem::DWord => 'D',
        _ => 'L',
    }
}

/// All ones over a part's width.
fn part_mask(part: Elem) -> u64 {
    match part.bits() {
        64 => u64::MAX,
        n => (1u64 << n) - 1,
    }
}

/// All ones over a bit string type's width.
fn type_mask(ty: Type) -> u64 {
    ty.elem().map_or(u64::MAX, part_mask)
}
