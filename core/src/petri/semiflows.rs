//! Minimal-support semiflows by the Farkas / Martinez–Silva algorithm, as TINA reports them.
//!
//! P-semiflows are the non-negative integer vectors y with yᵀC = 0 (weighted token sums
//! that no firing changes); T-semiflows the non-negative x with Cx = 0 (firing counts that
//! bring a marking back). Starting from the table [A | I], every column of A is cancelled
//! in turn by non-negative combinations of row pairs of opposite sign; rows whose support
//! strictly contains another row's support are dropped as they appear. What is left are
//! the minimal-support semiflows, each divided by the gcd of its entries. Every result is
//! checked against the definition before it is returned.

/// A semiflow: a non-negative integer vector (over places or over transitions).
pub type Semiflow = Vec<u64>;

pub use crate::limits::SEMIFLOW_ROW_LIMIT as ROW_LIMIT;

/// The outcome: the semiflows found, and whether the row limit or an integer overflow cut
/// the computation short.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Semiflows {
    /// Minimal-support semiflows, sorted by support.
    pub flows: Vec<Semiflow>,
    /// False when the computation was cut short.
    pub complete: bool,
}

/// An integer matrix kept by rows, each row as its non-zero entries `(column, value)` in
/// column order: a net's incidence matrix is mostly zeros, and a dense one of a
/// 10,000-place net would take 800 MB.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct SparseMatrix {
    /// Number of columns.
    pub columns: usize,
    /// Per row, its non-zero entries in column order.
    pub rows: Vec<Vec<(usize, i64)>>,
}

impl SparseMatrix {
    /// The sparse form of a dense rows × `columns` matrix.
    pub fn from_dense(matrix: &[Vec<i64>], columns: usize) -> Self {
        let rows = matrix
            .iter()
            .map(|row| {
                row.iter()
                    .take(columns)
                    .enumerate()
                    .filter(|(_, &v)| v != 0)
                    .map(|(c, &v)| (c, v))
                    .collect()
            })
            .collect();
        SparseMatrix { columns, rows }
    }

    /// The entry at row `r`, column `c` (0 outside the matrix).
    pub fn get(&self, r: usize, c: usize) -> i64 {
        self.rows
            .get(r)
            .map_or(0, |row| row.binary_search_by_key(&c, |&(col, _)| col).map_or(0, |i| row[i].1))
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        let mut rows = vec![Vec::new(); self.columns];
        for (r, row) in self.rows.iter().enumerate() {
            for &(c, v) in row {
                rows[c].push((r, v));
            }
        }
        SparseMatrix { columns: self.rows.len(), rows }
    }
}

/// A sparse vector: non-zero `(index, value)` entries in index order.
type SparseVec = Vec<(usize, i64)>;

/// One row of the Farkas table: what is left of yᵀC (`rest`) and y itself (`flow`).
#[derive(Clone, PartialEq, Eq)]
struct Row {
    rest: SparseVec,
    flow: SparseVec,
}

fn gcd(mut a: i64, mut b: i64) -> i64 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// `a·x + b·y` without the zero entries, or `None` on overflow.
fn mix(x: &[(usize, i64)], a: i64, y: &[(usize, i64)], b: i64) -> Option<SparseVec> {
    let mut out = Vec::with_capacity(x.len() + y.len());
    let (mut i, mut j) = (0, 0);
    while i < x.len() || j < y.len() {
        let (k, v) = match (x.get(i), y.get(j)) {
            (Some(&(kx, vx)), Some(&(ky, _))) if kx < ky => {
                i += 1;
                (kx, vx.checked_mul(a)?)
            }
            (Some(&(kx, vx)), Some(&(ky, vy))) if kx == ky => {
                i += 1;
                j += 1;
                (kx, vx.checked_mul(a)?.checked_add(vy.checked_mul(b)?)?)
            }
            (_, Some(&(ky, vy))) => {
                j += 1;
                (ky, vy.checked_mul(b)?)
            }
            (Some(&(kx, vx)), None) => {
                i += 1;
                (kx, vx.checked_mul(a)?)
            }
            (None, None) => break,
        };
        if v != 0 {
            out.push((k, v));
        }
    }
    Some(out)
}

impl Row {
    fn normalise(&mut self) {
        let g = self.rest.iter().chain(&self.flow).fold(0, |g, &(_, x)| gcd(g, x));
        if g > 1 {
            self.rest.iter_mut().chain(self.flow.iter_mut()).for_each(|(_, x)| *x /= g);
        }
    }

    /// The entry of `rest` in column `col`, when every earlier column is already cancelled.
    fn lead(&self, col: usize) -> i64 {
        match self.rest.first() {
            Some(&(c, v)) if c == col => v,
            _ => 0,
        }
    }

    /// `a·self + b·other`, or `None` on overflow.
    fn combine(&self, a: i64, other: &Row, b: i64) -> Option<Row> {
        let mut row = Row {
            rest: mix(&self.rest, a, &other.rest, b)?,
            flow: mix(&self.flow, a, &other.flow, b)?,
        };
        row.normalise();
        Some(row)
    }

    fn support_len(&self) -> usize {
        self.flow.len()
    }
}

/// Whether the support of `small` is strictly inside that of `big`.
fn strictly_inside(small: &Row, big: &Row) -> bool {
    small.support_len() < big.support_len()
        && small.flow.iter().all(|&(k, _)| big.flow.binary_search_by_key(&k, |&(i, _)| i).is_ok())
}

/// The support of `row` as a bit set over `n` indices, for many containment tests.
fn bits(row: &Row, n: usize) -> Vec<u64> {
    let mut set = vec![0u64; n.div_ceil(64)];
    for &(k, _) in &row.flow {
        set[k / 64] |= 1 << (k % 64);
    }
    set
}

/// Whether the support of `small` is strictly inside the support `big` given as bits.
fn strictly_inside_bits(small: &Row, big: &[u64], big_len: usize) -> bool {
    small.support_len() < big_len
        && small.flow.iter().all(|&(k, _)| big[k / 64] & (1 << (k % 64)) != 0)
}

/// The rows of `kept` (pairwise minimal and distinct, as an earlier prune left them) and
/// of `new` whose support is minimal among all of them, one row per identical vector.
fn prune(mut kept: Vec<Row>, new: Vec<Row>, n: usize) -> Vec<Row> {
    if new.is_empty() {
        return kept;
    }
    let new_bits: Vec<Vec<u64>> = new.iter().map(|r| bits(r, n)).collect();
    kept.retain(|z| !new.iter().any(|r| strictly_inside(r, z)));
    let mut out: Vec<Row> = Vec::with_capacity(new.len());
    for (i, row) in new.iter().enumerate() {
        let (set, len) = (&new_bits[i], row.support_len());
        let dominated = kept.iter().any(|z| strictly_inside_bits(z, set, len))
            || new.iter().enumerate().any(|(j, s)| j != i && strictly_inside_bits(s, set, len));
        if !dominated && !kept.contains(row) && !out.contains(row) {
            out.push(row.clone());
        }
    }
    kept.extend(out);
    kept
}

/// Minimal-support semiflows of the rows of `matrix`: the non-negative y over rows with
/// yᵀ·matrix = 0.
pub fn minimal_semiflows(matrix: &SparseMatrix) -> Semiflows {
    let n = matrix.rows.len();
    let mut rows: Vec<Row> = matrix
        .rows
        .iter()
        .enumerate()
        .map(|(i, rest)| Row { rest: rest.clone(), flow: vec![(i, 1)] })
        .collect();
    let mut complete = true;
    for col in 0..matrix.columns {
        if rows.iter().all(|r| r.lead(col) == 0) {
            continue;
        }
        let (zero, nonzero): (Vec<Row>, Vec<Row>) =
            rows.into_iter().partition(|r| r.lead(col) == 0);
        let mut new = Vec::new();
        let (pos, neg): (Vec<&Row>, Vec<&Row>) = nonzero.iter().partition(|r| r.lead(col) > 0);
        'pairs: for p in &pos {
            for q in &neg {
                let (a, b) = (-q.lead(col), p.lead(col));
                match p.combine(a, q, b) {
                    Some(row) => new.push(row),
                    None => {
                        complete = false;
                        continue;
                    }
                }
                if zero.len() + new.len() > ROW_LIMIT {
                    complete = false;
                    break 'pairs;
                }
            }
        }
        rows = prune(zero, new, n);
    }
    let flows: Vec<Semiflow> = rows
        .into_iter()
        .filter(|r| !r.flow.is_empty())
        .map(|r| {
            let mut y = vec![0u64; n];
            for (k, v) in r.flow {
                y[k] = v.unsigned_abs();
            }
            y
        })
        .collect();
    let mut keyed: Vec<(Vec<bool>, Semiflow)> =
        flows.into_iter().map(|f| (f.iter().map(|&x| x == 0).collect(), f)).collect();
    crate::order::sort_by(&mut keyed, |a, b| a.cmp(b));
    let mut flows: Vec<Semiflow> = keyed.into_iter().map(|(_, f)| f).collect();
    flows.retain(|f| is_semiflow(matrix, f));
    Semiflows { flows, complete }
}

/// Whether `y` (over the rows) satisfies yᵀ·matrix = 0 and is non-zero.
pub fn is_semiflow(matrix: &SparseMatrix, y: &[u64]) -> bool {
    if y.len() != matrix.rows.len() || y.iter().all(|&x| x == 0) {
        return false;
    }
    let mut sums = vec![0i128; matrix.columns];
    for (row, &w) in matrix.rows.iter().zip(y) {
        if w != 0 {
            for &(c, v) in row {
                sums[c] += i128::from(v) * i128::from(w);
            }
        }
    }
    sums.iter().all(|&s| s == 0)
}
