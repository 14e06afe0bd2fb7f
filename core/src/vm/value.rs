//! Values at the boundary of the VM: what the simulator, the variables table, `--set` and
//! the grader read and write. Never used inside a scan.

use std::fmt;

use crate::program::locate::element_size;
use crate::program::memory::{read_str_into, string_header, write_str, Memory};
use crate::program::{Executable, Slot};
use crate::semantic::ir::InitValue;
use crate::semantic::types::{dim_len, Elem, Type, TypeTable};
use crate::syntax::VarSection;
use crate::values::arith;

/// A value read from (or to be written to) memory.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// BOOL
    Bool(bool),
    /// Any integer or bit string, with its type.
    Int(i128, Elem),
    /// REAL or LREAL (for REAL, a value already of f32 precision).
    Real(f64, Elem),
    /// A STRING's bytes.
    Str(Vec<u8>),
    /// A WSTRING's UTF-16 code units.
    WStr(Vec<u16>),
    /// TIME in nanoseconds.
    Time(i64),
    /// DATE in microseconds since 1970-01-01 (a whole number of days).
    Date(i64),
    /// TIME_OF_DAY in nanoseconds since midnight.
    Tod(i64),
    /// DATE_AND_TIME in microseconds since 1970-01-01.
    Dt(i64),
    /// An enumeration value, with the name of its enumerator (`None` for a value that
    /// has no name).
    Enum {
        /// The value.
        value: i64,
        /// The enumerator's name.
        name: Option<String>,
    },
    /// Array elements (one nested array per dimension).
    Array(Vec<Value>),
    /// Struct fields or FB instance variables, in declaration order.
    Struct(Vec<(String, Value)>),
    /// A reference (`REF_TO`): the path of the variable it points to, `None` for NULL.
    Ref(Option<String>),
}

impl Value {
    /// Decodes one cell of scalar type `ty` (enumerator names from `types`).
    pub fn from_bits(ty: Type, bits: u64, types: &TypeTable) -> Value {
        match ty {
            Type::Enum(e) => {
                let value = bits as i64;
                let name = types
                    .enums
                    .get(e as usize)
                    .and_then(|d| d.values.iter().find(|x| x.1 == value))
                    .map(|x| x.0.clone());
                Value::Enum { value, name }
            }
            Type::Elem(e) => match e {
                Elem::Bool => Value::Bool(bits != 0),
                Elem::Real | Elem::LReal => Value::Real(f64::from_bits(bits), e),
                Elem::Time => Value::Time(bits as i64),
                Elem::Date => Value::Date(bits as i64),
                Elem::Tod => Value::Tod(bits as i64),
                Elem::Dt => Value::Dt(bits as i64),
                _ => Value::Int(arith::to_i128(e, bits), e),
            },
            // Without the executable only the address can be shown.
            Type::Ref(_) => Value::Ref(bits.checked_sub(1).map(|a| format!("@{a}"))),
            _ => Value::Int(0, Elem::LInt),
        }
    }
}

/// Reads the value at `slot`. Cells outside memory read as 0 (slots from
/// [`Executable::locate`] are always inside).
pub fn read(mem: &Memory, exe: &Executable, slot: &Slot) -> Value {
    let cell = |a: u32| mem.cells.get(a as usize).copied().unwrap_or(0);
    if let Some((n, _)) = slot.bit {
        // A located variable wider than a bit: its raw bits in the process image.
        if let Some(e) = slot.ty.elem().filter(|&e| e != Elem::Bool) {
            let bits = arith::get_slice(cell(slot.addr), n, e);
            return Value::from_bits(slot.ty, bits, &exe.type_table);
        }
        return Value::Bool(arith::get_bit(cell(slot.addr), n) != 0);
    }
    read_at(mem, exe, slot.addr, slot.ty)
}

/// Reads the value of type `ty` at `addr`: a single cell here, anything larger out of line
/// ([`read_composite`]), so that the plants and panels, which read single values on every
/// scan, run (and V8 optimises) only the small part.
fn read_at(mem: &Memory, exe: &Executable, addr: u32, ty: Type) -> Value {
    match ty {
        Type::Elem(_) | Type::Enum(_) => Value::from_bits(
            ty,
            mem.cells.get(addr as usize).copied().unwrap_or(0),
            &exe.type_table,
        ),
        _ => read_composite(mem, exe, addr, ty),
    }
}

/// [`read_at`] for strings, arrays, structures, function block instances and references.
#[inline(never)]
fn read_composite(mem: &Memory, exe: &Executable, addr: u32, ty: Type) -> Value {
    let cell = |a: u32| mem.cells.get(a as usize).copied().unwrap_or(0);
    match ty {
        Type::Elem(_) | Type::Enum(_) => read_at(mem, exe, addr, ty),
        Type::Str { wide, .. } => {
            let mut b = Vec::new();
            let _ = read_str_into(&mem.cells, addr as usize, &mut b);
            if wide {
                Value::WStr(b.chunks_exact(2).map(|c| u16::from_le_bytes([c[0], c[1]])).collect())
            } else {
                Value::Str(b)
            }
        }
        Type::Array(a) => {
            let Some(def) = exe.type_table.arrays.get(a as usize) else {
                return Value::Array(Vec::new());
            };
            let es = element_size(exe, def.element).unwrap_or(1);
            let dims: Vec<u64> = def.dims.iter().map(|&(l, h)| dim_len(l, h)).collect();
            read_dims(mem, exe, addr, def.element, es, &dims)
        }
        Type::Struct(s) => {
            let (Some(def), Some(offs)) =
                (exe.type_table.structs.get(s as usize), exe.lay.cached_struct(s))
            else {
                return Value::Struct(Vec::new());
            };
            let fields = def
                .fields
                .iter()
                .zip(offs)
                .map(|(f, off)| (f.name.clone(), read_at(mem, exe, addr + off, f.ty)))
                .collect();
            Value::Struct(fields)
        }
        Type::Fb(q) => {
            let Some(code) = exe.pous.get(q as usize) else {
                return Value::Struct(Vec::new());
            };
            let fields = code
                .vars
                .iter()
                .zip(&code.offsets)
                // VAR_EXTERNAL members are the globals, shown as such.
                .filter(|(v, _)| !matches!(v.section, VarSection::InOut | VarSection::External))
                .map(|(v, off)| (v.name.clone(), read_at(mem, exe, addr + off, v.ty)))
                .collect();
            Value::Struct(fields)
        }
        Type::Ref(_) => {
            let target = exe.type_table.ref_target(ty).unwrap_or(Type::Void);
            Value::Ref(cell(addr).checked_sub(1).map(|a| {
                u32::try_from(a)
                    .ok()
                    .and_then(|a| crate::program::refpath::path_of(exe, a, target))
                    .unwrap_or_else(|| format!("@{a}"))
            }))
        }
        Type::Void => Value::Struct(Vec::new()),
    }
}

fn read_dims(
    mem: &Memory,
    exe: &Executable,
    addr: u32,
    elem: Type,
    es: u32,
    dims: &[u64],
) -> Value {
    match dims.split_first() {
        None => read_at(mem, exe, addr, elem),
        Some((&n, rest)) => {
            let inner: u64 = rest.iter().product::<u64>() * u64::from(es);
            Value::Array(
                (0..n)
                    .map(|k| read_dims(mem, exe, addr + (k * inner) as u32, elem, es, rest))
                    .collect(),
            )
        }
    }
}

/// Why a value could not be written.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum WriteError {
    /// The value does not fit the variable's type.
    TypeMismatch {
        /// The variable's type.
        expected: String,
    },
    /// An integer outside the range of the variable's type.
    OutOfRange {
        /// The variable's type.
        expected: String,
    },
    /// The slot is outside memory.
    BadAddress,
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WriteError::TypeMismatch { expected } => {
                write!(f, "expected a value of type {expected}")
            }
            WriteError::OutOfRange { expected } => {
                write!(f, "the value is out of the range of {expected}")
            }
            WriteError::BadAddress => f.write_str("the variable is outside memory"),
        }
    }
}

impl std::error::Error for WriteError {}

/// Writes `value` to `slot` (for `--set`, forcing and the variables table).
pub fn write(
    mem: &mut Memory,
    exe: &Executable,
    slot: &Slot,
    value: &Value,
) -> Result<(), WriteError> {
    let mismatch =
        || WriteError::TypeMismatch { expected: exe.type_table.display(slot.ty).to_string() };
    if let (Some((n, _)), Some(e)) = (slot.bit, slot.ty.elem().filter(|&e| e != Elem::Bool)) {
        // A located variable wider than a bit: its raw bits in the process image.
        let mut one = Memory { cells: vec![0] };
        write_at(&mut one, exe, 0, slot.ty, value)?;
        let cur = mem.get(slot.addr as usize).map_err(|_| WriteError::BadAddress)?;
        return mem
            .set(slot.addr as usize, arith::set_slice(cur, n, e, one.cells[0]))
            .map_err(|_| WriteError::BadAddress);
    }
    if let Some((n, e)) = slot.bit {
        let b = match value {
            Value::Bool(b) => *b,
            Value::Int(v @ (0 | 1), _) => *v == 1,
            _ => return Err(mismatch()),
        };
        let cur = mem.get(slot.addr as usize).map_err(|_| WriteError::BadAddress)?;
        return mem
            .set(slot.addr as usize, arith::set_bit(e, cur, n, b))
            .map_err(|_| WriteError::BadAddress);
    }
    write_at(mem, exe, slot.addr, slot.ty, value)
}

/// Writes `value` as a value of type `ty` at `addr`: a single cell here, anything larger
/// out of line ([`write_composite`]), as [`read_at`] does.
fn write_at(
    mem: &mut Memory,
    exe: &Executable,
    addr: u32,
    ty: Type,
    value: &Value,
) -> Result<(), WriteError> {
    match ty {
        Type::Elem(_) | Type::Enum(_) | Type::Ref(_) => {
            let bits = cell_bits(exe, ty, value)?;
            mem.set(addr as usize, bits).map_err(|_| WriteError::BadAddress)
        }
        _ => write_composite(mem, exe, addr, ty, value),
    }
}

/// The bits of the cell that holds `value` as a value of the single-cell type `ty`.
fn cell_bits(exe: &Executable, ty: Type, value: &Value) -> Result<u64, WriteError> {
    let expected = || exe.type_table.display(ty).to_string();
    Ok(match (ty, value) {
        (Type::Elem(Elem::Bool), Value::Bool(b)) => u64::from(*b),
        (Type::Elem(e), Value::Int(value, _)) if e.is_integral() || e == Elem::Bool => {
            let (lo, hi) = e.int_range();
            if *value < lo || *value > hi {
                return Err(WriteError::OutOfRange { expected: expected() });
            }
            arith::norm(e, *value)
        }
        (Type::Elem(e), Value::Int(value, _)) if e.is_real() => arith::from_f64(e, *value as f64),
        (Type::Elem(e), Value::Real(value, _)) if e.is_real() => arith::from_f64(e, *value),
        (Type::Elem(Elem::Time), Value::Time(t))
        | (Type::Elem(Elem::Date), Value::Date(t))
        | (Type::Elem(Elem::Tod), Value::Tod(t))
        | (Type::Elem(Elem::Dt), Value::Dt(t)) => *t as u64,
        (Type::Enum(_), Value::Enum { value, .. }) => *value as u64,
        // Only NULL: an address typed in could point at a cell of another type.
        (Type::Ref(_), Value::Ref(None)) => 0,
        (Type::Enum(_), Value::Int(value, _)) => *value as i64 as u64,
        _ => return Err(WriteError::TypeMismatch { expected: expected() }),
    })
}

/// [`write_at`] for strings, arrays and structures.
#[inline(never)]
fn write_composite(
    mem: &mut Memory,
    exe: &Executable,
    addr: u32,
    ty: Type,
    value: &Value,
) -> Result<(), WriteError> {
    let expected = || exe.type_table.display(ty).to_string();
    let mismatch = || WriteError::TypeMismatch { expected: expected() };
    match (ty, value) {
        (Type::Str { wide: false, .. }, Value::Str(b)) => {
            write_str(&mut mem.cells, addr as usize, b, 1).map_err(|_| WriteError::BadAddress)
        }
        (Type::Str { wide: true, .. }, Value::WStr(u)) => {
            let b: Vec<u8> = u.iter().flat_map(|c| c.to_le_bytes()).collect();
            write_str(&mut mem.cells, addr as usize, &b, 2).map_err(|_| WriteError::BadAddress)
        }
        (Type::Array(a), Value::Array(items)) => {
            let def = exe.type_table.arrays.get(a as usize).ok_or(WriteError::BadAddress)?;
            let es = element_size(exe, def.element).ok_or(WriteError::BadAddress)?;
            let mut flat = Vec::new();
            flatten(items, &mut flat);
            if flat.len() as u64 != def.len() {
                return Err(mismatch());
            }
            for (k, v) in flat.into_iter().enumerate() {
                write_at(mem, exe, addr + k as u32 * es, def.element, v)?;
            }
            Ok(())
        }
        (Type::Struct(s), Value::Struct(fields)) => {
            let def = exe.type_table.structs.get(s as usize).ok_or(WriteError::BadAddress)?;
            let offs = exe.lay.cached_struct(s).ok_or(WriteError::BadAddress)?;
            for (name, v) in fields {
                let i = def
                    .fields
                    .iter()
                    .position(|f| f.name.eq_ignore_ascii_case(name))
                    .ok_or_else(mismatch)?;
                write_at(mem, exe, addr + offs[i], def.fields[i].ty, v)?;
            }
            Ok(())
        }
        _ => Err(mismatch()),
    }
}

fn flatten<'a>(items: &'a [Value], out: &mut Vec<&'a Value>) {
    for v in items {
        match v {
            Value::Array(inner) => flatten(inner, out),
            other => out.push(other),
        }
    }
}

/// Writes a checked constant (from `semantic::parse_value`) to `slot`.
pub fn write_init(
    mem: &mut Memory,
    exe: &Executable,
    slot: &Slot,
    init: &InitValue,
) -> Result<(), WriteError> {
    if let (Some((n, e)), InitValue::Scalar(b)) = (slot.bit, init) {
        let cur = mem.get(slot.addr as usize).map_err(|_| WriteError::BadAddress)?;
        let new = arith::put_at_bit(e, cur, n, slot.ty.elem().unwrap_or(Elem::Bool), *b);
        return mem.set(slot.addr as usize, new).map_err(|_| WriteError::BadAddress);
    }
    init_at(mem, exe, slot.addr, slot.ty, init)
}

fn init_at(
    mem: &mut Memory,
    exe: &Executable,
    addr: u32,
    ty: Type,
    init: &InitValue,
) -> Result<(), WriteError> {
    let mismatch = || WriteError::TypeMismatch { expected: exe.type_table.display(ty).to_string() };
    match (ty, init) {
        (Type::Elem(_) | Type::Enum(_), InitValue::Scalar(b))
        | (Type::Ref(_), InitValue::Scalar(b @ 0)) => {
            mem.set(addr as usize, *b).map_err(|_| WriteError::BadAddress)
        }
        (Type::Str { wide, len }, InitValue::Str(b)) => {
            let cap = len * if wide { 2 } else { 1 };
            if mem.get(addr as usize).is_err() {
                return Err(WriteError::BadAddress);
            }
            let _ = mem.set(addr as usize, string_header(cap, 0));
            write_str(&mut mem.cells, addr as usize, b, if wide { 2 } else { 1 })
                .map_err(|_| WriteError::BadAddress)
        }
        (Type::Array(a), InitValue::Array(items)) => {
            let def = exe.type_table.arrays.get(a as usize).ok_or(WriteError::BadAddress)?;
            let es = element_size(exe, def.element).ok_or(WriteError::BadAddress)?;
            for (k, v) in items.iter().enumerate().take(def.len() as usize) {
                init_at(mem, exe, addr + k as u32 * es, def.element, v)?;
            }
            Ok(())
        }
        (Type::Struct(s), InitValue::Struct(fields)) => {
            let def = exe.type_table.structs.get(s as usize).ok_or(WriteError::BadAddress)?;
            let offs = exe.lay.cached_struct(s).ok_or(WriteError::BadAddress)?;
            for (i, v) in fields.iter().enumerate() {
                if let (Some(v), Some(f), Some(off)) = (v, def.fields.get(i), offs.get(i)) {
                    init_at(mem, exe, addr + off, f.ty, v)?;
                }
            }
            Ok(())
        }
        _ => Err(mismatch()),
    }
}
