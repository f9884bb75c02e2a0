//! The shared conformance suite: every operator of a structure compared with the [`Oracle`].
//!
//! [`check`] is the whole suite for one mesh; the [`conformance!`](macro@crate::conformance) macro
//! turns it into tests over every canonical mesh and random meshes (proptest) for a structure.
//! `structures/tests/conformance.rs` runs it on every structure of the registry, so a
//! registered structure is conformance-tested without a line of its own:
//!
//! ```ignore
//! topolab_structures::for_each_structure!(topolab_structures::conformance);
//! ```
//!
//! Relations are compared as multisets, R20 and R21 as cyclic sequences (any rotation, same
//! direction); edges are compared by their end vertices. A structure that cannot store a mesh
//! must refuse it with the error its [`Capabilities`] announce, and only then.

use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, MeshTopology};
use crate::meshes::{self, RandomMeshParams};
use crate::testing::oracle::{pair, Oracle, Pair};
use std::collections::BTreeSet;

/// What happened when a structure met a mesh.
#[derive(Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Built, and every answer matched the oracle.
    Conforms,
    /// Refused, as its capabilities say it must, with this error kind.
    Refused(&'static str),
}

/// The error kinds a structure with `caps` must answer `soup` with, or `None` if it must build.
pub fn expected_refusals(
    soup: &PolygonSoup,
    caps: Capabilities,
    is_grid: bool,
) -> Option<Vec<&'static str>> {
    let mut kinds = Vec::new();
    match soup.connectivity() {
        Err(e) => kinds.push(e.kind()),
        Ok(c) => {
            if !caps.non_manifold_vertices && c.vertex_fans(soup).iter().any(|&n| n > 1) {
                kinds.push("non-manifold-vertex");
            }
        }
    }
    if caps.triangles_only && !soup.is_triangle_mesh() {
        kinds.push("not-triangles");
    }
    if caps.grids_only && !is_grid {
        kinds.push("not-a-grid");
    }
    if caps.distinct_positions {
        let mut seen = BTreeSet::new();
        if !soup
            .positions
            .iter()
            .all(|p| seen.insert(p.to_array().map(f64::to_bits)))
        {
            kinds.push("coincident-vertices");
        }
    }
    (!kinds.is_empty()).then_some(kinds)
}

/// Builds `M` from `soup` and compares every operator with the oracle. `is_grid` says whether
/// the soup is one of [`meshes::grid`]'s (for grid-only structures).
pub fn check<M: MeshTopology>(soup: &PolygonSoup, is_grid: bool) -> Result<Outcome, String> {
    let expected = expected_refusals(soup, M::capabilities(), is_grid);
    let built = M::from_soup(soup);
    match (expected, built) {
        (Some(kinds), Err(e)) if kinds.contains(&e.kind()) => Ok(Outcome::Refused(e.kind())),
        (Some(kinds), Err(e)) => Err(format!(
            "refused with {} ({e}); expected one of {kinds:?}",
            e.kind()
        )),
        (Some(kinds), Ok(_)) => Err(format!("built a mesh it must refuse with one of {kinds:?}")),
        (None, Err(e)) => Err(format!("refused a mesh it must store: {e}")),
        (None, Ok(m)) => compare(&m, soup).map(|()| Outcome::Conforms),
    }
}

fn sorted<T: Ord>(mut v: Vec<T>) -> Vec<T> {
    v.sort_unstable();
    v
}

/// `a` equals `b` up to a rotation.
fn cyclic_eq<T: PartialEq>(a: &[T], b: &[T]) -> bool {
    a.len() == b.len()
        && (a.is_empty()
            || (0..a.len()).any(|r| (0..a.len()).all(|i| a[(i + r) % a.len()] == b[i])))
}

macro_rules! ensure {
    ($cond:expr, $($fmt:tt)*) => {
        if !$cond {
            return Err(format!($($fmt)*));
        }
    };
}

/// Compares every answer of a built structure with the oracle of `soup`.
pub fn compare<M: MeshTopology>(m: &M, soup: &PolygonSoup) -> Result<(), String> {
    let o = Oracle::new(soup);
    m.validate()
        .map_err(|e| format!("validate() failed: {e}"))?;
    ensure!(
        m.num_vertices() == soup.num_vertices(),
        "num_vertices {} != {}",
        m.num_vertices(),
        soup.num_vertices()
    );
    ensure!(
        m.num_faces() == soup.num_faces(),
        "num_faces {} != {}",
        m.num_faces(),
        soup.num_faces()
    );
    ensure!(
        m.num_edges() == o.edge_faces.len(),
        "num_edges {} != {}",
        m.num_edges(),
        o.edge_faces.len()
    );
    let ends = |e: EdgeId| {
        let [a, b] = m.edge_vertices(e);
        pair(a.0, b.0)
    };
    // Edge ids: each edge once, and R10 names every oracle edge.
    let mut edges = Vec::new();
    m.for_each_edge(|e| edges.push(e));
    ensure!(
        edges.len() == o.edge_faces.len(),
        "for_each_edge gave {} edges, expected {}",
        edges.len(),
        o.edge_faces.len()
    );
    ensure!(
        edges.iter().collect::<BTreeSet<_>>().len() == edges.len(),
        "for_each_edge repeats an edge id"
    );
    let edge_pairs = sorted(edges.iter().map(|&e| ends(e)).collect::<Vec<_>>());
    let oracle_pairs: Vec<Pair> = o.edge_faces.keys().copied().collect();
    ensure!(
        edge_pairs == oracle_pairs,
        "R10 over all edges gives {edge_pairs:?}, expected {oracle_pairs:?}"
    );
    let boundary = o.boundary_edges();
    ensure!(
        m.num_boundary_edges() == boundary.len(),
        "num_boundary_edges {} != {}",
        m.num_boundary_edges(),
        boundary.len()
    );

    for v in 0..soup.num_vertices() {
        let vid = VertexId::new(v);
        ensure!(m.position(vid) == soup.positions[v], "position of v{v}");
        let mut vv = Vec::new();
        m.vertex_vertices(vid, |w| vv.push(w.0));
        ensure!(
            sorted(vv.clone()) == o.vertex_vertices[v],
            "R00(v{v}) = {vv:?}, expected {:?}",
            o.vertex_vertices[v]
        );
        let mut ve = Vec::new();
        m.vertex_edges(vid, |e| ve.push(ends(e)));
        ensure!(
            sorted(ve.clone()) == o.vertex_edges[v],
            "R01(v{v}) = {ve:?}, expected {:?}",
            o.vertex_edges[v]
        );
        let mut vf = Vec::new();
        m.vertex_faces(vid, |f| vf.push(f.0));
        ensure!(
            sorted(vf.clone()) == o.vertex_faces[v],
            "R02(v{v}) = {vf:?}, expected {:?}",
            o.vertex_faces[v]
        );
        ensure!(
            m.is_boundary_vertex(vid) == o.boundary_vertex[v],
            "is_boundary_vertex(v{v}) = {}, expected {}",
            m.is_boundary_vertex(vid),
            o.boundary_vertex[v]
        );
    }
    for &e in &edges {
        let p = ends(e);
        let mut ee = Vec::new();
        m.edge_edges(e, |x| ee.push(ends(x)));
        ensure!(
            sorted(ee.clone()) == o.edge_edges(p),
            "R11({p:?}) = {ee:?}, expected {:?}",
            o.edge_edges(p)
        );
        let mut ef = Vec::new();
        m.edge_faces(e, |f| ef.push(f.0));
        ensure!(
            sorted(ef.clone()) == o.edge_faces[&p],
            "R12({p:?}) = {ef:?}, expected {:?}",
            o.edge_faces[&p]
        );
        ensure!(
            m.is_boundary_edge(e) == o.is_boundary_edge(p),
            "is_boundary_edge({p:?}) wrong"
        );
    }
    for f in 0..soup.num_faces() {
        let fid = FaceId::new(f);
        let mut fv = Vec::new();
        m.face_vertices(fid, |v| fv.push(v.0));
        ensure!(
            cyclic_eq(&fv, &o.faces[f]),
            "R20(f{f}) = {fv:?}, expected a rotation of {:?}",
            o.faces[f]
        );
        let mut fe = Vec::new();
        m.face_edges(fid, |e| fe.push(e));
        let fe_pairs: Vec<Pair> = fe.iter().map(|&e| ends(e)).collect();
        ensure!(
            cyclic_eq(&fe_pairs, &o.face_edges(f)),
            "R21(f{f}) = {fe_pairs:?}, expected a rotation of {:?}",
            o.face_edges(f)
        );
        let mut ff = Vec::new();
        m.face_faces(fid, |g| ff.push(g.0));
        ensure!(
            sorted(ff.clone()) == o.face_faces(f),
            "R22(f{f}) = {ff:?}, expected {:?}",
            o.face_faces(f)
        );
        // Successor and predecessor along the face's cycle, by end vertices.
        let k = fe.len();
        for i in 0..k {
            let succ = m.edge_successor(fe[i], fid).map(ends);
            ensure!(
                succ == Some(fe_pairs[(i + 1) % k]),
                "successor of {:?} in f{f} = {succ:?}, expected {:?}",
                fe_pairs[i],
                fe_pairs[(i + 1) % k]
            );
            let pred = m.edge_predecessor(fe[i], fid).map(ends);
            ensure!(
                pred == Some(fe_pairs[(i + k - 1) % k]),
                "predecessor of {:?} in f{f} = {pred:?}, expected {:?}",
                fe_pairs[i],
                fe_pairs[(i + k - 1) % k]
            );
        }
    }
    // An edge not in a face has no successor there.
    if let (Some(&e), true) = (edges.first(), soup.num_faces() > 1) {
        let faces = &o.edge_faces[&ends(e)];
        if let Some(g) = (0..soup.num_faces() as u32).find(|g| !faces.contains(g)) {
            ensure!(
                m.edge_successor(e, FaceId(g)).is_none(),
                "successor of an edge in a face it does not bound"
            );
            ensure!(
                m.edge_predecessor(e, FaceId(g)).is_none(),
                "predecessor of an edge in a face it does not bound"
            );
        }
    }
    check_boundary_curves(m, &o, &boundary, ends)
}

fn check_boundary_curves<M: MeshTopology>(
    m: &M,
    o: &Oracle,
    boundary: &[Pair],
    ends: impl Fn(EdgeId) -> Pair,
) -> Result<(), String> {
    let mut curves = BoundaryCurves::default();
    // A dirty buffer must be cleared by the structure.
    curves.edges.push(EdgeId(12345));
    curves.starts = vec![0, 1];
    m.boundary_curves(&mut curves);
    let mut all = Vec::new();
    for i in 0..curves.len() {
        let c: Vec<Pair> = curves.curve(i).iter().map(|&e| ends(e)).collect();
        ensure!(!c.is_empty(), "boundary curve {i} is empty");
        // Consecutive edges share a vertex, and the walk closes.
        let shared = |x: Pair, y: Pair| x.0 == y.0 || x.0 == y.1 || x.1 == y.0 || x.1 == y.1;
        for j in 0..c.len() {
            ensure!(
                shared(c[j], c[(j + 1) % c.len()]),
                "boundary curve {i} = {c:?} is not a closed chain"
            );
        }
        all.extend(c);
    }
    ensure!(
        sorted(all.clone()) == boundary,
        "boundary curves cover {all:?}, expected each boundary edge once: {boundary:?}"
    );
    if let Ok(n) = o.boundary_curve_count() {
        ensure!(
            curves.len() == n,
            "{} boundary curves, expected {n}",
            curves.len()
        );
    }
    Ok(())
}

/// Random-mesh parameters that fit a structure's capabilities.
pub fn random_params(caps: Capabilities) -> RandomMeshParams {
    RandomMeshParams {
        triangles_only: caps.triangles_only,
        ..RandomMeshParams::default()
    }
}

/// The random mesh of `seed` for a structure (a random grid for grid-only structures), and
/// whether it is a grid.
pub fn random_case(seed: u64, caps: Capabilities) -> (PolygonSoup, bool) {
    if caps.grids_only {
        let (nx, ny) = (1 + (seed % 6) as usize, 1 + ((seed / 6) % 5) as usize);
        (
            meshes::grid(nx, ny, caps.triangles_only || seed.is_multiple_of(2)),
            true,
        )
    } else {
        (meshes::random_mesh(seed, random_params(caps)), false)
    }
}

/// Asserts that `M` conforms on canonical mesh `name` (refusing only what it must).
pub fn assert_canonical<M: MeshTopology>(name: &str) {
    let mesh =
        meshes::canonical_by_name(name).unwrap_or_else(|| panic!("no canonical mesh {name}"));
    match check::<M>(&mesh.soup, mesh.grid) {
        Ok(_) => {}
        Err(msg) => panic!("{} on {name}: {msg}", M::NAME),
    }
}

/// The structures of `registered` that `tested` leaves out, and those it tests that are not
/// registered: `Err` names them. The conformance suite's enrolment check (see
/// [`conformance!`](macro@crate::conformance)).
pub fn check_enrolment(tested: &[&str], registered: &[&str]) -> Result<(), String> {
    let missing: Vec<&str> = registered
        .iter()
        .copied()
        .filter(|n| !tested.contains(n))
        .collect();
    let unknown: Vec<&str> = tested
        .iter()
        .copied()
        .filter(|n| !registered.contains(n))
        .collect();
    if missing.is_empty() && unknown.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "registered but not conformance-tested: {missing:?}; tested but not registered: \
             {unknown:?} (generate the suite with for_each_structure!(conformance))"
        ))
    }
}

/// Generates conformance tests: for one structure, one test per canonical mesh (from
/// [`for_each_canonical_mesh!`](crate::for_each_canonical_mesh)) and a proptest on random
/// meshes; for a list `module => Type, ...` (what
/// [`for_each_structure!`](crate::for_each_structure) passes), those of each structure plus
/// `every_registered_structure_is_conformance_tested`, which fails unless the list is exactly
/// [`registry::NAMES`](crate::registry::NAMES).
///
/// The one-structure form is how a structure outside the lab gets the whole suite as its own
/// tests (the template `extend/sorted-edge-table/tests/conformance.rs` does): the macro
/// reaches proptest through this crate, so the calling crate needs no dependency but
/// `topolab-structures`.
///
/// ```ignore
/// topolab_structures::for_each_structure!(topolab_structures::conformance); // every structure
/// topolab_structures::conformance!(openmesh, topolab::openmesh::OpenMesh);  // one more
/// ```
#[macro_export]
macro_rules! conformance {
    ($($module:ident => $ty:ty $([$($capability:ident),*])?),+ $(,)?) => {
        $( $crate::conformance!($module, $ty); )+

        #[test]
        fn every_registered_structure_is_conformance_tested() {
            let tested = [$(<$ty as $crate::MeshTopology>::NAME),+];
            if let Err(msg) =
                $crate::testing::conformance::check_enrolment(&tested, $crate::registry::NAMES)
            {
                panic!("{msg}");
            }
        }
    };
    ($module:ident, $ty:ty) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::for_each_canonical_mesh!($crate::conformance; @canonical $ty);

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(48))]
                #[test]
                fn random_meshes(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    let caps = <$ty as $crate::MeshTopology>::capabilities();
                    let (soup, is_grid) = $crate::testing::conformance::random_case(seed, caps);
                    if let Err(msg) = $crate::testing::conformance::check::<$ty>(&soup, is_grid) {
                        panic!("{} on random mesh {seed}: {msg}\n{soup:?}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }
        }
    };
    (@canonical $ty:ty; $($test:ident => $name:literal, $about:literal, $soup:expr, $grid:expr;)*) => {
        $(
            #[test]
            fn $test() {
                $crate::testing::conformance::assert_canonical::<$ty>($name);
            }
        )*
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn enrolment_names_what_is_registered_but_not_tested_and_the_reverse() {
        let registered = ["a", "b", "c"];
        assert_eq!(check_enrolment(&["c", "a", "b"], &registered), Ok(()));
        let err = check_enrolment(&["a", "c", "z"], &registered).unwrap_err();
        assert!(err.contains(r#"not conformance-tested: ["b"]"#), "{err}");
        assert!(err.contains(r#"not registered: ["z"]"#), "{err}");
    }
}
