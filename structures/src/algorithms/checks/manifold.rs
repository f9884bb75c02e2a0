//! The edge analysis of the usable faces: non-manifold edges and vertices, orientation and
//! orientability, and per component its Euler characteristic, boundary and genus.
//!
//! Memory: the edge analysis ([`Connectivity`]: 8 bytes a corner, 4 of them dropped once the
//! non-manifold edges are marked, and 8 an edge), one union-find forest over the corners for
//! the fans and then the boundary curves, one over the faces for the orientation, a component
//! number a vertex, and the components themselves (20 bytes each: [`Components`]).

use super::{CheckSummary, Components, Counts, FindingKind, Findings, UNDEFINED};
use crate::algorithms::summary::Undefined;
use crate::algorithms::union_find::UnionFind;
use crate::core::error::Error;
use crate::core::soup::{find_root, Connectivity, PolygonSoup};
use std::collections::BTreeMap;

/// No vertex, corner or face.
const NONE: u32 = u32::MAX;

/// The edge analysis (non-manifold edges and vertices, orientation), components, boundary
/// curves, Euler characteristic and genus, on `clean`: the faces `kept` of the soup checked
/// (all of them when `None`), which has `vertices` vertices and `faces` faces.
pub(super) fn topology(
    clean: &PolygonSoup,
    kept: Option<&[u32]>,
    (vertices, faces): (usize, usize),
    found: &mut Findings,
) -> CheckSummary {
    let ids = found.numbering();
    // `clean` may have no positions left ([`super::check_owned`]): `vertices` counts them.
    let (mut conn, problems) = Connectivity::analyse_of(clean, vertices, false);
    // An edge of more than two corners (non-manifold): a corner maps to it that is neither
    // of the two it lists. Any other edge with one corner is on the boundary. Each corner's
    // edge is not read past this: dropped before the components and the fans are made.
    let mut crowded = vec![false; conn.num_edges()];
    for (c, &e) in conn.corner_edge.iter().enumerate() {
        let [c0, c1] = conn.edge_corners[e as usize];
        crowded[e as usize] |= c as u32 != c0 && c as u32 != c1;
    }
    conn.corner_edge = Vec::new();
    let original = |f: u32| kept.map_or(f, |kept| kept[f as usize]);
    let (nf, nc) = (clean.num_faces(), clean.num_corners());
    let indices = clean.indices();
    let (component_of, mut components) = components(clean, vertices);
    let component_of_face = |f: u32| component_of[clean.face(f as usize)[0] as usize] as usize;
    let mut non_manifold_edges = 0;
    for problem in problems {
        match problem {
            Error::NonManifoldEdge { a, b, faces } => {
                let c = &mut components[component_of[a as usize] as usize];
                c.manifold = false;
                // Its boundary curves are undefined where an edge has more than two faces.
                c.boundary_curves = UNDEFINED;
                non_manifold_edges += 1;
                found.add(FindingKind::NonManifoldEdge, || {
                    let faces: Vec<u32> = faces.into_iter().map(&original).collect();
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
    // The fans: one forest over the corners (corners at a vertex joined across interior
    // edges), flattened; a vertex whose corners have more than one root has more than one
    // fan. Per vertex, whether it has none, one or more (a byte); a finding kept counts them.
    let mut fan = conn.fan_forest(clean);
    for c in 0..nc as u32 {
        fan[c as usize] = find_root(&mut fan, c);
    }
    let roots_at = |v: u32, fan: &[u32]| {
        (0..nc)
            .filter(|&c| indices[c] == v && fan[c] == c as u32)
            .count()
    };
    {
        let mut fans = vec![0u8; component_of.len()];
        for c in (0..nc).filter(|&c| fan[c] == c as u32) {
            let n = &mut fans[indices[c] as usize];
            *n = n.saturating_add(1).min(2);
        }
        for v in (0..fans.len()).filter(|&v| fans[v] > 1) {
            components[component_of[v] as usize].manifold = false;
            found.add(FindingKind::NonManifoldVertex, || {
                (
                    vec![v as u32],
                    vec![],
                    format!(
                        "vertex {}: its faces form {} separate fans",
                        ids.id(v as u64),
                        roots_at(v as u32, &fan)
                    ),
                )
            });
        }
    }
    // Orientation: faces across an interior edge agree (parity 0), across an edge both
    // traverse the same way they disagree (parity 1); an odd cycle means no orientation exists.
    // Boundary curves per fan (the definition of `crate::summary`): each boundary edge joins
    // the fan of its face at one end with the fan of its face at the other; a curve is a
    // connected set of fans so joined (each open fan holds two boundary ends). The fans'
    // forest is joined on: its sets become the curves.
    let mut orientation = UnionFind::new(nf);
    // The first face of each component found non-orientable, by component.
    let mut non_orientable: Vec<(u32, u32)> = Vec::new();
    let mut boundary_edges = 0;
    for (e, &[c0, c1]) in conn.edge_corners.iter().enumerate() {
        let f = conn.corner_face[c0 as usize];
        components[component_of_face(f)].edges += 1;
        if c1 != NONE {
            let same_direction = indices[c0 as usize] == indices[c1 as usize];
            let g = conn.corner_face[c1 as usize];
            if !orientation.union(f, g, same_direction) {
                let c = component_of_face(f);
                if components[c].orientable {
                    components[c].orientable = false;
                    non_orientable.push((c as u32, original(f)));
                }
            }
        } else if !crowded[e] {
            let next = clean.next_corner(c0 as usize, f as usize) as u32;
            let (a, b) = (find_root(&mut fan, c0), find_root(&mut fan, next));
            if a != b {
                fan[a as usize] = b;
            }
            boundary_edges += 1;
        }
    }
    drop(orientation);
    let mut counted = vec![false; nc];
    for (e, &[c0, c1]) in conn.edge_corners.iter().enumerate() {
        if c1 == NONE && !crowded[e] {
            let curve = find_root(&mut fan, c0) as usize;
            if !counted[curve] {
                counted[curve] = true;
                let c = &mut components[component_of_face(conn.corner_face[c0 as usize])];
                if c.boundary_curves != UNDEFINED {
                    c.boundary_curves += 1;
                }
            }
        }
    }
    drop((fan, counted, crowded));
    for f in 0..nf as u32 {
        components[component_of_face(f)].faces += 1;
    }
    non_orientable.sort_unstable();
    for (_, face) in non_orientable {
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
    let components = Components(components);
    CheckSummary {
        vertices,
        faces,
        usable_faces: nf,
        edges: conn.num_edges(),
        boundary_edges,
        boundary_curves: components
            .iter()
            .map(|c| c.boundary_curves.map(|n| n as usize))
            .sum(),
        boundary_curves_undefined: (non_manifold_edges > 0)
            .then_some(Undefined::NonManifoldEdges(non_manifold_edges)),
        euler_characteristic: components.iter().map(|c| c.euler_characteristic).sum(),
        components,
        counts: BTreeMap::new(),
        near_duplicates_not_exhaustive: 0,
    }
}

/// Per vertex its component (faces joined through shared vertices; `NONE` for a vertex no
/// face uses), the components numbered in the order of the roots of the vertices'
/// union-find, as the report lists them; and the components, their vertices counted.
fn components(clean: &PolygonSoup, nv: usize) -> (Vec<u32>, Vec<Counts>) {
    let mut joined = UnionFind::new(nv);
    for face in clean.faces() {
        for w in face.windows(2) {
            joined.union(w[0], w[1], false);
        }
    }
    // Used vertices first marked 0, then numbered by root.
    let mut component_of = vec![NONE; nv];
    for &v in clean.indices() {
        component_of[v as usize] = 0;
    }
    let mut roots = 0;
    for v in 0..nv as u32 {
        if component_of[v as usize] != NONE && joined.find(v).0 == v {
            component_of[v as usize] = roots;
            roots += 1;
        }
    }
    for v in 0..nv as u32 {
        if component_of[v as usize] != NONE {
            component_of[v as usize] = component_of[joined.find(v).0 as usize];
        }
    }
    let empty = Counts {
        faces: 0,
        vertices: 0,
        edges: 0,
        boundary_curves: 0,
        orientable: true,
        manifold: true,
    };
    let mut components = vec![empty; roots as usize];
    for &c in component_of.iter().filter(|&&c| c != NONE) {
        components[c as usize].vertices += 1;
    }
    (component_of, components)
}
