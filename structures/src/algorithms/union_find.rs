//! Union-find with parity: the components of the checks, the summary and the repair, and the
//! orientability their parity unions decide.

/// Union-find over `0..n` (shared by the duplicate and manifold checks, the summary and the
/// repair's orientation) that also keeps, per element, the parity of its path to the root: plain unions
/// for components, parity unions for orientability.
pub(crate) struct UnionFind {
    parent: Vec<u32>,
    /// Parity of the link to `parent` (the root's is `false`).
    flip: Vec<bool>,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
            flip: vec![false; n],
        }
    }

    /// The root of `x` and the parity of `x` relative to it (path compressed).
    pub(crate) fn find(&mut self, x: u32) -> (u32, bool) {
        let (mut root, mut parity) = (x, false);
        while self.parent[root as usize] != root {
            parity ^= self.flip[root as usize];
            root = self.parent[root as usize];
        }
        let (mut y, mut y_parity) = (x, parity);
        while self.parent[y as usize] != y {
            let (next, next_parity) = (self.parent[y as usize], y_parity ^ self.flip[y as usize]);
            self.parent[y as usize] = root;
            self.flip[y as usize] = y_parity;
            y = next;
            y_parity = next_parity;
        }
        (root, parity)
    }

    /// Per element its root and its parity relative to the root: the forest itself, each
    /// path compressed to one link.
    pub(crate) fn into_roots(mut self) -> (Vec<u32>, Vec<bool>) {
        for x in 0..self.parent.len() as u32 {
            self.find(x);
        }
        (self.parent, self.flip)
    }

    /// Joins `a` and `b` with relative parity `flip`; `false` if they were already joined
    /// with the other parity (a contradiction).
    pub(crate) fn union(&mut self, a: u32, b: u32, flip: bool) -> bool {
        let ((ra, pa), (rb, pb)) = (self.find(a), self.find(b));
        if ra == rb {
            return pa ^ pb == flip;
        }
        self.parent[ra as usize] = rb;
        self.flip[ra as usize] = pa ^ pb ^ flip;
        true
    }
}
