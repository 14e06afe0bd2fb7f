//! The value rules: how elementary values wrap, round, convert and compare, and why an
//! operation on values can fail. The checker's constant folder and the VM both use these,
//! so a folded constant and a computed value can never differ; nothing here knows about
//! programs, source text or memory layout.

pub mod arith;
mod elem;
mod fault;
pub mod math;
mod ops;

pub use elem::Elem;
pub use fault::Fault;
pub use ops::{BinOp, Cmp, MathFn, StrFunc};
