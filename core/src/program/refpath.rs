//! The path of the variable a reference points to (`Tank.Level`, `Arr[2]`, `Scale.x` for a
//! FUNCTION's variable), found from the referenced cell's address: what the variable
//! table and `plc run --json` show for a `REF_TO` value. The inverse of `locate.rs`.

use super::locate::element_size;
use super::Executable;
use crate::semantic::types::{dim_len, Type};
use crate::syntax::VarSection;

/// The path of the variable of type `target` at absolute address `addr`: among the main
/// program's variables and the globals, then the other program instances' and the
/// FUNCTIONs' own variables (named `POU.var`). `None` when no variable of that type
/// starts there.
pub(crate) fn path_of(exe: &Executable, addr: u32, target: Type) -> Option<String> {
    let in_vars = exe.vars.iter().filter(|v| !v.global).chain(exe.vars.iter().filter(|v| v.global));
    for v in in_vars {
        if v.var.section == VarSection::InOut {
            continue;
        }
        let mut path = v.var.name.clone();
        if find(exe, addr, target, v.slot.addr, v.slot.ty, &mut path) {
            return Some(path);
        }
    }
    let frames = exe
        .instances
        .iter()
        .map(|&(q, base)| (q, base))
        .chain(exe.pous.iter().enumerate().filter_map(|(q, c)| Some((q as u32, c.frame?))));
    for (q, base) in frames {
        let (Some(code), Some(name)) =
            (exe.pous.get(q as usize), exe.type_table.pou_names.get(q as usize))
        else {
            continue;
        };
        for (v, off) in code.vars.iter().zip(&code.offsets) {
            let mut path = format!("{name}.{}", v.name);
            if v.section != VarSection::InOut
                && find(exe, addr, target, base.wrapping_add(*off), v.ty, &mut path)
            {
                return Some(path);
            }
        }
    }
    None
}

/// Whether the value of type `ty` at `at` is, or holds, the variable of type `target` at
/// `addr`; extends `path` with the fields and indices on the way.
fn find(exe: &Executable, addr: u32, target: Type, at: u32, ty: Type, path: &mut String) -> bool {
    if at == addr && ty == target {
        return true;
    }
    let size = element_size(exe, ty).unwrap_or(0);
    if addr < at || addr - at >= size {
        return false;
    }
    let rel = addr - at;
    match ty {
        Type::Struct(s) => {
            let (Some(def), Some(offs)) =
                (exe.type_table.structs.get(s as usize), exe.lay.cached_struct(s))
            else {
                return false;
            };
            let k = offs.partition_point(|&o| o <= rel).saturating_sub(1);
            let (Some(f), Some(&off)) = (def.fields.get(k), offs.get(k)) else { return false };
            path.push('.');
            path.push_str(&f.name);
            find(exe, addr, target, at + off, f.ty, path)
        }
        Type::Fb(q) => {
            let Some(code) = exe.pous.get(q as usize) else { return false };
            for (v, &off) in code.vars.iter().zip(&code.offsets) {
                let end = off.saturating_add(element_size(exe, v.ty).unwrap_or(0));
                if v.section != VarSection::InOut && off <= rel && rel < end {
                    path.push('.');
                    path.push_str(&v.name);
                    return find(exe, addr, target, at + off, v.ty, path);
                }
            }
            false
        }
        Type::Array(a) => {
            let Some(def) = exe.type_table.arrays.get(a as usize) else { return false };
            let es = element_size(exe, def.element).unwrap_or(0);
            if es == 0 {
                return false;
            }
            let mut flat = u64::from(rel / es);
            let mut idx = vec![0i64; def.dims.len()];
            for (k, &(lo, hi)) in def.dims.iter().enumerate().rev() {
                let n = dim_len(lo, hi).max(1);
                idx[k] = lo.wrapping_add((flat % n) as i64);
                flat /= n;
            }
            let shown: Vec<String> = idx.iter().map(i64::to_string).collect();
            path.push_str(&format!("[{}]", shown.join(",")));
            find(exe, addr, target, at + (rel / es) * es, def.element, path)
        }
        _ => false,
    }
}
