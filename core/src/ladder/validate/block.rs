//! The rules for one block cell: its type, instance, pins, wired inputs and power pins.
//! With a [`Catalog`] (the project's POUs and the POU's variables) pins are checked against
//! the block type's declared inputs and outputs and operands against their types; without
//! one only what the grid itself shows is checked.

use super::{is_operand, is_value, LadderDiagnostic};
use crate::diagnostics::Code;
use crate::ladder::blocks::is_standard_function;
use crate::ladder::catalog::{
    standard_function_inputs, BlockKind, BlockType, Catalog, Scope, TypeKey,
};
use crate::ladder::model::{standard_fb_power, Block, Pin};
use crate::syntax::{self, ExprKind};

/// What validation knows about the project: its block types and the POU's variables.
pub(crate) struct Context<'a> {
    pub catalog: &'a Catalog,
    pub scope: Scope,
    /// The variables the POU can name as declared: its own in declaration order, then the
    /// globals (for `did you mean`).
    pub names: Vec<String>,
}

impl Context<'_> {
    /// The declared variable `name` probably misspells.
    fn closest(&self, name: &str) -> Option<String> {
        crate::diagnostics::suggest::closest(name, self.names.iter().map(String::as_str))
            .map(str::to_string)
    }
}

/// Where a block stands: rung, row, column.
#[derive(Clone, Copy)]
pub(crate) struct At {
    pub rung: usize,
    pub row: usize,
    pub col: usize,
}

struct Sink<'a> {
    at: At,
    out: &'a mut Vec<LadderDiagnostic>,
}

impl Sink<'_> {
    /// An undeclared operand's error, with `did you mean NAME?` when there is a guess.
    fn undeclared(
        &mut self,
        message: impl Into<crate::diagnostics::Said>,
        suggestion: Option<String>,
    ) {
        let At { rung, row, col } = self.at;
        let mut d = LadderDiagnostic::error(Code::LadderUndeclaredOperand, rung, row, col, message);
        if let Some(s) = suggestion {
            d.message.push_str(&crate::diagnostics::suggest::hint(Some(&s)));
            d.suggestion = Some(s);
        }
        self.out.push(d);
    }

    fn error(&mut self, code: Code, message: impl Into<crate::diagnostics::Said>) {
        let At { rung, row, col } = self.at;
        self.out.push(LadderDiagnostic::error(code, rung, row, col, message));
    }

    fn error_at(&mut self, code: Code, row: usize, message: impl Into<crate::diagnostics::Said>) {
        let At { rung, col, .. } = self.at;
        self.out.push(LadderDiagnostic::error(code, rung, row, col, message));
    }
}

/// The root variable name of an operand (`T1` of `T1.ET`, `a` of `a[2]`), if any.
fn root_name(text: &str) -> Option<String> {
    fn root(e: &syntax::Expr) -> Option<String> {
        match &e.kind {
            ExprKind::Name(id) => Some(id.name.clone()),
            ExprKind::Member(b, _)
            | ExprKind::Bit(b, _)
            | ExprKind::Part { base: b, .. }
            | ExprKind::Index(b, _) => root(b),
            ExprKind::Paren(b) => root(b),
            _ => None,
        }
    }
    root(&syntax::parse_expression(text).ok()?)
}

/// Reports an operand naming an undeclared variable; true when it did. `pin` is the pin's
/// kind and name (`input`, `IN`) for a pin's operand, `None` for the instance of `block`.
fn undeclared(
    ctx: &Context<'_>,
    text: &str,
    pin: Option<(&str, &str)>,
    block: &str,
    sink: &mut Sink<'_>,
) -> bool {
    let Some(name) = root_name(text) else { return false };
    let key = name.to_ascii_uppercase();
    let known = ctx.scope.contains_key(&key)
        || ctx.catalog.is_enumerator(&name)
        || crate::semantic::SysVar::from_name(&key).is_some();
    if !known {
        let msg = match pin {
            Some((what, pin)) => {
                crate::msg!(
                    PinOperandNotDeclared,
                    what = what,
                    pin = pin,
                    block = block,
                    name = &name
                )
            }
            None => crate::msg!(InstanceOperandNotDeclared, block = block, name = &name),
        };
        sink.undeclared(msg, ctx.closest(&name));
    }
    !known
}

/// The problem with the operand of a contact or coil, if any: not declared (with the
/// declared name it probably misspells), or not a BOOL.
pub(crate) fn check_bool_operand(
    ctx: &Context<'_>,
    operand: &str,
    what: &str,
) -> Option<(Code, crate::diagnostics::Said, Option<String>)> {
    let name = root_name(operand)?;
    let key = name.to_ascii_uppercase();
    if !ctx.scope.contains_key(&key) && crate::semantic::SysVar::from_name(&key).is_none() {
        let suggestion = ctx.closest(&name);
        let message = crate::msg!(OperandNotDeclared, what = what, name = &name);
        return Some((Code::LadderUndeclaredOperand, message, suggestion));
    }
    match ctx.catalog.place_type(&ctx.scope, operand) {
        Some(t) if !t.is_bool() => Some((
            Code::LadderPinType,
            format!(
                "this {what} needs a BOOL, but `{}` is {}",
                operand.trim(),
                article(&t.to_string())
            )
            .into(),
            None,
        )),
        _ => None,
    }
}

/// Checks one block at `at` (its anchor cell).
pub(crate) fn validate_block(
    at: At,
    rows: usize,
    b: &Block,
    ctx: Option<&Context<'_>>,
    out: &mut Vec<LadderDiagnostic>,
) {
    let mut sink = Sink { at, out };
    let name = b.type_name.trim();
    if name.is_empty() {
        sink.error(Code::LadderMissingOperand, crate::msg!(BlockHasNoType));
        return;
    }
    let std_fb = standard_fb_power(name).is_some();
    let std_fn = is_standard_function(name);
    let user = ctx.and_then(|c| c.catalog.block(name)).filter(|_| !std_fn);
    let known = std_fb
        || std_fn
        || user.is_some()
        || (ctx.is_none()
            && syntax::parse_expression(name).is_ok_and(|e| matches!(e.kind, ExprKind::Name(_))));
    if !known {
        let functions = crate::ladder::blocks::STANDARD_FUNCTIONS.iter().copied();
        let hint = ctx
            .and_then(|c| c.catalog.closest_block(name))
            .or_else(|| crate::diagnostics::suggest::closest(name, functions));
        let msg = match hint {
            Some(hint) => crate::msg!(UnknownBlockDidYouMean, name = name, hint = hint),
            None => crate::msg!(UnknownBlock, name = name),
        };
        sink.error(Code::LadderUnknownBlock, msg);
    }
    let is_function = std_fn || user.is_some_and(|t| t.kind == BlockKind::Function);
    let needs_instance = std_fb || user.is_some_and(|t| t.kind == BlockKind::FunctionBlock);
    match b.instance.as_deref().map(str::trim) {
        Some(i) if !i.is_empty() => {
            if !is_operand(i) {
                let msg = crate::msg!(InstanceNotVariableName, i = i, name = name);
                sink.error(Code::LadderBadOperand, msg);
            } else if is_function && ctx.is_some() {
                let msg = crate::msg!(FunctionHasNoInstanceRemove, name = name, i = i);
                sink.error(Code::LadderInstanceType, msg);
            } else if let Some(c) = ctx {
                if !undeclared(c, i, None, name, &mut sink) {
                    let want = TypeKey::Named(name.to_ascii_uppercase());
                    match c.catalog.place_type(&c.scope, i) {
                        Some(t) if t != want && known => sink.error(
                            Code::LadderInstanceType,
                            format!("the instance `{i}` is declared as {t}, not as {name}"),
                        ),
                        _ => {}
                    }
                }
            }
        }
        _ if needs_instance => {
            sink.error(Code::LadderMissingInstance, crate::msg!(BlockNeedsInstance, name = name))
        }
        _ => {}
    }
    check_pins(b, name, rows, ctx, user, &mut sink);
    check_power_pins(b, name, ctx.map(|_| user), std_fb, &mut sink);
}

/// The declared type of input `pin` of a block, when the catalog can tell it.
fn input_type(user: Option<&BlockType>, std_fb: Option<&BlockType>, pin: &str) -> Option<TypeKey> {
    user.or(std_fb).and_then(|t| t.input(pin)).and_then(|p| p.ty.clone())
}

fn check_pins(
    b: &Block,
    name: &str,
    rows: usize,
    ctx: Option<&Context<'_>>,
    user: Option<&BlockType>,
    sink: &mut Sink<'_>,
) {
    let std_fb_type = ctx.and_then(|c| c.catalog.block(name)).filter(|_| user.is_none());
    let typed = user.or(std_fb_type);
    let std_fn = standard_function_inputs(name);
    let power_in = b.power_input();
    let height = b.height.max(1);
    let mut seen: Vec<String> = Vec::new();
    let mut wired_rows: Vec<u32> = Vec::new();
    for p in &b.inputs {
        let pin = p.name.trim();
        if pin.is_empty() {
            sink.error(Code::LadderMissingOperand, crate::msg!(InputHasNoName, name = name));
            continue;
        }
        if seen.iter().any(|s| s.eq_ignore_ascii_case(pin)) {
            sink.error(
                Code::LadderUnknownPin,
                crate::msg!(InputGivenTwice, pin = pin, name = name),
            );
        }
        seen.push(pin.to_string());
        if pin.eq_ignore_ascii_case(power_in) {
            let msg = crate::msg!(InputTakesRungSPower, pin = pin, name = name);
            sink.error(Code::LadderUnknownPin, msg);
            continue;
        }
        if ctx.is_some() {
            let exists = match (typed, std_fn) {
                (Some(t), _) => t.input(pin).is_some(),
                (None, Some((fixed, more))) => {
                    fixed.iter().any(|f| f.eq_ignore_ascii_case(pin))
                        || (more
                            && pin.get(..2).is_some_and(|p| p.eq_ignore_ascii_case("IN"))
                            && pin
                                .get(2..)
                                .and_then(|n| n.parse::<u32>().ok())
                                .is_some_and(|n| n >= 1))
                }
                (None, None) => true,
            };
            if !exists {
                let list: Vec<String> = match (typed, std_fn) {
                    (Some(t), _) => t.inputs.iter().map(|p| p.name.clone()).collect(),
                    (None, Some((fixed, _))) => fixed.iter().map(|s| s.to_string()).collect(),
                    _ => Vec::new(),
                };
                let msg = crate::msg!(
                    HasNoInputInputs,
                    name = name,
                    pin = pin,
                    join = (list.join(", ")).to_string()
                );
                sink.error(Code::LadderUnknownPin, msg);
                continue;
            }
        }
        let ty = input_type(user, std_fb_type, pin);
        match p.wired_row {
            Some(w) => {
                let row = sink.at.row + w as usize;
                let report_row = if row < rows { row } else { sink.at.row };
                if w == 0 || w >= height || row >= rows {
                    let msg = crate::msg!(
                        InputWiredBlockRowBut,
                        pin = pin,
                        name = name,
                        w = w,
                        height = (height - 1).to_string()
                    );
                    sink.error_at(Code::LadderBadWiredPin, report_row, msg);
                } else if wired_rows.contains(&w) {
                    let msg =
                        crate::msg!(InputSharesBlockRowAnother, pin = pin, name = name, w = w);
                    sink.error_at(Code::LadderBadWiredPin, report_row, msg);
                } else if !p.operand.trim().is_empty() {
                    let msg = crate::msg!(
                        InputWiredContactNetworkAlso,
                        pin = pin,
                        name = name,
                        trim = (p.operand.trim()).to_string()
                    );
                    sink.error_at(Code::LadderBadWiredPin, report_row, msg);
                } else if ty.as_ref().is_some_and(|t| !t.is_bool()) {
                    let msg = crate::msg!(
                        InputOnlyBoolInputCan,
                        pin = pin,
                        name = name,
                        article =
                            (article(&ty.as_ref().map(ToString::to_string).unwrap_or_default()))
                                .to_string()
                    );
                    sink.error_at(Code::LadderBadWiredPin, report_row, msg);
                }
                wired_rows.push(w);
            }
            None => check_value(p, "input", name, ty.as_ref(), ctx, sink),
        }
    }
    for p in &b.outputs {
        let pin = p.name.trim();
        if ctx.is_some() {
            let exists = match (typed, std_fn) {
                (Some(t), _) => t.output(pin).is_some(),
                (None, Some(_)) => pin.eq_ignore_ascii_case("OUT"),
                (None, None) => true,
            };
            if !exists {
                let list: Vec<String> = match (typed, std_fn) {
                    (Some(t), _) => t.outputs.iter().map(|p| p.name.clone()).collect(),
                    _ => vec!["OUT".to_string()],
                };
                let msg = crate::msg!(
                    HasNoOutputOutputs,
                    name = name,
                    pin = pin,
                    join = (list.join(", ")).to_string()
                );
                sink.error(Code::LadderUnknownPin, msg);
                continue;
            }
        }
        check_place(
            p,
            "output",
            name,
            typed.and_then(|t| t.output(pin)).and_then(|p| p.ty.clone()),
            false,
            ctx,
            sink,
        );
    }
    for p in &b.in_outs {
        let pin = p.name.trim();
        let declared = typed.and_then(|t| t.in_out(pin));
        if ctx.is_some() && declared.is_none() {
            let list: Vec<String> = typed
                .map(|t| t.in_outs.iter().map(|p| p.name.clone()).collect())
                .unwrap_or_default();
            let msg = crate::msg!(
                HasNoOutOuts,
                name = name,
                pin = pin,
                join = (list.join(", ")).to_string()
            );
            sink.error(Code::LadderUnknownPin, msg);
            continue;
        }
        check_place(p, "in-out", name, declared.and_then(|p| p.ty.clone()), true, ctx, sink);
    }
    if ctx.is_none() {
        return;
    }
    // Pins the block cannot do without.
    if let Some(t) = typed {
        for io in &t.in_outs {
            if !b.in_outs.iter().any(|p| p.name.trim().eq_ignore_ascii_case(&io.name)) {
                let msg = format!(
                    "in-out {} of this {name} is not connected; a VAR_IN_OUT needs a variable",
                    io.name
                );
                sink.error(Code::LadderMissingPin, msg);
            }
        }
    } else if let Some((fixed, _)) = std_fn {
        for f in fixed {
            let given = f.eq_ignore_ascii_case(power_in)
                || b.inputs.iter().any(|p| p.name.trim().eq_ignore_ascii_case(f));
            if !given {
                sink.error(Code::LadderMissingPin, crate::msg!(InputMissing, f = f, name = name));
            }
        }
    }
}

/// The checks every pin operand gets: present, a value (or a variable when `place`), and
/// declared. Returns the context when its type is worth checking.
fn operand_declared<'c>(
    p: &Pin,
    what: &str,
    name: &str,
    place: bool,
    ctx: Option<&'c Context<'c>>,
    sink: &mut Sink<'_>,
) -> Option<&'c Context<'c>> {
    let pin = p.name.trim();
    let operand = p.operand.trim();
    if operand.is_empty() {
        let msg = crate::msg!(HasNoOperand2, what = what, pin = pin, name = name);
        sink.error(Code::LadderMissingOperand, msg);
        return None;
    }
    let (ok, kind) =
        if place { (is_operand(operand), "variable") } else { (is_value(operand), "value") };
    if !ok {
        let msg =
            crate::msg!(Not, what = what, pin = pin, name = name, operand = operand, kind = kind);
        sink.error(Code::LadderBadOperand, msg);
        return None;
    }
    let c = ctx?;
    if undeclared(c, operand, Some((what, pin)), name, sink) {
        return None;
    }
    Some(c)
}

/// An input bound to a value.
fn check_value(
    p: &Pin,
    what: &str,
    name: &str,
    ty: Option<&TypeKey>,
    ctx: Option<&Context<'_>>,
    sink: &mut Sink<'_>,
) {
    let pin = p.name.trim();
    let operand = p.operand.trim();
    let Some(c) = operand_declared(p, what, name, false, ctx, sink) else { return };
    if let Some(t) = ty {
        if let Some((false, found)) = c.catalog.value_fits(&c.scope, operand, t) {
            let msg = crate::msg!(
                NeedsBut,
                what = what,
                pin = pin,
                name = name,
                article = (article(&t.to_string())).to_string(),
                operand = operand,
                article2 = (article(&found)).to_string()
            );
            sink.error(Code::LadderPinType, msg);
        }
    }
}

/// An output or in-out bound to a variable.
fn check_place(
    p: &Pin,
    what: &str,
    name: &str,
    ty: Option<TypeKey>,
    exact: bool,
    ctx: Option<&Context<'_>>,
    sink: &mut Sink<'_>,
) {
    let pin = p.name.trim();
    let operand = p.operand.trim();
    let Some(c) = operand_declared(p, what, name, true, ctx, sink) else { return };
    let (Some(t), Some(v)) = (ty, c.catalog.place_type(&c.scope, operand)) else { return };
    let ok = if exact { t == v } else { crate::ladder::catalog::fits(&t, &v) };
    if !ok {
        let msg = crate::msg!(
            But,
            what = what,
            pin = pin,
            name = name,
            article = (article(&t.to_string())).to_string(),
            operand = operand,
            article2 = (article(&v.to_string())).to_string()
        );
        sink.error(Code::LadderPinType, msg);
    }
}

/// "a BOOL", "an INT", or the description as it is ("an integer literal").
fn article(found: &str) -> String {
    if found.starts_with("a ") || found.starts_with("an ") {
        found.to_string()
    } else if found.starts_with(['A', 'E', 'I', 'O']) {
        format!("an {found}")
    } else {
        format!("a {found}")
    }
}

/// The power input must be EN or a BOOL input; the power output ENO (only with EN), a BOOL
/// output of an FB, or the BOOL result OUT of a function. `user` is `None` without a catalog.
fn check_power_pins(
    b: &Block,
    name: &str,
    user: Option<Option<&BlockType>>,
    std_fb: bool,
    sink: &mut Sink<'_>,
) {
    let pi = b.power_input();
    let po = b.power_output();
    let enable = b.has_enable();
    if po.eq_ignore_ascii_case("ENO") && !enable {
        let msg = crate::msg!(EnoCarriesPowerOnlyWhen, name = name);
        sink.error(Code::LadderBadPowerPin, msg);
        return;
    }
    if std_fb
        && !enable
        && b.power_in.is_some()
        && standard_fb_power(name).is_some_and(|(i, _)| !i.eq_ignore_ascii_case(pi))
    {
        // A standard FB may take power at EN instead of its own input, but nowhere else.
        let msg = crate::msg!(
            PowerEntersEnNot,
            name = name,
            standard_fb_power = (standard_fb_power(name).map_or("", |(i, _)| i)).to_string(),
            pi = pi
        );
        sink.error(Code::LadderBadPowerPin, msg);
    }
    let Some(user) = user else { return };
    let Some(t) = user else { return };
    if !enable {
        match t.input(pi) {
            Some(p) if p.ty.as_ref().is_none_or(TypeKey::is_bool) => {}
            Some(_) => sink.error(
                Code::LadderBadPowerPin,
                format!(
                    "input {pi} of this {name} is not BOOL, so it cannot take the rung's power"
                ),
            ),
            None => sink.error(
                Code::LadderBadPowerPin,
                format!("{name} has no input {pi} to take the rung's power"),
            ),
        }
    }
    if !po.eq_ignore_ascii_case("ENO") {
        match t.output(po) {
            Some(p) if p.ty.as_ref().is_none_or(TypeKey::is_bool) => {}
            Some(_) => sink.error(
                Code::LadderBadPowerPin,
                format!("output {po} of this {name} is not BOOL, so it cannot carry power"),
            ),
            None => sink.error(
                Code::LadderBadPowerPin,
                format!("{name} has no output {po} to carry power"),
            ),
        }
    }
}
