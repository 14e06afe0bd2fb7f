//! The checked, typed intermediate representation: what every front-end (ST, ladder,
//! Petri-net code) becomes before compilation to bytecode.
//!
//! Names are resolved to indices, every expression has a [`Type`], implicit conversions are
//! explicit [`ExprKind::Convert`] nodes, constants are folded into normalised cell bits.
//! The IR holds no source text; spans point into the text it came from.

use super::types::{ArrayId, Elem, PouId, Type, TypeTable};
use crate::diagnostics::Span;
use crate::syntax::{DirectAddress, PouKind, VarSection};

/// A whole checked program: types, global variables and every POU (user and library).
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// Derived types.
    pub types: TypeTable,
    /// VAR_GLOBAL variables (plus implicit ones for direct addresses used in code).
    pub globals: Vec<Var>,
    /// Every POU; library POUs first, then the user's in source order.
    pub pous: Vec<Pou>,
    /// How many of `pous` come from the standard library prelude.
    pub library_pous: usize,
    /// The CONFIGURATION, when the source declares one.
    pub config: Option<Configuration>,
}

/// A checked CONFIGURATION: its tasks and program instances, and the PROGRAM (`pou`, named
/// like the configuration, with an empty body) whose variables are the instances.
#[derive(Debug, Clone, PartialEq)]
pub struct Configuration {
    /// The configuration's name.
    pub name: String,
    /// The PROGRAM holding one variable per instance, of the instance's PROGRAM type.
    pub pou: PouId,
    /// Every task of every resource, in source order.
    pub tasks: Vec<Task>,
    /// Every program instance, in source order (as `pou`'s variables).
    pub instances: Vec<ProgramInstance>,
    /// The `VAR_CONFIG` entries: `(instance path, complete address)` of variables declared
    /// at an incomplete address, copied from the image before the tasks run (`%I`) or to
    /// it after (`%Q`, `%M`).
    pub io: Vec<(String, crate::syntax::DirectAddress)>,
    /// The whole CONFIGURATION block.
    pub span: Span,
}

/// A task: cyclic (`interval_ns` above 0), an event task (`single`), or, with neither,
/// one that runs on every scan.
#[derive(Debug, Clone, PartialEq)]
pub struct Task {
    /// The task's name.
    pub name: String,
    /// The resource declaring it.
    pub resource: String,
    /// The period in nanoseconds (0: none).
    pub interval_ns: i64,
    /// 0 is the most urgent; tasks due on one scan run in this order.
    pub priority: u32,
    /// The BOOL global whose rising edge starts the task.
    pub single: Option<String>,
    /// Where the task is declared.
    pub span: Span,
}

/// A program instance of a configuration.
#[derive(Debug, Clone, PartialEq)]
pub struct ProgramInstance {
    /// The instance's name.
    pub name: String,
    /// Its PROGRAM.
    pub pou: PouId,
    /// Its task, as an index into [`Configuration::tasks`] (none: every scan, after the
    /// tasks).
    pub task: Option<u32>,
    /// The resource declaring it.
    pub resource: String,
    /// `(VAR_INPUT, global)` pairs copied in before the instance runs.
    pub inputs: Vec<(String, String)>,
    /// `(VAR_OUTPUT, global)` pairs copied out after it runs.
    pub outputs: Vec<(String, String)>,
    /// Where it is declared.
    pub span: Span,
}

impl Program {
    /// The POU with `id`.
    pub fn pou(&self, id: PouId) -> &Pou {
        &self.pous[id as usize]
    }

    /// Finds a POU by case-insensitive name.
    pub fn find_pou(&self, name: &str) -> Option<PouId> {
        self.pous.iter().position(|p| p.name.eq_ignore_ascii_case(name)).map(|i| i as PouId)
    }

    /// The user's PROGRAMs, in source order.
    pub fn programs(&self) -> impl Iterator<Item = PouId> + '_ {
        self.pous
            .iter()
            .enumerate()
            .filter(|(_, p)| p.kind == PouKind::Program)
            .map(|(i, _)| i as PouId)
    }
}

/// A checked POU.
#[derive(Debug, Clone, PartialEq)]
pub struct Pou {
    /// Name as written.
    pub name: String,
    /// PROGRAM, FUNCTION or FUNCTION_BLOCK.
    pub kind: PouKind,
    /// Its variables in declaration order. A FUNCTION's result is the variable named like
    /// the function, at index `result`.
    pub vars: Vec<Var>,
    /// The index in `vars` of a FUNCTION's result variable.
    pub result: Option<u32>,
    /// The body.
    pub body: Vec<Stmt>,
    /// True for POUs of the standard library prelude.
    pub library: bool,
    /// Where the POU is declared.
    pub span: Span,
}

impl Pou {
    /// The result type of a FUNCTION (Void for others).
    pub fn result_type(&self) -> Type {
        self.result.map_or(Type::Void, |i| self.vars[i as usize].ty)
    }

    /// Finds a variable by case-insensitive name.
    pub fn find_var(&self, name: &str) -> Option<u32> {
        self.vars.iter().position(|v| v.name.eq_ignore_ascii_case(name)).map(|i| i as u32)
    }
}

/// A declared variable (or struct field of a program's instance).
#[derive(Debug, Clone, PartialEq)]
pub struct Var {
    /// Name as written.
    pub name: String,
    /// Its type.
    pub ty: Type,
    /// Which VAR section declared it.
    pub section: VarSection,
    /// Declared RETAIN.
    pub retain: bool,
    /// Declared CONSTANT.
    pub constant: bool,
    /// `AT %…` location.
    pub location: Option<DirectAddress>,
    /// The initial value (declared on the variable or on its type).
    pub init: Option<InitValue>,
    /// The subrange of its type, if any.
    pub range: Option<(i64, i64)>,
    /// The description from the declaration's comment.
    pub comment: Option<String>,
    /// Where it is declared.
    pub span: Span,
}

impl Var {
    /// The variable that stands for an instance of PROGRAM `q` (a plant) in the main
    /// scope: named as the POU, of its type, declared in `section`.
    pub(crate) fn program_instance(program: &Program, q: PouId, section: VarSection) -> Var {
        let pou = program.pou(q);
        Var {
            name: pou.name.clone(),
            ty: Type::Fb(q),
            section,
            retain: false,
            constant: false,
            location: None,
            init: None,
            range: None,
            comment: None,
            span: pou.span,
        }
    }

    /// An input of the program: VAR_INPUT or located at `%I`.
    pub fn is_input(&self) -> bool {
        self.section == VarSection::Input
            || matches!(&self.location, Some(a) if a.area == crate::syntax::AddressArea::Input)
    }

    /// An output of the program: VAR_OUTPUT or located at `%Q`.
    pub fn is_output(&self) -> bool {
        self.section == VarSection::Output
            || matches!(&self.location, Some(a) if a.area == crate::syntax::AddressArea::Output)
    }
}

pub use super::types::InitValue;

/// A system variable, read-only and visible in every POU.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SysVar {
    /// TRUE on the first scan after a cold or warm start.
    FirstScan,
    /// Square wave, period 10 ms.
    T10ms,
    /// Square wave, period 100 ms.
    T100ms,
    /// Square wave, period 1 s.
    TSec,
    /// Square wave, period 1 min.
    TMin,
    /// Always TRUE.
    AlwaysOn,
    /// Always FALSE.
    AlwaysOff,
    /// The virtual time since the last start (TIME).
    Clock,
}

impl SysVar {
    /// Looks up a system variable by upper-case name.
    pub fn from_name(upper: &str) -> Option<SysVar> {
        Some(match upper {
            "FST_SCN" => SysVar::FirstScan,
            "T_10MS" => SysVar::T10ms,
            "T_100MS" => SysVar::T100ms,
            "T_SEC" => SysVar::TSec,
            "T_MIN" => SysVar::TMin,
            "ALW_ON" => SysVar::AlwaysOn,
            "ALW_OFF" => SysVar::AlwaysOff,
            "SYS_CLOCK" => SysVar::Clock,
            _ => return None,
        })
    }

    /// The type of the system variable.
    pub fn ty(self) -> Type {
        match self {
            SysVar::Clock => Type::Elem(Elem::Time),
            _ => Type::BOOL,
        }
    }

    /// The period of a square-wave clock, in nanoseconds.
    pub fn period_ns(self) -> Option<i64> {
        match self {
            SysVar::T10ms => Some(10_000_000),
            SysVar::T100ms => Some(100_000_000),
            SysVar::TSec => Some(1_000_000_000),
            SysVar::TMin => Some(60_000_000_000),
            _ => None,
        }
    }
}

/// A place in memory that can be read and (usually) written.
#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// Variable `index` of the POU being executed (through the reference for VAR_IN_OUT).
    Local(u32),
    /// Global variable `index`.
    Global(u32),
    /// Field `index` of a struct, or variable `index` of an FB instance.
    Field(Box<Place>, u32),
    /// An array element; indices are LINT expressions, one per dimension.
    Element(Box<Place>, ArrayId, Vec<Expr>),
    /// Bit `n` of an integral value of type `Elem`.
    Bit(Box<Place>, u32, Elem),
    /// A located variable of type `Elem` in the process image: the raw bits of its value
    /// from bit `n` of the image cell (an LWORD) at the place.
    Slice(Box<Place>, u32, Elem),
    /// `r^`: the variable the reference `r` (an expression of a `REF_TO` type) points to;
    /// a NULL reference faults when the place is reached.
    Deref(Box<Expr>),
}

/// A typed expression.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    /// What it computes.
    pub kind: ExprKind,
    /// The type of its value.
    pub ty: Type,
    /// Its source text.
    pub span: Span,
}

pub use crate::values::{BinOp, Cmp, MathFn, StrFunc};

/// Unary operators of the IR.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnOp {
    /// Arithmetic negation.
    Neg,
    /// Logical NOT on BOOL, bitwise complement otherwise.
    Not,
}

/// The kinds of expression.
#[derive(Debug, Clone, PartialEq)]
pub enum ExprKind {
    /// A scalar constant: normalised cell bits.
    Const(u64),
    /// A string constant.
    ConstStr(Vec<u8>),
    /// Reads a place.
    Load(Place),
    /// Reads a system variable.
    Sys(SysVar),
    /// A unary operator.
    Unary(UnOp, Box<Expr>),
    /// A binary operator; `operand` is the type both operands were converted to (for
    /// comparisons the result is BOOL while operands are of `operand` type).
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// Converts the operand to this expression's type (`*_TO_*` and implicit widening).
    Convert(Box<Expr>),
    /// `TRUNC`: REAL/LREAL to an integer type, toward zero.
    Trunc(Box<Expr>),
    /// A call of a user or library FUNCTION.
    Call {
        /// The function.
        pou: PouId,
        /// Arguments bound to the function's variables.
        args: Vec<CallArg>,
    },
    /// `REF(place)`: a reference to the place (of this expression's `REF_TO` type).
    RefOf(Place),
    /// A call of a built-in function compiled inline.
    Builtin {
        /// Which.
        func: Builtin,
        /// Its arguments, already converted to the parameter types.
        args: Vec<Expr>,
    },
}

/// An argument bound to a parameter (a variable index of the callee).
#[derive(Debug, Clone, PartialEq)]
pub enum CallArg {
    /// An input value.
    In(u32, Expr),
    /// A VAR_IN_OUT reference.
    InOut(u32, Place),
    /// An output copied to a place after the call (`=>`), optionally negated.
    Out(u32, Place, bool),
}

/// Built-in functions that compile to VM instructions. The operand type decides the variant
/// of the instruction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Builtin {
    /// ABS, SQRT, LN, LOG, EXP, SIN … ATAN, EXPT (real base, LREAL exponent), SHL, SHR,
    /// ROL, ROR (value, count).
    Math(MathFn),
    /// SEL(g, in0, in1)
    Sel,
    /// MAX(a, b, ...)
    Max,
    /// MIN(a, b, ...)
    Min,
    /// LIMIT(mn, in, mx)
    Limit,
    /// A value stored into a subrange variable, checked: `(low, value, high)` gives the
    /// value, or faults outside the limits (the checker puts it around such stores).
    Subrange,
    /// MUX(k, in0, in1, ...)
    Mux,
    /// LEN, LEFT, RIGHT, MID, CONCAT, INSERT, DELETE, REPLACE, FIND.
    Str(StrFunc),
    /// Any value to its STRING text (`*_TO_STRING`).
    ToString,
    /// STRING text to a value (`STRING_TO_*`).
    FromString,
    /// BCD_TO_* : decode packed BCD.
    BcdToInt,
    /// *_TO_BCD : encode packed BCD.
    IntToBcd,
    /// A function called with `EN` (en, default, call): the call when `en` is TRUE, else
    /// the default value of its type without evaluating the call (IEC execution control;
    /// matiec gives the type's initial value).
    Enabled,
}

/// One CASE branch: inclusive ranges of selector values, and its body.
pub type CaseArm = (Vec<(i64, i64)>, Vec<Stmt>);

/// A statement with its source span (for the debug map).
#[derive(Debug, Clone, PartialEq)]
pub struct Stmt {
    /// What it does.
    pub kind: StmtKind,
    /// Its source text.
    pub span: Span,
}

/// The kinds of statement.
#[derive(Debug, Clone, PartialEq)]
pub enum StmtKind {
    /// `place := value` (value already of the place's type).
    Assign(Place, Expr),
    /// A call of an FB instance.
    CallFb {
        /// The instance.
        instance: Place,
        /// The FB type.
        fb: PouId,
        /// Arguments.
        args: Vec<CallArg>,
    },
    /// A function call used as a statement (its value is dropped).
    Eval(Expr),
    /// IF / ELSIF / ELSE.
    If {
        /// Conditions and bodies in order.
        branches: Vec<(Expr, Vec<Stmt>)>,
        /// The ELSE body (empty when absent).
        else_body: Vec<Stmt>,
    },
    /// CASE.
    Case {
        /// The selector (an integer or enumeration value).
        selector: Expr,
        /// Per arm: inclusive ranges of selector values, and the body.
        arms: Vec<CaseArm>,
        /// The ELSE body (empty when absent).
        else_body: Vec<Stmt>,
    },
    /// FOR (see docs/semantics.md: end and step evaluated once).
    For {
        /// The control variable.
        var: Place,
        /// Its integer type.
        ty: Elem,
        /// Start value.
        from: Expr,
        /// End value.
        to: Expr,
        /// Step (a constant 1 when not written).
        by: Expr,
        /// The body.
        body: Vec<Stmt>,
    },
    /// WHILE.
    While {
        /// The condition.
        cond: Expr,
        /// The body.
        body: Vec<Stmt>,
    },
    /// REPEAT … UNTIL.
    Repeat {
        /// The body.
        body: Vec<Stmt>,
        /// The exit condition.
        until: Expr,
    },
    /// EXIT the innermost loop.
    Exit,
    /// CONTINUE with the next iteration.
    Continue,
    /// RETURN from the POU.
    Return,
}
