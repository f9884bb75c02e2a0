//! The naive oracle: every relation computed directly from the face list with ordinary maps,
//! in the "vertex language" (edges as sorted end-vertex pairs) so that any structure's answers
//! can be compared with it. Slow and obviously right, on purpose.

use crate::core::soup::PolygonSoup;
use std::collections::{BTreeMap, BTreeSet};

/// An undirected edge by its end vertices, smaller first.
pub type Pair = (u32, u32);

/// Normalises an edge to a [`Pair`].
pub fn pair(a: u32, b: u32) -> Pair {
    if a < b {
        (a, b)
    } else {
        (b, a)
    }
}

/// Every relation of a soup, computed naively.
#[derive(Clone, Debug)]
pub struct Oracle {
    /// Faces as given.
    pub faces: Vec<Vec<u32>>,
    /// Edge → its faces (sorted).
    pub edge_faces: BTreeMap<Pair, Vec<u32>>,
    /// Vertex → sorted distinct neighbour vertices.
    pub vertex_vertices: Vec<Vec<u32>>,
    /// Vertex → sorted incident edges.
    pub vertex_edges: Vec<Vec<Pair>>,
    /// Vertex → sorted incident faces.
    pub vertex_faces: Vec<Vec<u32>>,
    /// Per vertex, whether a boundary edge touches it.
    pub boundary_vertex: Vec<bool>,
}

impl Oracle {
    /// Computes every relation of `soup` (which should pass [`PolygonSoup::check`]).
    pub fn new(soup: &PolygonSoup) -> Self {
        let faces: Vec<Vec<u32>> = soup.faces().map(|f| f.to_vec()).collect();
        let n = soup.num_vertices();
        let mut edge_faces: BTreeMap<Pair, Vec<u32>> = BTreeMap::new();
        let mut vertex_faces = vec![BTreeSet::new(); n];
        for (j, f) in faces.iter().enumerate() {
            for i in 0..f.len() {
                let (a, b) = (f[i], f[(i + 1) % f.len()]);
                edge_faces.entry(pair(a, b)).or_default().push(j as u32);
                vertex_faces[a as usize].insert(j as u32);
            }
        }
        let mut vertex_vertices = vec![BTreeSet::new(); n];
        let mut vertex_edges = vec![Vec::new(); n];
        let mut boundary_vertex = vec![false; n];
        for (&(a, b), fs) in &edge_faces {
            vertex_vertices[a as usize].insert(b);
            vertex_vertices[b as usize].insert(a);
            vertex_edges[a as usize].push((a, b));
            vertex_edges[b as usize].push((a, b));
            if fs.len() == 1 {
                boundary_vertex[a as usize] = true;
                boundary_vertex[b as usize] = true;
            }
        }
        for e in &mut vertex_edges {
            e.sort_unstable();
        }
        for fs in edge_faces.values_mut() {
            fs.sort_unstable();
        }
        Self {
            faces,
            edge_faces,
            vertex_vertices: vertex_vertices
                .into_iter()
                .map(|s| s.into_iter().collect())
                .collect(),
            vertex_edges,
            vertex_faces: vertex_faces
                .into_iter()
                .map(|s| s.into_iter().collect())
                .collect(),
            boundary_vertex,
        }
    }

    /// Edges of face `f` in order: edge i joins corner i and i + 1.
    pub fn face_edges(&self, f: usize) -> Vec<Pair> {
        let face = &self.faces[f];
        (0..face.len())
            .map(|i| pair(face[i], face[(i + 1) % face.len()]))
            .collect()
    }

    /// R11: the other edges of the faces of `e`, sorted.
    pub fn edge_edges(&self, e: Pair) -> Vec<Pair> {
        let mut out: Vec<Pair> = self.edge_faces[&e]
            .iter()
            .flat_map(|&f| self.face_edges(f as usize))
            .filter(|&x| x != e)
            .collect();
        out.sort_unstable();
        out
    }

    /// R22: the faces across the edges of `f`, sorted.
    pub fn face_faces(&self, f: usize) -> Vec<u32> {
        let mut out: Vec<u32> = self
            .face_edges(f)
            .iter()
            .flat_map(|e| {
                self.edge_faces[e]
                    .iter()
                    .copied()
                    .filter(|&g| g != f as u32)
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// Is `e` a boundary edge (one face)?
    pub fn is_boundary_edge(&self, e: Pair) -> bool {
        self.edge_faces[&e].len() == 1
    }

    /// All boundary edges, sorted.
    pub fn boundary_edges(&self) -> Vec<Pair> {
        self.edge_faces
            .iter()
            .filter(|(_, f)| f.len() == 1)
            .map(|(&e, _)| e)
            .collect()
    }

    /// The number of boundary curves, when every boundary vertex has exactly two boundary
    /// edges (so the curves are well defined); `None` otherwise.
    pub fn boundary_curve_count(&self) -> Option<usize> {
        let edges = self.boundary_edges();
        let mut adj: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
        for &(a, b) in &edges {
            adj.entry(a).or_default().push(b);
            adj.entry(b).or_default().push(a);
        }
        if adj.values().any(|n| n.len() != 2) {
            return None;
        }
        let mut seen = BTreeSet::new();
        let mut curves = 0;
        for &start in adj.keys() {
            if !seen.insert(start) {
                continue;
            }
            curves += 1;
            let mut stack = vec![start];
            while let Some(v) = stack.pop() {
                for &w in &adj[&v] {
                    if seen.insert(w) {
                        stack.push(w);
                    }
                }
            }
        }
        Some(curves)
    }

    /// Number of connected components of the faces (through shared vertices), ignoring unused vertices.
    pub fn face_components(&self) -> usize {
        let n = self.vertex_faces.len();
        let mut parent: Vec<usize> = (0..n).collect();
        fn find(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        for f in &self.faces {
            for w in f.windows(2) {
                let (a, b) = (
                    find(&mut parent, w[0] as usize),
                    find(&mut parent, w[1] as usize),
                );
                parent[a] = b;
            }
        }
        let mut roots = BTreeSet::new();
        for f in &self.faces {
            roots.insert(find(&mut parent, f[0] as usize));
        }
        roots.len()
    }
}

/// `f` rotated so that its smallest vertex comes first.
pub fn canonical_face(f: &[u32]) -> Vec<u32> {
    let i = (0..f.len()).min_by_key(|&i| f[i]).unwrap_or(0);
    f[i..].iter().chain(&f[..i]).copied().collect()
}
