//! [`MeshEdit`] for both half-edge storages, written once over [`HalfEdgeLinksMut`] as the
//! queries are written once over [`HalfEdgeLinks`]: the Euler operations of pmp-library's
//! `SurfaceMesh` and OpenMesh (`add_face`, `delete_face`, `flip`, `split`, `collapse` with
//! `is_collapse_ok`, and OpenMesh's `vertex_split`), translated to the lab's convention that a
//! half-edge stores the vertex it starts at (both libraries store the one it points to).
//!
//! Deletion marks ([`Deletion::Marked`], as both libraries do): a deleted vertex, edge or face
//! keeps its slot, flagged in [`Marks`], until [`MeshEdit::garbage_collection`] builds the
//! storage again from the survivors in their order (O(n)). `validate()` skips marked slots.
//!
//! ## Costs
//!
//! k is the size of the neighbourhood an operation touches (the valences of the vertices and
//! the sizes of the faces around the edit). Finding the half-edge between two vertices
//! (`find_halfedge`) rotates around one of them, O(k).
//!
//! | operation | how | cost |
//! |---|---|---|
//! | add vertex | append a record | O(1) |
//! | add face | find each side's half-edge, link the new half-edges into the boundary loops | O(k) |
//! | delete face | unlink the face's boundary edges, re-point its vertices at a boundary half-edge | O(k) |
//! | delete vertex | delete each face around it | O(k) |
//! | flip edge | relink two triangles; refuse if the new edge exists (a rotation) | O(k) |
//! | split edge | one new vertex, up to three edges and two faces, relinked in place | O(1) with `prev`, O(k) without |
//! | split face | a fan of k triangles around the new vertex | O(k) |
//! | collapse edge | the link condition (each neighbour of one end looked for by `find_halfedge` around the other, O(k²)) and the tetrahedron test, then re-point the removed vertex's half-edges (O(k)) | O(k²) |
//! | split vertex | move the half-edges of one side of the fan, add three edges and two triangles | O(k) |
//! | insert edge | a walk round the face and a rotation round one end (is the diagonal an edge already?), a new edge and face linked in (`euler/edges.rs`) | O(k) |
//! | delete edge | the two cycles joined into the first face, the edge and the second face marked | O(k) |
//! | set position | the position written | O(1) |
//! | select | a scan of the positions | O(n) |
//! | rotate, scale a selection | k positions written | O(k) |
//! | smooth | R00 and the boundary test of every vertex, each O(k) | O(n) |
//! | garbage collection | rebuild the storage from the survivors | O(n) |
//! | weld vertices | the lecture's "weld vertices": checks, rename the half-edges leaving one vertex, merge the one or two pairs of boundary edges where the fans meet (the freed pair marked) | O(k) + O(1) per merged edge (O(k) without `prev`) |
//! | weld meshes | [`weld_meshes`](crate::algorithms::weld::weld_meshes): a rebuild from the welded face list | O(n) |

mod euler;

use super::{HalfEdge, HalfEdgeArrays, HalfEdgeLinks, NONE};
use crate::core::edit::{smooth_cost, Deletion, EditOp, MeshEdit, Offers};
use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::Cost;
use crate::core::topology::MeshTopology;
use glam::DVec3;

/// What a half-edge storage must offer to be edited: writes by id, and new records.
///
/// Every write leaves the storage in a state the next writes of the same operation repair;
/// the operations ([`HalfEdge`]'s [`MeshEdit`]) leave it valid.
pub trait HalfEdgeLinksMut: HalfEdgeLinks {
    /// `next[h] = n` (and, where stored, `prev[n] = h`).
    fn set_next(&mut self, h: u32, n: u32);
    /// Half-edge `h` starts at vertex `v`.
    fn set_vertex(&mut self, h: u32, v: u32);
    /// Half-edge `h` borders face `f` (`u32::MAX`: a boundary half-edge).
    fn set_face(&mut self, h: u32, f: u32);
    /// Vertex `v`'s half-edge (`u32::MAX`: unused).
    fn set_outgoing(&mut self, v: u32, h: u32);
    /// Face `f`'s half-edge.
    fn set_face_half_edge(&mut self, f: u32, h: u32);
    /// Moves vertex `v`.
    fn set_position(&mut self, v: u32, p: DVec3);
    /// Appends an unused vertex at `p`; returns its id.
    fn push_vertex(&mut self, p: DVec3) -> u32;
    /// Appends an edge: half-edge `h` (returned, even) from `a` to `b` and `h + 1` from `b` to
    /// `a`, with no face; their `next` links are set by the caller.
    fn push_edge(&mut self, a: u32, b: u32) -> u32;
    /// Appends a face whose half-edge is `h`; returns its id.
    fn push_face(&mut self, h: u32) -> u32;
    /// Reserves room for more vertices, edges and faces.
    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize);
}

/// The deletion marks of an edited half-edge mesh, empty (no memory) until the first deletion.
#[derive(Clone, Debug, Default)]
pub struct Marks {
    vertex: Vec<bool>,
    edge: Vec<bool>,
    face: Vec<bool>,
    any: bool,
}

fn get(flags: &[bool], i: u32) -> bool {
    flags.get(i as usize).copied().unwrap_or(false)
}

#[inline]
fn set(flags: &mut Vec<bool>, i: u32) {
    let i = i as usize;
    if flags.len() <= i {
        grow(flags, i);
    }
    flags[i] = true;
}

/// Makes room for flag `i`, at least doubling: a sweep of deletions marks rising ids, and
/// growing to just `i + 1` called `resize` for nearly every mark (callgrind counted a
/// sizeable share of the collapse test's instructions in marking).
#[cold]
#[inline(never)]
fn grow(flags: &mut Vec<bool>, i: usize) {
    flags.resize((i + 1).max(2 * flags.len()).max(64), false);
}

impl Marks {
    /// Is vertex `v` deleted?
    #[inline]
    pub fn vertex(&self, v: u32) -> bool {
        get(&self.vertex, v)
    }
    /// Is edge `e` deleted?
    #[inline]
    pub fn edge(&self, e: u32) -> bool {
        get(&self.edge, e)
    }
    /// Is face `f` deleted?
    #[inline]
    pub fn face(&self, f: u32) -> bool {
        get(&self.face, f)
    }
    /// Nothing is deleted.
    #[inline]
    pub fn is_empty(&self) -> bool {
        !self.any
    }
    #[inline]
    fn mark_vertex(&mut self, v: u32) {
        set(&mut self.vertex, v);
        self.any = true;
    }
    #[inline]
    fn mark_edge(&mut self, e: u32) {
        set(&mut self.edge, e);
        self.any = true;
    }
    #[inline]
    fn mark_face(&mut self, f: u32) {
        set(&mut self.face, f);
        self.any = true;
    }
    /// Bytes of the flags.
    pub(crate) fn heap_bytes(&self) -> usize {
        self.vertex.capacity() + self.edge.capacity() + self.face.capacity()
    }
}

/// The cost table of the module docs; `predecessor` is the storage's cost of `prev`.
fn edit_cost<M: MeshTopology>(op: EditOp, predecessor: Cost) -> Cost {
    match op {
        EditOp::AddVertex => Cost::Constant,
        EditOp::SplitEdge => predecessor,
        EditOp::GarbageCollection | EditOp::WeldEdges | EditOp::WeldFaces | EditOp::WeldMeshes => {
            Cost::Linear
        }
        EditOp::AddFace
        | EditOp::WeldVertices
        | EditOp::DeleteFace
        | EditOp::DeleteVertex
        | EditOp::FlipEdge
        | EditOp::SplitFace
        | EditOp::SplitVertex => Cost::Local,
        // Each neighbour of one end looked for in the other's rotation (see the table).
        EditOp::CollapseEdge => Cost::LocalSquared,
        // A walk around the face (and around a corner: is the diagonal an edge already?);
        // the two faces' cycles relinked.
        EditOp::InsertEdge | EditOp::DeleteEdge => Cost::Local,
        EditOp::SetPosition => Cost::Constant,
        EditOp::Select => Cost::Linear,
        // k: the vertices selected, each moved by `set_position`.
        EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
        EditOp::Smooth => smooth_cost::<M>(),
    }
}

impl<L: HalfEdgeLinksMut> MeshEdit for HalfEdge<L> {
    const DELETION: Deletion = Deletion::Marked;

    fn edit_cost(op: EditOp) -> Cost {
        edit_cost::<Self>(op, L::PREDECESSOR)
    }
    /// Every topological edit of the lecture.
    const OFFERS: Offers<Self> = Offers {
        add_vertex: Some(|m, p| {
            m.room(1, 0, 0)?;
            Ok(VertexId(m.links.push_vertex(p)))
        }),
        add_face: Some(|m, vertices| m.add_face_checked(vertices).map(FaceId)),
        delete_face: Some(|m, f| m.delete_face_checked(f.0)),
        delete_vertex: Some(|m, v| m.delete_vertex_checked(v.0)),
        flip_edge: Some(|m, e| m.flip_checked(e.0)),
        split_edge: Some(|m, e, p| m.split_edge_checked(e.0, p).map(VertexId)),
        split_face: Some(|m, f, p| m.split_face_checked(f.0, p).map(VertexId)),
        collapse_edge: Some(|m, from, to| m.collapse_checked(from.0, to.0)),
        split_vertex: Some(|m, v, p, left, right| {
            m.split_vertex_checked(v.0, p, left.0, right.0)
                .map(VertexId)
        }),
        weld_vertices: Some(|m, a, b| m.weld_checked(a.0, b.0)),
        insert_edge: Some(|m, f, a, b| m.insert_edge_checked(f.0, a.0, b.0).map(FaceId)),
        delete_edge: Some(|m, e| m.delete_edge_checked(e.0)),
        rebuilds: true,
    };
    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
        self.live_vertex(v.0, EditOp::SetPosition)?;
        self.links.set_position(v.0, p);
        Ok(())
    }
    fn check_collapse(&self, from: VertexId, to: VertexId) -> Result<()> {
        self.collapse_check(from.0, to.0).map(drop)
    }
    fn is_deleted_vertex(&self, v: VertexId) -> bool {
        self.marks.vertex(v.0)
    }
    fn is_deleted_face(&self, f: FaceId) -> bool {
        self.marks.face(f.0)
    }
    fn is_deleted_edge(&self, e: EdgeId) -> bool {
        self.marks.edge(e.0)
    }
    fn garbage_collection(&mut self) {
        if self.marks.is_empty() {
            return;
        }
        let l = &self.links;
        let m = &self.marks;
        let renumber = |n: usize, deleted: &dyn Fn(u32) -> bool| -> Vec<u32> {
            let mut next = 0u32;
            (0..n as u32)
                .map(|i| {
                    if deleted(i) {
                        NONE
                    } else {
                        next += 1;
                        next - 1
                    }
                })
                .collect()
        };
        let vmap = renumber(l.num_vertices(), &|v| m.vertex(v));
        let emap = renumber(l.num_half_edges() / 2, &|e| m.edge(e));
        let fmap = renumber(l.num_faces(), &|f| m.face(f));
        let hmap = |h: u32| {
            if h == NONE {
                NONE
            } else {
                2 * emap[(h >> 1) as usize] + (h & 1)
            }
        };
        let live_edges = emap.iter().filter(|&&e| e != NONE).count();
        let mut arrays = HalfEdgeArrays {
            vertex: Vec::with_capacity(2 * live_edges),
            next: Vec::with_capacity(2 * live_edges),
            face: Vec::with_capacity(2 * live_edges),
            vertex_half_edge: Vec::new(),
            face_half_edge: Vec::new(),
        };
        for h in 0..l.num_half_edges() as u32 {
            if emap[(h >> 1) as usize] == NONE {
                continue;
            }
            arrays.vertex.push(vmap[self.start_v(h) as usize]);
            arrays.next.push(hmap(self.nx(h)));
            let f = self.face_of(h);
            arrays
                .face
                .push(if f == NONE { NONE } else { fmap[f as usize] });
        }
        let mut positions = Vec::with_capacity(vmap.len());
        for v in 0..l.num_vertices() as u32 {
            if vmap[v as usize] != NONE {
                positions.push(l.position(VertexId(v)));
                arrays.vertex_half_edge.push(hmap(self.out_of(v)));
            }
        }
        for f in 0..l.num_faces() as u32 {
            if fmap[f as usize] != NONE {
                arrays
                    .face_half_edge
                    .push(hmap(l.id(l.face_half_edge(FaceId(f)))));
            }
        }
        self.links = L::from_arrays(arrays, &positions);
        self.marks = Marks::default();
    }
    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.links.reserve(vertices, edges, faces);
    }
}
