//! The instruction set of the VM: a flat `Vec<Op>` of compact (16-byte) instructions.
//!
//! Operands named `dst`, `a`, `b`, `v`, … are *registers*: cell offsets relative to the
//! frame base of the running POU (the instance of a PROGRAM or FB, or the static frame of
//! a FUNCTION). Offsets wrap (`base.wrapping_add(off)`), so code of a POU whose frame has a
//! fixed address reaches globals without a separate instruction. A *pointer* register
//! holds an absolute cell address. Non-scalar values (strings, arrays, structs) are always
//! handled through pointers; a string occupies a header cell (`capacity << 32 | length`,
//! both in bytes) followed by its bytes packed eight to a cell.
//!
//! This module only defines data; it executes nothing (see `crate::vm`).

use crate::semantic::ir::{BinOp, SysVar};
use crate::semantic::types::{Elem, PouId};

pub use super::tables::{Branch, CaseTable, DimInfo, ElemSite, MathFn, Reg, StrFunc, R3};

/// One VM instruction. Kept at 16 bytes (checked by a test).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Op {
    /// `dst := bits`.
    Const {
        /// Destination register.
        dst: Reg,
        /// The cell bits.
        bits: u64,
    },
    /// `dst := a`.
    Move {
        /// Destination.
        dst: Reg,
        /// Source.
        a: Reg,
    },
    /// `dst := cells[addr]` (absolute address).
    LoadAbs {
        /// Destination.
        dst: Reg,
        /// Absolute address.
        addr: u32,
    },
    /// `cells[addr] := a`.
    StoreAbs {
        /// Absolute address.
        addr: u32,
        /// Source.
        a: Reg,
    },
    /// `dst := cells[ptr + off]`.
    LoadInd {
        /// Destination.
        dst: Reg,
        /// Pointer register.
        ptr: Reg,
        /// Offset added to the pointer.
        off: u32,
    },
    /// `cells[ptr + off] := a`.
    StoreInd {
        /// Pointer register.
        ptr: Reg,
        /// Offset added to the pointer.
        off: u32,
        /// Source.
        a: Reg,
    },
    /// `dst := base + off`: the absolute address of a frame cell.
    AddrOf {
        /// Destination pointer register.
        dst: Reg,
        /// Frame offset.
        off: u32,
    },
    /// `dst := cells[a] - 1`: the address a reference (`REF_TO`) holds, as a pointer; a
    /// NULL reference (0) faults, and so does one that points outside memory.
    Deref {
        /// Destination pointer register.
        dst: Reg,
        /// The reference.
        a: Reg,
    },
    /// `dst := ptr + off` (pointer arithmetic).
    PtrAdd {
        /// Destination pointer register.
        dst: Reg,
        /// Source pointer register.
        ptr: Reg,
        /// Offset.
        off: u32,
    },
    /// Bounds-checks index register `idx` (LINT) against dimension `dim` of the
    /// executable's dimension table and advances pointer `ptr` by `(idx - low) * stride`.
    Index {
        /// Pointer register, updated in place.
        ptr: Reg,
        /// The index (LINT).
        idx: Reg,
        /// Entry in `Executable::dims`.
        dim: u32,
    },
    /// `dst := element of a frame array` (address, bounds check and load in one step).
    LoadElem {
        /// Destination.
        dst: Reg,
        /// The index register (a LINT, or the operand of `add` in its own type).
        idx: Reg,
        /// Entry in `Executable::sites`.
        site: u32,
    },
    /// `element of a frame array := a`.
    StoreElem {
        /// The index register.
        idx: Reg,
        /// Entry in `Executable::sites`.
        site: u32,
        /// Source.
        a: Reg,
    },
    /// `arr1[i] := arr2[k]` on scalar elements: the destination is bounds-checked first
    /// (site `site`), then the source (site `site + 1`).
    MoveElem {
        /// Index register of the destination.
        didx: Reg,
        /// Index register of the source.
        sidx: Reg,
        /// Entry in `Executable::sites` of the destination; the source's follows.
        site: u32,
    },
    /// `dst := absolute address of an element of a frame array` (bounds-checked).
    ElemAddr {
        /// Destination pointer register.
        dst: Reg,
        /// The index register.
        idx: Reg,
        /// Entry in `Executable::sites`.
        site: u32,
    },
    /// Any arithmetic or bitwise operator through `arith::binary`.
    Bin {
        /// Operator.
        op: BinOp,
        /// Operand type.
        elem: Elem,
        /// Destination.
        dst: Reg,
        /// Left operand.
        a: Reg,
        /// Right operand.
        b: Reg,
    },
    /// A comparison through `arith::compare` (result BOOL).
    Cmp {
        /// Operator.
        op: BinOp,
        /// Operand type.
        elem: Elem,
        /// Destination.
        dst: Reg,
        /// Left operand.
        a: Reg,
        /// Right operand.
        b: Reg,
    },
    /// LINT/TIME `+` (i64, wrapping).
    AddI64(R3),
    /// LINT/TIME `-`.
    SubI64(R3),
    /// LINT `*`.
    MulI64(R3),
    /// DINT `+`.
    AddI32(R3),
    /// DINT `-`.
    SubI32(R3),
    /// DINT `*`.
    MulI32(R3),
    /// INT `+`.
    AddI16(R3),
    /// INT `-`.
    SubI16(R3),
    /// LREAL `+`.
    AddF64(R3),
    /// LREAL `-`.
    SubF64(R3),
    /// LREAL `*`.
    MulF64(R3),
    /// LREAL `/`.
    DivF64(R3),
    /// REAL `+` (computed in f64, rounded to f32 as `arith::binary` does).
    AddF32(R3),
    /// REAL `-`.
    SubF32(R3),
    /// REAL `*`.
    MulF32(R3),
    /// REAL `/`.
    DivF32(R3),
    /// `=` on any non-real cell (cells are normalised, so equal bits mean equal values).
    EqCell(R3),
    /// `<>` on any non-real cell.
    NeCell(R3),
    /// `<` on cells that order as i64 (all but ULINT, LWORD and reals).
    LtI64(R3),
    /// `<=` likewise.
    LeI64(R3),
    /// `>` likewise.
    GtI64(R3),
    /// `>=` likewise.
    GeI64(R3),
    /// AND (logical on BOOL, bitwise otherwise).
    And(R3),
    /// OR.
    Or(R3),
    /// XOR.
    Xor(R3),
    /// `a AND NOT b` on any non-real cell (a ladder's normally closed contact): `a & !b`,
    /// which is `a AND NOT b` in every integral type since cells are normalised.
    AndNot(R3),
    /// TIME (TOD, DT) scaled by a LINT (`real` false) or LREAL factor.
    ScaleTime {
        /// Mul or Div.
        op: BinOp,
        /// The temporal type.
        elem: Elem,
        /// Factor is an LREAL.
        real: bool,
        /// Destination.
        dst: Reg,
        /// The time.
        a: Reg,
        /// The factor.
        b: Reg,
    },
    /// Arithmetic negation.
    Neg {
        /// Type.
        elem: Elem,
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
    },
    /// NOT (logical on BOOL, bitwise otherwise).
    Not {
        /// Type.
        elem: Elem,
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
    },
    /// `arith::convert`.
    Conv {
        /// Source type.
        from: Elem,
        /// Target type.
        to: Elem,
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
    },
    /// REAL → DINT with rounding half to even (the hot case of `arith::convert`).
    RealToDint {
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
    },
    /// `REAL_TO_DINT(a * b)` on REALs in one step (the scaling of an analog value):
    /// `MulF32` then `RealToDint`.
    MulRealToDint(R3),
    /// `arith::trunc`.
    Trunc {
        /// Source type.
        from: Elem,
        /// Target type.
        to: Elem,
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
    },
    /// `dst := bit n of a`.
    GetBit {
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
        /// Bit number.
        n: u32,
    },
    /// `dst := a with bit n set to the BOOL in v` (re-normalised as `elem`).
    SetBit {
        /// Type of the integral value.
        elem: Elem,
        /// Bit number.
        n: u8,
        /// In/out: the value.
        dst: Reg,
        /// The BOOL.
        v: Reg,
    },
    /// `dst := the elem stored from bit shift of the image cell a` (a located variable
    /// in the process image; see `arith::get_slice`).
    GetSlice {
        /// Type of the value.
        elem: Elem,
        /// Its first bit in the cell.
        shift: u8,
        /// Destination.
        dst: Reg,
        /// The image cell.
        a: Reg,
    },
    /// `dst := the image cell dst with the elem in v stored from bit shift`.
    SetSlice {
        /// Type of the value.
        elem: Elem,
        /// Its first bit in the cell.
        shift: u8,
        /// In/out: the image cell.
        dst: Reg,
        /// The value.
        v: Reg,
    },
    /// Reads a system variable.
    Sys {
        /// Which.
        var: SysVar,
        /// Destination.
        dst: Reg,
    },
    /// Unconditional jump.
    Jump {
        /// Target instruction.
        target: u32,
    },
    /// Jumps when `a < b` (cells that order as i64, as [`Op::LtI64`]).
    JumpLt(Branch),
    /// Jumps when `a <= b`.
    JumpLe(Branch),
    /// Jumps when `a > b`.
    JumpGt(Branch),
    /// Jumps when `a >= b`.
    JumpGe(Branch),
    /// Jumps when `a = b` (any non-real cell, as [`Op::EqCell`]).
    JumpEq(Branch),
    /// Jumps when `a <> b`.
    JumpNe(Branch),
    /// Jumps when the BOOL in `c` is TRUE.
    JumpIf {
        /// Condition.
        c: Reg,
        /// Target.
        target: u32,
    },
    /// Jumps when the BOOL in `c` is FALSE.
    JumpIfNot {
        /// Condition.
        c: Reg,
        /// Target.
        target: u32,
    },
    /// FOR entry check: faults when the step (at `lim + 1`) is zero.
    ForStart {
        /// End value at `lim`, step at `lim + 1`.
        lim: Reg,
    },
    /// FOR test: jumps to `target` when `v` is past the end (`lim`) in the step's direction.
    ForTest {
        /// Type of the control variable.
        elem: Elem,
        /// Control variable value.
        v: Reg,
        /// End at `lim`, step at `lim + 1`.
        lim: Reg,
        /// Exit target.
        target: u32,
    },
    /// FOR increment: `v += step` (wrapping in `elem`), then jumps to `target` (the body)
    /// when the unwrapped sum still passes the test.
    ForNext {
        /// Type of the control variable.
        elem: Elem,
        /// Control variable, updated in place.
        v: Reg,
        /// End at `lim`, step at `lim + 1`.
        lim: Reg,
        /// Body target.
        target: u32,
    },
    /// `ForNext` for integer types of at most 32 bits (no i128 arithmetic): `bits` is the
    /// width, `signed` whether the type is signed.
    ForNext32 {
        /// Width of the control variable's type.
        bits: u8,
        /// Signed type.
        signed: bool,
        /// Control variable, updated in place.
        v: Reg,
        /// End at `lim`, step at `lim + 1`.
        lim: Reg,
        /// Body target.
        target: u32,
    },
    /// `ForNext32` for a loop whose step is the constant 1 (the step is not read).
    ForInc32 {
        /// Width of the control variable's type.
        bits: u8,
        /// Signed type.
        signed: bool,
        /// Control variable, updated in place.
        v: Reg,
        /// End at `lim`.
        lim: Reg,
        /// Body target.
        target: u32,
    },
    /// FOR increment without the jump: as `ForNext`, writing the BOOL "go on" to
    /// `lim + 2` (used when the variable is not a register).
    ForStep {
        /// Type of the control variable.
        elem: Elem,
        /// Control variable, updated in place.
        v: Reg,
        /// End at `lim`, step at `lim + 1`, flag at `lim + 2`.
        lim: Reg,
    },
    /// CASE dispatch through `Executable::cases[table]`.
    Case {
        /// Selector type (enumerations use LINT).
        elem: Elem,
        /// Selector.
        sel: Reg,
        /// Table index.
        table: u32,
    },
    /// Calls the body of FB (or program) `pou` with the instance at the address in `ptr`.
    CallFb {
        /// The POU.
        pou: PouId,
        /// Pointer register holding the instance address.
        ptr: Reg,
    },
    /// Calls FUNCTION `pou` on its static frame.
    CallFn {
        /// The function.
        pou: PouId,
    },
    /// Resets the static frame of FUNCTION `pou` to its initial values.
    InitFrame {
        /// The function.
        pou: PouId,
    },
    /// Re-initialises the VAR_TEMP variables of the running POU `pou`.
    InitTemps {
        /// The POU.
        pou: PouId,
    },
    /// Returns from the running POU.
    Ret,
    /// Ends a breakpoint condition with the BOOL in `a`.
    Halt {
        /// Result.
        a: Reg,
    },
    /// Copies `n` cells from the address in pointer `src` to the address in pointer `dst`.
    Copy {
        /// Destination pointer.
        dst: Reg,
        /// Source pointer.
        src: Reg,
        /// Cell count.
        n: u32,
    },
    /// Copies the string at pointer `src` to the string at pointer `dst`, truncating to
    /// the destination's capacity.
    StrCopy {
        /// Destination pointer.
        dst: Reg,
        /// Source pointer.
        src: Reg,
    },
    /// Compares two strings (pointers) byte-wise, result BOOL.
    StrCmp {
        /// Operator.
        op: BinOp,
        /// Destination.
        dst: Reg,
        /// Left string pointer.
        a: Reg,
        /// Right string pointer.
        b: Reg,
    },
    /// A string function (see [`StrFunc`]); arguments in consecutive registers from
    /// `args` (strings as pointers, numbers as LINT); `dst` is a pointer to the result
    /// string, or the INT/LINT result register for LEN and FIND.
    Str {
        /// Which.
        f: StrFunc,
        /// Argument count (CONCAT).
        n: u8,
        /// WSTRING (positions count 2-byte units).
        wide: bool,
        /// Result.
        dst: Reg,
        /// First argument.
        args: Reg,
    },
    /// A numeric built-in (see [`MathFn`]) on `a` (and `b` for EXPT).
    Math {
        /// Which.
        f: MathFn,
        /// Operand/result type.
        elem: Elem,
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
        /// Second operand (EXPT exponent, SHL count as LINT).
        b: Reg,
    },
    /// `dst := if g { in1 } else { in0 }`, in0 and in1 at `a` and `a + 1`.
    Select {
        /// Destination.
        dst: Reg,
        /// Selector (BOOL).
        g: Reg,
        /// in0; in1 follows.
        a: Reg,
    },
    /// MAX (`max`) or MIN of `n` values at `args..`.
    MinMax {
        /// MAX rather than MIN.
        max: bool,
        /// Value type.
        elem: Elem,
        /// Count.
        n: u8,
        /// Destination.
        dst: Reg,
        /// First value.
        args: Reg,
    },
    /// LIMIT(mn, in, mx) with the three values at `args..`; with `check`, a value outside
    /// the limits faults instead (a store into a subrange variable).
    Limit {
        /// Value type.
        elem: Elem,
        /// Fault instead of clamping.
        check: bool,
        /// Destination.
        dst: Reg,
        /// mn; in and mx follow.
        args: Reg,
    },
    /// MUX: `k` (LINT) at `args`, then `n` values; copies one cell.
    Mux {
        /// Number of inputs.
        n: u32,
        /// Destination.
        dst: Reg,
        /// k; the inputs follow.
        args: Reg,
    },
    /// Renders the value in `a` (of `Executable::types[ty]`) as text into the string at
    /// pointer `dst`.
    ToStr {
        /// Index in `Executable::types`.
        ty: u32,
        /// Destination string pointer.
        dst: Reg,
        /// The value.
        a: Reg,
    },
    /// Parses the string at pointer `a` as `elem`.
    FromStr {
        /// Target type.
        elem: Elem,
        /// Destination.
        dst: Reg,
        /// String pointer.
        a: Reg,
    },
    /// Packed BCD: decode (`encode` false) or encode a value of type `elem`.
    Bcd {
        /// Encode rather than decode.
        encode: bool,
        /// Argument type.
        from: Elem,
        /// Result type.
        to: Elem,
        /// Destination.
        dst: Reg,
        /// Operand.
        a: Reg,
    },
}

/// The instructions of the standard functions, which the VM's outer loop hands to its
/// built-ins (`vm/builtins.rs`). With [`outer_loop_ops`], the one place that says which
/// loop runs an instruction: the inner loop (`vm/fast.rs`) stops at these, the outer loop
/// (`vm/machine.rs`) dispatches them, the verifier (`verify.rs`) leaves their operands to
/// the outer loop's checks. A pattern: `builtin_ops!() => …`.
macro_rules! builtin_ops {
    () => {
        $crate::program::op::Op::StrCmp { .. }
            | $crate::program::op::Op::Str { .. }
            | $crate::program::op::Op::Math { .. }
            | $crate::program::op::Op::Select { .. }
            | $crate::program::op::Op::MinMax { .. }
            | $crate::program::op::Op::Limit { .. }
            | $crate::program::op::Op::Mux { .. }
            | $crate::program::op::Op::ToStr { .. }
            | $crate::program::op::Op::FromStr { .. }
            | $crate::program::op::Op::Bcd { .. }
    };
}
pub(crate) use builtin_ops;

/// Every instruction the VM's outer loop runs (the generic operators, conversions, FOR
/// loops over any type, CASE, calls, frames, copies, and [`builtin_ops`]); every other
/// instruction is the inner loop's (`vm/fast.rs`), which the compiler checks: the inner
/// loop matches its own instructions and `outer_loop_ops!()`, with no catch-all, so a new
/// instruction must be given to one loop here or there.
macro_rules! outer_loop_ops {
    () => {
        $crate::program::op::Op::Bin { .. }
            | $crate::program::op::Op::Cmp { .. }
            | $crate::program::op::Op::ScaleTime { .. }
            | $crate::program::op::Op::Conv { .. }
            | $crate::program::op::Op::Trunc { .. }
            | $crate::program::op::Op::SetBit { .. }
            | $crate::program::op::Op::GetSlice { .. }
            | $crate::program::op::Op::SetSlice { .. }
            | $crate::program::op::Op::Sys { .. }
            | $crate::program::op::Op::ForStart { .. }
            | $crate::program::op::Op::ForTest { .. }
            | $crate::program::op::Op::ForNext { .. }
            | $crate::program::op::Op::ForStep { .. }
            | $crate::program::op::Op::Case { .. }
            | $crate::program::op::Op::CallFb { .. }
            | $crate::program::op::Op::CallFn { .. }
            | $crate::program::op::Op::InitFrame { .. }
            | $crate::program::op::Op::InitTemps { .. }
            | $crate::program::op::Op::Ret
            | $crate::program::op::Op::Halt { .. }
            | $crate::program::op::Op::Copy { .. }
            | $crate::program::op::Op::StrCopy { .. }
            | $crate::program::op::Op::Deref { .. }
            | $crate::program::op::builtin_ops!()
    };
}
pub(crate) use outer_loop_ops;
