//! Union-find over small integer ids: the one used to merge the electrical nodes of rungs
//! (grid nodes joined by links and wires on export, element ends joined by wires on import).

/// Disjoint sets of the ids `0..len`, with path halving.
#[derive(Debug, Clone, Default)]
pub(crate) struct UnionFind(Vec<usize>);

impl UnionFind {
    /// `n` ids, each in a set of its own.
    pub fn new(n: usize) -> Self {
        UnionFind((0..n).collect())
    }

    /// A new id in a set of its own.
    pub fn add(&mut self) -> usize {
        self.0.push(self.0.len());
        self.0.len() - 1
    }

    /// The representative of `x`'s set.
    pub fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }

    /// Joins the sets of `a` and `b`.
    pub fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.0[b] = a;
        }
    }
}
