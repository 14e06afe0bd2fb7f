//! Validation of ladder POUs with located diagnostics (rung, row, column).

use std::collections::HashMap;
use std::fmt;

use serde::Serialize;

mod block;

use super::catalog::Catalog;
use super::model::{CoilKind, Element, LadderPou, Rung};
use super::network::{is_terminal, Network};
use crate::diagnostics::{Code, Severity};
use crate::syntax::{self, ExprKind};
use block::{validate_block, At, Context};

/// A problem in a ladder POU. `rung`, `row` and `column` are 0-based; `Display` prints them
/// 1-based as students count.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LadderDiagnostic {
    /// The stable problem code.
    pub code: Code,
    /// A message a student understands (English).
    pub message: String,
    /// The message as data, to be shown in any language.
    #[serde(skip)]
    pub msg: crate::diagnostics::Message,
    /// 0-based rung index.
    pub rung: usize,
    /// 0-based row.
    pub row: usize,
    /// 0-based column.
    pub column: usize,
    /// Error or warning.
    pub severity: Severity,
    /// The declared name an undeclared operand probably misspells (the message ends with
    /// `did you mean NAME?`): the editor's `Replace with NAME` fix.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub suggestion: Option<String>,
}

impl LadderDiagnostic {
    fn error(
        code: Code,
        rung: usize,
        row: usize,
        column: usize,
        message: impl Into<crate::diagnostics::Said>,
    ) -> Self {
        let severity = Severity::Error;
        let crate::diagnostics::Said { message: msg, english: message } = message.into();
        LadderDiagnostic { code, message, msg, rung, row, column, severity, suggestion: None }
    }

    fn warning(
        code: Code,
        rung: usize,
        row: usize,
        column: usize,
        message: impl Into<crate::diagnostics::Said>,
    ) -> Self {
        let severity = Severity::Warning;
        let crate::diagnostics::Said { message: msg, english: message } = message.into();
        LadderDiagnostic { code, message, msg, rung, row, column, severity, suggestion: None }
    }

    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

impl fmt::Display for LadderDiagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "rung {}, row {}, column {}: {}",
            self.rung + 1,
            self.row + 1,
            self.column + 1,
            self.message
        )
    }
}

/// Validates a ladder POU on its own. Block types that are not standard are accepted when
/// they are identifiers, and pins are not checked against declarations (the ST checker
/// reports what is wrong later); see [`validate_with`].
pub fn validate(pou: &LadderPou) -> Vec<LadderDiagnostic> {
    validate_inner(pou, None)
}

/// Validates a ladder POU knowing the project ((`Project::catalog`)): unknown block types,
/// pins the block type does not have, operands that are not declared or do not fit their
/// pin, and wrong power pins are reported at their rung, row and column.
pub fn validate_with(pou: &LadderPou, catalog: &Catalog) -> Vec<LadderDiagnostic> {
    let names = catalog.variables(&pou.declarations).into_iter().map(|v| v.name).collect();
    let ctx = Context { catalog, scope: catalog.scope(&pou.declarations), names };
    validate_inner(pou, Some(&ctx))
}

fn is_operand(text: &str) -> bool {
    fn place(e: &syntax::Expr) -> bool {
        match &e.kind {
            ExprKind::Name(_) | ExprKind::Direct(_) => true,
            ExprKind::Member(b, _) | ExprKind::Bit(b, _) | ExprKind::Part { base: b, .. } => {
                place(b)
            }
            ExprKind::Index(b, _) => place(b),
            _ => false,
        }
    }
    syntax::parse_expression(text).is_ok_and(|e| place(&e))
}

fn is_value(text: &str) -> bool {
    syntax::parse_expression(text).is_ok()
}

fn validate_inner(pou: &LadderPou, ctx: Option<&Context<'_>>) -> Vec<LadderDiagnostic> {
    let mut out = Vec::new();
    let labels: HashMap<String, usize> = pou
        .rungs
        .iter()
        .enumerate()
        .filter_map(|(i, r)| r.label.as_ref().map(|l| (l.to_ascii_uppercase(), i)))
        .collect();
    let mut coils: HashMap<String, (usize, usize, usize)> = HashMap::new();
    for (ri, rung) in pou.rungs.iter().enumerate() {
        validate_rung(ri, rung, ctx, &labels, &mut coils, &mut out);
    }
    out
}

fn validate_rung(
    ri: usize,
    rung: &Rung,
    ctx: Option<&Context<'_>>,
    labels: &HashMap<String, usize>,
    coils: &mut HashMap<String, (usize, usize, usize)>,
    out: &mut Vec<LadderDiagnostic>,
) {
    let start = out.len();
    let cols = rung.columns();
    for (r, row) in rung.cells.iter().enumerate() {
        if row.len() != cols {
            out.push(LadderDiagnostic::error(
                Code::LadderBadGrid,
                ri,
                r,
                0,
                crate::msg!(
                    RowHasCellsButRung,
                    r = (r + 1).to_string(),
                    row = (row.len()).to_string(),
                    cols = cols
                ),
            ));
            return;
        }
    }
    // Cell-level rules.
    let mut coil_count = 0;
    let mut edge_coil = None;
    for (r, row) in rung.cells.iter().enumerate() {
        let mut ended = false;
        for (c, cell) in row.iter().enumerate() {
            let e = &cell.element;
            if ended && !matches!(e, Element::Empty) {
                out.push(LadderDiagnostic::error(
                    Code::LadderAfterCoil,
                    ri,
                    r,
                    c,
                    crate::msg!(NothingMayFollowCoilJump),
                ));
                continue;
            }
            match e {
                Element::Contact { operand, .. } | Element::Coil { operand, .. } => {
                    let what =
                        if matches!(e, Element::Contact { .. }) { "contact" } else { "coil" };
                    if operand.trim().is_empty() {
                        out.push(LadderDiagnostic::error(
                            Code::LadderMissingOperand,
                            ri,
                            r,
                            c,
                            crate::msg!(HasNoOperand, what = what),
                        ));
                    } else if !is_operand(operand) {
                        out.push(LadderDiagnostic::error(
                            Code::LadderBadOperand,
                            ri,
                            r,
                            c,
                            crate::msg!(NotVariableMemberElementDirect, operand = operand),
                        ));
                    } else if let Some(ctx) = ctx {
                        if let Some((code, message, suggestion)) =
                            block::check_bool_operand(ctx, operand, what)
                        {
                            let mut d = LadderDiagnostic::error(code, ri, r, c, message);
                            let hint = crate::diagnostics::suggest::hint(suggestion.as_deref());
                            d.message.push_str(&hint);
                            d.suggestion = suggestion;
                            out.push(d);
                        }
                    }
                    if let Element::Coil { kind, operand } = e {
                        coil_count += 1;
                        if matches!(kind, CoilKind::Rising | CoilKind::Falling) {
                            edge_coil = edge_coil.or(Some((r, c)));
                        }
                        if matches!(kind, CoilKind::Normal | CoilKind::Negated)
                            || matches!(kind, CoilKind::Rising | CoilKind::Falling)
                        {
                            let key = operand.trim().to_ascii_uppercase();
                            if let Some(&(pr, prow, pcol)) = coils.get(&key) {
                                out.push(LadderDiagnostic::warning(
                                    Code::LadderDuplicateCoil,
                                    ri,
                                    r,
                                    c,
                                    crate::msg!(
                                        AlreadyWrittenCoilRungRow,
                                        trim = (operand.trim()).to_string(),
                                        pr = (pr + 1).to_string(),
                                        prow = (prow + 1).to_string(),
                                        pcol = (pcol + 1).to_string()
                                    ),
                                ));
                            } else if !key.is_empty() {
                                coils.insert(key, (ri, r, c));
                            }
                        }
                    }
                }
                Element::Block(b) => {
                    let at = At { rung: ri, row: r, col: c };
                    validate_block(at, rung.rows(), b, ctx, out);
                    let h = b.height.max(1) as usize;
                    if r + h > rung.rows() {
                        out.push(LadderDiagnostic::error(
                            Code::LadderBadGrid,
                            ri,
                            r,
                            c,
                            crate::msg!(RowsHighLeavesGrid, type_name = b.type_name, h = h),
                        ));
                    }
                }
                Element::Covered => {
                    let covered =
                        (0..r).rev().find_map(|a| match rung.cell(a, c).map(|x| &x.element) {
                            Some(Element::Covered) => None,
                            Some(Element::Block(b)) => Some(a + (b.height.max(1) as usize) > r),
                            _ => Some(false),
                        });
                    if covered != Some(true) {
                        out.push(LadderDiagnostic::error(
                            Code::LadderStrayCovered,
                            ri,
                            r,
                            c,
                            crate::msg!(CellMarkedPartBlockBut),
                        ));
                    }
                }
                Element::Jump { label } => match labels.get(&label.trim().to_ascii_uppercase()) {
                    None => out.push(LadderDiagnostic::error(
                        Code::LadderBadJump,
                        ri,
                        r,
                        c,
                        format!("there is no rung labelled `{}`", label.trim()),
                    )),
                    Some(&target) if target <= ri => out.push(LadderDiagnostic::error(
                        Code::LadderBadJump,
                        ri,
                        r,
                        c,
                        format!(
                            "jumps may only go forward; `{}` is not below this rung",
                            label.trim()
                        ),
                    )),
                    Some(_) => {}
                },
                _ => {}
            }
            if is_terminal(e) {
                ended = true;
            }
        }
    }
    if let Some((r, c)) = edge_coil {
        if coil_count > 1 {
            out.push(LadderDiagnostic::error(
                Code::LadderEdgeCoilShared,
                ri,
                r,
                c,
                crate::msg!(EdgeCoilMustOnlyCoil),
            ));
        }
    }
    // Power flow rules.
    let net = Network::new(rung);
    let mut open = false;
    for e in &net.elements {
        if !net.powered[e.input] {
            open = true;
            let what = match e.element {
                Element::Coil { .. } => crate::msg!(CoilNotReached),
                Element::Block(_) => crate::msg!(BlockNotReached),
                _ => crate::msg!(OpenCircuit),
            };
            out.push(LadderDiagnostic::error(Code::LadderOpenCircuit, ri, e.row, e.col, what));
            continue;
        }
        match e.element {
            Element::Contact { .. } | Element::Wire if !net.consumed(e.output) => {
                open = true;
                out.push(LadderDiagnostic::error(
                    Code::LadderOpenCircuit,
                    ri,
                    e.row,
                    e.col,
                    crate::msg!(OpenCircuitElementLeadsNowhere),
                ));
            }
            Element::Coil { .. } if !net.conditioned[e.input] => out.push(LadderDiagnostic::error(
                Code::LadderShortCircuit,
                ri,
                e.row,
                e.col,
                crate::msg!(CoilHasNoCondition),
            )),
            Element::Block(b) if !net.conditioned[e.input] => out.push(LadderDiagnostic::warning(
                Code::LadderEnableFromRail,
                ri,
                e.row,
                e.col,
                crate::msg!(EnableTiedStraightRail, type_name = b.type_name),
            )),
            _ => {}
        }
    }
    for p in &net.pins {
        let Element::Block(b) = net.elements[p.block].element else { continue };
        let pin = b.inputs.get(p.pin).map_or("", |x| x.name.trim());
        if !net.powered[p.node] {
            open = true;
            out.push(LadderDiagnostic::error(
                Code::LadderOpenCircuit,
                ri,
                p.row,
                p.col,
                crate::msg!(InputWiredRowButNo, pin = pin, type_name = b.type_name),
            ));
        } else if !net.conditioned[p.node] {
            out.push(LadderDiagnostic::warning(
                Code::LadderPinFromRail,
                ri,
                p.row,
                p.col,
                crate::msg!(InputTiedStraightRailSo, pin = pin, type_name = b.type_name),
            ));
        }
    }
    let has_errors = out[start..].iter().any(LadderDiagnostic::is_error);
    if !open && !has_errors {
        if let Some(node) = net.non_series_parallel() {
            let (r, c) = net.place[node];
            // Report the link that opens or closes the overlapping branch.
            out.push(LadderDiagnostic::error(
                Code::LadderAmbiguousBranch,
                ri,
                r,
                c,
                crate::msg!(BranchStartsEndsInsideAnother),
            ));
        }
    }
}
