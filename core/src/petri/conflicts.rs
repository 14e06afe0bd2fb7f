//! Structural conflicts (transitions sharing an input place) and whether their guards are
//! mutually exclusive.
//!
//! What we can prove: a guard is read as a boolean formula (`NOT`, `AND`, `AND_THEN`, `OR`,
//! `OR_ELSE`, `XOR`, `TRUE`, `FALSE`) over atoms of two kinds:
//! - a comparison of a variable with an integer literal (`Weight >= 500`, `-3 < x`): its
//!   truth depends only on where the variable lies among the literals, so the variable takes
//!   one value in each region (each literal, and a point between neighbours, counted in
//!   half-steps so that it holds for REAL variables too);
//! - anything else (`Fault`, `Timer.Q`, `Weight >= Setpoint`), an opaque boolean. The same
//!   text is the same atom; `a < b` is read as `NOT (a >= b)`, `a > b` as `NOT (a <= b)` and
//!   `a <> b` as `NOT (a = b)`, with the sides put in one order, so `g` vs `NOT g`,
//!   `x >= k` vs `x < k` and `a > b` vs `b >= a` are all proved exclusive.
//!
//! Two guards are mutually exclusive when no assignment of the atoms makes both TRUE (a
//! truth table, up to [`MAX_ASSIGNMENTS`] rows). Opaque atoms are taken as independent, so
//! "exclusive" is always true of the program; "not exclusive" may be a false alarm (for
//! example `x > y` vs `y > x`, which we do not relate).

use crate::syntax::{self, BinaryOp, Cmp, Expr, ExprKind, LiteralValue, UnaryOp};

/// The largest truth table the check builds; larger guard pairs count as not exclusive.
pub const MAX_ASSIGNMENTS: u64 = 1 << 16;

#[derive(Debug, Clone)]
enum Formula {
    Const(bool),
    Atom(usize),
    /// Numeric variable index, comparison, literal ×2.
    Cmp(usize, Cmp, i128),
    Not(Box<Formula>),
    And(Box<Formula>, Box<Formula>),
    Or(Box<Formula>, Box<Formula>),
    Xor(Box<Formula>, Box<Formula>),
}

/// The atoms of the guards read so far.
#[derive(Default)]
struct Atoms {
    booleans: Vec<String>,
    numerics: Vec<String>,
    literals: Vec<Vec<i128>>,
}

fn key(text: &str) -> String {
    text.chars().filter(|c| !c.is_whitespace()).collect::<String>().to_ascii_uppercase()
}

impl Atoms {
    fn boolean(&mut self, name: String) -> usize {
        match self.booleans.iter().position(|b| *b == name) {
            Some(i) => i,
            None => {
                self.booleans.push(name);
                self.booleans.len() - 1
            }
        }
    }

    fn numeric(&mut self, name: String, literal: i128) -> usize {
        let i = match self.numerics.iter().position(|b| *b == name) {
            Some(i) => i,
            None => {
                self.numerics.push(name);
                self.literals.push(Vec::new());
                self.numerics.len() - 1
            }
        };
        if !self.literals[i].contains(&literal) {
            self.literals[i].push(literal);
        }
        i
    }

    fn read(&mut self, src: &str, e: &Expr) -> Formula {
        let text =
            |e: &Expr| key(src.get(e.span.start as usize..e.span.end as usize).unwrap_or(""));
        match &e.kind {
            ExprKind::Paren(inner) => self.read(src, inner),
            ExprKind::Literal(l) if matches!(l.value, LiteralValue::Bool(_)) => {
                Formula::Const(matches!(l.value, LiteralValue::Bool(true)))
            }
            ExprKind::Unary(UnaryOp::Not, inner) => Formula::Not(Box::new(self.read(src, inner))),
            ExprKind::Binary(op, a, b) => {
                let both = |s: &mut Self| (Box::new(s.read(src, a)), Box::new(s.read(src, b)));
                match op {
                    BinaryOp::And | BinaryOp::AndThen => {
                        let (x, y) = both(self);
                        Formula::And(x, y)
                    }
                    BinaryOp::Or | BinaryOp::OrElse => {
                        let (x, y) = both(self);
                        Formula::Or(x, y)
                    }
                    BinaryOp::Xor => {
                        let (x, y) = both(self);
                        Formula::Xor(x, y)
                    }
                    _ => match comparison(*op) {
                        Some(cmp) => self.comparison(cmp, &text(a), a, &text(b), b),
                        None => Formula::Atom(self.boolean(text(e))),
                    },
                }
            }
            _ => Formula::Atom(self.boolean(text(e))),
        }
    }

    fn comparison(&mut self, cmp: Cmp, ta: &str, a: &Expr, tb: &str, b: &Expr) -> Formula {
        match (int_literal(a), int_literal(b)) {
            (None, Some(k)) => {
                return Formula::Cmp(self.numeric(ta.to_string(), k * 2), cmp, k * 2)
            }
            (Some(k), None) => {
                return Formula::Cmp(self.numeric(tb.to_string(), k * 2), cmp.flip(), k * 2)
            }
            _ => {}
        }
        // Opaque: normalise to `lhs >= rhs`, `lhs <= rhs` or `lhs = rhs`, possibly negated.
        let (mut cmp, mut l, mut r) = (cmp, ta, tb);
        if l > r {
            (cmp, l, r) = (cmp.flip(), r, l);
        }
        let (base, negated) = match cmp {
            Cmp::Lt => (">=", true),
            Cmp::Gt => ("<=", true),
            Cmp::Ne => ("=", true),
            Cmp::Ge => (">=", false),
            Cmp::Le => ("<=", false),
            Cmp::Eq => ("=", false),
        };
        let atom = Formula::Atom(self.boolean(format!("{l}{base}{r}")));
        if negated {
            Formula::Not(Box::new(atom))
        } else {
            atom
        }
    }
}

fn comparison(op: BinaryOp) -> Option<Cmp> {
    match op {
        BinaryOp::Cmp(c) => Some(c),
        _ => None,
    }
}

fn int_literal(e: &Expr) -> Option<i128> {
    match &e.kind {
        ExprKind::Literal(l) => match l.value {
            LiteralValue::Int(v) => Some(v),
            _ => None,
        },
        ExprKind::Unary(UnaryOp::Neg, inner) => int_literal(inner).map(|v| -v),
        ExprKind::Paren(inner) => int_literal(inner),
        _ => None,
    }
}

fn eval(f: &Formula, bools: u64, nums: &[i128]) -> bool {
    match f {
        Formula::Const(b) => *b,
        Formula::Atom(i) => bools >> i & 1 == 1,
        Formula::Cmp(v, c, k) => c.holds(nums[*v].cmp(k)),
        Formula::Not(x) => !eval(x, bools, nums),
        Formula::And(x, y) => eval(x, bools, nums) && eval(y, bools, nums),
        Formula::Or(x, y) => eval(x, bools, nums) || eval(y, bools, nums),
        Formula::Xor(x, y) => eval(x, bools, nums) != eval(y, bools, nums),
    }
}

/// Whether the two guards (ST expressions; empty is TRUE) are provably mutually exclusive.
/// A guard that does not parse counts as not exclusive (its own error is reported
/// elsewhere).
pub fn mutually_exclusive(g1: &str, g2: &str) -> bool {
    let mut atoms = Atoms::default();
    let mut read = |g: &str| -> Option<Formula> {
        if g.trim().is_empty() {
            return Some(Formula::Const(true));
        }
        let e = syntax::parse_expression(g).ok()?;
        Some(atoms.read(g, &e))
    };
    let (Some(f1), Some(f2)) = (read(g1), read(g2)) else { return false };
    // Candidate values per numeric variable: each literal and the points half a step away.
    let values: Vec<Vec<i128>> = atoms
        .literals
        .iter()
        .map(|ks| {
            let mut v: Vec<i128> = ks.iter().flat_map(|&k| [k - 1, k, k + 1]).collect();
            crate::order::sort(&mut v);
            v.dedup();
            v
        })
        .collect();
    let n_bool = atoms.booleans.len() as u32;
    let mut rows: u64 = if n_bool >= 63 { u64::MAX } else { 1 << n_bool };
    for v in &values {
        rows = rows.saturating_mul(v.len() as u64);
    }
    if rows > MAX_ASSIGNMENTS {
        return false;
    }
    let mut nums: Vec<i128> = values.iter().map(|v| v[0]).collect();
    let mut idx = vec![0usize; values.len()];
    loop {
        for bools in 0..(1u64 << n_bool) {
            if eval(&f1, bools, &nums) && eval(&f2, bools, &nums) {
                return false;
            }
        }
        // Next combination of numeric values (odometer).
        let mut i = 0;
        loop {
            if i == idx.len() {
                return true;
            }
            idx[i] += 1;
            if idx[i] < values[i].len() {
                nums[i] = values[i][idx[i]];
                break;
            }
            idx[i] = 0;
            nums[i] = values[i][0];
            i += 1;
        }
    }
}
