//! The edge analysis of the usable faces: non-manifold edges and vertices, orientation and
//! orientability, and per component its Euler characteristic, boundary and genus.

use super::{CheckSummary, Component, FindingKind, Findings};
use crate::algorithms::summary::Undefined;
use crate::algorithms::union_find::UnionFind;
use crate::core::error::Error;
use crate::core::soup::{Connectivity, PolygonSoup};
use std::collections::{BTreeMap, HashSet};

/// The edge analysis (non-manifold edges and vertices, orientation), components, boundary
/// curves, Euler characteristic and genus, on `clean` (the faces `kept` of `soup`).
pub(super) fn topology(
    clean: &PolygonSoup,
    kept: &[u32],
    soup: &PolygonSoup,
    found: &mut Findings,
) -> CheckSummary {
    let ids = found.numbering();
    let (conn, problems) = Connectivity::analyse(clean, false);
    let original = |f: u32| kept[f as usize];
    let nf = clean.num_faces();
    // Components: faces joined through shared vertices, keyed by the root of their vertices.
    let mut joined = UnionFind::new(clean.num_vertices());
    for face in clean.faces() {
        for w in face.windows(2) {
            joined.union(w[0], w[1], false);
        }
    }
    let root_of_face: Vec<u32> = clean.faces().map(|f| joined.find(f[0]).0).collect();
    let mut components: BTreeMap<u32, Component> = BTreeMap::new();
    // Orientation: faces across an interior edge agree (parity 0), across an edge both
    // traverse the same way they disagree (parity 1); an odd cycle means no orientation exists.
    let mut orientation = UnionFind::new(nf);
    let mut first_face_of_non_orientable: BTreeMap<u32, u32> = BTreeMap::new();
    let mut relate = |f: u32, g: u32, flip: bool, orientation: &mut UnionFind| {
        if !orientation.union(f, g, flip) {
            first_face_of_non_orientable
                .entry(root_of_face[f as usize])
                .or_insert(original(f));
        }
    };
    // Components where an edge has more than two faces: their boundary curves are undefined.
    let mut with_non_manifold_edge = HashSet::new();
    for problem in problems {
        match problem {
            Error::NonManifoldEdge { a, b, faces } => {
                let root = joined.find(a).0;
                component(&mut components, root).manifold = false;
                with_non_manifold_edge.insert(root);
                found.add(FindingKind::NonManifoldEdge, || {
                    let faces: Vec<u32> = faces.into_iter().map(original).collect();
                    (
                        vec![a, b],
                        faces.clone(),
                        format!(
                            "edge ({}, {}) is shared by {} faces {}",
                            ids.id(a),
                            ids.id(b),
                            faces.len(),
                            ids.list(&faces)
                        ),
                    )
                });
            }
            Error::InconsistentOrientation { a, b, f, g } => {
                let (f, g) = (original(f), original(g));
                found.add(FindingKind::InconsistentOrientation, || {
                    (
                        vec![a, b],
                        vec![f, g],
                        format!(
                            "faces {} and {} both traverse edge ({} -> {})",
                            ids.id(f),
                            ids.id(g),
                            ids.id(a),
                            ids.id(b)
                        ),
                    )
                });
            }
            _ => {}
        }
    }
    for (v, &fans) in conn.vertex_fans(clean).iter().enumerate() {
        if fans > 1 {
            component(&mut components, joined.find(v as u32).0).manifold = false;
            found.add(FindingKind::NonManifoldVertex, || {
                (
                    vec![v as u32],
                    vec![],
                    format!(
                        "vertex {}: its faces form {fans} separate fans",
                        ids.id(v as u64)
                    ),
                )
            });
        }
    }
    // Corners per edge: 1 on the boundary, 2 for an interior edge (or an inconsistent pair),
    // more on a non-manifold edge.
    let mut corners_per_edge = vec![0u32; conn.num_edges()];
    for &e in &conn.corner_edge {
        corners_per_edge[e as usize] += 1;
    }
    // Boundary curves per fan (the definition of `crate::summary`): each boundary edge joins
    // the fan of its face at one end with the fan of its face at the other; a curve is a
    // connected set of fans so joined (each open fan holds two boundary ends).
    let fans = conn.corner_fans(clean);
    let mut curves = UnionFind::new(clean.num_corners());
    let mut boundary_edges = 0;
    for (e, &[c0, c1]) in conn.edge_corners.iter().enumerate() {
        let (f, c0) = (conn.corner_face[c0 as usize], c0 as usize);
        component(&mut components, root_of_face[f as usize]).edges += 1;
        if c1 != u32::MAX {
            let same_direction = clean.indices()[c0] == clean.indices()[c1 as usize];
            relate(
                f,
                conn.corner_face[c1 as usize],
                same_direction,
                &mut orientation,
            );
        } else if corners_per_edge[e] == 1 {
            let next = clean.next_corner(c0, f as usize);
            curves.union(fans[c0], fans[next], false);
            boundary_edges += 1;
        }
    }
    let mut counted_curves = HashSet::new();
    for (e, &[c0, _]) in conn.edge_corners.iter().enumerate() {
        if corners_per_edge[e] == 1 {
            let curve = curves.find(fans[c0 as usize]).0;
            if counted_curves.insert(curve) {
                let f = conn.corner_face[c0 as usize];
                let c = component(&mut components, root_of_face[f as usize]);
                c.boundary_curves = c.boundary_curves.map(|n| n + 1);
            }
        }
    }
    for &root in &root_of_face {
        component(&mut components, root).faces += 1;
    }
    let mut in_use = vec![false; clean.num_vertices()];
    for &v in clean.indices() {
        in_use[v as usize] = true;
    }
    for v in (0..clean.num_vertices() as u32).filter(|&v| in_use[v as usize]) {
        component(&mut components, joined.find(v).0).vertices += 1;
    }
    for (root, face) in first_face_of_non_orientable {
        component(&mut components, root).orientable = false;
        found.add(FindingKind::NonOrientable, || {
            (
                vec![],
                vec![face],
                format!(
                    "the component of face {} cannot be oriented consistently (like a Möbius strip)",
                    ids.id(face)
                ),
            )
        });
    }
    let components: Vec<Component> = components
        .into_iter()
        .map(|(root, mut c)| {
            c.euler_characteristic = c.vertices as i64 - c.edges as i64 + c.faces as i64;
            if with_non_manifold_edge.contains(&root) {
                c.boundary_curves = None;
            }
            // χ = 2 - 2g - b for a connected orientable surface.
            c.genus = match (c.manifold && c.orientable, c.boundary_curves) {
                (true, Some(b)) => Some((2 - c.euler_characteristic - b as i64) / 2),
                _ => None,
            };
            c
        })
        .collect();
    CheckSummary {
        vertices: soup.num_vertices(),
        faces: soup.num_faces(),
        usable_faces: nf,
        edges: conn.num_edges(),
        boundary_edges,
        boundary_curves: components.iter().map(|c| c.boundary_curves).sum(),
        boundary_curves_undefined: (!with_non_manifold_edge.is_empty()).then(|| {
            Undefined::NonManifoldEdges(corners_per_edge.iter().filter(|&&n| n > 2).count())
        }),
        euler_characteristic: components.iter().map(|c| c.euler_characteristic).sum(),
        components,
        counts: BTreeMap::new(),
        near_duplicates_not_exhaustive: 0,
    }
}

/// The component with vertex root `root`, created empty (and manifold) on first use.
fn component(components: &mut BTreeMap<u32, Component>, root: u32) -> &mut Component {
    components.entry(root).or_insert(Component {
        faces: 0,
        vertices: 0,
        edges: 0,
        boundary_curves: Some(0),
        euler_characteristic: 0,
        orientable: true,
        manifold: true,
        genus: None,
    })
}
