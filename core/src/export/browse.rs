//! The parts of aggregate variables, for an expandable variables table and snapshots.

use crate::program::Executable;
use crate::semantic::types::Type;
use crate::sim::Simulator;
use crate::syntax::VarSection;

use super::value_text;

/// The most children [`children`] lists for one array (the rest are left out).
pub const MAX_CHILDREN: usize = 1000;

/// The most rows [`snapshot`] produces.
const MAX_ROWS: usize = 100_000;

/// One part of an aggregate: a struct field, an FB instance variable, an array element.
#[derive(Debug, Clone, PartialEq)]
pub struct Child {
    /// The full path (`Tank.Level`, `Arr[3]`, `M[1,2]`).
    pub path: String,
    /// The last step as shown (`Level`, `[3]`).
    pub label: String,
    /// Its type.
    pub ty: Type,
    /// Its description (FB variables' comments).
    pub comment: Option<String>,
    /// Its subrange, if any.
    pub range: Option<(i64, i64)>,
}

/// True for types whose values have parts (structs, arrays, FB instances).
pub fn is_expandable(ty: Type) -> bool {
    matches!(ty, Type::Struct(_) | Type::Array(_) | Type::Fb(_))
}

/// The parts of the variable at `path` of type `ty` (empty for scalars). Arrays list at
/// most [`MAX_CHILDREN`] elements; VAR_IN_OUT of FB instances are left out (they are
/// references, not values).
pub fn children(exe: &Executable, path: &str, ty: Type) -> Vec<Child> {
    let types = exe.type_table();
    match ty {
        Type::Struct(s) => types
            .structs
            .get(s as usize)
            .map(|def| {
                def.fields
                    .iter()
                    .map(|f| Child {
                        path: format!("{path}.{}", f.name),
                        label: f.name.clone(),
                        ty: f.ty,
                        comment: None,
                        range: f.range,
                    })
                    .collect()
            })
            .unwrap_or_default(),
        Type::Fb(q) => exe
            .pous
            .get(q as usize)
            .map(|code| {
                code.vars
                    .iter()
                    // VAR_EXTERNAL members are the globals, listed as such.
                    .filter(|v| !matches!(v.section, VarSection::InOut | VarSection::External))
                    .map(|v| Child {
                        path: format!("{path}.{}", v.name),
                        label: v.name.clone(),
                        ty: v.ty,
                        comment: v.comment.clone(),
                        range: v.range,
                    })
                    .collect()
            })
            .unwrap_or_default(),
        Type::Array(a) => {
            let Some(def) = types.arrays.get(a as usize) else { return Vec::new() };
            let mut out = Vec::new();
            let mut idx: Vec<i64> = def.dims.iter().map(|(l, _)| *l).collect();
            if def.dims.iter().any(|(l, h)| h < l) || idx.is_empty() {
                return out;
            }
            while out.len() < MAX_CHILDREN {
                let label =
                    format!("[{}]", idx.iter().map(i64::to_string).collect::<Vec<_>>().join(","));
                out.push(Child {
                    path: format!("{path}{label}"),
                    label,
                    ty: def.element,
                    comment: None,
                    range: def.element_range,
                });
                // Odometer increment, last index fastest.
                let mut k = idx.len();
                loop {
                    if k == 0 {
                        return out;
                    }
                    k -= 1;
                    if idx[k] < def.dims[k].1 {
                        idx[k] += 1;
                        break;
                    }
                    idx[k] = def.dims[k].0;
                }
            }
            out
        }
        _ => Vec::new(),
    }
}

/// One row of a variables snapshot.
#[derive(Debug, Clone, PartialEq)]
pub struct SnapshotRow {
    /// The path (`Motor`, `Tank.Level`, `Arr[2]`).
    pub path: String,
    /// The `AT` address of a top-level variable, else empty.
    pub address: String,
    /// The type's name.
    pub ty: String,
    /// The value as an IEC literal.
    pub value: String,
}

/// Every variable of the main program and the globals, aggregates flattened to their
/// scalar parts (at most 100 000 rows).
pub fn snapshot(sim: &Simulator) -> Vec<SnapshotRow> {
    let exe = sim.executable();
    let mut rows = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for entry in exe.main_vars() {
        if entry.var.section == VarSection::InOut
            || !seen.insert(entry.var.name.to_ascii_uppercase())
        {
            continue;
        }
        let address = entry.var.location.as_ref().map(|a| a.text.clone()).unwrap_or_default();
        flatten(sim, &entry.var.name, entry.var.ty, address, &mut rows);
    }
    rows
}

fn flatten(sim: &Simulator, path: &str, ty: Type, address: String, rows: &mut Vec<SnapshotRow>) {
    if rows.len() >= MAX_ROWS {
        return;
    }
    let exe = sim.executable();
    if is_expandable(ty) {
        for c in children(exe, path, ty) {
            flatten(sim, &c.path, c.ty, String::new(), rows);
        }
        return;
    }
    let value = sim.read(path).map(|v| value_text(&v)).unwrap_or_default();
    rows.push(SnapshotRow {
        path: path.to_string(),
        address,
        ty: exe.type_table().display(ty).to_string(),
        value,
    });
}
