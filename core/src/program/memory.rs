//! The memory image: one flat vector of 64-bit cells holding every variable, FB instance,
//! function frame and compiler temporary. Scalars take one cell (encoding in `arith`);
//! a string takes a header cell (`capacity << 32 | length`, in bytes) and its bytes packed
//! little-endian, eight to a cell. One address space means a reference (VAR_IN_OUT) is one
//! cell address and copying an aggregate is copying a range of cells.
//!
//! Every access is checked: a bad address is `Fault::Internal`, never a panic.

use crate::values::Fault;

/// The memory of one machine.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Memory {
    /// The cells.
    pub cells: Vec<u64>,
}

const BAD_ADDRESS: Fault = Fault::Internal("memory address out of range");

/// Number of cells a string of `cap_bytes` bytes takes (header included).
pub fn string_cells(cap_bytes: u32) -> u32 {
    1 + cap_bytes.div_ceil(8)
}

/// The header cell of a string with capacity `cap` and length `len` (bytes).
pub fn string_header(cap: u32, len: u32) -> u64 {
    (u64::from(cap) << 32) | u64::from(len.min(cap))
}

/// The capacity and length (bytes) of the string at `addr` of `cells`.
pub fn str_header(cells: &[u64], addr: usize) -> Result<(u32, u32), Fault> {
    let h = *cells.get(addr).ok_or(BAD_ADDRESS)?;
    let cap = (h >> 32) as u32;
    Ok((cap, (h as u32).min(cap)))
}

/// Appends the bytes of the string at `addr` of `cells` to `out`.
pub fn read_str_into(cells: &[u64], addr: usize, out: &mut Vec<u8>) -> Result<(), Fault> {
    let (_, len) = str_header(cells, addr)?;
    let len = len as usize;
    let src = cells.get(addr + 1..addr + 1 + len.div_ceil(8)).ok_or(BAD_ADDRESS)?;
    let start = out.len();
    for c in src {
        out.extend_from_slice(&c.to_le_bytes());
    }
    out.truncate(start + len);
    Ok(())
}

/// Writes `bytes` to the string at `addr` of `cells`, truncated to its capacity and to
/// whole characters of `unit` bytes (2 for WSTRING).
pub fn write_str(cells: &mut [u64], addr: usize, bytes: &[u8], unit: u32) -> Result<(), Fault> {
    let (cap, _) = str_header(cells, addr)?;
    let unit = unit.max(1) as usize;
    let mut len = bytes.len().min(cap as usize);
    len -= len % unit;
    let dst = cells.get_mut(addr + 1..addr + 1 + len.div_ceil(8)).ok_or(BAD_ADDRESS)?;
    for (cell, chunk) in dst.iter_mut().zip(bytes[..len].chunks(8)) {
        let mut b = [0u8; 8];
        b[..chunk.len()].copy_from_slice(chunk);
        *cell = u64::from_le_bytes(b);
    }
    *cells.get_mut(addr).ok_or(BAD_ADDRESS)? = string_header(cap, len as u32);
    Ok(())
}

/// Copies the string at `src` to the string at `dst` (truncated to the destination's
/// capacity), cell by cell.
pub fn copy_str(cells: &mut [u64], dst: usize, src: usize) -> Result<(), Fault> {
    let (_, len) = str_header(cells, src)?;
    let (cap, _) = str_header(cells, dst)?;
    let n = len.min(cap);
    let k = (n as usize).div_ceil(8);
    if src.checked_add(1 + k).is_none_or(|e| e > cells.len())
        || dst.checked_add(1 + k).is_none_or(|e| e > cells.len())
    {
        return Err(BAD_ADDRESS);
    }
    cells.copy_within(src + 1..src + 1 + k, dst + 1);
    cells[dst] = string_header(cap, n);
    Ok(())
}

/// Copies `n` cells from `src` to `dst` (ranges may overlap).
pub fn copy_cells(cells: &mut [u64], dst: usize, src: usize, n: usize) -> Result<(), Fault> {
    let len = cells.len();
    if src.checked_add(n).is_none_or(|e| e > len) || dst.checked_add(n).is_none_or(|e| e > len) {
        return Err(BAD_ADDRESS);
    }
    cells.copy_within(src..src + n, dst);
    Ok(())
}

impl Memory {
    /// Reads cell `addr`.
    pub fn get(&self, addr: usize) -> Result<u64, Fault> {
        self.cells.get(addr).copied().ok_or(BAD_ADDRESS)
    }

    /// Writes cell `addr`.
    pub fn set(&mut self, addr: usize, bits: u64) -> Result<(), Fault> {
        *self.cells.get_mut(addr).ok_or(BAD_ADDRESS)? = bits;
        Ok(())
    }

    /// The bytes of the string at `addr`.
    pub fn read_str(&self, addr: usize) -> Result<Vec<u8>, Fault> {
        let mut v = Vec::new();
        read_str_into(&self.cells, addr, &mut v)?;
        Ok(v)
    }

    /// Writes `bytes` to the string at `addr` (see the free function `write_str`).
    pub fn write_str(&mut self, addr: usize, bytes: &[u8], unit: u32) -> Result<(), Fault> {
        write_str(&mut self.cells, addr, bytes, unit)
    }
}
