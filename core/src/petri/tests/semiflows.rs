//! Farkas / Martinez–Silva against the definition and against brute force.

use proptest::prelude::*;

use super::super::semiflows::{self, SparseMatrix};

fn minimal_semiflows(matrix: &[Vec<i64>], columns: usize) -> semiflows::Semiflows {
    semiflows::minimal_semiflows(&SparseMatrix::from_dense(matrix, columns))
}

fn is_semiflow(matrix: &[Vec<i64>], columns: usize, y: &[u64]) -> bool {
    semiflows::is_semiflow(&SparseMatrix::from_dense(matrix, columns), y)
}

fn transpose(matrix: &[Vec<i64>], columns: usize) -> Vec<Vec<i64>> {
    (0..columns).map(|c| matrix.iter().map(|row| row[c]).collect()).collect()
}

fn support(v: &[u64]) -> Vec<bool> {
    v.iter().map(|&x| x > 0).collect()
}

fn strictly_inside(small: &[bool], big: &[bool]) -> bool {
    small != big && small.iter().zip(big).all(|(&s, &b)| !s || b)
}

/// Every non-zero vector with entries 0..=3 that is a semiflow.
fn brute_force(matrix: &[Vec<i64>], columns: usize) -> Vec<Vec<u64>> {
    let n = matrix.len();
    let mut out = Vec::new();
    let mut v = vec![0u64; n];
    loop {
        let mut i = 0;
        while i < n && v[i] == 3 {
            v[i] = 0;
            i += 1;
        }
        if i == n {
            return out;
        }
        v[i] += 1;
        if is_semiflow(matrix, columns, &v) {
            out.push(v.clone());
        }
    }
}

#[test]
fn a_cycle_has_one_p_and_one_t_semiflow() {
    // p0 -t0-> p1 -t1-> p2 -t2-> p0: C has a −1 and a +1 per column.
    let c = vec![vec![-1, 0, 1], vec![1, -1, 0], vec![0, 1, -1]];
    assert_eq!(minimal_semiflows(&c, 3).flows, vec![vec![1, 1, 1]]);
    assert_eq!(minimal_semiflows(&transpose(&c, 3), 3).flows, vec![vec![1, 1, 1]]);
}

#[test]
fn semiflow_check_rejects_zero_and_wrong_vectors() {
    let c = vec![vec![-1, 1], vec![1, -1]];
    assert!(is_semiflow(&c, 2, &[1, 1]));
    assert!(!is_semiflow(&c, 2, &[1, 0]));
    assert!(!is_semiflow(&c, 2, &[0, 0]));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// On random incidence matrices (up to 6 places × 5 transitions, entries −2..2):
    /// every result satisfies yᵀC = 0, has a minimal support, and every minimal support
    /// that brute force finds among the vectors with entries up to 3 is among the results (or
    /// contains one of them).
    #[test]
    fn results_are_exactly_the_minimal_supports(
        rows in 1usize..=6,
        cols in 1usize..=5,
        cells in proptest::collection::vec(-2i64..=2, 30),
    ) {
        let c: Vec<Vec<i64>> = (0..rows).map(|r| cells[r * cols..r * cols + cols].to_vec()).collect();
        let found = minimal_semiflows(&c, cols);
        prop_assert!(found.complete);
        for y in &found.flows {
            prop_assert!(is_semiflow(&c, cols, y), "{y:?} is not a semiflow of {c:?}");
            for z in &found.flows {
                prop_assert!(!strictly_inside(&support(z), &support(y)), "{y:?} not minimal: {z:?}");
            }
        }
        let brute = brute_force(&c, cols);
        let minimal: Vec<&Vec<u64>> = brute
            .iter()
            .filter(|y| !brute.iter().any(|z| strictly_inside(&support(z), &support(y))))
            .collect();
        // A support brute force thinks minimal may hide a smaller one whose semiflow
        // needs entries above 3; then the algorithm must have found that smaller one.
        for y in minimal {
            prop_assert!(
                found.flows.iter().any(|f| {
                    let (f, y) = (support(f), support(y));
                    f == y || strictly_inside(&f, &y)
                }),
                "minimal support of {y:?} missing from {:?} for {c:?}", found.flows
            );
        }
    }
}

#[test]
fn a_long_cycle_has_one_semiflow_over_every_place() {
    // 3,000 places in one cycle: the sparse table never holds more than one combined row,
    // and a dense incidence matrix of this net would have 9,000,000 entries.
    let n = 3_000;
    let rows = (0..n).map(|p| {
        let mut row = vec![(p, -1), ((p + n - 1) % n, 1)];
        row.sort_unstable();
        row
    });
    let c = SparseMatrix { columns: n, rows: rows.collect() };
    let found = semiflows::minimal_semiflows(&c);
    assert!(found.complete);
    assert_eq!(found.flows, vec![vec![1; n]]);
    assert_eq!(semiflows::minimal_semiflows(&c.transpose()).flows, vec![vec![1; n]]);
}

#[test]
fn sparse_and_dense_forms_agree() {
    let dense = vec![vec![-1, 0, 2], vec![0, 0, 0], vec![3, -4, 0]];
    let c = SparseMatrix::from_dense(&dense, 3);
    assert_eq!(c.rows[1], vec![]);
    for (r, row) in dense.iter().enumerate() {
        for (col, &v) in row.iter().enumerate() {
            assert_eq!(c.get(r, col), v);
            assert_eq!(c.transpose().get(col, r), v);
        }
    }
}
