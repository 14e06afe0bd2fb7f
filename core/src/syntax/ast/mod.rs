//! The abstract syntax tree of IEC 61131-3 Structured Text.
//!
//! The parser produces it; the checker (`crate::semantic`) reads it. Every node carries the
//! byte [`Span`] of the text it came from so diagnostics can point at it. Names keep the
//! spelling the user wrote; comparisons are case-insensitive (see [`Ident::key`]).
//! This module holds data only: no parsing, no checking.

mod config;
pub(crate) mod il;
pub(crate) mod sfc;

pub use config::{ConfigVar, Configuration, Connection, ProgramDecl, Resource, TaskDecl};

use crate::diagnostics::Span;

/// An identifier as written, with its place in the source.
#[derive(Debug, Clone, PartialEq)]
pub struct Ident {
    /// The spelling the user wrote.
    pub name: String,
    /// Where it stands in the source.
    pub span: Span,
}

impl Ident {
    /// The case-insensitive lookup key (upper case).
    pub fn key(&self) -> String {
        self.name.to_ascii_uppercase()
    }
}

/// A whole source file: type declarations, global variables and POUs in source order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SourceFile {
    /// The top-level items in source order.
    pub items: Vec<Item>,
}

/// A top-level item of a source file.
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// `TYPE … END_TYPE` (one block may declare several types).
    Types(Vec<TypeDef>),
    /// A top-level `VAR_GLOBAL … END_VAR` block (outside any POU).
    Globals(VarBlock),
    /// A PROGRAM, FUNCTION or FUNCTION_BLOCK.
    Pou(Pou),
    /// A `CONFIGURATION` with its resources, tasks and program instances.
    Configuration(Configuration),
}

/// The kind of a program organisation unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PouKind {
    /// `PROGRAM … END_PROGRAM`
    Program,
    /// `FUNCTION name : TYPE … END_FUNCTION`
    Function,
    /// `FUNCTION_BLOCK … END_FUNCTION_BLOCK`
    FunctionBlock,
}

/// A program organisation unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Pou {
    /// PROGRAM, FUNCTION or FUNCTION_BLOCK.
    pub kind: PouKind,
    /// The POU's name.
    pub name: Ident,
    /// The result type of a FUNCTION (`None` for the others, and for a function declared
    /// without one).
    pub return_type: Option<TypeRef>,
    /// Declaration blocks in source order.
    pub var_blocks: Vec<VarBlock>,
    /// The statements of the body (empty when the body is a sequential function chart).
    pub body: Vec<Stmt>,
    /// The body written as a textual sequential function chart, if it is one.
    pub sfc: Option<sfc::SfcBody>,
    /// The body written in Instruction List, if it is one (`crate::il` lowers it into
    /// `body` before the checker runs).
    pub il: Option<il::IlBody>,
    /// The whole POU, from its keyword to its END keyword.
    pub span: Span,
}

/// Which `VAR…` keyword opened a declaration block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VarSection {
    /// `VAR`
    Var,
    /// `VAR_INPUT`
    Input,
    /// `VAR_OUTPUT`
    Output,
    /// `VAR_IN_OUT`
    InOut,
    /// `VAR_GLOBAL`
    Global,
    /// `VAR_EXTERNAL`
    External,
    /// `VAR_TEMP`
    Temp,
}

impl VarSection {
    /// The keyword that opens a block of this section (`VAR_INPUT`).
    pub fn keyword(self) -> &'static str {
        match self {
            VarSection::Var => "VAR",
            VarSection::Input => "VAR_INPUT",
            VarSection::Output => "VAR_OUTPUT",
            VarSection::InOut => "VAR_IN_OUT",
            VarSection::Global => "VAR_GLOBAL",
            VarSection::External => "VAR_EXTERNAL",
            VarSection::Temp => "VAR_TEMP",
        }
    }
}

/// One `VAR… [RETAIN|NON_RETAIN] [CONSTANT] … END_VAR` block.
#[derive(Debug, Clone, PartialEq)]
pub struct VarBlock {
    /// The opening keyword.
    pub section: VarSection,
    /// `RETAIN` was written.
    pub retain: bool,
    /// `CONSTANT` was written.
    pub constant: bool,
    /// The declarations inside.
    pub decls: Vec<VarDecl>,
    /// From the opening keyword to `END_VAR`.
    pub span: Span,
}

/// One declaration line: `a, b AT %IX0.0 : BOOL := TRUE; (* comment *)`.
#[derive(Debug, Clone, PartialEq)]
pub struct VarDecl {
    /// The declared names (several when written `a, b : INT`).
    pub names: Vec<Ident>,
    /// `AT %…` location, if any.
    pub location: Option<DirectAddress>,
    /// The declared type.
    pub ty: TypeRef,
    /// The initial value, if any.
    pub init: Option<Initializer>,
    /// The text of a comment that follows the declaration on the same line (without the
    /// comment delimiters, trimmed), used as the variable's description.
    pub comment: Option<String>,
    /// The whole declaration.
    pub span: Span,
}

/// The memory area of a directly represented variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AddressArea {
    /// `%I` inputs.
    Input,
    /// `%Q` outputs.
    Output,
    /// `%M` memory.
    Memory,
}

/// The size prefix of a directly represented variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AddressSize {
    /// `X` or no size letter: a single bit.
    Bit,
    /// `B`: byte.
    Byte,
    /// `W`: word (16 bits).
    Word,
    /// `D`: double word (32 bits).
    DWord,
    /// `L`: long word (64 bits).
    LWord,
}

/// A directly represented address such as `%IX0.0`, `%QW4`, `%MW6` or `%I*`.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectAddress {
    /// I, Q or M.
    pub area: AddressArea,
    /// The size letter (X when absent).
    pub size: AddressSize,
    /// The dotted numbers: `%IX1.2` gives `[1, 2]`.
    pub path: Vec<u32>,
    /// The text as written, e.g. `%IX0.0`.
    pub text: String,
    /// Where it stands.
    pub span: Span,
}

/// A reference to a type where a variable, field, element or result is declared.
#[derive(Debug, Clone, PartialEq)]
pub enum TypeRef {
    /// An elementary or user type by name: `INT`, `TON`, `MyStruct`.
    Named(Ident),
    /// `STRING`, `STRING[10]`, `STRING(10)`, `WSTRING[…]`.
    String {
        /// `WSTRING` rather than `STRING`.
        wide: bool,
        /// The declared maximum length, if written.
        length: Option<Box<Expr>>,
        /// The whole type text.
        span: Span,
    },
    /// `ARRAY [lo..hi, lo..hi] OF elem`.
    Array {
        /// One range per dimension.
        ranges: Vec<(Expr, Expr)>,
        /// The element type.
        element: Box<TypeRef>,
        /// The whole type text.
        span: Span,
    },
    /// `INT (0..100)`: a subrange of an integer type.
    Subrange {
        /// The base type.
        base: Ident,
        /// Lower limit.
        low: Box<Expr>,
        /// Upper limit.
        high: Box<Expr>,
        /// The whole type text.
        span: Span,
    },
    /// `(Red, Green := 5, Blue)`, optionally with a base type `INT (A, B)` — only in a TYPE
    /// block or inline in a declaration.
    Enum {
        /// The enumerators with their optional explicit values.
        values: Vec<(Ident, Option<Expr>)>,
        /// The whole type text.
        span: Span,
    },
    /// `STRUCT … END_STRUCT` (only in a TYPE block).
    Struct {
        /// The fields, declared like variables.
        fields: Vec<VarDecl>,
        /// The whole type text.
        span: Span,
    },
    /// `REF_TO T`: a reference to a variable of type `T` (IEC 61131-3 ed. 3).
    Ref {
        /// The referenced type.
        target: Box<TypeRef>,
        /// The whole type text.
        span: Span,
    },
}

impl TypeRef {
    /// The source span of the whole type reference.
    pub fn span(&self) -> Span {
        match self {
            TypeRef::Named(id) => id.span,
            TypeRef::String { span, .. }
            | TypeRef::Array { span, .. }
            | TypeRef::Subrange { span, .. }
            | TypeRef::Enum { span, .. }
            | TypeRef::Struct { span, .. }
            | TypeRef::Ref { span, .. } => *span,
        }
    }
}

/// One type in a `TYPE … END_TYPE` block: `Name : spec [:= init];`.
#[derive(Debug, Clone, PartialEq)]
pub struct TypeDef {
    /// The new type's name.
    pub name: Ident,
    /// What it is.
    pub ty: TypeRef,
    /// The initial value declared on the type, if any.
    pub init: Option<Initializer>,
    /// The whole definition.
    pub span: Span,
}

/// An initial value.
#[derive(Debug, Clone, PartialEq)]
pub enum Initializer {
    /// A plain expression (must be constant).
    Expr(Expr),
    /// `[1, 2, 3(0), 2(5)]` for arrays.
    Array {
        /// The elements, in order.
        elements: Vec<ArrayInitElement>,
        /// The whole initializer.
        span: Span,
    },
    /// `(field := value, other := value)` for structs.
    Struct {
        /// Field initializers in order.
        fields: Vec<(Ident, Initializer)>,
        /// The whole initializer.
        span: Span,
    },
}

impl Initializer {
    /// The source span of the whole initializer.
    pub fn span(&self) -> Span {
        match self {
            Initializer::Expr(e) => e.span,
            Initializer::Array { span, .. } | Initializer::Struct { span, .. } => *span,
        }
    }
}

/// One element of an array initializer.
#[derive(Debug, Clone, PartialEq)]
pub enum ArrayInitElement {
    /// A single value.
    Single(Initializer),
    /// `n(value)` — the value repeated n times; `n()` repeats the default.
    Repeat {
        /// How many times.
        count: Expr,
        /// The value, or `None` for `n()`.
        value: Option<Box<Initializer>>,
        /// The whole element.
        span: Span,
    },
}

/// A statement with its span.
#[derive(Debug, Clone, PartialEq)]
pub struct Stmt {
    /// What the statement is.
    pub kind: StmtKind,
    /// From its first token to its terminating `;` (inclusive when present).
    pub span: Span,
}

/// The kinds of statement.
#[derive(Debug, Clone, PartialEq)]
pub enum StmtKind {
    /// `target := value;`
    Assign {
        /// The assigned place (a variable, member, element or bit).
        target: Expr,
        /// The new value.
        value: Expr,
    },
    /// A call used as a statement: `Timer(IN := x, PT := T#1s);` or `F(1, 2);`.
    /// The expression is always an [`ExprKind::Call`].
    Call(Expr),
    /// `IF c THEN … ELSIF c THEN … ELSE … END_IF;`
    If {
        /// The IF and ELSIF branches in order.
        branches: Vec<(Expr, Vec<Stmt>)>,
        /// The ELSE branch, if written.
        else_body: Option<Vec<Stmt>>,
    },
    /// `CASE selector OF labels: … ELSE … END_CASE;`
    Case {
        /// The selector expression.
        selector: Expr,
        /// The labelled branches in order.
        arms: Vec<CaseArm>,
        /// The ELSE branch, if written.
        else_body: Option<Vec<Stmt>>,
    },
    /// `FOR var := from TO to [BY step] DO … END_FOR;`
    For {
        /// The control variable.
        var: Ident,
        /// Start value.
        from: Expr,
        /// End value.
        to: Expr,
        /// Step, if written.
        by: Option<Expr>,
        /// The loop body.
        body: Vec<Stmt>,
    },
    /// `WHILE cond DO … END_WHILE;`
    While {
        /// Loop condition.
        cond: Expr,
        /// The loop body.
        body: Vec<Stmt>,
    },
    /// `REPEAT … UNTIL cond END_REPEAT;`
    Repeat {
        /// The loop body.
        body: Vec<Stmt>,
        /// Exit condition.
        until: Expr,
    },
    /// `EXIT;`
    Exit,
    /// `CONTINUE;`
    Continue,
    /// `RETURN;`
    Return,
    /// A lone `;`.
    Empty,
}

/// One branch of a CASE statement.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseArm {
    /// The labels before the colon.
    pub labels: Vec<CaseLabel>,
    /// The statements of the branch.
    pub body: Vec<Stmt>,
    /// From the first label to the colon.
    pub span: Span,
}

/// A CASE label.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseLabel {
    /// A single value (a constant expression or enumerator).
    Value(Expr),
    /// `low..high`.
    Range(Expr, Expr),
}

/// An expression with its span.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    /// What the expression is.
    pub kind: ExprKind,
    /// Its text in the source.
    pub span: Span,
}

/// The kinds of expression.
#[derive(Debug, Clone, PartialEq)]
pub enum ExprKind {
    /// A literal constant.
    Literal(Literal),
    /// A name: a variable, a constant, an enumerator or a system variable.
    Name(Ident),
    /// `Type#Value` for an enumerator qualified by its type.
    EnumValue {
        /// The enumeration type.
        type_name: Ident,
        /// The enumerator.
        value: Ident,
    },
    /// `base.field` — a struct field or FB member.
    Member(Box<Expr>, Ident),
    /// `base.3` or `base.%X3` — one bit of an integer or bit string.
    Bit(Box<Expr>, u32),
    /// `base.%B1`, `.%W0`, `.%D1`, `.%L0` — partial access (IEC 61131-3 ed. 3): byte,
    /// word, double or long word number `index` of a bit string, `width` bits wide.
    Part {
        /// The bit string.
        base: Box<Expr>,
        /// 8, 16, 32 or 64.
        width: u32,
        /// Which one, from the least significant.
        index: u32,
    },
    /// `base[i, j]` — an array element.
    Index(Box<Expr>, Vec<Expr>),
    /// A prefix operator.
    Unary(UnaryOp, Box<Expr>),
    /// An infix operator.
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// A call of a function or a function block instance.
    Call {
        /// What is called: a function name, or an FB instance (a name, member or element).
        callee: Box<Expr>,
        /// The arguments as written.
        args: Vec<Arg>,
    },
    /// A directly represented variable used in code: `%IX0.1`.
    Direct(DirectAddress),
    /// An expression in parentheses (kept so spans and ST views stay faithful).
    Paren(Box<Expr>),
    /// `r^` — the variable a reference points to (IEC 61131-3 ed. 3).
    Deref(Box<Expr>),
}

impl Expr {
    /// The height of the expression tree (a name or literal is 1, `a + b` is 2), measured
    /// without recursion so that it is safe on any tree.
    pub fn height(&self) -> usize {
        let mut tallest = 0;
        let mut todo: Vec<(&Expr, usize)> = vec![(self, 1)];
        while let Some((e, h)) = todo.pop() {
            tallest = tallest.max(h);
            match &e.kind {
                ExprKind::Literal(_)
                | ExprKind::Name(_)
                | ExprKind::EnumValue { .. }
                | ExprKind::Direct(_) => {}
                ExprKind::Member(b, _)
                | ExprKind::Bit(b, _)
                | ExprKind::Part { base: b, .. }
                | ExprKind::Unary(_, b)
                | ExprKind::Paren(b)
                | ExprKind::Deref(b) => todo.push((b, h + 1)),
                ExprKind::Index(b, indices) => {
                    todo.push((b, h + 1));
                    todo.extend(indices.iter().map(|i| (i, h + 1)));
                }
                ExprKind::Binary(_, l, r) => {
                    todo.push((l, h + 1));
                    todo.push((r, h + 1));
                }
                ExprKind::Call { callee, args } => {
                    todo.push((callee, h + 1));
                    todo.extend(args.iter().map(|a| match a {
                        Arg::Positional(v) | Arg::Input { value: v, .. } => (v, h + 1),
                        Arg::Output { target, .. } => (target, h + 1),
                    }));
                }
            }
        }
        tallest
    }
}

/// A prefix operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnaryOp {
    /// `-x`
    Neg,
    /// `+x`
    Plus,
    /// `NOT x`
    Not,
}

/// An infix operator, from loosest to tightest binding:
/// `OR OR_ELSE` < `XOR` < `AND & AND_THEN` < `= <>` < `< > <= >=` < `+ -` < `* / MOD` < `**`.
/// Unary operators bind tighter than `**`. The checked IR uses the same enum
/// (`values::BinOp`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinaryOp {
    /// `OR` (logical on BOOL, bitwise otherwise)
    Or,
    /// `OR_ELSE`: short-circuit, BOOL only
    OrElse,
    /// `XOR`
    Xor,
    /// `AND` or `&` (logical on BOOL, bitwise otherwise)
    And,
    /// `AND_THEN`: short-circuit, BOOL only
    AndThen,
    /// A comparison (`=`, `<>`, `<`, `<=`, `>`, `>=`; result BOOL).
    Cmp(Cmp),
    /// `+` (TIME + TIME, TOD/DT + TIME also)
    Add,
    /// `-`
    Sub,
    /// `*` (TIME * number: right operand LINT or LREAL)
    Mul,
    /// `/` (TIME / number: right operand LINT or LREAL)
    Div,
    /// `MOD`
    Mod,
    /// `**` (on LREAL)
    Pow,
}

/// A comparison operator: the one definition for the AST, the checked IR
/// (`values::BinOp::Cmp`), ladder comparison blocks (`GT`, `LE`, …) and the Petri net
/// guard analysis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Cmp {
    /// `=` (`EQ`)
    Eq,
    /// `<>` (`NE`)
    Ne,
    /// `<` (`LT`)
    Lt,
    /// `<=` (`LE`)
    Le,
    /// `>` (`GT`)
    Gt,
    /// `>=` (`GE`)
    Ge,
}

impl Cmp {
    /// Every comparison, in the order of the standard functions EQ, NE, LT, LE, GT, GE.
    pub const ALL: [Cmp; 6] = [Cmp::Eq, Cmp::Ne, Cmp::Lt, Cmp::Le, Cmp::Gt, Cmp::Ge];

    /// The operator as written in ST (`<=`).
    pub fn symbol(self) -> &'static str {
        match self {
            Cmp::Eq => "=",
            Cmp::Ne => "<>",
            Cmp::Lt => "<",
            Cmp::Le => "<=",
            Cmp::Gt => ">",
            Cmp::Ge => ">=",
        }
    }

    /// The name of the standard function (`LE`).
    pub fn function(self) -> &'static str {
        match self {
            Cmp::Eq => "EQ",
            Cmp::Ne => "NE",
            Cmp::Lt => "LT",
            Cmp::Le => "LE",
            Cmp::Gt => "GT",
            Cmp::Ge => "GE",
        }
    }

    /// The comparison a standard function name stands for (any case): `le` → `Le`.
    pub fn from_function(name: &str) -> Option<Cmp> {
        Cmp::ALL.into_iter().find(|c| c.function().eq_ignore_ascii_case(name))
    }

    /// The same comparison with its operands swapped: `a < b` is `b > a`.
    pub fn flip(self) -> Cmp {
        match self {
            Cmp::Lt => Cmp::Gt,
            Cmp::Le => Cmp::Ge,
            Cmp::Gt => Cmp::Lt,
            Cmp::Ge => Cmp::Le,
            c => c,
        }
    }

    /// Whether the comparison holds for two operands ordered as `ord` (`a.cmp(&b)`).
    pub fn holds(self, ord: std::cmp::Ordering) -> bool {
        use std::cmp::Ordering::{Equal, Greater, Less};
        match self {
            Cmp::Eq => ord == Equal,
            Cmp::Ne => ord != Equal,
            Cmp::Lt => ord == Less,
            Cmp::Le => ord != Greater,
            Cmp::Gt => ord == Greater,
            Cmp::Ge => ord != Less,
        }
    }
}

/// An argument of a call.
#[derive(Debug, Clone, PartialEq)]
pub enum Arg {
    /// An informal (positional) argument.
    Positional(Expr),
    /// `name := value`
    Input {
        /// The parameter name.
        name: Ident,
        /// The value.
        value: Expr,
    },
    /// `name => target` or `NOT name => target`.
    Output {
        /// The output parameter name.
        name: Ident,
        /// The variable that receives it.
        target: Expr,
        /// `NOT` was written before the name.
        negated: bool,
    },
}

/// A literal constant.
#[derive(Debug, Clone, PartialEq)]
pub struct Literal {
    /// The value.
    pub value: LiteralValue,
    /// A type prefix such as `DINT#`, `REAL#`, `BOOL#`, `STRING#`, when written.
    pub type_prefix: Option<Ident>,
}

/// The value of a literal.
#[derive(Debug, Clone, PartialEq)]
pub enum LiteralValue {
    /// An integer, any base. Wide enough for every IEC integer type and a sign.
    Int(i128),
    /// A real number.
    Real(f64),
    /// `TRUE` / `FALSE`.
    Bool(bool),
    /// A `'…'` string, escapes resolved, as bytes.
    String(Vec<u8>),
    /// A `"…"` wide string, escapes resolved, as UTF-16 code units.
    WString(Vec<u16>),
    /// `T#…` / `TIME#…` / `LTIME#…`: nanoseconds.
    Time(i64),
    /// `D#…` / `DATE#…`: microseconds since 1970-01-01 00:00 (a whole number of days).
    Date(i64),
    /// `TOD#…` / `TIME_OF_DAY#…`: nanoseconds since midnight.
    TimeOfDay(i64),
    /// `DT#…` / `DATE_AND_TIME#…`: microseconds since 1970-01-01 00:00.
    DateTime(i64),
}
