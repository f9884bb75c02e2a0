//! Whole-mesh facts computed through a structure's operators: counts, boundary curves, Euler
//! characteristic, genus. What `topolab info` prints.

use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::{BoundaryCurves, MeshTopology};

/// Counts and topological invariants of a mesh, as one structure computed them.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Summary {
    /// The structure that answered.
    pub structure: &'static str,
    /// Number of vertices (including unused ones).
    pub vertices: usize,
    /// Vertices used by no face.
    pub unused_vertices: usize,
    /// Number of edges.
    pub edges: usize,
    /// Number of faces.
    pub faces: usize,
    /// Number of boundary edges.
    pub boundary_edges: usize,
    /// Number of boundary curves.
    pub boundary_curves: usize,
    /// Connected components (of faces, through shared edges and vertices).
    pub components: usize,
    /// V - E + F over used vertices.
    pub euler_characteristic: i64,
    /// Genus, when the mesh is one connected orientable surface: (2 - χ - b) / 2.
    pub genus: Option<i64>,
    /// Every face is a triangle.
    pub triangles_only: bool,
}

/// Computes the [`Summary`] through `m`'s relations (R02, R22 and the boundary curves).
pub fn summarize<M: MeshTopology>(m: &M) -> Summary {
    let (nv, nf) = (m.num_vertices(), m.num_faces());
    let mut unused = 0;
    for v in 0..nv {
        let mut any = false;
        m.vertex_faces(VertexId::new(v), |_| any = true);
        unused += !any as usize;
    }
    // Components: flood fill over faces through R22, then merge those joined only at a vertex (R02).
    let mut comp = vec![u32::MAX; nf];
    let mut components = 0u32;
    let mut stack = Vec::new();
    for start in 0..nf {
        if comp[start] != u32::MAX {
            continue;
        }
        comp[start] = components;
        stack.push(start);
        while let Some(f) = stack.pop() {
            let mut push = |g: FaceId| {
                if comp[g.index()] == u32::MAX {
                    comp[g.index()] = components;
                    stack.push(g.index());
                }
            };
            m.face_faces(FaceId::new(f), &mut push);
            m.face_vertices(FaceId::new(f), |v| m.vertex_faces(v, &mut push));
        }
        components += 1;
    }
    let mut curves = BoundaryCurves::default();
    m.boundary_curves(&mut curves);
    let edges = m.num_edges();
    let chi = (nv - unused) as i64 - edges as i64 + nf as i64;
    // χ = 2 - 2g - b for one connected orientable surface; anything else (several
    // components, a pinched vertex) leaves the genus undefined.
    let twice_genus = 2 - chi - curves.len() as i64;
    let genus = (components == 1 && twice_genus >= 0 && twice_genus.rem_euclid(2) == 0)
        .then_some(twice_genus / 2);
    let mut triangles_only = nf > 0;
    for f in 0..nf {
        let mut k = 0;
        m.face_vertices(FaceId::new(f), |_| k += 1);
        triangles_only &= k == 3;
    }
    Summary {
        structure: M::NAME,
        vertices: nv,
        unused_vertices: unused,
        edges,
        faces: nf,
        boundary_edges: m.num_boundary_edges(),
        boundary_curves: curves.len(),
        components: components as usize,
        euler_characteristic: chi,
        genus,
        triangles_only,
    }
}
