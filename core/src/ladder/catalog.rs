//! What a rung may call and what its operands are: the pins and types of the standard FBs
//! (read from the prelude's ST), of the standard functions, and of the project's own
//! FUNCTION_BLOCKs and FUNCTIONs (read from the project's ST source and its ladder FBs), and
//! the declared types of the variables a ladder POU can name. Validation uses it to report a
//! wrong block, pin or operand at its rung, row and column before the ST checker runs.
//!
//! Types are compared by name after resolving aliases and subranges; whatever cannot be told
//! here (arrays of structs, expressions) is left to the ST checker, whose messages are mapped
//! back to the cell anyway.

use std::collections::HashMap;

use crate::semantic::{can_widen, Elem, SysVar};
use crate::syntax::ast::{AddressSize, Item, LiteralValue, PouKind, TypeRef, VarSection};
use crate::syntax::{self, ExprKind};

/// The type of a value, as far as the ladder needs to know it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TypeKey {
    /// An elementary type, a string (`STRING`, `WSTRING`) or a named user type (upper case).
    Named(String),
    /// An array of elements of this type.
    Array(Box<TypeKey>),
}

impl TypeKey {
    fn named(s: &str) -> Self {
        TypeKey::Named(s.to_ascii_uppercase())
    }

    /// Whether this is BOOL.
    pub fn is_bool(&self) -> bool {
        matches!(self, TypeKey::Named(n) if n == "BOOL")
    }

    fn elem(&self) -> Option<Elem> {
        match self {
            TypeKey::Named(n) => Elem::from_name(n),
            TypeKey::Array(_) => None,
        }
    }
}

impl std::fmt::Display for TypeKey {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TypeKey::Named(n) => f.write_str(n),
            TypeKey::Array(e) => write!(f, "ARRAY OF {e}"),
        }
    }
}

/// Whether a value of type `from` may be given where `to` is expected (same type, or an
/// implicit widening as the ST checker allows it).
pub fn fits(from: &TypeKey, to: &TypeKey) -> bool {
    if from == to {
        return true;
    }
    match (from.elem(), to.elem()) {
        (Some(a), Some(b)) => can_widen(a, b),
        _ => false,
    }
}

/// One parameter of a block type.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    /// The formal name as declared.
    pub name: String,
    /// Its type, when the catalog can tell it.
    pub ty: Option<TypeKey>,
}

/// Whether a block type keeps state between calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BlockKind {
    /// A FUNCTION_BLOCK: needs an instance variable.
    FunctionBlock,
    /// A FUNCTION.
    Function,
}

/// The pins of a block type a rung may use.
#[derive(Debug, Clone, PartialEq)]
pub struct BlockType {
    /// The type's name as declared.
    pub name: String,
    /// FB or function.
    pub kind: BlockKind,
    /// VAR_INPUT parameters, in declaration order.
    pub inputs: Vec<Param>,
    /// VAR_OUTPUT parameters; a function's result is the output `OUT`.
    pub outputs: Vec<Param>,
    /// VAR_IN_OUT parameters.
    pub in_outs: Vec<Param>,
}

impl BlockType {
    /// Whether the type is a FUNCTION_BLOCK (its uses need an instance variable).
    pub fn is_function_block(&self) -> bool {
        self.kind == BlockKind::FunctionBlock
    }

    /// The input named `name` (any case).
    pub fn input(&self, name: &str) -> Option<&Param> {
        self.inputs.iter().find(|p| p.name.eq_ignore_ascii_case(name.trim()))
    }

    /// The output named `name` (any case).
    pub fn output(&self, name: &str) -> Option<&Param> {
        self.outputs.iter().find(|p| p.name.eq_ignore_ascii_case(name.trim()))
    }

    /// The in-out named `name` (any case).
    pub fn in_out(&self, name: &str) -> Option<&Param> {
        self.in_outs.iter().find(|p| p.name.eq_ignore_ascii_case(name.trim()))
    }

    /// The member `name` (an input or output) that code outside the block may read.
    fn member(&self, name: &str) -> Option<&Param> {
        self.output(name).or_else(|| self.input(name))
    }
}

/// The pin names a standard function accepts: its inputs, and whether more `INn` may follow.
pub fn standard_function_inputs(name: &str) -> Option<(&'static [&'static str], bool)> {
    Some(match name.trim().to_ascii_uppercase().as_str() {
        "ADD" | "MUL" | "AND" | "OR" | "XOR" | "EQ" | "NE" | "GT" | "GE" | "LT" | "LE" => {
            (&["IN1", "IN2"], true)
        }
        "SUB" | "DIV" | "MOD" => (&["IN1", "IN2"], false),
        "SQRT" | "MOVE" | "NOT" | "BCD_TO_INT" | "INT_TO_BCD" => (&["IN"], false),
        "SHL" | "SHR" | "ROL" | "ROR" => (&["IN", "N"], false),
        _ if super::blocks::is_conversion(name) => (&["IN"], false),
        _ => return None,
    })
}

/// Block types, user types and global variables a ladder POU of a project can use.
#[derive(Debug, Clone, Default)]
pub struct Catalog {
    blocks: HashMap<String, BlockType>,
    aliases: HashMap<String, TypeKey>,
    structs: HashMap<String, Vec<Param>>,
    enumerators: Vec<String>,
    globals: HashMap<String, TypeKey>,
    global_vars: Vec<Variable>,
}

/// A variable a POU can name, as it is declared (for the operand box's completion).
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// The name as declared.
    pub name: String,
    /// Its type (aliases and subranges resolved).
    pub ty: TypeKey,
    /// The section it is declared in (`VAR_GLOBAL` for the project's globals).
    pub section: VarSection,
    /// Declared `CONSTANT`: cannot be written.
    pub constant: bool,
    /// Its `AT` address (`%IX0.0`).
    pub address: Option<crate::syntax::ast::DirectAddress>,
}

impl Variable {
    /// Whether a rung may write it (a coil, an output pin): not an input, not a constant.
    pub fn writable(&self) -> bool {
        !self.constant && self.section != VarSection::Input
    }
}

/// The variables a POU can name, with their types (upper-case keys).
pub type Scope = HashMap<String, TypeKey>;

impl Catalog {
    /// The standard FBs only.
    pub fn standard() -> Self {
        let mut c = Catalog::default();
        c.add_source(crate::semantic::PRELUDE_SOURCE);
        c
    }

    /// The standard FBs, the ST POUs, types and globals of `source`, and the ladder FBs
    /// among `ladder` (a project's catalog: `Project::catalog`).
    pub fn of_parts(source: &str, ladder: &[super::LadderPou]) -> Self {
        let mut c = Catalog::standard();
        c.add_source(source);
        for pou in ladder {
            if pou.kind == super::LadderPouKind::FunctionBlock {
                let text = format!(
                    "FUNCTION_BLOCK {}\n{}\nEND_FUNCTION_BLOCK\n",
                    pou.name, pou.declarations
                );
                c.add_source(&text);
            }
        }
        c
    }

    /// The names of the project's own FUNCTION and FUNCTION_BLOCK types (not the standard
    /// ones), sorted.
    pub fn user_block_names(&self) -> Vec<String> {
        let standard = Catalog::standard();
        let mut names: Vec<String> = self
            .blocks
            .values()
            .filter(|b| standard.block(&b.name).is_none())
            .map(|b| b.name.clone())
            .collect();
        crate::order::sort(&mut names);
        names
    }

    /// Adds the types, globals and FUNCTION / FUNCTION_BLOCK signatures of an ST text.
    pub fn add_source(&mut self, source: &str) {
        let (file, _) = syntax::parse(source);
        for item in &file.items {
            if let Item::Types(defs) = item {
                for d in defs {
                    let key = d.name.key();
                    match &d.ty {
                        TypeRef::Struct { fields, .. } => {
                            let mut list = Vec::new();
                            for f in fields {
                                for n in &f.names {
                                    list.push(Param { name: n.name.clone(), ty: key_of(&f.ty) });
                                }
                            }
                            self.structs.insert(key, list);
                        }
                        TypeRef::Enum { values, .. } => {
                            self.enumerators.extend(values.iter().map(|(v, _)| v.key()));
                        }
                        other => {
                            if let Some(k) = key_of(other) {
                                self.aliases.insert(key, k);
                            }
                        }
                    }
                }
            }
        }
        for item in &file.items {
            match item {
                Item::Globals(block) => {
                    for v in self.variables_of(block) {
                        self.globals.insert(v.name.to_ascii_uppercase(), v.ty.clone());
                        self.global_vars.push(v);
                    }
                }
                Item::Pou(p) if p.kind != PouKind::Program => {
                    let mut t = BlockType {
                        name: p.name.name.clone(),
                        kind: if p.kind == PouKind::Function {
                            BlockKind::Function
                        } else {
                            BlockKind::FunctionBlock
                        },
                        inputs: Vec::new(),
                        outputs: Vec::new(),
                        in_outs: Vec::new(),
                    };
                    if let Some(rt) = &p.return_type {
                        let ty = key_of(rt).map(|k| self.resolve(k));
                        t.outputs.push(Param { name: "OUT".into(), ty });
                    }
                    for b in &p.var_blocks {
                        let list = match b.section {
                            VarSection::Input => &mut t.inputs,
                            VarSection::Output => &mut t.outputs,
                            VarSection::InOut => &mut t.in_outs,
                            _ => continue,
                        };
                        for d in &b.decls {
                            let ty = key_of(&d.ty).map(|k| self.resolve(k));
                            for n in &d.names {
                                list.push(Param { name: n.name.clone(), ty: ty.clone() });
                            }
                        }
                    }
                    self.blocks.insert(p.name.key(), t);
                }
                _ => {}
            }
        }
    }

    /// The block type `name` probably misspells (`did you mean TON?`), as declared.
    pub fn closest_block(&self, name: &str) -> Option<&str> {
        crate::diagnostics::suggest::closest_in_set(
            name,
            self.blocks.values().map(|b| b.name.as_str()),
        )
    }

    /// The FB or FUNCTION type named `name` (standard FBs and the project's POUs).
    pub fn block(&self, name: &str) -> Option<&BlockType> {
        self.blocks.get(&name.trim().to_ascii_uppercase())
    }

    /// Follows type aliases and subranges to the type they stand for.
    pub fn resolve(&self, key: TypeKey) -> TypeKey {
        let mut k = key;
        for _ in 0..16 {
            match &k {
                TypeKey::Named(n) => match self.aliases.get(n) {
                    Some(next) => k = next.clone(),
                    None => break,
                },
                TypeKey::Array(e) => return TypeKey::Array(Box::new(self.resolve((**e).clone()))),
            }
        }
        k
    }

    /// The variables a POU with these declarations (ST `VAR…` blocks) can name: its own
    /// and the project's globals.
    pub fn scope(&self, declarations: &str) -> Scope {
        let mut scope = self.globals.clone();
        for b in declaration_blocks(declarations) {
            for d in &b.decls {
                let Some(k) = key_of(&d.ty) else { continue };
                let k = self.resolve(k);
                for n in &d.names {
                    scope.insert(n.key(), k.clone());
                }
            }
        }
        scope
    }

    /// The variables a POU with these declarations can name, as declared: its own in
    /// declaration order, then the project's globals it does not hide.
    pub fn variables(&self, declarations: &str) -> Vec<Variable> {
        let mut list: Vec<Variable> =
            declaration_blocks(declarations).iter().flat_map(|b| self.variables_of(b)).collect();
        for g in &self.global_vars {
            if !list.iter().any(|v| v.name.eq_ignore_ascii_case(&g.name)) {
                list.push(g.clone());
            }
        }
        list
    }

    fn variables_of(&self, block: &crate::syntax::ast::VarBlock) -> Vec<Variable> {
        let mut list = Vec::new();
        for d in &block.decls {
            let Some(k) = key_of(&d.ty) else { continue };
            let ty = self.resolve(k);
            for n in &d.names {
                list.push(Variable {
                    name: n.name.clone(),
                    ty: ty.clone(),
                    section: block.section,
                    constant: block.constant,
                    address: d.location.clone(),
                });
            }
        }
        list
    }

    /// Whether `name` is an enumerator of a declared enumeration.
    pub fn is_enumerator(&self, name: &str) -> bool {
        self.enumerators.iter().any(|e| e.eq_ignore_ascii_case(name.trim()))
    }

    /// The type of a place operand (`x`, `T1.ET`, `a[2]`, `s.f`, `%IW3`, `w.3`) in `scope`;
    /// `None` when it cannot be told here.
    pub fn place_type(&self, scope: &Scope, text: &str) -> Option<TypeKey> {
        let e = syntax::parse_expression(text).ok()?;
        self.expr_type(scope, &e)
    }

    fn expr_type(&self, scope: &Scope, e: &syntax::Expr) -> Option<TypeKey> {
        match &e.kind {
            ExprKind::Name(id) => scope.get(&id.key()).cloned().or_else(|| {
                let sys = SysVar::from_name(&id.key())?;
                Some(TypeKey::named(sys.ty().elem()?.name()))
            }),
            ExprKind::Direct(d) => Some(TypeKey::named(match d.size {
                AddressSize::Bit => "BOOL",
                AddressSize::Byte => "BYTE",
                AddressSize::Word => "WORD",
                AddressSize::DWord => "DWORD",
                AddressSize::LWord => "LWORD",
            })),
            ExprKind::Bit(..) => Some(TypeKey::named("BOOL")),
            ExprKind::Index(base, _) => match self.expr_type(scope, base)? {
                TypeKey::Array(el) => Some(*el),
                TypeKey::Named(_) => None,
            },
            ExprKind::Member(base, field) => {
                let TypeKey::Named(n) = self.expr_type(scope, base)? else { return None };
                if let Some(b) = self.blocks.get(&n) {
                    return b.member(&field.name)?.ty.clone();
                }
                let fields = self.structs.get(&n)?;
                let f = fields.iter().find(|f| f.name.eq_ignore_ascii_case(&field.name))?;
                f.ty.clone().map(|k| self.resolve(k))
            }
            ExprKind::Paren(inner) => self.expr_type(scope, inner),
            _ => None,
        }
    }

    /// Whether the value `text` may be given to a pin of type `to`: `Some(true)` yes,
    /// `Some(false)` no (with the value's type when it is known), `None` cannot tell.
    pub fn value_fits(&self, scope: &Scope, text: &str, to: &TypeKey) -> Option<(bool, String)> {
        let e = syntax::parse_expression(text).ok()?;
        let to_elem = to.elem();
        if let ExprKind::Literal(lit) = &e.kind {
            if let Some(prefix) = &lit.type_prefix {
                let k = self.resolve(TypeKey::named(&prefix.name));
                return Some((fits(&k, to), k.to_string()));
            }
            let (ok, what) = match (&lit.value, to_elem) {
                (LiteralValue::Int(_), Some(t)) => {
                    (t.is_integral() || t.is_real(), "an integer literal")
                }
                (LiteralValue::Real(_), Some(t)) => (t.is_real(), "a REAL literal"),
                (LiteralValue::Bool(_), Some(t)) => (t == Elem::Bool, "a BOOL literal"),
                (LiteralValue::Time(_), Some(t)) => (t == Elem::Time, "a TIME literal"),
                (LiteralValue::Date(_), Some(t)) => (t == Elem::Date, "a DATE literal"),
                (LiteralValue::TimeOfDay(_), Some(t)) => (t == Elem::Tod, "a TIME_OF_DAY literal"),
                (LiteralValue::DateTime(_), Some(t)) => (t == Elem::Dt, "a DATE_AND_TIME literal"),
                (LiteralValue::String(_), _) => {
                    (matches!(to, TypeKey::Named(n) if n == "STRING"), "a STRING literal")
                }
                (LiteralValue::WString(_), _) => {
                    (matches!(to, TypeKey::Named(n) if n == "WSTRING"), "a WSTRING literal")
                }
                _ => return None,
            };
            return Some((ok, what.to_string()));
        }
        let from = self.expr_type(scope, &e)?;
        Some((fits(&from, to), from.to_string()))
    }
}

/// The type key of a declared type (strings without their length, subranges as their base).
/// The variable blocks of a ladder POU's declarations text (parsed inside a stand-in POU).
fn declaration_blocks(declarations: &str) -> Vec<crate::syntax::ast::VarBlock> {
    let text = format!("FUNCTION_BLOCK X__\n{declarations}\nEND_FUNCTION_BLOCK\n");
    let (file, _) = syntax::parse(&text);
    file.items
        .into_iter()
        .filter_map(|item| match item {
            Item::Pou(p) => Some(p.var_blocks),
            _ => None,
        })
        .flatten()
        .collect()
}

/// Every name a ladder POU's declarations text declares, whatever its type.
pub(crate) fn declared_names(declarations: &str) -> Vec<String> {
    declaration_blocks(declarations)
        .into_iter()
        .flat_map(|b| b.decls)
        .flat_map(|d| d.names)
        .map(|n| n.name)
        .collect()
}

fn key_of(t: &TypeRef) -> Option<TypeKey> {
    Some(match t {
        TypeRef::Named(id) => match Elem::from_name(&id.key()) {
            Some(e) => TypeKey::named(e.name()),
            None => TypeKey::named(&id.name),
        },
        TypeRef::String { wide, .. } => TypeKey::named(if *wide { "WSTRING" } else { "STRING" }),
        TypeRef::Array { element, .. } => TypeKey::Array(Box::new(key_of(element)?)),
        TypeRef::Subrange { base, .. } => key_of(&TypeRef::Named(base.clone()))?,
        TypeRef::Enum { .. } | TypeRef::Struct { .. } | TypeRef::Ref { .. } => return None,
    })
}
