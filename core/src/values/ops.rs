//! The binary operators on values (the IR uses them as they are).

pub use crate::syntax::Cmp;

/// Binary operators on values. Operands of a binary operator have the same type unless noted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
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
    /// `AND` (logical on BOOL, bitwise otherwise)
    And,
    /// `OR`
    Or,
    /// `XOR`
    Xor,
    /// `AND_THEN`: short-circuit, BOOL only
    AndThen,
    /// `OR_ELSE`: short-circuit, BOOL only
    OrElse,
    /// A comparison (result BOOL).
    Cmp(Cmp),
}

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
