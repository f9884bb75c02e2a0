//! The decimater's priority queue: a binary min-heap of vertices keyed by their best
//! collapse's error, with each vertex's place in the heap stored so that a key can change or a
//! vertex leave in O(log n), as OpenMesh's `HeapT` (the heap of `DecimaterT`) does.

/// Marks a vertex that is not in the heap.
const OUT: u32 = u32::MAX;

/// An indexed binary min-heap of vertex ids; the keys live in the caller's array, passed to
/// every call, so that the decimater keeps one array per vertex attribute.
#[derive(Clone, Debug, Default)]
pub(super) struct VertexHeap {
    /// The heap, vertex ids.
    items: Vec<u32>,
    /// Per vertex, its index in `items`, [`OUT`] when not stored.
    place: Vec<u32>,
}

impl VertexHeap {
    /// An empty heap for vertices `0..n`.
    pub(super) fn new(n: usize) -> Self {
        Self {
            items: Vec::with_capacity(n),
            place: vec![OUT; n],
        }
    }

    /// Inserts `v`, or moves it to its place for its new key.
    pub(super) fn upsert(&mut self, v: u32, key: &[f32]) {
        let i = self.place[v as usize];
        if i == OUT {
            self.items.push(v);
            let i = self.items.len() - 1;
            self.place[v as usize] = i as u32;
            self.up(i, key);
        } else {
            let i = self.down(i as usize, key);
            self.up(i, key);
        }
    }

    /// Removes `v` if stored.
    pub(super) fn remove(&mut self, v: u32, key: &[f32]) {
        let i = self.place[v as usize];
        if i == OUT {
            return;
        }
        let i = i as usize;
        let last = self.items.len() - 1;
        self.swap(i, last);
        self.items.pop();
        self.place[v as usize] = OUT;
        if i < self.items.len() {
            let i = self.down(i, key);
            self.up(i, key);
        }
    }

    /// Removes and returns the vertex with the smallest key.
    pub(super) fn pop(&mut self, key: &[f32]) -> Option<u32> {
        let v = *self.items.first()?;
        self.remove(v, key);
        Some(v)
    }

    fn swap(&mut self, i: usize, j: usize) {
        self.items.swap(i, j);
        self.place[self.items[i] as usize] = i as u32;
        self.place[self.items[j] as usize] = j as u32;
    }

    fn less(&self, i: usize, j: usize, key: &[f32]) -> bool {
        key[self.items[i] as usize] < key[self.items[j] as usize]
    }

    fn up(&mut self, mut i: usize, key: &[f32]) -> usize {
        while i > 0 {
            let parent = (i - 1) / 2;
            if !self.less(i, parent, key) {
                break;
            }
            self.swap(i, parent);
            i = parent;
        }
        i
    }

    fn down(&mut self, mut i: usize, key: &[f32]) -> usize {
        loop {
            let (l, r) = (2 * i + 1, 2 * i + 2);
            let mut smallest = i;
            if l < self.items.len() && self.less(l, smallest, key) {
                smallest = l;
            }
            if r < self.items.len() && self.less(r, smallest, key) {
                smallest = r;
            }
            if smallest == i {
                return i;
            }
            self.swap(i, smallest);
            i = smallest;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pops_in_key_order_after_updates_and_removals() {
        let mut key = vec![5.0, 3.0, 8.0, 1.0, 9.0, 2.0];
        let mut h = VertexHeap::new(key.len());
        for v in 0..key.len() as u32 {
            h.upsert(v, &key);
        }
        key[4] = 0.5;
        h.upsert(4, &key);
        key[3] = 7.0;
        h.upsert(3, &key);
        h.remove(5, &key);
        let mut out = Vec::new();
        while let Some(v) = h.pop(&key) {
            out.push(v);
        }
        assert_eq!(out, vec![4, 1, 0, 3, 2]);
    }
}
