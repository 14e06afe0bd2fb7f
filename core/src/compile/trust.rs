//! Which code regions the VM's inner loop may run without checking register operands:
//! after every compile (and every breakpoint condition added), each POU's code and each
//! condition's code is checked once by `program::verify` against the frame it runs in.
//! A region that fails (a compiler bug) simply runs with every check on.

use super::Executable;
use crate::program::verify::{verify, FrameKind};
use crate::syntax::PouKind;

/// Recomputes `PouCode::trusted` and `Executable::condition_trusted`.
pub(crate) fn mark_trusted(exe: &mut Executable, kinds: &[PouKind]) {
    enum Owner {
        Pou(usize),
        Condition(usize),
    }
    let mut starts: Vec<(usize, Owner)> = Vec::new();
    for (q, code) in exe.pous.iter().enumerate() {
        if code.entry != u32::MAX {
            starts.push((code.entry as usize, Owner::Pou(q)));
        }
    }
    for (k, &entry) in exe.conditions.iter().enumerate() {
        starts.push((entry as usize, Owner::Condition(k)));
    }
    crate::order::sort_by_key(&mut starts, |s| s.0);
    let image = exe.out.init.len();
    let code_len = exe.out.code.len();
    exe.condition_trusted = vec![false; exe.conditions.len()];
    let main_frame = FrameKind::Static { base: exe.main_base, image };
    for (n, (start, owner)) in starts.iter().enumerate() {
        let end = starts.get(n + 1).map_or(code_len, |s| s.0);
        let frame = match owner {
            Owner::Condition(_) => Some(main_frame),
            Owner::Pou(q) => match (kinds.get(*q), exe.pous[*q].frame) {
                (Some(PouKind::FunctionBlock), _) => {
                    Some(FrameKind::Instance { size: exe.pous[*q].size })
                }
                (Some(_), Some(base)) => Some(FrameKind::Static { base, image }),
                _ => None,
            },
        };
        let ok = frame.is_some_and(|f| {
            verify(&exe.out.code, (*start, end), exe.out.sites.len(), &exe.out.cases, f)
        });
        match owner {
            Owner::Pou(q) => exe.pous[*q].trusted = ok,
            Owner::Condition(k) => exe.condition_trusted[*k] = ok,
        }
    }
}
