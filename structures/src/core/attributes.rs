//! Geometric attributes computed through any structure's relations: the face, edge and vertex
//! attributes (*Flächen-, Kanten-, Punkt-Attribute*) of the lecture on polygon-mesh data
//! structures. One implementation serves every structure (a blanket impl), so timing them
//! measures each structure's relations.

use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::MeshTopology;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// A plane `normal · x = offset`, normal of unit length.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Plane {
    /// Unit normal.
    pub normal: DVec3,
    /// Signed distance of the plane from the origin along `normal`.
    pub offset: f64,
}

/// Newell's vector of a polygon, accumulated corner by corner (no allocation): the sum of
/// `p_i × p_{i+1}` around the polygon, whose direction is the normal and length twice the area.
#[derive(Copy, Clone, Debug, Default)]
pub struct NewellSum {
    first: Option<DVec3>,
    prev: DVec3,
    sum: DVec3,
}

impl NewellSum {
    /// Adds the next corner.
    pub fn add(&mut self, p: DVec3) {
        match self.first {
            None => self.first = Some(p),
            Some(_) => self.sum += self.prev.cross(p),
        }
        self.prev = p;
    }

    /// Closes the polygon and returns the vector.
    pub fn finish(self) -> DVec3 {
        match self.first {
            Some(p0) => self.sum + self.prev.cross(p0),
            None => self.sum,
        }
    }
}

/// Attributes of faces, edges and vertices, for every [`MeshTopology`].
pub trait MeshAttributes: MeshTopology {
    /// Newell's vector of a face: its direction is the face normal, its length twice the area
    /// (exact for planar polygons of any size, robust for nearly planar ones).
    fn face_area_vector(&self, face: FaceId) -> DVec3 {
        let mut newell = NewellSum::default();
        self.face_vertices(face, |v| newell.add(self.position(v)));
        newell.finish()
    }

    /// Unit face normal (zero for a degenerate face).
    fn face_normal(&self, face: FaceId) -> DVec3 {
        self.face_area_vector(face).normalize_or_zero()
    }

    /// Face area.
    fn face_area(&self, face: FaceId) -> f64 {
        0.5 * self.face_area_vector(face).length()
    }

    /// The face's plane through its centroid.
    fn face_plane(&self, face: FaceId) -> Plane {
        let normal = self.face_normal(face);
        let (mut sum, mut n) = (DVec3::ZERO, 0.0f64);
        self.face_vertices(face, |v| {
            sum += self.position(v);
            n += 1.0;
        });
        Plane {
            normal,
            offset: normal.dot(sum / n.max(1.0)),
        }
    }

    /// Edge length.
    fn edge_length(&self, e: EdgeId) -> f64 {
        let [a, b] = self.edge_vertices(e);
        self.position(a).distance(self.position(b))
    }

    /// Angle between the normals of the two faces of `e` (0 when flat), `None` on the boundary.
    fn dihedral_angle(&self, e: EdgeId) -> Option<f64> {
        let mut faces = [None, None];
        let mut i = 0;
        self.edge_faces(e, |f| {
            if i < 2 {
                faces[i] = Some(f);
            }
            i += 1;
        });
        match faces {
            [Some(f), Some(g)] => {
                let (a, b) = (self.face_normal(f), self.face_normal(g));
                Some(a.dot(b).clamp(-1.0, 1.0).acos())
            }
            _ => None,
        }
    }

    /// The lecture's sharp edge (feature line): a dihedral angle above `threshold` radians, or a
    /// boundary edge. Other edges are "virtual" and should vanish in rendering.
    fn is_sharp_edge(&self, e: EdgeId, threshold: f64) -> bool {
        self.dihedral_angle(e).is_none_or(|a| a > threshold)
    }

    /// Vertex normal: the area-weighted mean of its faces' normals.
    fn vertex_normal(&self, v: VertexId) -> DVec3 {
        let mut sum = DVec3::ZERO;
        self.vertex_faces(v, |f| sum += self.face_area_vector(f));
        sum.normalize_or_zero()
    }

    /// Interior angle of `face` at its corner `v` (0 if `v` is not a corner). Two walks
    /// around the face: one to find `v`, one to read its two neighbours.
    fn corner_angle(&self, face: FaceId, v: VertexId) -> f64 {
        let (mut k, mut at) = (0usize, None);
        self.face_vertices(face, |w| {
            if w == v {
                at = Some(k);
            }
            k += 1;
        });
        let Some(i) = at else { return 0.0 };
        let (ib, ia) = ((i + k - 1) % k, (i + 1) % k);
        let (mut before, mut after, mut j) = (v, v, 0);
        self.face_vertices(face, |w| {
            if j == ib {
                before = w;
            }
            if j == ia {
                after = w;
            }
            j += 1;
        });
        let p = self.position(v);
        (self.position(before) - p).angle_between(self.position(after) - p)
    }

    /// Discrete Gaussian curvature estimate: the angle defect, 2π minus the corner angles
    /// around an interior vertex (π minus them on the boundary).
    fn angle_defect(&self, v: VertexId) -> f64 {
        let mut sum = 0.0;
        self.vertex_faces(v, |f| sum += self.corner_angle(f, v));
        let full = if self.is_boundary_vertex(v) { PI } else { TAU };
        full - sum
    }
}

impl<M: MeshTopology> MeshAttributes for M {}
