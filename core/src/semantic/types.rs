//! The type system after name resolution: elementary types, and ids for the derived types
//! kept in a [`TypeTable`].

use std::fmt;

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
    /// DATE: nanoseconds since 1970-01-01 (whole days)
    Date,
    /// TIME_OF_DAY: nanoseconds since midnight
    Tod,
    /// DATE_AND_TIME: nanoseconds since 1970-01-01
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

/// Index of an enumeration in [`TypeTable::enums`].
pub type EnumId = u32;
/// Index of an array type in [`TypeTable::arrays`].
pub type ArrayId = u32;
/// Index of a struct type in [`TypeTable::structs`].
pub type StructId = u32;
/// Index of a POU in the checked program.
pub type PouId = u32;

/// A resolved type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Type {
    /// An elementary type.
    Elem(Elem),
    /// STRING[len] or WSTRING[len].
    Str {
        /// WSTRING.
        wide: bool,
        /// Maximum length in characters.
        len: u32,
    },
    /// A user enumeration.
    Enum(EnumId),
    /// An array type.
    Array(ArrayId),
    /// A struct type.
    Struct(StructId),
    /// An instance of a function block.
    Fb(PouId),
    /// No value (a function without result).
    Void,
}

impl Type {
    /// Shorthand for BOOL.
    pub const BOOL: Type = Type::Elem(Elem::Bool);

    /// The elementary type, if this is one.
    pub fn elem(self) -> Option<Elem> {
        match self {
            Type::Elem(e) => Some(e),
            _ => None,
        }
    }

    /// True for BOOL.
    pub fn is_bool(self) -> bool {
        self == Type::BOOL
    }

    /// True for STRING/WSTRING.
    pub fn is_string(self) -> bool {
        matches!(self, Type::Str { .. })
    }

    /// True for values that live in one memory cell (everything but strings and aggregates).
    pub fn is_scalar(self) -> bool {
        matches!(self, Type::Elem(_) | Type::Enum(_))
    }
}

/// One enumeration type.
#[derive(Debug, Clone, PartialEq)]
pub struct EnumDef {
    /// The type name as written (or a generated name for an inline enum).
    pub name: String,
    /// Enumerators in declaration order: (name as written, value).
    pub values: Vec<(String, i64)>,
}

/// One array type.
#[derive(Debug, Clone, PartialEq)]
pub struct ArrayDef {
    /// `(low, high)` per dimension.
    pub dims: Vec<(i64, i64)>,
    /// The element type.
    pub element: Type,
    /// The element's subrange, if it has one.
    pub element_range: Option<(i64, i64)>,
    /// The initial value of every element declared on the element's type, if any.
    pub element_init: Option<super::ir::InitValue>,
}

impl ArrayDef {
    /// Total number of elements.
    pub fn len(&self) -> u64 {
        self.dims.iter().map(|(l, h)| (h - l + 1).max(0) as u64).product()
    }

    /// True when the array has no elements.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One field of a struct.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldDef {
    /// Name as written.
    pub name: String,
    /// Its type.
    pub ty: Type,
    /// Its initial value (declared on the field, or on the field's type).
    pub init: Option<super::ir::InitValue>,
    /// Its subrange, if any.
    pub range: Option<(i64, i64)>,
}

/// One struct type.
#[derive(Debug, Clone, PartialEq)]
pub struct StructDef {
    /// The type name as written.
    pub name: String,
    /// Fields in declaration order.
    pub fields: Vec<FieldDef>,
}

/// All derived types of a checked program.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TypeTable {
    /// Enumerations.
    pub enums: Vec<EnumDef>,
    /// Array types.
    pub arrays: Vec<ArrayDef>,
    /// Struct types.
    pub structs: Vec<StructDef>,
    /// Names of POUs (for naming FB types in messages).
    pub pou_names: Vec<String>,
}

impl TypeTable {
    /// Adds an array type (re-using an identical one) and returns its type.
    pub fn array(&mut self, def: ArrayDef) -> Type {
        if let Some(i) = self.arrays.iter().position(|a| *a == def) {
            return Type::Array(i as ArrayId);
        }
        self.arrays.push(def);
        Type::Array(self.arrays.len() as ArrayId - 1)
    }

    /// A readable name of `ty` for messages.
    pub fn display(&self, ty: Type) -> TypeName<'_> {
        TypeName { table: self, ty }
    }
}

/// Displays a type by name (see [`TypeTable::display`]).
pub struct TypeName<'a> {
    table: &'a TypeTable,
    ty: Type,
}

impl fmt::Display for TypeName<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let t = self.table;
        match self.ty {
            Type::Elem(e) => f.write_str(e.name()),
            Type::Str { wide, len } => {
                let kw = if wide { "WSTRING" } else { "STRING" };
                write!(f, "{kw}[{len}]")
            }
            Type::Enum(i) => f.write_str(t.enums.get(i as usize).map_or("?", |e| &e.name)),
            Type::Struct(i) => f.write_str(t.structs.get(i as usize).map_or("?", |s| &s.name)),
            Type::Fb(i) => f.write_str(t.pou_names.get(i as usize).map_or("?", |s| s)),
            Type::Array(i) => match t.arrays.get(i as usize) {
                Some(a) => {
                    f.write_str("ARRAY[")?;
                    for (k, (l, h)) in a.dims.iter().enumerate() {
                        if k > 0 {
                            f.write_str(", ")?;
                        }
                        write!(f, "{l}..{h}")?;
                    }
                    write!(f, "] OF {}", t.display(a.element))
                }
                None => f.write_str("ARRAY"),
            },
            Type::Void => f.write_str("nothing"),
        }
    }
}
