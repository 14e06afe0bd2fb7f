//! The operators and function families on values that the IR and the VM share.

pub use crate::syntax::Cmp;

/// The binary operators of the checked IR are those of the AST: the checker keeps the
/// operator as written and types its operands (both of the same type unless the operator
/// says otherwise: TIME + TIME, TOD/DT + TIME, TIME * or / a LINT or LREAL, `**` on LREAL).
pub use crate::syntax::BinaryOp as BinOp;

/// The numeric and bit-string standard functions of one value (with a shift count or an
/// exponent): one list for the checker's IR (`Builtin::Math`) and the VM's `Op::Math`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MathFn {
    /// ABS (wraps for integers).
    Abs,
    /// SQRT
    Sqrt,
    /// LN
    Ln,
    /// LOG
    Log,
    /// EXP
    Exp,
    /// SIN
    Sin,
    /// COS
    Cos,
    /// TAN
    Tan,
    /// ASIN
    Asin,
    /// ACOS
    Acos,
    /// ATAN
    Atan,
    /// EXPT with an exponent of the same real type as the base.
    Expt,
    /// SHL with the count as LINT in `b`.
    Shl,
    /// SHR
    Shr,
    /// ROL
    Rol,
    /// ROR
    Ror,
}

/// The string standard functions (and the two conversions between STRING and WSTRING):
/// one list for the checker's IR (`Builtin::Str`) and the VM's `Op::Str`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StrFunc {
    /// LEN(s) → INT
    Len,
    /// LEFT(s, n)
    Left,
    /// RIGHT(s, n)
    Right,
    /// MID(s, n, p)
    Mid,
    /// CONCAT(a, b, …)
    Concat,
    /// INSERT(s1, s2, p)
    Insert,
    /// DELETE(s, n, p)
    Delete,
    /// REPLACE(s1, s2, n, p)
    Replace,
    /// FIND(s1, s2) → INT
    Find,
    /// STRING → WSTRING (each byte a Latin-1 character).
    Widen,
    /// WSTRING → STRING (characters above 255 become `?`).
    Narrow,
}
