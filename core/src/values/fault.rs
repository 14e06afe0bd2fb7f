//! Runtime faults: why the PLC stopped. A typed value carried in results, never a panic.

use std::fmt;

/// A runtime fault. The simulator stops in FAULT with this and the source location.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Fault {
    /// Integer (or TIME) division by zero.
    DivisionByZero,
    /// An array index outside the declared bounds.
    IndexOutOfRange {
        /// The index that was used.
        index: i64,
        /// The lowest allowed index.
        low: i64,
        /// The highest allowed index.
        high: i64,
    },
    /// A string position or length outside the string.
    StringPosition {
        /// The function that failed (`MID`, `LEFT`, …).
        function: &'static str,
        /// The position or length asked for.
        position: i64,
        /// The string's length.
        length: usize,
    },
    /// A value stored into a variable outside the subrange it is declared with
    /// (`level : INT(0..100)`).
    SubrangeViolation {
        /// The value stored.
        value: i64,
        /// The subrange's lower limit.
        low: i64,
        /// Its upper limit.
        high: i64,
    },
    /// A FOR loop whose step evaluated to zero.
    ForStepZero,
    /// `r^` (a read, a write, a member or an element through it) with `r` NULL.
    NullReference,
    /// The scan ran more instructions than the watchdog allows.
    Watchdog {
        /// The instruction budget per scan.
        budget: u64,
    },
    /// Calls nested deeper than the VM allows.
    CallDepth,
    /// A text that does not convert to the requested type (`STRING_TO_INT('abc')`).
    BadConversion {
        /// The text.
        text: String,
        /// The target type name.
        target: &'static str,
    },
    /// An invariant of the compiled code did not hold (a bug in the compiler, reported
    /// as a fault instead of a crash).
    Internal(&'static str),
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fault::DivisionByZero => f.write_str("division by zero"),
            Fault::IndexOutOfRange { index, low, high } => {
                write!(f, "array index {index} is out of range {low}..{high}")
            }
            Fault::StringPosition { function, position, length } => write!(
                f,
                "{function}: position or length {position} is outside the string of length {length}"
            ),
            Fault::SubrangeViolation { value, low, high } => {
                write!(f, "{value} is outside the subrange {low}..{high} of the variable it is stored in")
            }
            Fault::NullReference => f.write_str("dereference of a NULL reference"),
            Fault::ForStepZero => f.write_str("FOR loop step is zero: the loop would never end"),
            Fault::Watchdog { budget } => write!(
                f,
                "watchdog: the scan did more than {budget} units of work (an instruction, 8 array cells or 8 string bytes each): an endless loop?"
            ),
            Fault::CallDepth => f.write_str("calls are nested too deeply"),
            Fault::BadConversion { text, target } => {
                write!(f, "cannot convert '{text}' to {target}")
            }
            Fault::Internal(what) => write!(f, "internal error in the VM: {what}"),
        }
    }
}

impl std::error::Error for Fault {}
