//! The elementary IEC types: their names, sizes, ranges and families.

/// An elementary IEC type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Elem {
    /// BOOL
    Bool,
    /// SINT (8-bit signed)
    SInt,
    /// INT (16-bit signed)
    Int,
    /// DINT (32-bit signed)
    DInt,
    /// LINT (64-bit signed)
    LInt,
    /// USINT
    USInt,
    /// UINT
    UInt,
    /// UDINT
    UDInt,
    /// ULINT
    ULInt,
    /// BYTE
    Byte,
    /// WORD
    Word,
    /// DWORD
    DWord,
    /// LWORD
    LWord,
    /// REAL (32-bit float)
    Real,
    /// LREAL (64-bit float)
    LReal,
    /// TIME (and LTIME): signed nanoseconds
    Time,
    /// DATE: microseconds since 1970-01-01 (whole days), 0001-01-01 to 9999-12-31 and
    /// beyond
    Date,
    /// TIME_OF_DAY: nanoseconds since midnight
    Tod,
    /// DATE_AND_TIME: microseconds since 1970-01-01
    Dt,
}

impl Elem {
    /// Looks up an elementary type by (upper-case) name.
    pub fn from_name(upper: &str) -> Option<Elem> {
        Some(match upper {
            "BOOL" => Elem::Bool,
            "SINT" => Elem::SInt,
            "INT" => Elem::Int,
            "DINT" => Elem::DInt,
            "LINT" => Elem::LInt,
            "USINT" => Elem::USInt,
            "UINT" => Elem::UInt,
            "UDINT" => Elem::UDInt,
            "ULINT" => Elem::ULInt,
            "BYTE" => Elem::Byte,
            "WORD" => Elem::Word,
            "DWORD" => Elem::DWord,
            "LWORD" => Elem::LWord,
            "REAL" => Elem::Real,
            "LREAL" => Elem::LReal,
            "TIME" | "LTIME" => Elem::Time,
            "DATE" | "LDATE" => Elem::Date,
            "TIME_OF_DAY" | "TOD" | "LTOD" | "LTIME_OF_DAY" => Elem::Tod,
            "DATE_AND_TIME" | "DT" | "LDT" | "LDATE_AND_TIME" => Elem::Dt,
            _ => return None,
        })
    }

    /// Every elementary type, in the order of the enumeration.
    pub const ALL: [Elem; 19] = [
        Elem::Bool,
        Elem::SInt,
        Elem::Int,
        Elem::DInt,
        Elem::LInt,
        Elem::USInt,
        Elem::UInt,
        Elem::UDInt,
        Elem::ULInt,
        Elem::Byte,
        Elem::Word,
        Elem::DWord,
        Elem::LWord,
        Elem::Real,
        Elem::LReal,
        Elem::Time,
        Elem::Date,
        Elem::Tod,
        Elem::Dt,
    ];

    /// The canonical name.
    pub fn name(self) -> &'static str {
        match self {
            Elem::Bool => "BOOL",
            Elem::SInt => "SINT",
            Elem::Int => "INT",
            Elem::DInt => "DINT",
            Elem::LInt => "LINT",
            Elem::USInt => "USINT",
            Elem::UInt => "UINT",
            Elem::UDInt => "UDINT",
            Elem::ULInt => "ULINT",
            Elem::Byte => "BYTE",
            Elem::Word => "WORD",
            Elem::DWord => "DWORD",
            Elem::LWord => "LWORD",
            Elem::Real => "REAL",
            Elem::LReal => "LREAL",
            Elem::Time => "TIME",
            Elem::Date => "DATE",
            Elem::Tod => "TIME_OF_DAY",
            Elem::Dt => "DATE_AND_TIME",
        }
    }

    /// Width in bits of integer and bit-string types (BOOL is 1).
    pub fn bits(self) -> u32 {
        match self {
            Elem::Bool => 1,
            Elem::SInt | Elem::USInt | Elem::Byte => 8,
            Elem::Int | Elem::UInt | Elem::Word => 16,
            Elem::DInt | Elem::UDInt | Elem::DWord | Elem::Real => 32,
            _ => 64,
        }
    }

    /// A signed integer type.
    pub fn is_signed_int(self) -> bool {
        matches!(self, Elem::SInt | Elem::Int | Elem::DInt | Elem::LInt)
    }

    /// An unsigned integer type.
    pub fn is_unsigned_int(self) -> bool {
        matches!(self, Elem::USInt | Elem::UInt | Elem::UDInt | Elem::ULInt)
    }

    /// Any integer type (ANY_INT).
    pub fn is_int(self) -> bool {
        self.is_signed_int() || self.is_unsigned_int()
    }

    /// A bit string type other than BOOL (BYTE, WORD, DWORD, LWORD).
    pub fn is_bitstring(self) -> bool {
        matches!(self, Elem::Byte | Elem::Word | Elem::DWord | Elem::LWord)
    }

    /// REAL or LREAL.
    pub fn is_real(self) -> bool {
        matches!(self, Elem::Real | Elem::LReal)
    }

    /// ANY_NUM.
    pub fn is_num(self) -> bool {
        self.is_int() || self.is_real()
    }

    /// Integers and bit strings: the types held as integers that wrap.
    pub fn is_integral(self) -> bool {
        self.is_int() || self.is_bitstring()
    }

    /// Values held zero-extended (unsigned integers and bit strings).
    pub fn is_zero_extended(self) -> bool {
        self.is_unsigned_int() || self.is_bitstring() || self == Elem::Bool
    }

    /// TIME, DATE, TOD, DT.
    pub fn is_temporal(self) -> bool {
        matches!(self, Elem::Time | Elem::Date | Elem::Tod | Elem::Dt)
    }

    /// The smallest and largest value of an integral type, as i128.
    pub fn int_range(self) -> (i128, i128) {
        let bits = self.bits();
        if self.is_signed_int() {
            (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
        } else if self == Elem::Bool {
            (0, 1)
        } else {
            (0, (1i128 << bits) - 1)
        }
    }
}
