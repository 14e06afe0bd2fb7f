//! The string functions: LEN, LEFT, RIGHT, MID, CONCAT, INSERT, DELETE, REPLACE, FIND.
//! Positions are 1-based and count characters (bytes for STRING, 2-byte units for
//! WSTRING). A length or position outside the string is `Fault::StringPosition`
//! (docs/semantics.md: reading past the end is a runtime fault). Work happens in the machine's
//! scratch buffers, so no allocation once they have grown.

use crate::program::memory::{read_str_into, write_str};
use crate::program::op::{Reg, StrFunc};
use crate::values::Fault;

/// Reusable buffers for string work.
#[derive(Debug, Clone, Default)]
pub(crate) struct Scratch {
    pub a: Vec<u8>,
    pub b: Vec<u8>,
    pub text: String,
    /// FIND's failure function.
    pub table: Vec<usize>,
}

const BAD: Fault = Fault::Internal("register address out of range");

fn name(f: StrFunc) -> &'static str {
    match f {
        StrFunc::Len => "LEN",
        StrFunc::Left => "LEFT",
        StrFunc::Right => "RIGHT",
        StrFunc::Mid => "MID",
        StrFunc::Concat => "CONCAT",
        StrFunc::Insert => "INSERT",
        StrFunc::Delete => "DELETE",
        StrFunc::Replace => "REPLACE",
        StrFunc::Find => "FIND",
        StrFunc::Widen => "STRING_TO_WSTRING",
        StrFunc::Narrow => "WSTRING_TO_STRING",
    }
}

/// Executes string function `f` with `n` arguments from register `args` on.
#[allow(clippy::too_many_arguments)]
pub(crate) fn exec(
    f: StrFunc,
    n: u8,
    wide: bool,
    dst: Reg,
    args: Reg,
    cells: &mut [u64],
    base: u32,
    s: &mut Scratch,
) -> Result<u64, Fault> {
    let unit = if wide { 2 } else { 1 };
    if matches!(f, StrFunc::Widen | StrFunc::Narrow) {
        return convert_width(f, dst, args, cells, base, s);
    }
    let reg = |k: u32| base.wrapping_add(args.wrapping_add(k)) as usize;
    let arg = |cells: &[u64], k: u32| cells.get(reg(k)).copied().ok_or(BAD);
    let int = |cells: &[u64], k: u32| arg(cells, k).map(|v| v as i64);
    s.a.clear();
    read_str_into(cells, arg(cells, 0)? as usize, &mut s.a)?;
    let len = (s.a.len() / unit) as i64;
    let fault =
        |position: i64| Fault::StringPosition { function: name(f), position, length: len as usize };
    // Checks a count `k` (0..=len) and a 1-based position `p` with `p + k - 1 <= len`.
    let check_np = |k: i64, p: i64| -> Result<(usize, usize), Fault> {
        if k < 0 {
            return Err(fault(k));
        }
        if p < 1 || p.saturating_add(k) - 1 > len {
            return Err(fault(p));
        }
        Ok(((p - 1) as usize * unit, k as usize * unit))
    };
    s.b.clear();
    match f {
        StrFunc::Widen | StrFunc::Narrow => return Err(Fault::Internal("string width")),
        StrFunc::Len | StrFunc::Find => {
            let v = if f == StrFunc::Len {
                len
            } else {
                read_str_into(cells, arg(cells, 1)? as usize, &mut s.b)?;
                find(&s.a, &s.b, unit, &mut s.table)
            };
            *cells.get_mut(base.wrapping_add(dst) as usize).ok_or(BAD)? = v as u64;
            return Ok((s.a.len() + s.b.len()) as u64);
        }
        StrFunc::Left | StrFunc::Right => {
            let k = int(cells, 1)?;
            if k < 0 || k > len {
                return Err(fault(k));
            }
            let k = k as usize * unit;
            let part = if f == StrFunc::Left { &s.a[..k] } else { &s.a[s.a.len() - k..] };
            s.b.extend_from_slice(part);
        }
        StrFunc::Mid => {
            let (p, k) = check_np(int(cells, 1)?, int(cells, 2)?)?;
            s.b.extend_from_slice(&s.a[p..p + k]);
        }
        StrFunc::Concat => {
            s.b.extend_from_slice(&s.a);
            for k in 1..u32::from(n) {
                read_str_into(cells, arg(cells, k)? as usize, &mut s.b)?;
            }
        }
        StrFunc::Insert => {
            let p = int(cells, 2)?;
            if p < 0 || p > len {
                return Err(fault(p));
            }
            let p = p as usize * unit;
            s.b.extend_from_slice(&s.a[..p]);
            read_str_into(cells, arg(cells, 1)? as usize, &mut s.b)?;
            s.b.extend_from_slice(&s.a[p..]);
        }
        StrFunc::Delete => {
            let (p, k) = check_np(int(cells, 1)?, int(cells, 2)?)?;
            s.b.extend_from_slice(&s.a[..p]);
            s.b.extend_from_slice(&s.a[p + k..]);
        }
        StrFunc::Replace => {
            let (p, k) = check_np(int(cells, 2)?, int(cells, 3)?)?;
            s.b.extend_from_slice(&s.a[..p]);
            read_str_into(cells, arg(cells, 1)? as usize, &mut s.b)?;
            s.b.extend_from_slice(&s.a[p + k..]);
        }
    }
    let d = cells.get(base.wrapping_add(dst) as usize).copied().ok_or(BAD)? as usize;
    write_str(cells, d, &s.b, unit as u32)?;
    Ok((s.a.len() + s.b.len()) as u64)
}

/// STRING ↔ WSTRING: the argument (a pointer at `args`) converted into the string at
/// pointer `dst`.
fn convert_width(
    f: StrFunc,
    dst: Reg,
    args: Reg,
    cells: &mut [u64],
    base: u32,
    s: &mut Scratch,
) -> Result<u64, Fault> {
    let ptr = |cells: &[u64], r: Reg| cells.get(base.wrapping_add(r) as usize).copied().ok_or(BAD);
    s.a.clear();
    read_str_into(cells, ptr(cells, args)? as usize, &mut s.a)?;
    s.b.clear();
    if f == StrFunc::Widen {
        s.b.extend(s.a.iter().flat_map(|&c| [c, 0]));
    } else {
        s.b.extend(s.a.chunks_exact(2).map(|u| if u[1] == 0 { u[0] } else { b'?' }));
    }
    let d = ptr(cells, dst)? as usize;
    write_str(cells, d, &s.b, if f == StrFunc::Widen { 2 } else { 1 })?;
    Ok((s.a.len() + s.b.len()) as u64)
}

/// 1-based character position of `needle` in `hay`, 0 when absent (or empty). Characters
/// are `unit` bytes. Knuth–Morris–Pratt over characters, so the time is linear in both
/// lengths whatever they hold (a byte-by-byte search took 32K × 32K steps on
/// `FIND(aaa…ab, aa…ab)`); `table` is a reusable buffer for the failure function.
pub(super) fn find(hay: &[u8], needle: &[u8], unit: usize, table: &mut Vec<usize>) -> i64 {
    if needle.is_empty() || needle.len() > hay.len() {
        return 0;
    }
    fn ch(s: &[u8], unit: usize, i: usize) -> &[u8] {
        &s[i * unit..(i + 1) * unit]
    }
    let (n, m) = (hay.len() / unit, needle.len() / unit);
    // table[i]: the length of the longest proper border of needle[..=i].
    table.clear();
    table.resize(m, 0);
    let mut k = 0;
    for i in 1..m {
        while k > 0 && ch(needle, unit, i) != ch(needle, unit, k) {
            k = table[k - 1];
        }
        if ch(needle, unit, i) == ch(needle, unit, k) {
            k += 1;
        }
        table[i] = k;
    }
    let mut q = 0;
    for i in 0..n {
        while q > 0 && ch(hay, unit, i) != ch(needle, unit, q) {
            q = table[q - 1];
        }
        if ch(hay, unit, i) == ch(needle, unit, q) {
            q += 1;
        }
        if q == m {
            return (i + 2 - m) as i64;
        }
    }
    0
}
