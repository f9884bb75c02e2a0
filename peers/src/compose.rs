//! What the adapters share: the lab's checks before a crate sees a soup ([`admit`]), and the
//! queries composed from a structure's other answers where a crate has no query of its own
//! (each adapter's `cost()` declares which it uses).

use topolab_structures::{
    BoundaryCurves, BuildFacts, Connectivity, EdgeId, Error, FaceId, MeshTopology, PolygonSoup,
    Result,
};

/// The `MeshTopology` methods an adapter answers by composition alike: `boundary_curves`,
/// `edge_successor` and `edge_predecessor` from [`boundary_curves`], [`edge_successor`] and
/// [`edge_predecessor`], and `validate` by [`validate_answers`]. Used inside an
/// `impl MeshTopology` block (its file imports `compose`, `BoundaryCurves`, `EdgeId`, `FaceId`
/// and `Result`).
macro_rules! composed_queries {
    () => {
        #[inline]
        fn boundary_curves(&self, out: &mut BoundaryCurves) {
            compose::boundary_curves(self, out);
        }
        #[inline]
        fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
            compose::edge_successor(self, e, face)
        }
        #[inline]
        fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
            compose::edge_predecessor(self, e, face)
        }

        fn validate(&self) -> Result<()> {
            compose::validate_answers(self)
        }
    };
}
pub(crate) use composed_queries;

/// The `MeshTopology` methods both lox adapters forward to lox alike: the counts of vertices
/// and faces, the positions kept beside the mesh, and R00, R02 and R20 by lox's circulators
/// (`vertices_around_vertex`, `faces_around_vertex`, `vertices_around_face`). Used inside an
/// `impl MeshTopology` block of a struct with fields `mesh` (a lox mesh) and `positions` (its
/// file imports lox's prelude, `VertexHandle`, `FaceHandle`, `DVec3`, `VertexId` and `FaceId`).
macro_rules! lox_forwarded_queries {
    () => {
        #[inline]
        fn num_vertices(&self) -> usize {
            self.mesh.num_vertices() as usize
        }
        #[inline]
        fn num_faces(&self) -> usize {
            self.mesh.num_faces() as usize
        }
        #[inline]
        fn position(&self, v: VertexId) -> DVec3 {
            self.positions[v.index()]
        }
        #[inline]
        fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
            for w in self.mesh.vertices_around_vertex(VertexHandle::new(v.0)) {
                f(VertexId(w.idx()));
            }
        }
        #[inline]
        fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
            for g in self.mesh.faces_around_vertex(VertexHandle::new(v.0)) {
                f(FaceId(g.idx()));
            }
        }
        #[inline]
        fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
            for v in self.mesh.vertices_around_face(FaceHandle::new(face.0)) {
                f(VertexId(v.idx()));
            }
        }
    };
}
pub(crate) use lox_forwarded_queries;

/// Refuses what the crates mis-handle, before the crate sees it: indices out of range and
/// repeated corners ([`PolygonSoup::check`]), an edge with more than two faces or two faces
/// running one way along their edge ([`PolygonSoup::connectivity`]), a vertex whose faces form
/// several fans, and, when `triangles_only`, polygons ([`Error::NotTriangles`]). Returns what
/// the crate's construction is told ([`BuildFacts`], with the edge count of the analysis, which
/// a crate that keeps no edges answers `num_edges` from). Every adapter's
/// [`SeparateConstruction::admit`](topolab_structures::SeparateConstruction::admit): the report
/// runs it before the clock, as it runs the lab's checks before a C++ baseline's construction.
///
/// Why each check: tri-mesh pairs twins by an unordered vertex pair in a hash map, so a third
/// face or a reversed face is paired silently with the wrong half-edge; lox panics on a
/// non-manifold edge or vertex; and every crate walks one fan per vertex.
pub fn admit<'a>(
    soup: &'a PolygonSoup,
    structure: &'static str,
    triangles_only: bool,
) -> Result<BuildFacts<'a>> {
    let connectivity = admitted(soup, structure, triangles_only)?;
    BuildFacts::new(soup, connectivity.num_edges())
}

/// [`admit`], and then a refusal of a vertex of so many faces that a construction searching
/// the vertex's half-edges for each face it adds there takes time quadratic in them
/// ([`Connectivity::check_star_sizes`], [`Error::StarTooLarge`]): lox's `add_face` does, for
/// a vertex whose faces come in an order that leaves several pieces of its fan open.
pub fn admit_small_stars<'a>(
    soup: &'a PolygonSoup,
    structure: &'static str,
    triangles_only: bool,
) -> Result<BuildFacts<'a>> {
    let connectivity = admitted(soup, structure, triangles_only)?;
    connectivity.check_star_sizes(soup)?;
    BuildFacts::new(soup, connectivity.num_edges())
}

/// The checks of [`admit`]; the soup's connectivity once they pass.
fn admitted(
    soup: &PolygonSoup,
    structure: &'static str,
    triangles_only: bool,
) -> Result<Connectivity> {
    soup.check()?;
    if triangles_only {
        if let Some((face, corners)) = soup.first_non_triangle() {
            return Err(Error::NotTriangles {
                structure,
                face,
                corners,
            });
        }
    }
    soup.manifold_connectivity()
}

/// Runs a crate's construction, `build`, so that a panic inside the crate is an error, never a
/// panic of the lab: facts from [`admit`] never make a crate panic, but
/// [`SeparateConstruction::construction`](topolab_structures::SeparateConstruction::construction)
/// is public and may be handed facts of a soup [`admit`] would refuse. Costs nothing when
/// nothing panics (the timed path).
pub fn without_panic<T>(structure: &'static str, build: impl FnOnce() -> Result<T>) -> Result<T> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(build)).unwrap_or_else(|panic| {
        let message = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Err(Error::Unsupported(format!(
            "{structure}: the crate failed on a soup the lab's checks did not admit ({message})"
        )))
    })
}

/// R11 from R12 and R21: the other edges of each face of `e`.
#[inline]
pub fn edge_edges<M: MeshTopology>(m: &M, e: EdgeId, mut f: impl FnMut(EdgeId)) {
    m.edge_faces(e, |face| {
        m.face_edges(face, |x| {
            if x != e {
                f(x)
            }
        })
    });
}

/// Successor from R21: the edge after `e` in `face`'s edges (cyclically), `None` if `e` is
/// not one of them.
#[inline]
pub fn edge_successor<M: MeshTopology>(m: &M, e: EdgeId, face: FaceId) -> Option<EdgeId> {
    let (mut first, mut found, mut after) = (None, false, None);
    m.face_edges(face, |x| {
        first.get_or_insert(x);
        if found && after.is_none() {
            after = Some(x);
        }
        found |= x == e;
    });
    if found {
        after.or(first)
    } else {
        None
    }
}

/// Predecessor from R21: the edge before `e` in `face`'s edges (cyclically), `None` if `e`
/// is not one of them.
#[inline]
pub fn edge_predecessor<M: MeshTopology>(m: &M, e: EdgeId, face: FaceId) -> Option<EdgeId> {
    let (mut last, mut before, mut found, mut is_first) = (None, None, false, false);
    m.face_edges(face, |x| {
        if x == e && !found {
            found = true;
            before = last;
            is_first = last.is_none();
        }
        last = Some(x);
    });
    match (found, is_first) {
        (false, _) => None,
        (true, true) => last,
        (true, false) => before,
    }
}

/// Boundary curves from the enumeration, R01, R10 and the boundary-edge test: every
/// boundary edge not yet in a curve starts one, which goes on through the other boundary
/// edge at its far end (a manifold vertex has two; [`admit`] refused the others) until it
/// comes back.
///
/// O(n1 + ∂n1 log ∂n1), without a buffer of its own: as the lab's index half-edge does, the
/// boundary edges are first listed, sorted, at the front of `out` as scratch, where a binary
/// search marks each walked edge with the top bit (edge ids stay below 2^31: a soup's counts
/// fit `u32` and every adapter's edge ids are below three per face), and the scratch is
/// dropped at the end.
pub fn boundary_curves<M: MeshTopology>(m: &M, out: &mut BoundaryCurves) {
    const WALKED: u32 = 1 << 31;
    out.clear();
    m.for_each_edge(|e| {
        if m.is_boundary_edge(e) {
            out.edges.push(e);
        }
    });
    let scratch = out.edges.len();
    out.edges.sort_unstable();
    // Marks `e` walked; `false` when it was already.
    let mark = |edges: &mut Vec<EdgeId>, e: EdgeId| match edges[..scratch]
        .binary_search_by_key(&e.0, |x| x.0 & !WALKED)
    {
        Ok(i) if edges[i].0 & WALKED == 0 => {
            edges[i].0 |= WALKED;
            true
        }
        _ => false,
    };
    for i in 0..scratch {
        if out.edges[i].0 & WALKED != 0 {
            continue;
        }
        let start = out.edges[i];
        let (mut e, mut at) = (start, m.edge_vertices(start)[1]);
        while mark(&mut out.edges, e) {
            out.edges.push(e);
            let mut next = None;
            m.vertex_edges(at, |x| {
                if next.is_none() && x != e && m.is_boundary_edge(x) {
                    next = Some(x);
                }
            });
            let Some(x) = next else { break };
            let [a, b] = m.edge_vertices(x);
            at = if a == at { b } else { a };
            e = x;
        }
        out.end_curve();
    }
    // Drop the scratch list; curve starts were recorded after it.
    out.edges.drain(..scratch);
    for s in &mut out.starts[1..] {
        *s -= scratch as u32;
    }
}

/// What the lab can check of a crate that keeps its invariants private: every answer of the
/// faces and edges names a vertex, face and edge in range, each face has three or more
/// corners, and each edge two distinct ends.
pub fn validate_answers<M: MeshTopology>(m: &M) -> Result<()> {
    validate_live_answers(m, |_| false, |_| false)
}

/// [`validate_answers`] for a structure that marks deletions (`Deletion::Marked`): the faces
/// and edges `face_deleted` and `edge_deleted` name keep their slots until garbage
/// collection, and the answers about them are meaningless, so only the others are checked.
pub fn validate_live_answers<M: MeshTopology>(
    m: &M,
    face_deleted: impl Fn(FaceId) -> bool,
    edge_deleted: impl Fn(EdgeId) -> bool,
) -> Result<()> {
    let (nv, nf) = (m.num_vertices(), m.num_faces());
    let mut problem = None;
    for f in 0..nf {
        if face_deleted(FaceId(f as u32)) {
            continue;
        }
        let mut corners = 0;
        m.face_vertices(FaceId(f as u32), |v| {
            corners += 1;
            if v.index() >= nv {
                problem.get_or_insert(format!("face {f} names vertex {}", v.0));
            }
        });
        if corners < 3 {
            problem.get_or_insert(format!("face {f} has {corners} corners"));
        }
    }
    m.for_each_edge(|e| {
        if edge_deleted(e) {
            return;
        }
        let [a, b] = m.edge_vertices(e);
        if a == b || a.index() >= nv || b.index() >= nv {
            problem.get_or_insert(format!("edge {} has ends {} and {}", e.0, a.0, b.0));
        }
        m.edge_faces(e, |f| {
            if f.index() >= nf {
                problem.get_or_insert(format!("edge {} names face {}", e.0, f.0));
            }
        });
    });
    match problem {
        None => Ok(()),
        Some(message) => Err(Error::Invariant {
            structure: M::NAME,
            message,
        }),
    }
}

/// For `explain`: each vertex's neighbours (R00), one line per vertex, the records the crate
/// keeps being private.
pub fn write_one_rings<M: MeshTopology>(m: &M, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
    for v in 0..m.num_vertices() {
        write!(w, "v{v}:")?;
        let mut result = Ok(());
        m.vertex_vertices(topolab_structures::VertexId(v as u32), |x| {
            result = result.and_then(|()| write!(w, " {}", x.0));
        });
        result?;
        writeln!(w)?;
    }
    Ok(())
}
