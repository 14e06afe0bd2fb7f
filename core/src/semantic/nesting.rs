//! How deeply data types contain each other: an FB instance inside an FB inside an FB …,
//! a struct inside a struct, an array of arrays. Laying out, reading and rendering a value
//! recurse once per level, so types nested deeper than [`MAX_TYPE_NESTING`] are refused
//! here, at the declaration that goes past the limit. Measured without recursion;
//! containment cycles are left to the compiler's layout, which reports them.

use std::collections::{HashMap, HashSet};

use super::check::Checker;
use super::ir::Var;
use super::types::{PouId, Type};
use crate::diagnostics::{Code, Span};
use crate::limits::MAX_TYPE_NESTING;
use crate::syntax::{PouKind, VarSection};

/// The values a variable of this section holds inside its owner (VAR_IN_OUT and
/// VAR_EXTERNAL are references to values held elsewhere).
fn contained(v: &Var) -> bool {
    !matches!(v.section, VarSection::InOut | VarSection::External)
}

impl Checker<'_> {
    /// The types directly inside a value of type `ty`.
    fn parts(&self, ty: Type) -> Vec<Type> {
        match ty {
            Type::Array(a) => self.types.arrays.get(a as usize).map(|d| vec![d.element]),
            Type::Struct(s) => {
                self.types.structs.get(s as usize).map(|d| d.fields.iter().map(|f| f.ty).collect())
            }
            Type::Fb(p) => self
                .pous
                .get(p as usize)
                .map(|pou| pou.vars.iter().filter(|v| contained(v)).map(|v| v.ty).collect()),
            _ => None,
        }
        .unwrap_or_default()
    }

    /// How many levels of arrays, structs and FB instances a value of `ty` has (0 for an
    /// elementary value), memoised in `depth`.
    fn nesting(&self, ty: Type, depth: &mut HashMap<Type, usize>) -> usize {
        let mut stack = vec![(ty, false)];
        // Types being measured: a part among them closes a cycle.
        let mut open = HashSet::new();
        while let Some((t, expanded)) = stack.pop() {
            if depth.contains_key(&t) {
                continue;
            }
            let parts = self.parts(t);
            if parts.is_empty() {
                depth.insert(t, 0);
            } else if expanded {
                // A part still missing is on a cycle (the layout reports it): count it 0.
                let d = parts.iter().map(|p| depth.get(p).copied().unwrap_or(0)).max();
                depth.insert(t, 1 + d.unwrap_or(0));
                open.remove(&t);
            } else if open.insert(t) {
                stack.push((t, true));
                for p in parts {
                    if !depth.contains_key(&p) && !open.contains(&p) {
                        stack.push((p, false));
                    }
                }
            }
        }
        depth.get(&ty).copied().unwrap_or(0)
    }

    /// Reports every variable whose type nests deeper than [`MAX_TYPE_NESTING`] where its
    /// owner (an FB, or the program and globals) is not already too deep itself: one error
    /// per chain, at the declaration that goes past the limit.
    pub(super) fn check_type_nesting(&mut self) {
        let mut depth = HashMap::new();
        let mut found: Vec<(Span, String)> = Vec::new();
        for (p, pou) in self.pous.iter().enumerate() {
            if pou.library {
                continue;
            }
            let own = if pou.kind == PouKind::FunctionBlock {
                self.nesting(Type::Fb(p as PouId), &mut depth)
            } else {
                0
            };
            if own > MAX_TYPE_NESTING + 2 {
                continue;
            }
            for v in pou.vars.iter().filter(|v| contained(v)) {
                if self.nesting(v.ty, &mut depth) > MAX_TYPE_NESTING {
                    found.push((v.span, v.name.clone()));
                }
            }
        }
        for v in &self.globals {
            if self.nesting(v.ty, &mut depth) > MAX_TYPE_NESTING {
                found.push((v.span, v.name.clone()));
            }
        }
        for (span, name) in found {
            let message = crate::msg!(
                TypeNestsFbInstancesStructs,
                name = name,
                MAX_TYPE_NESTING = MAX_TYPE_NESTING
            );
            self.error(Code::TooComplex, span, message);
        }
    }
}
