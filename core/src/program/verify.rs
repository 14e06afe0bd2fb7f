//! Which code regions the VM's inner loop (`vm/fast.rs`) may run without checking register
//! operands and element sites. A property of the compiled code alone: the compiler marks
//! regions after every compile (`compile/trust.rs`), the VM trusts the marks.

use super::op::{outer_loop_ops, CaseTable, Op, Reg, R3};

/// How the frame of a code region is placed, for [`verify`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum FrameKind {
    /// A frame at a fixed address (the main program, a function, a breakpoint condition):
    /// registers reach `base + x` (wrapping, so globals below the frame are reachable),
    /// which must lie inside the initial image of `image` cells.
    Static {
        /// The frame's address.
        base: u32,
        /// Cells of the initial image (memory is never smaller).
        image: usize,
    },
    /// An FB instance, wherever the caller puts it: registers must lie inside the
    /// instance's `size` cells (the caller checks that the instance lies inside memory).
    Instance {
        /// Cells of one instance.
        size: u32,
    },
}

/// Whether the inner loop may run the region `code[start..end]` (one POU's or condition's
/// code) without checking register operands and element sites: every register of every
/// instruction the inner loop runs lies inside the frame, every site index inside `sites`,
/// every jump (and CASE target) stays in the region, and the region ends with `Ret` or
/// `Halt`, so control never runs into another region's code. The outer loop's own operand
/// accesses are not looked at (they keep their checks).
pub(crate) fn verify(
    code: &[Op],
    (start, end): (usize, usize),
    sites: usize,
    cases: &[CaseTable],
    frame: FrameKind,
) -> bool {
    let Some(region) = code.get(start..end) else { return false };
    if !matches!(region.last(), Some(Op::Ret | Op::Halt { .. })) {
        return false;
    }
    let inside = |t: u32| (start..end).contains(&(t as usize));
    let jumps_ok = region.iter().all(|op| match *op {
        Op::Jump { target }
        | Op::JumpIf { target, .. }
        | Op::JumpIfNot { target, .. }
        | Op::ForTest { target, .. }
        | Op::ForNext { target, .. }
        | Op::ForNext32 { target, .. }
        | Op::ForInc32 { target, .. } => inside(target),
        Op::JumpLt(b)
        | Op::JumpLe(b)
        | Op::JumpGt(b)
        | Op::JumpGe(b)
        | Op::JumpEq(b)
        | Op::JumpNe(b) => inside(b.target),
        Op::Case { table, .. } => match cases.get(table as usize) {
            Some(CaseTable::Dense { targets, default, .. }) => {
                inside(*default) && targets.iter().all(|&t| inside(t))
            }
            Some(CaseTable::Sparse { ranges, default }) => {
                inside(*default) && ranges.iter().all(|r| inside(r.2))
            }
            None => false,
        },
        _ => true,
    });
    jumps_ok && verify_operands(region, sites, frame)
}

fn verify_operands(code: &[Op], sites: usize, frame: FrameKind) -> bool {
    let reg_ok = |x: Reg| match frame {
        FrameKind::Static { base, image } => (base.wrapping_add(x) as usize) < image,
        FrameKind::Instance { size } => x < size,
    };
    let site_ok = |k: u32| (k as usize) < sites;
    code.iter().all(|op| {
        let mut ok = true;
        let mut reg = |x: Reg| ok &= reg_ok(x);
        let r3 = |o: R3, reg: &mut dyn FnMut(Reg)| {
            reg(o.dst);
            reg(o.a);
            reg(o.b);
        };
        match *op {
            Op::Const { dst, .. } | Op::LoadAbs { dst, .. } | Op::AddrOf { dst, .. } => reg(dst),
            Op::StoreAbs { a, .. } | Op::JumpIf { c: a, .. } | Op::JumpIfNot { c: a, .. } => reg(a),
            Op::Move { dst, a }
            | Op::RealToDint { dst, a }
            | Op::Not { dst, a, .. }
            | Op::Neg { dst, a, .. }
            | Op::GetBit { dst, a, .. }
            | Op::LoadInd { dst, ptr: a, .. }
            | Op::PtrAdd { dst, ptr: a, .. }
            | Op::StoreInd { ptr: dst, a, .. }
            | Op::Index { ptr: dst, idx: a, .. } => {
                reg(dst);
                reg(a);
            }
            Op::LoadElem { dst, idx, site } | Op::ElemAddr { dst, idx, site } => {
                reg(dst);
                reg(idx);
                ok &= site_ok(site);
            }
            Op::StoreElem { idx, site, a } => {
                reg(idx);
                reg(a);
                ok &= site_ok(site);
            }
            Op::MoveElem { didx, sidx, site } => {
                reg(didx);
                reg(sidx);
                ok &= site_ok(site) && site_ok(site.wrapping_add(1));
            }
            Op::AddI64(o)
            | Op::SubI64(o)
            | Op::MulI64(o)
            | Op::AddI32(o)
            | Op::SubI32(o)
            | Op::MulI32(o)
            | Op::AddI16(o)
            | Op::SubI16(o)
            | Op::AddF64(o)
            | Op::SubF64(o)
            | Op::MulF64(o)
            | Op::DivF64(o)
            | Op::AddF32(o)
            | Op::SubF32(o)
            | Op::MulF32(o)
            | Op::DivF32(o)
            | Op::EqCell(o)
            | Op::NeCell(o)
            | Op::LtI64(o)
            | Op::LeI64(o)
            | Op::GtI64(o)
            | Op::GeI64(o)
            | Op::And(o)
            | Op::Or(o)
            | Op::Xor(o)
            | Op::AndNot(o)
            | Op::MulRealToDint(o) => r3(o, &mut reg),
            Op::JumpLt(b)
            | Op::JumpLe(b)
            | Op::JumpGt(b)
            | Op::JumpGe(b)
            | Op::JumpEq(b)
            | Op::JumpNe(b) => {
                reg(b.a);
                reg(b.b);
            }
            Op::ForNext32 { v, lim, .. } => {
                reg(v);
                reg(lim);
                reg(lim.wrapping_add(1));
            }
            Op::ForInc32 { v, lim, .. } => {
                reg(v);
                reg(lim);
            }
            // No register, or run by the outer loop, which checks its operands itself (no
            // catch-all: a new instruction must be decided on here).
            Op::Jump { .. } | outer_loop_ops!() => {}
        }
        ok
    })
}
