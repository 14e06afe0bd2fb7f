//! The checker's state and its driver: collect declarations, resolve types, declare
//! variables, check bodies, then reject recursion.

use std::collections::{HashMap, HashSet};

use super::ir::{self, Pou, Program, Var};
use super::prelude;
use super::types::{PouId, Type, TypeTable};
use crate::diagnostics::{Code, Diagnostic, Span};
use crate::syntax::{self as ast, Item, PouKind, VarSection};

/// A type declared in a TYPE block, resolved on first use.
pub(super) enum TypeSlot<'a> {
    /// Not looked at yet.
    Pending(&'a ast::TypeDef),
    /// Being resolved (seeing it again means the type contains itself).
    Resolving(Span),
    /// Resolved.
    Done(Resolved),
    /// Resolution failed (already reported).
    Failed,
}

/// A resolved type with what a declaration of it inherits.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Resolved {
    /// The type.
    pub ty: Type,
    /// Its subrange, if any.
    pub range: Option<(i64, i64)>,
    /// The initial value declared on the type, if any.
    pub init: Option<ir::InitValue>,
}

/// Per-body state while checking statements.
#[derive(Default)]
pub(super) struct BodyState {
    /// The POU whose body is being checked.
    pub pou: PouId,
    /// How many loops enclose the current statement.
    pub loop_depth: u32,
    /// True when reading/writing from a breakpoint condition (no writes allowed).
    pub read_only: bool,
}

/// Where a declaration whose initial value may be `REF()` is: the POU whose variables it
/// sees (`PouId::MAX` for VAR_GLOBAL: the globals only).
#[derive(Debug, Clone, Copy)]
pub(super) struct RefScope {
    /// The declaring POU.
    pub pou: PouId,
}

/// A `REF(…)` initial value waiting for every declaration (`ref_init.rs`).
pub(super) struct PendingRefInit {
    /// Where it is declared.
    pub scope: RefScope,
    /// The `REF(…)` call.
    pub expr: ast::Expr,
    /// The type of the variable it initialises.
    pub ty: Type,
}

/// The checker's state for one program.
pub(super) struct Checker<'a> {
    pub types: TypeTable,
    pub type_slots: HashMap<String, TypeSlot<'a>>,
    pub type_order: Vec<String>,
    /// The declared types' names as written, in declaration order (for `did you mean`).
    pub type_spellings: Vec<String>,
    pub pous: Vec<Pou>,
    pub pou_index: HashMap<String, PouId>,
    pub pou_asts: Vec<&'a ast::Pou>,
    pub globals: Vec<Var>,
    pub global_index: HashMap<String, u32>,
    pub diags: Vec<Diagnostic>,
    pub body: BodyState,
    pub calls: Vec<HashSet<PouId>>,
    pub library_pous: usize,
    /// Per POU: its variables by upper-case name, and how many variables the index covers
    /// (a POU's variable list only grows while it is declared). Without it every name in a
    /// body was a linear search, and a 1,000-rung ladder POU took seconds to check.
    pub var_index: HashMap<usize, (usize, HashMap<String, u32>)>,
    /// How many type resolutions are under way (a named type resolving the types of its
    /// fields recurses), capped by `limits::MAX_TYPE_NESTING`.
    pub resolve_depth: usize,
    /// `REF_TO X` met while the named type `X` is being resolved (a struct with a field
    /// referring to its own type): the reference type's id and `X`'s key, completed when
    /// `X` is (`refs.rs`).
    pub pending_refs: Vec<(super::types::RefId, String)>,
    /// Set while the initial value of a variable is checked: `REF(x)` may be that value,
    /// `x` a variable of this POU or a global (`ref_init.rs`).
    pub ref_scope: Option<RefScope>,
    /// The `REF(x)` initial values met, checked once every variable is declared.
    pub ref_inits: Vec<PendingRefInit>,
}

impl<'a> Checker<'a> {
    pub fn new() -> Self {
        Checker {
            types: TypeTable::default(),
            type_slots: HashMap::new(),
            type_order: Vec::new(),
            type_spellings: Vec::new(),
            pous: Vec::new(),
            pou_index: HashMap::new(),
            pou_asts: Vec::new(),
            globals: Vec::new(),
            global_index: HashMap::new(),
            diags: Vec::new(),
            body: BodyState::default(),
            calls: Vec::new(),
            library_pous: 0,
            var_index: HashMap::new(),
            resolve_depth: 0,
            pending_refs: Vec::new(),
            ref_scope: None,
            ref_inits: Vec::new(),
        }
    }

    /// The index of the variable named `key` (upper case, as [`ast::Ident::key`] gives it)
    /// in POU `pou`: the first one declared with that name, as [`Pou::find_var`] finds it.
    pub fn local_var(&mut self, pou: usize, key: &str) -> Option<u32> {
        let vars = &self.pous.get(pou)?.vars;
        let entry = self.var_index.entry(pou).or_default();
        if entry.0 != vars.len() {
            for (i, v) in vars.iter().enumerate().skip(entry.0) {
                entry.1.entry(v.name.to_ascii_uppercase()).or_insert(i as u32);
            }
            entry.0 = vars.len();
        }
        entry.1.get(key).copied()
    }

    /// Reports an error.
    pub fn error(&mut self, code: Code, span: Span, message: impl Into<crate::diagnostics::Said>) {
        self.diags.push(Diagnostic::error(code, span, message));
    }

    /// Reports an error about the unknown `name` at `span`, ending in `did you mean NAME?`
    /// when one of `candidates` (in the order a hint prefers them) is close to it; true
    /// when it did.
    pub fn error_suggesting(
        &mut self,
        code: Code,
        span: Span,
        message: impl Into<crate::diagnostics::Said>,
        name: &str,
        candidates: Vec<String>,
    ) -> bool {
        let suggestion =
            crate::diagnostics::suggest::closest(name, candidates.iter().map(String::as_str));
        let found = suggestion.is_some();
        self.diags.push(Diagnostic::error(code, span, message).suggesting(suggestion));
        found
    }

    /// The names a declaration can give as a type, in the order a hint prefers them: the
    /// elementary types, the declared types, the function blocks.
    pub fn type_names(&self) -> Vec<String> {
        let mut names: Vec<String> =
            crate::values::Elem::ALL.iter().map(|e| e.name().to_string()).collect();
        names.push("STRING".into());
        names.push("WSTRING".into());
        names.extend_from_slice(&self.type_spellings);
        for p in &self.pous {
            if p.kind == PouKind::FunctionBlock {
                names.push(p.name.clone());
            }
        }
        names
    }

    /// Reports a warning.
    pub fn warning(
        &mut self,
        code: Code,
        span: Span,
        message: impl Into<crate::diagnostics::Said>,
    ) {
        self.diags.push(Diagnostic::warning(code, span, message));
    }

    /// A type's name for messages.
    pub fn tname(&self, ty: Type) -> String {
        self.types.display(ty).to_string()
    }

    /// Registers the types and POUs of a file.
    fn collect(&mut self, file: &'a ast::SourceFile, library: bool) {
        for item in &file.items {
            match item {
                Item::Types(defs) => {
                    for def in defs {
                        let key = def.name.key();
                        if self.type_slots.contains_key(&key) || ast_elem_name(&key) {
                            self.error(
                                Code::DuplicateDeclaration,
                                def.name.span,
                                crate::msg!(TypeAlreadyDeclared, name = def.name.name),
                            );
                            continue;
                        }
                        self.type_order.push(key.clone());
                        self.type_spellings.push(def.name.name.clone());
                        self.type_slots.insert(key, TypeSlot::Pending(def));
                    }
                }
                Item::Pou(pou) => {
                    let key = pou.name.key();
                    if let Some(&other) = self.pou_index.get(&key) {
                        let what = if self.pous[other as usize].library {
                            "a standard library POU"
                        } else {
                            "already declared"
                        };
                        self.error(
                            Code::DuplicateDeclaration,
                            pou.name.span,
                            crate::msg!(ChooseAnotherName, name = pou.name.name, what = what),
                        );
                        continue;
                    }
                    let id = self.pous.len() as PouId;
                    self.pou_index.insert(key, id);
                    self.types.pou_names.push(pou.name.name.clone());
                    self.pou_asts.push(pou);
                    self.calls.push(HashSet::new());
                    self.pous.push(Pou {
                        name: pou.name.name.clone(),
                        kind: pou.kind,
                        vars: Vec::new(),
                        result: None,
                        body: Vec::new(),
                        library,
                        span: pou.span,
                    });
                }
                Item::Globals(_) | Item::Configuration(_) => {}
            }
        }
    }

    /// Declares the top-level VAR_GLOBAL blocks of a file.
    fn declare_file_globals(&mut self, file: &'a ast::SourceFile) {
        for item in &file.items {
            match item {
                Item::Globals(block) => self.declare_globals(block),
                Item::Configuration(c) => c.global_blocks().for_each(|b| self.declare_globals(b)),
                _ => {}
            }
        }
    }

    /// Declares a VAR_GLOBAL block (top-level or inside a PROGRAM).
    pub fn declare_globals(&mut self, block: &ast::VarBlock) {
        self.body.pou = PouId::MAX;
        let mut vars = Vec::new();
        self.declare_block(block, PouKind::Program, &mut vars);
        for var in vars {
            let key = var.name.to_ascii_uppercase();
            if self.global_index.contains_key(&key) {
                self.error(
                    Code::DuplicateDeclaration,
                    var.span,
                    crate::msg!(GlobalVariableAlreadyDeclared, name = var.name),
                );
                continue;
            }
            self.global_index.insert(key, self.globals.len() as u32);
            self.globals.push(var);
        }
    }

    fn finish(self) -> (Program, Vec<Diagnostic>) {
        let program = Program {
            types: self.types,
            globals: self.globals,
            pous: self.pous,
            library_pous: self.library_pous,
            config: None,
        };
        (program, self.diags)
    }

    /// Reports calls that recurse (a POU reaching itself through the call graph).
    fn check_recursion(&mut self) {
        let n = self.pous.len();
        for start in 0..n {
            let mut seen = HashSet::new();
            let mut stack: Vec<PouId> = self.calls[start].iter().copied().collect();
            while let Some(p) = stack.pop() {
                if p as usize == start {
                    let span = self.pous[start].span;
                    let name = self.pous[start].name.clone();
                    self.error(
                        Code::RecursiveCall,
                        span,
                        crate::msg!(CallsItselfDirectlyThroughOther, name = name),
                    );
                    break;
                }
                if seen.insert(p) {
                    stack.extend(self.calls[p as usize].iter().copied());
                }
            }
        }
    }
}

fn ast_elem_name(key: &str) -> bool {
    super::types::Elem::from_name(key).is_some() || key == "STRING" || key == "WSTRING"
}

/// Checks a parsed user file together with the standard library prelude.
pub(super) fn check_with_prelude(file: &ast::SourceFile) -> (Option<Program>, Vec<Diagnostic>) {
    let (lib, lib_diags) = crate::syntax::parse(prelude::SOURCE);
    let mut checker = Checker::new();
    checker.collect(&lib, true);
    checker.library_pous = checker.pous.len();
    checker.collect(file, false);
    let order = checker.type_order.clone();
    for key in &order {
        checker.resolve_named_type(key);
    }
    checker.declare_file_globals(&lib);
    checker.declare_file_globals(file);
    // Program-level VAR_GLOBAL blocks first, so every POU sees them.
    for i in 0..checker.pous.len() {
        let pou = checker.pou_asts[i];
        if pou.kind == PouKind::Program {
            for block in pou.var_blocks.iter().filter(|b| b.section == VarSection::Global) {
                checker.declare_globals(block);
            }
        }
    }
    // Functions and function blocks first: declarations of instances may initialise
    // their members.
    let n = checker.pous.len();
    let (blocks, programs): (Vec<usize>, Vec<usize>) =
        (0..n).partition(|&i| checker.pous[i].kind != PouKind::Program);
    for i in blocks.into_iter().chain(programs) {
        checker.declare_pou_vars(i as PouId);
    }
    // Initial values `REF(x)`: now that every variable is declared, in any order.
    checker.resolve_ref_inits();
    checker.place_located_vars();
    for i in 0..checker.pous.len() {
        checker.check_body(i as PouId);
    }
    let config = checker.check_configurations(file);
    checker.check_recursion();
    checker.check_type_nesting();
    let (mut program, mut diags) = checker.finish();
    program.config = config;
    if !lib_diags.is_empty() {
        diags.extend(lib_diags.into_iter().map(|mut d| {
            d.message = format!("standard library: {}", d.message);
            d.msg = crate::diagnostics::Message::text(d.message.clone());
            d.span = Span::default();
            d
        }));
    }
    (Some(program), diags)
}

/// The checker's answers to the IL lowering (`crate::il`): types of expressions in the
/// scope of a POU of the file's declarations, checked once.
pub(super) struct IlTyping {
    checker: Checker<'static>,
}

impl IlTyping {
    /// Checks `declarations` (a file whose bodies are removed) to answer from.
    pub(super) fn new(declarations: &ast::SourceFile) -> Option<Self> {
        let program = check_with_prelude(declarations).0?;
        Some(IlTyping { checker: Checker::around(&program) })
    }
}

impl crate::il::Typing for IlTyping {
    fn type_of(
        &mut self,
        pou: &str,
        expr: &ast::Expr,
    ) -> Result<crate::il::ValueType, Vec<Diagnostic>> {
        use crate::il::ValueType;
        let c = &mut self.checker;
        let Some(&id) = c.pou_index.get(&pou.to_ascii_uppercase()) else {
            return Err(Vec::new());
        };
        if let ast::ExprKind::Name(n) = &expr.kind {
            let named = |v: &&ir::Var| v.name.eq_ignore_ascii_case(&n.name);
            let var = c.pous[id as usize].vars.iter().find(named).or(c.globals.iter().find(named));
            if matches!(var.map(|v| v.ty), Some(Type::Fb(_))) {
                return Ok(ValueType::Instance);
            }
        }
        c.body = BodyState { pou: id, loop_depth: 0, read_only: true };
        c.diags.clear();
        let typed = c.expr(expr, None);
        let diags = std::mem::take(&mut c.diags);
        match typed {
            Some(t) if !crate::diagnostics::has_errors(&diags) => Ok(match t.e.ty {
                Type::Elem(e) => ValueType::Elementary(e.name()),
                Type::Fb(_) => ValueType::Instance,
                other => ValueType::Other(c.types.display(other).to_string()),
            }),
            _ => Err(diags),
        }
    }

    fn function(&self, name: &str) -> Option<bool> {
        let key = name.to_ascii_uppercase();
        let pou = self.checker.pou_index.get(&key).map(|&id| &self.checker.pous[id as usize]);
        match pou {
            Some(p) if p.kind == PouKind::Function => Some(p.library),
            Some(_) => None,
            None => super::is_builtin(&key).then_some(true),
        }
    }
}

impl<'a> Checker<'a> {
    /// Rebuilds a checker around an already checked program (for conditions and values).
    fn around(program: &Program) -> Checker<'static> {
        let mut c = Checker::new();
        c.types = program.types.clone();
        c.pous = program.pous.clone();
        c.globals = program.globals.clone();
        c.library_pous = program.library_pous;
        for (i, p) in program.pous.iter().enumerate() {
            c.pou_index.insert(p.name.to_ascii_uppercase(), i as PouId);
            c.calls.push(HashSet::new());
        }
        for (i, g) in program.globals.iter().enumerate() {
            c.global_index.insert(g.name.to_ascii_uppercase(), i as u32);
        }
        c
    }

    /// Checks the body of POU `id`.
    fn check_body(&mut self, id: PouId) {
        let ast = self.pou_asts[id as usize];
        self.body = BodyState { pou: id, loop_depth: 0, read_only: false };
        let body = self.stmts(&ast.body);
        self.pous[id as usize].body = body;
    }
}

/// The subrange declared for the variable `expr` names (`Level`, `Arr[2]`) in the scope
/// of `pou`, if it has one.
pub(super) fn subrange_in(program: &Program, pou: PouId, expr: &ast::Expr) -> Option<(i64, i64)> {
    let mut c = Checker::around(program);
    c.body = BodyState { pou, loop_depth: 0, read_only: true };
    let (place, _) = c.place(expr, false)?;
    c.place_range(&place)
}

/// Checks one expression in the scope of `pou` of an already checked program.
pub(super) fn check_expression_in(
    program: &Program,
    pou: PouId,
    expr: &ast::Expr,
    expected: Option<Type>,
    read_only: bool,
) -> Result<ir::Expr, Vec<Diagnostic>> {
    let mut c = Checker::around(program);
    c.body = BodyState { pou, loop_depth: 0, read_only };
    let globals_before = c.globals.len();
    let result = c.expr(expr, expected).and_then(|t| match expected {
        Some(ty) => c.coerce(t, ty, expr.span),
        None => Some(t.e),
    });
    if c.globals.len() != globals_before {
        c.error(Code::UndeclaredName, expr.span, crate::msg!(DirectAddressProgramDoesNot));
    }
    if crate::diagnostics::has_errors(&c.diags) {
        return Err(c.diags);
    }
    result.ok_or(c.diags)
}

/// The inputs, outputs and in-outs of a POU as declared: what a caller can name.
pub(super) fn interface_names(pou: &Pou) -> Vec<String> {
    let mut names = Vec::new();
    for v in &pou.vars {
        let public =
            matches!(v.section, VarSection::Input | VarSection::Output | VarSection::InOut);
        if public && !v.name.contains("__") {
            names.push(v.name.clone());
        }
    }
    names
}
