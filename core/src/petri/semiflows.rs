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

/// More rows than this in the table and the computation stops (the count of minimal
/// semiflows can grow exponentially with the net).
pub const ROW_LIMIT: usize = 20_000;

/// The outcome: the semiflows found, and whether the row limit or an integer overflow cut
/// the computation short.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Semiflows {
    /// Minimal-support semiflows, sorted by support.
    pub flows: Vec<Semiflow>,
    /// False when the computation was cut short.
    pub complete: bool,
}

#[derive(Clone, PartialEq, Eq)]
struct Row {
    rest: Vec<i64>,
    flow: Vec<i64>,
}

fn gcd(mut a: i64, mut b: i64) -> i64 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl Row {
    fn normalise(&mut self) {
        let g = self.rest.iter().chain(&self.flow).fold(0, |g, &x| gcd(g, x));
        if g > 1 {
            self.rest.iter_mut().chain(self.flow.iter_mut()).for_each(|x| *x /= g);
        }
    }

    fn support(&self) -> Vec<bool> {
        self.flow.iter().map(|&x| x != 0).collect()
    }

    /// `a·self + b·other`, or `None` on overflow.
    fn combine(&self, a: i64, other: &Row, b: i64) -> Option<Row> {
        let mix = |x: &[i64], y: &[i64]| -> Option<Vec<i64>> {
            x.iter()
                .zip(y)
                .map(|(&u, &v)| u.checked_mul(a)?.checked_add(v.checked_mul(b)?))
                .collect()
        };
        let mut row =
            Row { rest: mix(&self.rest, &other.rest)?, flow: mix(&self.flow, &other.flow)? };
        row.normalise();
        Some(row)
    }
}

fn strictly_contains(big: &[bool], small: &[bool]) -> bool {
    big != small && small.iter().zip(big).all(|(&s, &b)| !s || b)
}

/// Keeps the rows whose support is minimal, and one row per identical vector.
fn prune(rows: Vec<Row>) -> Vec<Row> {
    let supports: Vec<Vec<bool>> = rows.iter().map(Row::support).collect();
    let mut out: Vec<Row> = Vec::new();
    for (i, row) in rows.into_iter().enumerate() {
        let dominated =
            supports.iter().enumerate().any(|(j, s)| j != i && strictly_contains(&supports[i], s));
        if !dominated && !out.contains(&row) {
            out.push(row);
        }
    }
    out
}

/// Minimal-support semiflows of the rows of `matrix` (rows × columns): the non-negative
/// y over rows with yᵀ·matrix = 0.
pub fn minimal_semiflows(matrix: &[Vec<i64>], columns: usize) -> Semiflows {
    let n = matrix.len();
    let mut rows: Vec<Row> = (0..n)
        .map(|i| {
            let mut flow = vec![0; n];
            flow[i] = 1;
            Row { rest: matrix[i].clone(), flow }
        })
        .collect();
    let mut complete = true;
    for col in 0..columns {
        let (zero, nonzero): (Vec<Row>, Vec<Row>) =
            rows.into_iter().partition(|r| r.rest[col] == 0);
        let mut next = zero;
        let (pos, neg): (Vec<&Row>, Vec<&Row>) = nonzero.iter().partition(|r| r.rest[col] > 0);
        'pairs: for p in &pos {
            for q in &neg {
                let (a, b) = (-q.rest[col], p.rest[col]);
                match p.combine(a, q, b) {
                    Some(row) => next.push(row),
                    None => {
                        complete = false;
                        continue;
                    }
                }
                if next.len() > ROW_LIMIT {
                    complete = false;
                    break 'pairs;
                }
            }
        }
        rows = prune(next);
    }
    let mut flows: Vec<Semiflow> = rows
        .into_iter()
        .filter(|r| r.flow.iter().any(|&x| x != 0))
        .map(|r| r.flow.iter().map(|&x| x.unsigned_abs()).collect())
        .collect();
    flows.sort_by(|a, b| {
        let key = |f: &Semiflow| f.iter().map(|&x| x == 0).collect::<Vec<_>>();
        key(a).cmp(&key(b)).then_with(|| a.cmp(b))
    });
    flows.retain(|f| is_semiflow(matrix, columns, f));
    Semiflows { flows, complete }
}

/// Whether `y` (over the rows) satisfies yᵀ·matrix = 0 and is non-zero.
pub fn is_semiflow(matrix: &[Vec<i64>], columns: usize, y: &[u64]) -> bool {
    if y.len() != matrix.len() || y.iter().all(|&x| x == 0) {
        return false;
    }
    (0..columns).all(|c| {
        let sum: i128 =
            matrix.iter().zip(y).map(|(row, &w)| i128::from(row[c]) * i128::from(w)).sum();
        sum == 0
    })
}

/// The transpose of a rows × columns matrix.
pub fn transpose(matrix: &[Vec<i64>], columns: usize) -> Vec<Vec<i64>> {
    (0..columns).map(|c| matrix.iter().map(|row| row[c]).collect()).collect()
}
