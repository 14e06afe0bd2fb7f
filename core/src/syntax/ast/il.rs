//! The syntax tree of an Instruction List (IL, IEC 61131-3 ed. 2 §3.2) body.
//!
//! An IL body is a list of instructions, one per line, each an operator with its modifiers
//! and operands acting on the *current result* (CR). The parser builds this tree; the
//! lowering in `crate::il` turns it into ordinary statements before the checker runs, so
//! nothing after it knows IL exists. Data only: no parsing, no checking.

use super::{Arg, BinaryOp, Expr, Ident};
use crate::diagnostics::Span;

/// A POU body written in IL.
#[derive(Debug, Clone, PartialEq)]
pub struct IlBody {
    /// The instructions in source order.
    pub instructions: Vec<IlInstruction>,
    /// The labels with the index of the instruction they stand before (the number of
    /// instructions for a label at the end of the body).
    pub labels: Vec<(Ident, usize)>,
    /// From the first instruction or label to the end of the last.
    pub span: Span,
}

/// When a jump, call or return happens.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IlCondition {
    /// Always (`JMP`, `CAL`, `RET`).
    Always,
    /// When the CR is TRUE (`JMPC`, `CALC`, `RETC`).
    IfTrue,
    /// When the CR is FALSE (`JMPCN`, `CALCN`, `RETCN`).
    IfFalse,
}

/// One instruction: its operator, modifiers and operands.
#[derive(Debug, Clone, PartialEq)]
pub struct IlInstruction {
    /// What it does.
    pub kind: IlKind,
    /// The operator as written (`ANDN`, `&`, `JMPC`, a function's name).
    pub operator: Ident,
    /// From the operator to the end of its last operand.
    pub span: Span,
}

/// The kinds of IL instruction.
#[derive(Debug, Clone, PartialEq)]
pub enum IlKind {
    /// `LD x` (CR := x) or `LDN x` (CR := NOT x).
    Load {
        /// `LDN`.
        negated: bool,
        /// What is loaded.
        operand: Expr,
    },
    /// `ST x` (x := CR) or `STN x` (x := NOT CR).
    Store {
        /// `STN`.
        negated: bool,
        /// Where the CR goes.
        target: Expr,
    },
    /// `S x` (x := TRUE when CR) or `R x` (x := FALSE when CR); with an SR/RS instance as
    /// operand these are the input operators of its `S`/`R` input instead.
    SetReset {
        /// `S` rather than `R`.
        set: bool,
        /// The BOOL variable or the flip-flop instance.
        target: Expr,
    },
    /// `NOT`: CR := NOT CR.
    Not,
    /// `AND`, `OR`, `XOR`, `ADD` … `MOD`, `GT` … `LE` (and `ANDN`, `&`, `&N`, …): CR := CR op
    /// operand, deferred until the matching `)` when written with `(`.
    Operate {
        /// The operation (`And`, `Or`, `Xor`, `Add` … `Mod`, `Cmp(_)`).
        op: BinaryOp,
        /// The `N` modifier: the operand is negated.
        negated: bool,
        /// The `(` modifier: the operation waits for the result of the nested list.
        deferred: bool,
        /// The operand; with `(` it is the first value of the nested list, and may be absent.
        operand: Option<Expr>,
    },
    /// `)`: performs the operation deferred by the matching `(`.
    Close,
    /// `JMP L`, `JMPC L`, `JMPCN L`.
    Jump {
        /// When.
        condition: IlCondition,
        /// The label.
        label: Ident,
    },
    /// `CAL inst`, `CAL inst(args)`, `CALC …`, `CALCN …`.
    Call {
        /// When.
        condition: IlCondition,
        /// The function block instance.
        instance: Expr,
        /// The arguments written in parentheses (none without them).
        args: Vec<Arg>,
    },
    /// `RET`, `RETC`, `RETCN`.
    Return {
        /// When.
        condition: IlCondition,
    },
    /// An input operator of a standard function block: `S1 FF1`, `CU C1`, `PT T1`, …:
    /// sets that input of the instance from the CR and calls the instance.
    Input {
        /// The input's name as written (`S1`, `CLK`, …).
        input: Ident,
        /// The instance.
        instance: Expr,
    },
    /// A function called with the CR as its first argument (`LIMIT 0, 10`, `ABS`) or
    /// with a formal argument list (`LIMIT(MN := 0, IN := x, MX := 10)`), the CR taking
    /// its result.
    Function {
        /// The function's name.
        name: Ident,
        /// The operands after the name (informal), or the formal list.
        args: Vec<Arg>,
        /// Written with a formal list in parentheses: the CR is not an argument.
        formal: bool,
    },
    /// A line that did not parse (its error is reported); the CR is unknown after it.
    Invalid,
}

impl IlKind {
    /// Whether the instruction reads the CR (a load, an unconditional jump, call or return
    /// do not).
    pub fn reads_result(&self) -> bool {
        match self {
            IlKind::Load { .. } | IlKind::Invalid => false,
            IlKind::Jump { condition, .. }
            | IlKind::Call { condition, .. }
            | IlKind::Return { condition } => *condition != IlCondition::Always,
            IlKind::Function { formal, .. } => !formal,
            _ => true,
        }
    }
}
