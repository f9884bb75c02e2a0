//! The naive oracle: every relation computed directly from the face list with ordinary maps,
//! in the "vertex language" (edges as sorted end-vertex pairs) so that any structure's answers
//! can be compared with it. Slow and obviously right, on purpose.

use crate::algorithms::summary::{ManifoldFacts, Summary, Undefined};
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

    /// The fans of vertex `v` (see [`crate::summary`]): its faces grouped by walking across
    /// edges at `v` that have exactly two faces. Naively: repeated merging of groups.
    pub fn fans(&self, v: u32) -> Vec<Vec<u32>> {
        let mut fans: Vec<Vec<u32>> = self.vertex_faces[v as usize]
            .iter()
            .map(|&f| vec![f])
            .collect();
        let links: Vec<(u32, u32)> = self.vertex_edges[v as usize]
            .iter()
            .filter_map(|e| match self.edge_faces[e][..] {
                [f, g] => Some((f, g)),
                _ => None,
            })
            .collect();
        let mut merged = true;
        while merged {
            merged = false;
            'search: for i in 0..fans.len() {
                for j in i + 1..fans.len() {
                    let joined = links.iter().any(|&(f, g)| {
                        (fans[i].contains(&f) && fans[j].contains(&g))
                            || (fans[i].contains(&g) && fans[j].contains(&f))
                    });
                    if joined {
                        let other = fans.remove(j);
                        fans[i].extend(other);
                        merged = true;
                        break 'search;
                    }
                }
            }
        }
        fans
    }

    /// Edges with more than two faces.
    pub fn non_manifold_edges(&self) -> usize {
        self.edge_faces.values().filter(|f| f.len() > 2).count()
    }

    /// The number of boundary curves by the lab's definition (see [`crate::summary`]): the two
    /// boundary edges of each open fan follow each other; a curve is a cycle of boundary edges
    /// linked that way. Undefined where an edge has more than two faces.
    pub fn boundary_curve_count(&self) -> Result<usize, Undefined> {
        let non_manifold = self.non_manifold_edges();
        if non_manifold > 0 {
            return Err(Undefined::NonManifoldEdges(non_manifold));
        }
        let edges = self.boundary_edges();
        // Per boundary edge, the boundary edges it is linked to (at either end).
        let mut linked: BTreeMap<Pair, Vec<Pair>> = BTreeMap::new();
        for v in 0..self.vertex_faces.len() as u32 {
            for fan in self.fans(v) {
                let ends: Vec<Pair> = edges
                    .iter()
                    .copied()
                    .filter(|&(a, b)| {
                        (a == v || b == v) && fan.contains(&self.edge_faces[&(a, b)][0])
                    })
                    .collect();
                assert!(
                    ends.is_empty() || ends.len() == 2,
                    "an open fan of a mesh without non-manifold edges has two boundary ends"
                );
                if let [x, y] = ends[..] {
                    linked.entry(x).or_default().push(y);
                    linked.entry(y).or_default().push(x);
                }
            }
        }
        let mut seen = BTreeSet::new();
        let mut curves = 0;
        for &start in &edges {
            if !seen.insert(start) {
                continue;
            }
            curves += 1;
            let mut stack = vec![start];
            while let Some(e) = stack.pop() {
                for &next in &linked[&e] {
                    if seen.insert(next) {
                        stack.push(next);
                    }
                }
            }
        }
        Ok(curves)
    }

    /// Can the faces be oriented consistently? Naively: give the first face of each component
    /// its own orientation, then spread across two-face edges (a face that traverses the
    /// shared edge the same way as its neighbour is flipped), and look for a contradiction.
    pub fn orientable(&self) -> bool {
        // flipped[f]: None until reached.
        let mut flipped: Vec<Option<bool>> = vec![None; self.faces.len()];
        let direction = |f: u32, (a, b): Pair| {
            let face = &self.faces[f as usize];
            let i = face.iter().position(|&x| x == a).expect("edge of its face");
            face[(i + 1) % face.len()] == b
        };
        for start in 0..self.faces.len() {
            if flipped[start].is_some() {
                continue;
            }
            flipped[start] = Some(false);
            let mut stack = vec![start as u32];
            while let Some(f) = stack.pop() {
                for e in self.face_edges(f as usize) {
                    if let [g0, g1] = self.edge_faces[&e][..] {
                        let g = if g0 == f { g1 } else { g0 };
                        // Same direction in both faces: one of them must be flipped.
                        let wanted =
                            flipped[f as usize].unwrap() ^ (direction(f, e) == direction(g, e));
                        match flipped[g as usize] {
                            None => {
                                flipped[g as usize] = Some(wanted);
                                stack.push(g);
                            }
                            Some(was) if was != wanted => return false,
                            Some(_) => {}
                        }
                    }
                }
            }
        }
        true
    }

    /// What `topolab info` should say of the soup, by the lab's definitions (see
    /// [`crate::summary`]), computed naively: every structure that accepts the soup must
    /// answer this (apart from its name, `structure` here is `"oracle"`).
    pub fn summary(&self) -> Summary {
        let facts = ManifoldFacts {
            non_manifold_edges: self.non_manifold_edges(),
            non_manifold_vertices: (0..self.vertex_faces.len() as u32)
                .filter(|&v| self.fans(v).len() > 1)
                .count(),
            orientable: self.orientable(),
        };
        let nv = self.vertex_faces.len();
        // The count the definition leaves undefined is never used: `Summary::new` asks the facts.
        let curves = self.boundary_curve_count().unwrap_or(0);
        Summary::new(
            "oracle",
            [
                nv,
                self.vertex_faces.iter().filter(|f| f.is_empty()).count(),
                self.edge_faces.len(),
                self.faces.len(),
                self.boundary_edges().len(),
                curves,
                self.face_components(),
            ],
            !self.faces.is_empty() && self.faces.iter().all(|f| f.len() == 3),
            &facts,
        )
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
