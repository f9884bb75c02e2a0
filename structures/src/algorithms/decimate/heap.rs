//! The decimater's priority queue: a binary min-heap of vertices keyed by their best
//! collapse's error, with each vertex's place in the heap stored so that a key can change or a
//! vertex leave in O(log n), as OpenMesh's `HeapT` (the heap of `DecimaterT`) does. It sifts
//! as `HeapT` does, equal keys included: an entry rises past a strictly larger parent only,
//! sinks past a child that is not larger (the right child taken only when strictly smaller
//! than the left), a key change or a removal sinks then rises, so that for the same
//! operations equal keys leave in the same order as from OpenMesh's heap. With `IDS` the
//! order is total instead, `(key, vertex id)`: no two entries are equal, so the vertex that
//! leaves first is the smallest of the entries stored, whatever the order of the operations
//! that stored them (the decimater's tie rule [`super::Ties::Ids`]).

/// Marks a vertex that is not in the heap.
const OUT: u32 = u32::MAX;

/// An indexed binary min-heap of vertex ids; the keys live in the caller's array, passed to
/// every call, so that the decimater keeps one array per vertex attribute. `IDS`: equal keys
/// ordered by vertex id (a constant, so that each order compiles to its own comparison).
#[derive(Clone, Debug, Default)]
pub(super) struct VertexHeap<const IDS: bool> {
    /// The heap, vertex ids.
    items: Vec<u32>,
    /// Per vertex, its index in `items`, [`OUT`] when not stored.
    place: Vec<u32>,
}

impl<const IDS: bool> VertexHeap<IDS> {
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

    #[inline]
    fn less(&self, i: usize, j: usize, key: &[f32]) -> bool {
        let (a, b) = (self.items[i], self.items[j]);
        let (ka, kb) = (key[a as usize], key[b as usize]);
        ka < kb || (IDS && ka == kb && a < b)
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
            if l >= self.items.len() {
                return i;
            }
            let child = if r < self.items.len() && self.less(r, l, key) {
                r
            } else {
                l
            };
            // `HeapT::downheap` stops only at a strictly larger child: an equal one rises.
            if self.less(i, child, key) {
                return i;
            }
            self.swap(i, child);
            i = child;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pops_in_key_order_after_updates_and_removals() {
        let mut key = vec![5.0, 3.0, 8.0, 1.0, 9.0, 2.0];
        let mut h = VertexHeap::<false>::new(key.len());
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

    /// Equal keys leave as from OpenMesh's `HeapT`: worked by hand through its `insert`
    /// (push, rise past strictly larger parents) and `pop_front` (the last entry to the top,
    /// sinking past children not larger than it, the right child only when strictly smaller).
    #[test]
    fn equal_keys_leave_in_the_order_of_openmesh_heap() {
        let key = vec![1.0, 1.0, 1.0, 1.0];
        let mut h = VertexHeap::<false>::new(key.len());
        for v in 0..4 {
            h.upsert(v, &key);
        }
        // [0 1 2 3]; pop 0: 3 to the top, sinks past 1 (equal): [1 3 2]; pop 1: 2 to the top,
        // sinks past 3: [3 2]; pop 3, then 2. A heap that stops at equal children would give
        // 0 3 2 1.
        let mut out = Vec::new();
        while let Some(v) = h.pop(&key) {
            out.push(v);
        }
        assert_eq!(out, vec![0, 1, 3, 2]);
    }

    /// With ids, equal keys leave by id whatever the order they came in and were changed in:
    /// the same heap operations in two orders give one sequence.
    #[test]
    fn with_ids_equal_keys_leave_by_id_whatever_the_order_of_operations() {
        let key = vec![2.0, 1.0, 1.0, 3.0, 1.0, 2.0, 1.0];
        let order = |vs: &[u32]| {
            let mut h = VertexHeap::<true>::new(key.len());
            for &v in vs {
                h.upsert(v, &key);
            }
            let mut out = Vec::new();
            while let Some(v) = h.pop(&key) {
                out.push(v);
            }
            out
        };
        let expected = vec![1, 2, 4, 6, 0, 5, 3];
        assert_eq!(order(&[0, 1, 2, 3, 4, 5, 6]), expected);
        assert_eq!(order(&[6, 5, 4, 3, 2, 1, 0]), expected);
        assert_eq!(order(&[3, 6, 0, 4, 1, 5, 2]), expected);
        // Without ids the order of insertion shows through.
        let mut h = VertexHeap::<false>::new(key.len());
        for v in [6, 4, 2, 1] {
            h.upsert(v, &key);
        }
        assert_ne!(h.pop(&key), Some(1));
    }
}
