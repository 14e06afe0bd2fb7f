//! Declarations: TYPE definitions, variable blocks and initial values.

use super::check::{Checker, Resolved, TypeSlot};
use super::consts;
use super::ir::{InitValue, Var};
use super::types::{dim_len, ArrayDef, Elem, EnumDef, FieldDef, PouId, StructDef, Type};
use crate::diagnostics::Code;
use crate::limits::MAX_TYPE_NESTING;
use crate::syntax::{self as ast, AddressSize, PouKind, TypeRef, VarSection};

use crate::limits::{MAX_ARRAY_ELEMENTS, MAX_STRING_LEN};

impl<'a> Checker<'a> {
    /// Resolves the TYPE declared under `key` (upper case), once.
    pub fn resolve_named_type(&mut self, key: &str) -> Option<Resolved> {
        let def = match self.type_slots.get(key) {
            Some(TypeSlot::Done(r)) => return Some(r.clone()),
            Some(TypeSlot::Failed) | None => return None,
            Some(TypeSlot::Resolving(span)) => {
                let span = *span;
                self.error(Code::RecursiveType, span, crate::msg!(TypeContainsItself, key = key));
                self.type_slots.insert(key.to_string(), TypeSlot::Failed);
                return None;
            }
            Some(TypeSlot::Pending(def)) => *def,
        };
        self.type_slots.insert(key.to_string(), TypeSlot::Resolving(def.name.span));
        let resolved = self.resolve_type(&def.ty, &def.name.name).and_then(|mut r| {
            if let Some(init) = &def.init {
                r.init = Some(self.init_value(init, r.ty, r.range)?);
            }
            Some(r)
        });
        if matches!(self.type_slots.get(key), Some(TypeSlot::Failed)) {
            return None;
        }
        self.complete_pending_refs(key, resolved.as_ref().map(|r| r.ty), &def.name);
        let slot = match &resolved {
            Some(r) => TypeSlot::Done(r.clone()),
            None => TypeSlot::Failed,
        };
        self.type_slots.insert(key.to_string(), slot);
        resolved
    }

    /// Resolves a type reference. `owner` names the declaration (for inline enums). Types
    /// that name types that name types … recurse here; past `MAX_TYPE_NESTING` levels the
    /// type is refused at `span` of the reference rather than exhausting the stack.
    pub fn resolve_type(&mut self, tr: &TypeRef, owner: &str) -> Option<Resolved> {
        if self.resolve_depth >= MAX_TYPE_NESTING {
            let message = crate::msg!(
                TypeBuiltFromTypesNested,
                owner = owner,
                MAX_TYPE_NESTING = MAX_TYPE_NESTING
            );
            self.error(Code::TooComplex, tr.span(), message);
            return None;
        }
        self.resolve_depth += 1;
        let r = self.resolve_type_inner(tr, owner);
        self.resolve_depth -= 1;
        r
    }

    fn resolve_type_inner(&mut self, tr: &TypeRef, owner: &str) -> Option<Resolved> {
        let plain = |ty| Some(Resolved { ty, range: None, init: None });
        match tr {
            TypeRef::Named(id) => {
                let key = id.key();
                if let Some(e) = Elem::from_name(&key) {
                    return plain(Type::Elem(e));
                }
                match key.as_str() {
                    "STRING" => return plain(Type::Str { wide: false, len: 80 }),
                    "WSTRING" => return plain(Type::Str { wide: true, len: 80 }),
                    _ => {}
                }
                if self.type_slots.contains_key(&key) {
                    return self.resolve_named_type(&key);
                }
                if let Some(&pou) = self.pou_index.get(&key) {
                    if self.pous[pou as usize].kind == PouKind::FunctionBlock {
                        return plain(Type::Fb(pou));
                    }
                    self.error(
                        Code::UnknownType,
                        id.span,
                        crate::msg!(
                            NotType,
                            name = id.name,
                            kind_name = (kind_name(self.pous[pou as usize].kind)).to_string()
                        ),
                    );
                    return None;
                }
                let msg = format!("unknown type `{}`", id.name);
                let types = self.type_names();
                self.error_suggesting(Code::UnknownType, id.span, msg, &id.name, types);
                None
            }
            TypeRef::Ref { target, .. } => {
                if let Some(r) = self.ref_to_resolving(target) {
                    return plain(r);
                }
                let t = self.resolve_type(target, owner)?;
                plain(self.types.reference(t.ty))
            }
            TypeRef::String { wide, length, span } => {
                let len = match length {
                    Some(e) => self.const_int(e)?,
                    None => 80,
                };
                if !(1..=MAX_STRING_LEN).contains(&len) {
                    self.error(
                        Code::InvalidArraySize,
                        *span,
                        crate::msg!(
                            StringLengthMustBetween1,
                            MAX_STRING_LEN = MAX_STRING_LEN,
                            len = len
                        ),
                    );
                    return None;
                }
                plain(Type::Str { wide: *wide, len: len as u32 })
            }
            TypeRef::Array { ranges, element, span } => {
                let mut dims = Vec::new();
                for (lo, hi) in ranges {
                    let (l, h) = (self.const_int(lo)?, self.const_int(hi)?);
                    if l > h {
                        self.error(
                            Code::InvalidRange,
                            lo.span.to(hi.span),
                            crate::msg!(ArrayBoundsLowerBoundAbove, l = l, h = h),
                        );
                        return None;
                    }
                    dims.push((l, h));
                }
                let elem = self.resolve_type(element, owner)?;
                let def = ArrayDef {
                    dims,
                    element: elem.ty,
                    element_range: elem.range,
                    element_init: elem.init,
                };
                let total =
                    def.dims.iter().try_fold(1u64, |acc, &(l, h)| acc.checked_mul(dim_len(l, h)));
                if total.is_none_or(|t| t > MAX_ARRAY_ELEMENTS) {
                    self.error(
                        Code::InvalidArraySize,
                        *span,
                        crate::msg!(
                            ArraysMayHoldMostElements,
                            MAX_ARRAY_ELEMENTS = MAX_ARRAY_ELEMENTS
                        ),
                    );
                    return None;
                }
                plain(self.types.array(def))
            }
            TypeRef::Subrange { base, low, high, span } => {
                let base_ty = Elem::from_name(&base.key()).filter(|e| e.is_int());
                let Some(elem) = base_ty else {
                    self.error(
                        Code::TypeMismatch,
                        base.span,
                        crate::msg!(SubrangeNeedsIntegerBaseType, name = base.name),
                    );
                    return None;
                };
                let (l, h) = (self.const_int(low)?, self.const_int(high)?);
                let (min, max) = elem.int_range();
                if l > h || (l as i128) < min || (h as i128) > max {
                    self.error(
                        Code::InvalidRange,
                        *span,
                        crate::msg!(
                            SubrangeEmptyDoesNotFit,
                            l = l,
                            h = h,
                            name = (elem.name()).to_string()
                        ),
                    );
                    return None;
                }
                Some(Resolved {
                    ty: Type::Elem(elem),
                    range: Some((l, h)),
                    init: Some(InitValue::Scalar(crate::values::arith::norm(elem, l as i128))),
                })
            }
            TypeRef::Enum { values, span: _ } => {
                let mut def = EnumDef { name: owner.to_string(), values: Vec::new() };
                let mut next = 0i64;
                for (name, value) in values {
                    if let Some(v) = value {
                        next = self.const_int(v)?;
                    }
                    if def.values.iter().any(|(n, _)| n.eq_ignore_ascii_case(&name.name)) {
                        self.error(
                            Code::DuplicateEnumerator,
                            name.span,
                            crate::msg!(AppearsTwiceEnumeration, name = name.name),
                        );
                        continue;
                    }
                    def.values.push((name.name.clone(), next));
                    next = next.wrapping_add(1);
                }
                let first = def.values.first().map_or(0, |(_, v)| *v);
                self.types.enums.push(def);
                let id = self.types.enums.len() as u32 - 1;
                Some(Resolved {
                    ty: Type::Enum(id),
                    range: None,
                    init: Some(InitValue::Scalar(first as u64)),
                })
            }
            TypeRef::Struct { fields, span: _ } => {
                let mut def = StructDef { name: owner.to_string(), fields: Vec::new() };
                for decl in fields {
                    let Some(r) = self.resolve_type(&decl.ty, owner) else { continue };
                    if let Type::Fb(_) = r.ty {
                        // FB instances inside structs are allowed (CODESYS does too).
                    }
                    let init = match &decl.init {
                        Some(i) => self.init_value(i, r.ty, r.range),
                        None => r.init.clone(),
                    };
                    for name in &decl.names {
                        if def.fields.iter().any(|f| f.name.eq_ignore_ascii_case(&name.name)) {
                            self.error(
                                Code::DuplicateDeclaration,
                                name.span,
                                crate::msg!(FieldDeclaredTwice, name = name.name),
                            );
                            continue;
                        }
                        def.fields.push(FieldDef {
                            name: name.name.clone(),
                            ty: r.ty,
                            init: init.clone(),
                            range: r.range,
                        });
                    }
                }
                self.types.structs.push(def);
                plain(Type::Struct(self.types.structs.len() as u32 - 1))
            }
        }
    }

    /// Evaluates a constant integer expression (array bounds, string lengths, CASE labels).
    pub fn const_int(&mut self, e: &ast::Expr) -> Option<i64> {
        let typed = self.expr(e, None)?;
        let value = consts::int_value(&typed.e);
        if value.is_none() {
            self.error(Code::NotConstant, e.span, crate::msg!(MustConstantIntegerLiteralConstant));
        }
        value
    }

    /// Resolves an initializer for a value of type `ty`.
    pub fn init_value(
        &mut self,
        init: &ast::Initializer,
        ty: Type,
        range: Option<(i64, i64)>,
    ) -> Option<InitValue> {
        match (init, ty) {
            (ast::Initializer::Expr(e), _) => {
                if let Some(pending) = self.ref_init(e, ty) {
                    return pending;
                }
                let typed = self.expr(e, Some(ty))?;
                let value = self.coerce(typed, ty, e.span)?;
                let Some(v) = consts::to_init_value(&value) else {
                    self.error(Code::NotConstant, e.span, crate::msg!(InitialValueMustConstant));
                    return None;
                };
                if let (Some((lo, hi)), InitValue::Scalar(bits), Type::Elem(el)) = (range, &v, ty) {
                    let n = crate::values::arith::to_i128(el, *bits);
                    if n < lo as i128 || n > hi as i128 {
                        self.error(
                            Code::SubrangeViolation,
                            e.span,
                            crate::msg!(InitialValueOutsideSubrange, n = n, lo = lo, hi = hi),
                        );
                    }
                }
                Some(v)
            }
            (ast::Initializer::Array { elements, span }, Type::Array(id)) => {
                let def = self.types.arrays[id as usize].clone();
                let mut out = Vec::new();
                for el in elements {
                    match el {
                        ast::ArrayInitElement::Single(i) => {
                            out.push(self.init_value(i, def.element, def.element_range)?)
                        }
                        ast::ArrayInitElement::Repeat { count, value, span } => {
                            let n = self.const_int(count)?;
                            if n < 0 || n as u64 > def.len() {
                                self.error(
                                    Code::TooManyInitializers,
                                    *span,
                                    crate::msg!(
                                        RepeatCountDoesNotFit,
                                        n = n,
                                        def = (def.len()).to_string()
                                    ),
                                );
                                return None;
                            }
                            let v = match value {
                                Some(v) => self.init_value(v, def.element, def.element_range)?,
                                None => consts::default_value(&self.types, &self.pous, def.element),
                            };
                            out.extend(std::iter::repeat_n(v, n as usize));
                        }
                    }
                    if out.len() as u64 > def.len() {
                        self.error(
                            Code::TooManyInitializers,
                            *span,
                            crate::msg!(
                                InitialValuesArrayElements,
                                out = (out.len()).to_string(),
                                def = (def.len()).to_string()
                            ),
                        );
                        return None;
                    }
                }
                Some(InitValue::Array(out))
            }
            (ast::Initializer::Struct { fields, span: _ }, Type::Struct(id)) => {
                let def = self.types.structs[id as usize].clone();
                let mut out = vec![None; def.fields.len()];
                for (name, value) in fields {
                    let Some(i) =
                        def.fields.iter().position(|f| f.name.eq_ignore_ascii_case(&name.name))
                    else {
                        let fields = def.fields.iter().map(|f| f.name.clone()).collect();
                        self.no_member(name, &def.name, true, fields);
                        continue;
                    };
                    let f = &def.fields[i];
                    out[i] = Some(self.init_value(value, f.ty, f.range)?);
                }
                Some(InitValue::Struct(out))
            }
            (ast::Initializer::Struct { fields, span: _ }, Type::Fb(pou)) => {
                // `tmr : TON := (PT := T#1s);`
                let mut out = vec![None; self.pous[pou as usize].vars.len()];
                for (name, value) in fields {
                    let Some(i) = self.pous[pou as usize].find_var(&name.name) else {
                        let fb = self.pous[pou as usize].name.clone();
                        let members = super::check::interface_names(&self.pous[pou as usize]);
                        self.no_member(name, &fb, false, members);
                        continue;
                    };
                    let (vty, vrange) = {
                        let v = &self.pous[pou as usize].vars[i as usize];
                        (v.ty, v.range)
                    };
                    out[i as usize] = Some(self.init_value(value, vty, vrange)?);
                }
                Some(InitValue::Struct(out))
            }
            (other, _) => {
                let what = match other {
                    ast::Initializer::Array { .. } => "an array initializer `[…]`",
                    _ => "a structure initializer `(…)`",
                };
                self.error(
                    Code::TypeMismatch,
                    other.span(),
                    crate::msg!(
                        CannotInitialiseValueType,
                        what = what,
                        ty = (self.tname(ty)).to_string()
                    ),
                );
                None
            }
        }
    }

    /// Declares the variables of one VAR block into `out`.
    pub fn declare_block(&mut self, block: &ast::VarBlock, kind: PouKind, out: &mut Vec<Var>) {
        let mut declared: std::collections::HashSet<String> =
            out.iter().map(|v| v.name.to_ascii_uppercase()).collect();
        for decl in &block.decls {
            let owner = decl.names.first().map_or("", |n| n.name.as_str()).to_string();
            let Some(r) = self.resolve_type(&decl.ty, &owner) else { continue };
            if kind == PouKind::Function && matches!(r.ty, Type::Fb(_)) {
                self.error(
                    Code::FunctionBlockInFunction,
                    decl.ty.span(),
                    crate::msg!(FunctionCannotHoldFunctionBlock),
                );
                continue;
            }
            if block.section == VarSection::External {
                for name in &decl.names {
                    self.check_external(name, r.ty);
                }
            }
            let init = match &decl.init {
                Some(i) => {
                    // `REF(x)` may be the initial value here, of a variable of this POU.
                    let scope = super::check::RefScope { pou: self.body.pou };
                    let outer = self.ref_scope.replace(scope);
                    let v = self.init_value(i, r.ty, r.range);
                    self.ref_scope = outer;
                    v
                }
                None => r.init.clone(),
            };
            if let Some(loc) = &decl.location {
                self.check_location(loc, r.ty);
            }
            // `AT %QW4 : WORD;` declares a variable known by its address.
            let unnamed = decl.location.as_ref().filter(|_| decl.names.is_empty()).map(|loc| {
                ast::Ident { name: super::expr::normalize_address(loc), span: loc.span }
            });
            for name in decl.names.iter().chain(unnamed.as_ref()) {
                if !declared.insert(name.key()) {
                    self.error(
                        Code::DuplicateDeclaration,
                        name.span,
                        crate::msg!(AlreadyDeclaredPou, name = name.name),
                    );
                    continue;
                }
                out.push(Var {
                    name: name.name.clone(),
                    ty: r.ty,
                    section: block.section,
                    retain: block.retain,
                    constant: block.constant,
                    location: decl.location.clone(),
                    init: init.clone(),
                    range: r.range,
                    comment: decl.comment.clone(),
                    span: name.span,
                });
            }
        }
    }

    fn check_external(&mut self, name: &ast::Ident, ty: Type) {
        match self.global_index.get(&name.key()) {
            None => self.error(
                Code::ExternalWithoutGlobal,
                name.span,
                crate::msg!(VarExternalHasNoMatching, name = name.name),
            ),
            Some(&g) if self.globals[g as usize].ty != ty => {
                let want = self.tname(self.globals[g as usize].ty);
                self.error(
                    Code::ExternalWithoutGlobal,
                    name.span,
                    crate::msg!(VarExternalMustHaveType, name = name.name, want = want),
                );
            }
            Some(_) => {}
        }
    }

    fn check_location(&mut self, loc: &ast::DirectAddress, ty: Type) {
        // An array at an address (`Outs AT %QW6 : ARRAY[0..9] OF INT`) occupies consecutive
        // locations of its element's size.
        let ty = match ty {
            Type::Array(id) => self.types.arrays[id as usize].element,
            other => other,
        };
        let Type::Elem(e) = ty else {
            self.error(
                Code::InvalidLocation,
                loc.span,
                crate::msg!(
                    CanOnlyHoldElementaryValue,
                    text = loc.text,
                    ty = (self.tname(ty)).to_string()
                ),
            );
            return;
        };
        let fits = match loc.size {
            AddressSize::Bit => e == Elem::Bool,
            AddressSize::Byte => e.bits() == 8,
            AddressSize::Word => e.bits() == 16,
            AddressSize::DWord => e.bits() == 32,
            AddressSize::LWord => e.bits() == 64,
        };
        if !fits {
            self.error(
                Code::InvalidLocation,
                loc.span,
                crate::msg!(DoesNotFitVariableType, text = loc.text, name = (e.name()).to_string()),
            );
        }
    }

    /// The variables of POU `id` while its blocks are declared: `vars` so far, then the
    /// constants of later blocks (`known`) not declared yet, so that they can size arrays.
    /// The name index is rebuilt: the list does not only grow.
    fn set_declared_vars(&mut self, id: PouId, mut vars: Vec<Var>, known: &[Var]) {
        for k in known {
            if !vars.iter().any(|v| v.name.eq_ignore_ascii_case(&k.name)) {
                vars.push(k.clone());
            }
        }
        self.pous[id as usize].vars = vars;
        self.var_index.remove(&(id as usize));
    }

    /// Declares the variables of POU `id` (and a FUNCTION's result variable).
    pub fn declare_pou_vars(&mut self, id: PouId) {
        let ast = self.pou_asts[id as usize];
        let kind = ast.kind;
        let mut vars = Vec::new();
        // Constants may size arrays declared before or after them (`VAR A : ARRAY[1..N]
        // …` then `VAR CONSTANT N …`, as CODESYS reads it): a quiet first pass over the
        // CONSTANT blocks makes them known, then every block is declared in order.
        self.body.pou = id;
        let constant_later = ast.var_blocks.iter().skip_while(|b| b.constant).any(|b| b.constant);
        let mut known = Vec::new();
        if constant_later {
            let (quiet, pending) = (self.diags.len(), self.ref_inits.len());
            for block in
                ast.var_blocks.iter().filter(|b| b.constant && b.section != VarSection::Global)
            {
                self.declare_block(block, kind, &mut known);
            }
            self.diags.truncate(quiet);
            self.ref_inits.truncate(pending);
            self.set_declared_vars(id, Vec::new(), &known);
        }
        for block in &ast.var_blocks {
            if block.section == VarSection::Global {
                if kind != PouKind::Program {
                    self.error(
                        Code::SectionNotAllowed,
                        block.span,
                        crate::msg!(VarGlobalOnlyAllowedTop),
                    );
                }
                continue;
            }
            if kind == PouKind::Function && block.section == VarSection::External {
                // Allowed: functions may read globals.
            }
            self.declare_block(block, kind, &mut vars);
            if constant_later {
                self.set_declared_vars(id, vars.clone(), &known);
            } else {
                self.pous[id as usize].vars = vars.clone();
            }
        }
        let mut result = None;
        if kind == PouKind::Function {
            if let Some(rt) = &ast.return_type {
                if let Some(r) = self.resolve_type(rt, &ast.name.name) {
                    if vars.iter().any(|v: &Var| v.name.eq_ignore_ascii_case(&ast.name.name)) {
                        self.error(
                            Code::DuplicateDeclaration,
                            ast.name.span,
                            crate::msg!(VariableCannotHaveNameFunction),
                        );
                    }
                    result = Some(vars.len() as u32);
                    vars.push(Var {
                        name: ast.name.name.clone(),
                        ty: r.ty,
                        section: VarSection::Output,
                        retain: false,
                        constant: false,
                        location: None,
                        init: r.init,
                        range: r.range,
                        comment: None,
                        span: rt.span(),
                    });
                }
            }
        }
        let pou = &mut self.pous[id as usize];
        pou.vars = vars;
        pou.result = result;
        if constant_later {
            self.var_index.remove(&(id as usize));
        }
    }
}

fn kind_name(kind: PouKind) -> &'static str {
    match kind {
        PouKind::Program => "PROGRAM",
        PouKind::Function => "FUNCTION",
        PouKind::FunctionBlock => "FUNCTION_BLOCK",
    }
}
