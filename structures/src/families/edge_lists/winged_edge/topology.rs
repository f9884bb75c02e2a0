//! [`MeshTopology`] for the winged-edge: building from a soup, the queries (see the cost
//! table of the module docs), `validate`, `heap_bytes` and `explain`.

use super::records::EdgeRecord;
use super::WingedEdge;
use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::reads::traced;
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use crate::families::edge_lists::boundary_walk;
use glam::DVec3;
use std::fmt::Write;

impl MeshTopology for WingedEdge {
    const NAME: &'static str = "winged-edge";
    const FAMILY: crate::core::family::Family = crate::core::family::Family::EdgeLists;

    fn capabilities() -> Capabilities {
        Capabilities::POLYGONS
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => Cost::Local,
            Operator::R10 | Operator::R12 | Operator::BoundaryEdge => Cost::Constant,
            Operator::EdgeSuccessor | Operator::EdgePredecessor => Cost::Constant,
            Operator::R11 | Operator::R20 | Operator::R21 | Operator::R22 => Cost::Local,
            Operator::BoundaryCurves => Cost::Linear,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        let mut mesh = Self::records_of(soup)?;
        mesh.positions = soup.positions.clone();
        Ok(mesh)
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.live_edges
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.live_faces
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for (e, r) in self.edges.iter().enumerate() {
            if r.is_live() {
                f(EdgeId::new(e));
            }
        }
    }
    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.walk_star(v, |e| f(self.edge(e).other_end(v)), |_| {});
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, f: impl FnMut(EdgeId)) {
        self.walk_star(v, f, |_| {});
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, f: impl FnMut(FaceId)) {
        self.walk_star(v, |_| {}, f);
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let r = self.edge(e);
        [r.v1, r.v2]
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        self.edge_faces(e, |face| {
            self.walk_face(face, |x, _| {
                if x != e {
                    f(x);
                }
            })
        });
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        let r = self.edge(e);
        f(r.fccw);
        if let Some(right) = r.fcw.valid() {
            f(right);
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        self.walk_face(face, |_, r| f(r.ends_in(face)[0]));
    }
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        self.walk_face(face, |e, _| f(e));
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        self.walk_face(face, |_, r| {
            if let Some(other) = r.other_face(face).valid() {
                f(other);
            }
        });
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.walk_star(v, |_| {}, |_| {})
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        !self.edge(e).fcw.is_valid()
    }
    #[inline]
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        boundary_walk::boundary_curves(self, out);
    }
    #[inline]
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let r = self.edges.get(e.index())?;
        traced!("E", e.0, *r);
        r.next_in(face)
    }
    #[inline]
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let r = self.edges.get(e.index())?;
        traced!("E", e.0, *r);
        r.prev_in(face)
    }

    fn validate(&self) -> Result<()> {
        self.check_records()?;
        self.check_faces()?;
        self.check_vertices()?;
        self.check_index()
    }

    fn heap_bytes(&self) -> usize {
        let index = self.index.as_ref().map_or(0, |i| i.heap_bytes());
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + (self.av.capacity() + self.af.capacity()) * 4
            + self.edges.capacity() * std::mem::size_of::<EdgeRecord>()
            + index
            + self.stitching.heap_bytes()
            + self.deleted.capacity()
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        let name = |x: u32, prefix: &str| {
            if x == u32::MAX {
                "-".to_string()
            } else {
                format!("{prefix}{x}")
            }
        };
        writeln!(
            w,
            "winged-edge (doppelt verkettete Kantenliste, arestas aladas): the records of the lecture on 3D convex hulls"
        )?;
        writeln!(w, "- = none (the polygon-mesh lecture's N); pccw/nccw = before/after e in fccw (left face, runs v1 -> v2),")?;
        writeln!(w, "pcw/ncw = before/after e in fcw (right face, runs v2 -> v1), each in the face's own cycle")?;
        writeln!(
            w,
            "vertices: {} (coordinates, av = one incident edge)",
            self.positions.len()
        )?;
        for (v, (p, e)) in self.positions.iter().zip(&self.av).enumerate() {
            writeln!(
                w,
                "  v{v}: ({:.3}, {:.3}, {:.3})  av = {}",
                p.x,
                p.y,
                p.z,
                name(e.0, "e")
            )?;
        }
        writeln!(
            w,
            "faces: {} (af = one edge of the face's cycle)",
            self.live_faces
        )?;
        for (f, e) in self.af.iter().enumerate() {
            writeln!(w, "  f{f}: af = {}", name(e.0, "e"))?;
        }
        writeln!(w, "edges: {}", self.live_edges)?;
        writeln!(
            w,
            "  {:>4}  {:>4} {:>4}  {:>5} {:>5}  {:>5} {:>5} {:>5} {:>5}",
            "e", "v1", "v2", "fccw", "fcw", "pccw", "nccw", "pcw", "ncw"
        )?;
        for (e, r) in self.edges.iter().enumerate() {
            writeln!(
                w,
                "  {:>4}  {:>4} {:>4}  {:>5} {:>5}  {:>5} {:>5} {:>5} {:>5}",
                format!("e{e}"),
                name(r.v1.0, "v"),
                name(r.v2.0, "v"),
                name(r.fccw.0, "f"),
                name(r.fcw.0, "f"),
                name(r.pccw.0, "e"),
                name(r.nccw.0, "e"),
                name(r.pcw.0, "e"),
                name(r.ncw.0, "e"),
            )?;
        }
        writeln!(
            w,
            "all edges of a vertex: rotate from av through the wings, O(k)"
        )
    }
}

impl WingedEdge {
    /// [`MeshTopology::from_soup`] without copying the coordinates: the structure takes the
    /// soup's (the 3D hull algorithms start from a soup of all their points).
    pub fn from_owned_soup(mut soup: PolygonSoup) -> Result<Self> {
        let mut mesh = Self::records_of(&soup)?;
        mesh.positions = std::mem::take(&mut soup.positions);
        Ok(mesh)
    }

    /// Everything [`MeshTopology::from_soup`] builds except the coordinates (left empty).
    fn records_of(soup: &PolygonSoup) -> Result<Self> {
        let conn = soup.manifold_connectivity()?;
        let corner_face = |c: usize| conn.corner_face[c] as usize;
        // The edges leaving the corners before and after corner c in its face.
        let wings = |c: usize| {
            let f = corner_face(c);
            (
                EdgeId(conn.corner_edge[soup.prev_corner(c, f)]),
                EdgeId(conn.corner_edge[soup.next_corner(c, f)]),
            )
        };
        let mut edges = Vec::with_capacity(conn.num_edges());
        for &[first, other] in &conn.edge_corners {
            let first = first as usize;
            let (pccw, nccw) = wings(first);
            let mut record = EdgeRecord {
                v1: VertexId(soup.indices()[first]),
                v2: VertexId(soup.indices()[soup.next_corner(first, corner_face(first))]),
                fccw: FaceId::new(corner_face(first)),
                pccw,
                nccw,
                ..EdgeRecord::REMOVED
            };
            if other != u32::MAX {
                let other = other as usize;
                (record.pcw, record.ncw) = wings(other);
                record.fcw = FaceId::new(corner_face(other));
            }
            edges.push(record);
        }
        // av(v): the edge leaving v's last corner; af(f): the edge leaving f's first corner.
        let mut av = vec![EdgeId::INVALID; soup.num_vertices()];
        for (&v, &e) in soup.indices().iter().zip(&conn.corner_edge) {
            av[v as usize] = EdgeId(e);
        }
        let af = (0..soup.num_faces())
            .map(|f| EdgeId(conn.corner_edge[soup.face_start(f)]))
            .collect();
        Ok(Self {
            positions: Vec::new(),
            av,
            af,
            live_edges: edges.len(),
            live_faces: soup.num_faces(),
            edges,
            index: None,
            stitching: Default::default(),
            deleted: Vec::new(),
        })
    }
}
