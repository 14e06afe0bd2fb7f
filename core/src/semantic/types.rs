//! The type system after name resolution: elementary types, and ids for the derived types
//! kept in a [`TypeTable`].

use std::fmt;

pub use crate::values::Elem;

/// Index of an enumeration in [`TypeTable::enums`].
pub type EnumId = u32;
/// Index of an array type in [`TypeTable::arrays`].
pub type ArrayId = u32;
/// Index of a struct type in [`TypeTable::structs`].
pub type StructId = u32;
/// Index of a POU in the checked program.
pub type PouId = u32;
/// Index of a reference type in [`TypeTable::refs`]; [`NULL_REF`] is the type of `NULL`.
pub type RefId = u32;
/// The [`RefId`] of `NULL`'s own type, which converts to every reference type.
pub const NULL_REF: RefId = u32::MAX;

/// A resolved type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Type {
    /// An elementary type.
    Elem(Elem),
    /// `STRING[len]` or `WSTRING[len]`.
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
    /// `REF_TO T` (one cell: the referenced cell's address plus one, 0 for NULL).
    Ref(RefId),
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
        matches!(self, Type::Elem(_) | Type::Enum(_) | Type::Ref(_))
    }

    /// True for `REF_TO …` types and `NULL`'s type.
    pub fn is_ref(self) -> bool {
        matches!(self, Type::Ref(_))
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
    pub element_init: Option<InitValue>,
}

/// The number of indices in `l..=h`, computed without overflow (0 when `h < l`; an
/// extent beyond `u64` saturates, and the checker refuses such arrays).
pub fn dim_len(l: i64, h: i64) -> u64 {
    let n = i128::from(h) - i128::from(l) + 1;
    u64::try_from(n.max(0)).unwrap_or(u64::MAX)
}

impl ArrayDef {
    /// Total number of elements.
    pub fn len(&self) -> u64 {
        self.dims.iter().map(|&(l, h)| dim_len(l, h)).fold(1u64, u64::saturating_mul)
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
    pub init: Option<InitValue>,
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
    /// The referenced type of each reference type (`REF_TO T`).
    pub refs: Vec<Type>,
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

    /// Adds the reference type `REF_TO target` (re-using an identical one) and returns it.
    pub fn reference(&mut self, target: Type) -> Type {
        if let Some(i) = self.refs.iter().position(|t| *t == target) {
            return Type::Ref(i as RefId);
        }
        self.refs.push(target);
        Type::Ref(self.refs.len() as RefId - 1)
    }

    /// The type a reference type points to (`None` for `NULL`'s type and non-references).
    pub fn ref_target(&self, ty: Type) -> Option<Type> {
        match ty {
            Type::Ref(r) => self.refs.get(r as usize).copied(),
            _ => None,
        }
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
            Type::Ref(NULL_REF) => f.write_str("NULL"),
            Type::Ref(r) => match t.refs.get(r as usize) {
                Some(target) => write!(f, "REF_TO {}", t.display(*target)),
                None => f.write_str("REF_TO ?"),
            },
            Type::Void => f.write_str("nothing"),
        }
    }
}

/// A compile-time initial value, already converted to the variable's type.
#[derive(Debug, Clone, PartialEq)]
pub enum InitValue {
    /// One cell's normalised bits (encoding in `crate::values::arith`).
    Scalar(u64),
    /// A string's bytes.
    Str(Vec<u8>),
    /// Array elements in memory order; missing trailing elements take their default.
    Array(Vec<InitValue>),
    /// Struct fields by index; `None` keeps the field's default.
    Struct(Vec<Option<InitValue>>),
    /// A reference's initial value `REF(x)`: where `x` is, written as an address when the
    /// program is laid out (`docs/references.md`).
    Ref(RefInit),
}

/// The variable a reference's initial value points to: a variable of the POU whose
/// declaration holds the value, or a global; then fields, members and constant elements.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RefInit {
    /// The variable the path starts at.
    pub root: RefRoot,
    /// The fields, members and elements from there to the referenced variable.
    pub steps: Vec<RefStep>,
}

/// Where a reference's initial value starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RefRoot {
    /// Variable `.1` of POU `.0`, in the instance (or static frame) of `.0` that holds the
    /// declaration: the innermost instance of `.0` among those being initialised.
    Own(PouId, u32),
    /// Global variable `index`.
    Global(u32),
    /// Not resolved yet: the checker's pending entry `index` (never in a checked program).
    Pending(u32),
}

/// One step of a [`RefInit`] path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RefStep {
    /// Field `.1` of struct `.0`.
    Field(StructId, u32),
    /// Variable `.1` of an instance of function block (or PROGRAM) `.0`.
    Member(PouId, u32),
    /// Element `.1` (counted from 0, last dimension fastest) of an array of type `.0`.
    Element(ArrayId, u64),
}
