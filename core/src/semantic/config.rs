//! Checking a CONFIGURATION: its tasks (constant INTERVAL and PRIORITY, a BOOL global for
//! SINGLE), its program instances (a PROGRAM type, a task of their resource, connections
//! to globals of the parameter's type), and the PROGRAM that holds the instances.
//!
//! The configuration becomes [`ir::Configuration`] and one more PROGRAM POU named like
//! the configuration, whose variables are the program instances (each of its PROGRAM's
//! type): the simulator runs that POU as its main program (its body is empty) and each
//! instance under its task, so `Main1.Count` names a variable of instance `Main1`
//! everywhere a path is read. The configuration's and resources' VAR_GLOBAL blocks are
//! declared with the file's other globals (`check.rs`).

use std::collections::HashMap;

use super::check::Checker;
use super::ir::{self, Pou, Var};
use super::types::{Elem, PouId, Type};
use crate::diagnostics::Code;
use crate::syntax::{self as ast, PouKind, VarSection};

/// The highest task PRIORITY accepted (0 is the most urgent).
pub const MAX_PRIORITY: i64 = 9999;

impl Checker<'_> {
    /// Checks the file's configuration (the first one; others are E0620) and adds the
    /// PROGRAM holding its instances.
    pub(super) fn check_configurations(
        &mut self,
        file: &ast::SourceFile,
    ) -> Option<ir::Configuration> {
        let mut configs = file.items.iter().filter_map(|i| match i {
            ast::Item::Configuration(c) => Some(c),
            _ => None,
        });
        let first = configs.next()?;
        for other in configs {
            self.error(
                Code::UnsupportedConfiguration,
                other.name.span,
                crate::msg!(
                    ProgramHasOneConfigurationSecond,
                    name = other.name.name,
                    name2 = first.name.name
                ),
            );
        }
        Some(self.check_configuration(first))
    }

    fn check_configuration(&mut self, c: &ast::Configuration) -> ir::Configuration {
        self.body.pou = PouId::MAX;
        let mut tasks = Vec::new();
        let mut instances: Vec<ir::ProgramInstance> = Vec::new();
        let mut names: HashMap<String, &str> = HashMap::new();
        for r in &c.resources {
            let first_task = tasks.len();
            for t in &r.tasks {
                if self.clash(&mut names, &t.name, "task") {
                    continue;
                }
                tasks.push(self.task(t, &r.name.name));
            }
            for p in &r.programs {
                if self.clash(&mut names, &p.name, "program instance") {
                    continue;
                }
                if self.global_index.contains_key(&p.name.key()) {
                    self.error(
                        Code::DuplicateDeclaration,
                        p.name.span,
                        crate::msg!(AlreadyGlobalVariableNameProgram, name = p.name.name),
                    );
                    continue;
                }
                if let Some(inst) =
                    self.program_instance(p, &tasks[first_task..], first_task, &r.name.name)
                {
                    instances.push(inst);
                }
            }
        }
        let pou = self.pous.len() as PouId;
        let vars = instances
            .iter()
            .map(|i| Var {
                name: i.name.clone(),
                ty: Type::Fb(i.pou),
                section: VarSection::Var,
                retain: false,
                constant: false,
                location: None,
                init: None,
                range: None,
                comment: Some(match i.task.and_then(|t| tasks.get(t as usize)) {
                    Some(t) => describe_task(t),
                    None => "no task: runs on every scan, after the tasks".to_string(),
                }),
                span: i.span,
            })
            .collect();
        self.types.pou_names.push(c.name.name.clone());
        self.calls.push(Default::default());
        self.pous.push(Pou {
            name: c.name.name.clone(),
            kind: PouKind::Program,
            vars,
            result: None,
            body: Vec::new(),
            library: false,
            span: c.span,
        });
        let io = self.config_vars(c, &instances, pou);
        ir::Configuration { name: c.name.name.clone(), pou, tasks, instances, io, span: c.span }
    }

    /// Reports `name` when a task or program instance of the configuration has it already.
    fn clash<'n>(
        &mut self,
        names: &mut HashMap<String, &'n str>,
        name: &'n ast::Ident,
        what: &'n str,
    ) -> bool {
        if let Some(other) = names.get(&name.key()) {
            let msg = crate::msg!(AlreadyNamesConfiguration, name = name.name, other = other);
            self.error(Code::DuplicateDeclaration, name.span, msg);
            return true;
        }
        names.insert(name.key(), what);
        false
    }

    fn task(&mut self, t: &ast::TaskDecl, resource: &str) -> ir::Task {
        let mut task = ir::Task {
            name: t.name.name.clone(),
            resource: resource.to_string(),
            interval_ns: 0,
            priority: 0,
            single: None,
            span: t.span,
        };
        if let Some(e) = &t.interval {
            let ns = self
                .expr(e, Some(Type::Elem(Elem::Time)))
                .and_then(|v| self.coerce(v, Type::Elem(Elem::Time), e.span));
            // A value of another type is reported by the checker already.
            let ns = ns.map(|v| match v.kind {
                ir::ExprKind::Const(bits) => bits as i64,
                _ => 0,
            });
            match ns {
                None => {}
                Some(ns) if ns > 0 => task.interval_ns = ns,
                Some(_) => self.error(
                    Code::BadTaskSetting,
                    e.span,
                    crate::msg!(IntervalTaskMustConstantTime, name = t.name.name),
                ),
            }
        }
        if let Some(e) = &t.priority {
            let p = self.expr(e, None).as_ref().and_then(|v| super::consts::int_value(&v.e));
            match p {
                Some(p) if (0..=MAX_PRIORITY).contains(&p) => task.priority = p as u32,
                _ => self.error(
                    Code::BadTaskSetting,
                    e.span,
                    format!("the PRIORITY of task `{}` must be a constant from 0 (most urgent) to {MAX_PRIORITY}", t.name.name),
                ),
            }
        }
        if let Some(e) = &t.single {
            match self.global_bool(e) {
                Some(name) => task.single = Some(name),
                None => self.error(
                    Code::BadTaskSetting,
                    e.span,
                    crate::msg!(SingleTaskMustBoolGlobal, name = t.name.name),
                ),
            }
        }
        task
    }

    /// The name of the global variable `e` names, when it is one of type BOOL.
    fn global_bool(&self, e: &ast::Expr) -> Option<String> {
        let (name, ty) = self.global_named(e)?;
        (ty == Type::BOOL).then_some(name)
    }

    /// The name (as declared) and type of the global variable `e` names.
    fn global_named(&self, e: &ast::Expr) -> Option<(String, Type)> {
        let ast::ExprKind::Name(id) = &e.kind else { return None };
        let g = &self.globals[*self.global_index.get(&id.key())? as usize];
        Some((g.name.clone(), g.ty))
    }

    fn program_instance(
        &mut self,
        p: &ast::ProgramDecl,
        tasks: &[ir::Task],
        first_task: usize,
        resource: &str,
    ) -> Option<ir::ProgramInstance> {
        let pou = match self.pou_index.get(&p.type_name.key()) {
            Some(&q) if self.pous[q as usize].kind == PouKind::Program => q,
            found => {
                let what = if found.is_some() { "is not a PROGRAM" } else { "is not declared" };
                self.error(
                    Code::NotAProgramType,
                    p.type_name.span,
                    crate::msg!(ProgramInstanceNamesProgram, name = p.type_name.name, what = what),
                );
                return None;
            }
        };
        let task = match &p.task {
            None => None,
            Some(t) => match tasks.iter().position(|k| k.name.eq_ignore_ascii_case(&t.name)) {
                Some(k) => Some((first_task + k) as u32),
                None => {
                    self.error(
                        Code::UnknownTask,
                        t.span,
                        crate::msg!(ResourceDeclaresNoTask, resource = resource, name = t.name),
                    );
                    return None;
                }
            },
        };
        let mut inst = ir::ProgramInstance {
            name: p.name.name.clone(),
            pou,
            task,
            resource: resource.to_string(),
            inputs: Vec::new(),
            outputs: Vec::new(),
            span: p.span,
        };
        for conn in &p.connections {
            self.connection(&mut inst, conn);
        }
        Some(inst)
    }

    fn connection(&mut self, inst: &mut ir::ProgramInstance, conn: &ast::Connection) {
        let prog = &self.pous[inst.pou as usize];
        let wanted = if conn.output { VarSection::Output } else { VarSection::Input };
        let param = prog
            .find_var(&conn.param.name)
            .map(|k| &prog.vars[k as usize])
            .filter(|v| v.section == wanted)
            .map(|v| (v.name.clone(), v.ty));
        let Some((param, ty)) = param else {
            let what = if conn.output { "VAR_OUTPUT (`=>`)" } else { "VAR_INPUT (`:=`)" };
            let msg =
                crate::msg!(NotProgram, name = conn.param.name, what = what, name2 = prog.name);
            self.error(Code::BadProgramConnection, conn.param.span, msg);
            return;
        };
        match self.global_named(&conn.variable) {
            Some((global, gty)) if gty == ty && matches!(ty, Type::Elem(_) | Type::Enum(_)) => {
                let list = if conn.output { &mut inst.outputs } else { &mut inst.inputs };
                list.push((param, global));
            }
            found => {
                let msg = match found {
                    Some((g, gty)) => format!(
                        "`{param}` is {} and the global `{g}` is {}; connect a global of the same elementary type",
                        self.tname(ty),
                        self.tname(gty)
                    ),
                    None => format!("connect `{param}` to a global variable of the configuration"),
                };
                self.error(Code::BadProgramConnection, conn.variable.span, msg);
            }
        }
    }
}

impl Checker<'_> {
    /// Checks the `VAR_CONFIG` entries: each one's path and type; the complete address of
    /// one that gives an address (returned, for the image), and the initial value of one
    /// that gives a value, which becomes the initial value of that variable of that
    /// instance (`pou` is the configuration's PROGRAM, whose variables are the instances).
    fn config_vars(
        &mut self,
        c: &ast::Configuration,
        instances: &[ir::ProgramInstance],
        pou: PouId,
    ) -> Vec<(String, crate::syntax::DirectAddress)> {
        let mut io = Vec::new();
        let mut initialised = std::collections::HashSet::new();
        for v in &c.var_config {
            let Some((steps, var)) = self.config_path(v, instances, pou) else { continue };
            let Some(ty) = self.resolve_type(&v.ty, &var.name).map(|r| r.ty) else { continue };
            if ty != var.ty {
                let msg = crate::msg!(
                    DeclaredVarConfigEntryGives,
                    name = var.name,
                    ty = (self.tname(var.ty)).to_string(),
                    ty2 = (self.tname(ty)).to_string()
                );
                self.error(Code::BadConfigVar, v.ty.span(), msg);
                continue;
            }
            if let Some(init) = &v.init {
                let key = v.path.iter().map(|i| i.key()).collect::<Vec<_>>().join(".");
                if self.config_init(v, init, &var, &steps) && !initialised.insert(key) {
                    let msg = "this variable is given an initial value by an entry above already";
                    self.error(Code::BadConfigVar, init.span(), msg);
                }
            }
            if let Some(loc) = &v.location {
                if let Some(entry) = self.config_address(v, loc, &var) {
                    io.push(entry);
                }
            }
        }
        io
    }

    /// The variable `v`'s path names: the `(POU, variable index)` of each name (the first
    /// one the instance among `pou`'s variables), and the variable.
    fn config_path(
        &mut self,
        v: &ast::ConfigVar,
        instances: &[ir::ProgramInstance],
        pou: PouId,
    ) -> Option<(Vec<(PouId, u32)>, Var)> {
        let fail = |c: &mut Self, span, msg: String| {
            c.error(Code::BadConfigVar, span, msg);
            None
        };
        let (first, rest) = v.path.split_first()?;
        let Some(k) = instances.iter().position(|i| i.name.eq_ignore_ascii_case(&first.name))
        else {
            let msg = format!("`{}` is not a program instance of the configuration", first.name);
            let names = instances.iter().map(|i| i.name.clone()).collect();
            self.error_suggesting(Code::BadConfigVar, first.span, msg, &first.name, names);
            return None;
        };
        if rest.is_empty() {
            let msg = format!(
                "`{}` is a program instance; name one of its variables (`{}.Name`)",
                first.name, first.name
            );
            return fail(self, first.span, msg);
        }
        let mut steps = vec![(pou, k as u32)];
        let mut owner = instances[k].pou;
        let mut found = None;
        for (j, name) in rest.iter().enumerate() {
            let vars = &self.pous[owner as usize].vars;
            let Some(i) = vars.iter().position(|x| x.name.eq_ignore_ascii_case(&name.name)) else {
                let msg = format!("`{}` has no `{}`", self.pous[owner as usize].name, name.name);
                let names = vars.iter().map(|x| x.name.clone()).collect();
                self.error_suggesting(Code::BadConfigVar, name.span, msg, &name.name, names);
                return None;
            };
            let var = vars[i].clone();
            steps.push((owner, i as u32));
            if j + 1 < rest.len() {
                let Type::Fb(q) = var.ty else {
                    return fail(
                        self,
                        name.span,
                        format!("`{}` is not a function block instance", name.name),
                    );
                };
                owner = q;
            } else {
                found = Some(var);
            }
        }
        Some((steps, found?))
    }

    /// Checks the initial value of entry `v` for `var` and makes it the initial value of
    /// the variable at `steps`; false when it is refused.
    fn config_init(
        &mut self,
        v: &ast::ConfigVar,
        init: &ast::Initializer,
        var: &Var,
        steps: &[(PouId, u32)],
    ) -> bool {
        let refused = match var.section {
            VarSection::Temp => Some("it is a VAR_TEMP, which starts over on every call"),
            VarSection::InOut => Some("it is a VAR_IN_OUT, which names the caller's variable"),
            VarSection::External => {
                Some("it is a VAR_EXTERNAL: give the global its initial value in its VAR_GLOBAL")
            }
            _ if var.constant => Some("it is a CONSTANT, the same in every instance"),
            _ if var.location.as_ref().is_some_and(|l| !l.path.is_empty()) => {
                Some("it is at a complete address, in the process image: give the value in its declaration")
            }
            _ => None,
        };
        if let Some(why) = refused {
            let name = v.path.last().map_or(v.span, |n| n.span);
            let msg = crate::msg!(CannotTakeInitialValueFrom, name = var.name, why = why);
            self.error(Code::BadConfigVar, name, msg);
            return false;
        }
        let errors = self.diags.len();
        let Some(value) = self.init_value(init, var.ty, var.range) else { return false };
        if crate::diagnostics::has_errors(&self.diags[errors..]) {
            return false;
        }
        self.override_init(steps, value);
        true
    }

    /// Makes `value` the initial value of the variable at `steps` (the instance among the
    /// configuration's variables, then a variable of each POU): each instance on the way
    /// starts from its declared initial value, so what the entry does not name stays as
    /// declared.
    fn override_init(&mut self, steps: &[(PouId, u32)], value: ir::InitValue) {
        let declared: Vec<Option<ir::InitValue>> = steps
            .iter()
            .map(|&(q, i)| self.pous.get(q as usize)?.vars.get(i as usize)?.init.clone())
            .collect();
        let widths: Vec<usize> = steps
            .iter()
            .skip(1)
            .map(|&(q, _)| self.pous.get(q as usize).map_or(0, |p| p.vars.len()))
            .collect();
        let Some(&(q0, i0)) = steps.first() else { return };
        let Some(mut slot) = self
            .pous
            .get_mut(q0 as usize)
            .and_then(|p| p.vars.get_mut(i0 as usize))
            .map(|v| &mut v.init)
        else {
            return;
        };
        for (j, &(_, member)) in steps.iter().enumerate().skip(1) {
            // `slot` is the initial value of an instance of the POU declaring `member`.
            let width = widths.get(j - 1).copied().unwrap_or(0);
            if !matches!(slot, Some(ir::InitValue::Struct(_))) {
                *slot = match declared.get(j - 1).cloned().flatten() {
                    Some(s @ ir::InitValue::Struct(_)) => Some(s),
                    _ => Some(ir::InitValue::Struct(vec![None; width])),
                };
            }
            let Some(ir::InitValue::Struct(members)) = slot else { return };
            if members.len() < width {
                members.resize(width, None);
            }
            let Some(next) = members.get_mut(member as usize) else { return };
            slot = next;
        }
        *slot = Some(value);
    }

    /// Checks the address of entry `v` for `var`, declared at an incomplete address of
    /// the same area and size: the instance path and the complete address.
    fn config_address(
        &mut self,
        v: &ast::ConfigVar,
        loc: &crate::syntax::DirectAddress,
        var: &Var,
    ) -> Option<(String, crate::syntax::DirectAddress)> {
        let incomplete = var.location.as_ref().filter(|l| l.path.is_empty());
        let Some(decl) = incomplete else {
            let msg = crate::msg!(NotDeclaredIncompleteAddressQ, name = var.name);
            self.error(Code::BadConfigVar, v.span, msg);
            return None;
        };
        if decl.area != loc.area || decl.size != loc.size || loc.path.is_empty() {
            let msg = crate::msg!(
                DeclaredGiveCompleteAddressArea,
                name = var.name,
                text = decl.text,
                ty = (self.tname(var.ty)).to_string()
            );
            self.error(Code::BadConfigVar, loc.span, msg);
            return None;
        }
        // The image holds the completed address.
        self.image_place(&Var { location: Some(loc.clone()), ..var.clone() });
        let path: Vec<&str> = v.path.iter().map(|i| i.name.as_str()).collect();
        Some((path.join("."), loc.clone()))
    }
}

/// How a task runs, as the variable table describes its instances: `task Fast: every
/// 10 ms, priority 1`.
fn describe_task(t: &ir::Task) -> String {
    let period = |ns: i64| match ns % 1_000_000_000 {
        0 => format!("every {} s", ns / 1_000_000_000),
        _ => format!("every {} ms", ns as f64 / 1e6),
    };
    let when = match (&t.single, t.interval_ns) {
        (Some(g), 0) => format!("when {g} turns TRUE"),
        (Some(g), ns) => format!("{}, and when {g} turns TRUE", period(ns)),
        (None, 0) => "every scan".to_string(),
        (None, ns) => period(ns),
    };
    format!("task {}: {when}, priority {}", t.name, t.priority)
}
