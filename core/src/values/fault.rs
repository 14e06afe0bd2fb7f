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
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for Fault {}

impl Fault {
    /// The fault as a message (`fault.*` of the message catalogue), to be shown in the
    /// language asked for; its English text is the fault's `Display`.
    pub fn message(&self) -> crate::diagnostics::Message {
        self.said().message
    }

    /// The fault's message with its English text.
    fn said(&self) -> crate::diagnostics::Said {
        match self {
            Fault::DivisionByZero => crate::msg!(FaultDivisionByZero),
            Fault::IndexOutOfRange { index, low, high } => {
                crate::msg!(FaultIndexOutOfRange, index = index, low = low, high = high)
            }
            Fault::StringPosition { function, position, length } => crate::msg!(
                FaultStringPosition,
                function = function,
                position = position,
                length = length
            ),
            Fault::SubrangeViolation { value, low, high } => {
                crate::msg!(FaultSubrangeViolation, value = value, low = low, high = high)
            }
            Fault::NullReference => crate::msg!(FaultNullReference),
            Fault::ForStepZero => crate::msg!(FaultForStepZero),
            Fault::Watchdog { budget } => crate::msg!(FaultWatchdog, budget = budget),
            Fault::CallDepth => crate::msg!(FaultCallDepth),
            Fault::BadConversion { text, target } => {
                crate::msg!(FaultBadConversion, text = text, target = target)
            }
            Fault::Internal(what) => crate::msg!(FaultInternal, what = what),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Fault;
    use crate::i18n::Lang;

    #[test]
    fn every_fault_says_in_english_what_it_displays_and_is_translated() {
        let all = [
            Fault::DivisionByZero,
            Fault::IndexOutOfRange { index: 6, low: 1, high: 5 },
            Fault::StringPosition { function: "MID", position: 9, length: 3 },
            Fault::SubrangeViolation { value: 101, low: 0, high: 100 },
            Fault::ForStepZero,
            Fault::NullReference,
            Fault::Watchdog { budget: 1_000_000 },
            Fault::CallDepth,
            Fault::BadConversion { text: "abc".into(), target: "INT" },
            Fault::Internal("no frame"),
        ];
        for fault in &all {
            let message = fault.message();
            assert_eq!(message.render(Lang::En), fault.to_string(), "{fault:?}");
            for lang in [Lang::Pl, Lang::Cs] {
                assert_ne!(message.render(lang), fault.to_string(), "{fault:?} in {lang}");
            }
        }
        assert_eq!(
            Fault::IndexOutOfRange { index: 6, low: 1, high: 5 }.message().render(Lang::Pl),
            "indeks tablicy 6 jest poza zakresem 1..5"
        );
    }
}
