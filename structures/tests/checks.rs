//! The consistency checks: clean meshes are clean and their summary agrees with the one
//! computed through a structure; each problem is found, on the right elements.

use glam::DVec3;
use proptest::prelude::*;
use topolab_structures::checks::{check, FindingKind, Options, Report};
use topolab_structures::io::{read_bytes_raw, RawSoup};
use topolab_structures::meshes::{self, RandomMeshParams};
use topolab_structures::summary::{summarize, Summary};
use topolab_structures::testing::{differential, oracle::Oracle};
use topolab_structures::{Format, MeshTopology, PolygonSoup, VertexList};

fn report(soup: &PolygonSoup) -> Report {
    let raw = RawSoup {
        soup: soup.clone(),
        ..RawSoup::default()
    };
    check(&raw, &Options::default())
}

fn kinds(r: &Report) -> Vec<FindingKind> {
    let mut k: Vec<FindingKind> = r.findings.iter().map(|f| f.kind).collect();
    k.dedup();
    k
}

/// The summary of `check` agrees with `summarize` through the vertex list, and both with the
/// oracle, on every field they share.
fn agrees_with_the_structure(soup: &PolygonSoup, r: &Report) {
    let s = summarize(&VertexList::from_soup(soup).unwrap());
    let mut oracle = Oracle::new(soup).summary();
    oracle.structure = s.structure;
    assert_eq!(s, oracle);
    agrees_with_info(&oracle, r);
}

/// The fields `check`'s summary shares with `info`'s (`expected`) are equal.
fn agrees_with_info(expected: &Summary, r: &Report) {
    let c = &r.summary;
    assert_eq!(c.vertices, expected.vertices);
    assert_eq!(c.faces, expected.faces);
    assert_eq!(c.edges, expected.edges);
    assert_eq!(c.boundary_edges, expected.boundary_edges);
    assert_eq!(c.boundary_curves, expected.boundary_curves);
    assert_eq!(
        c.boundary_curves_undefined,
        expected.boundary_curves_undefined
    );
    assert_eq!(c.components.len(), expected.components);
    assert_eq!(c.euler_characteristic, expected.euler_characteristic);
    // One component: its genus is the mesh's, where info defines it.
    if expected.genus.is_some() {
        assert_eq!(c.components.get(0).unwrap().genus, expected.genus);
    }
}

#[test]
fn canonical_meshes_are_clean_except_the_bowtie_and_agree_with_summarize() {
    for m in meshes::canonical() {
        let r = report(&m.soup);
        let expected = if m.name == "bowtie" {
            vec![FindingKind::NonManifoldVertex]
        } else {
            vec![]
        };
        assert_eq!(kinds(&r), expected, "{}: {:?}", m.name, r.findings);
        agrees_with_the_structure(&m.soup, &r);
    }
    let torus = report(&meshes::torus(5, 4));
    assert_eq!(torus.summary.components.get(0).unwrap().genus, Some(1));
    let annulus = report(&meshes::annulus(6));
    assert_eq!(annulus.summary.boundary_curves, Some(2));
}

/// The soup of issue #38 (five vertices of two fans): four boundary curves, per fan.
#[test]
fn check_counts_boundary_curves_per_fan() {
    let soup = differential::two_fan_soup();
    let r = report(&soup);
    assert_eq!(r.summary.boundary_curves, Some(4));
    agrees_with_the_structure(&soup, &r);
}

proptest! {
    /// On the differential test's soups that every structure may store (they pass
    /// `PolygonSoup::check`, and no face repeats another, which `check` sets aside), `check`'s
    /// summary says what `info` says.
    #[test]
    fn check_and_info_agree_on_the_fields_they_share(soup in differential::info_soups()) {
        let r = report(&soup);
        let duplicates = r.findings.iter().any(|f| f.kind == FindingKind::DuplicateFace);
        if soup.check().is_ok() && !duplicates {
            agrees_with_info(&Oracle::new(&soup).summary(), &r);
        }
    }

    #[test]
    fn random_meshes_agree_with_summarize(seed in any::<u64>()) {
        let soup = meshes::random_mesh(seed, RandomMeshParams::default());
        let r = report(&soup);
        agrees_with_the_structure(&soup, &r);
        // The generator jitters z, so its quads are not planar.
        let allowed = [
            FindingKind::UnusedVertex,
            FindingKind::NonManifoldVertex,
            FindingKind::NonPlanarFace,
        ];
        prop_assert!(r.findings.iter().all(|f| allowed.contains(&f.kind)), "{:?}", r.findings);
    }
}

/// A triangulated Möbius strip of `n` quads.
fn mobius(n: usize) -> PolygonSoup {
    let mut s = PolygonSoup::new();
    for i in 0..n {
        let t = std::f64::consts::TAU * i as f64 / n as f64;
        for w in [-0.3, 0.3] {
            let r = 1.0 + w * (t / 2.0).cos();
            s.push_vertex(DVec3::new(r * t.cos(), r * t.sin(), w * (t / 2.0).sin()));
        }
    }
    for i in 0..n as u32 {
        let (a, b) = (2 * i, 2 * i + 1);
        let (c, d) = if i + 1 < n as u32 {
            (a + 2, a + 3)
        } else {
            (1, 0)
        };
        s.push_face(&[a, c, d]);
        s.push_face(&[a, d, b]);
    }
    s
}

#[test]
fn a_mobius_strip_is_a_non_orientable_manifold_with_one_boundary_curve() {
    let r = report(&mobius(7));
    assert_eq!(
        kinds(&r),
        vec![
            FindingKind::InconsistentOrientation,
            FindingKind::NonOrientable
        ]
    );
    let c = r.summary.components.get(0).unwrap();
    assert_eq!((c.orientable, c.manifold), (false, true));
    assert_eq!(
        (c.euler_characteristic, c.boundary_curves, c.genus),
        (0, Some(1), None)
    );
    // A flipped face of an orientable strip is inconsistent but orientable.
    let mut band = PolygonSoup::new();
    band.positions = meshes::quad_strip(3).positions;
    let strip = meshes::quad_strip(3);
    for (j, f) in strip.faces().enumerate() {
        let mut f = f.to_vec();
        if j == 1 {
            f.reverse();
        }
        band.push_face(&f);
    }
    let r = report(&band);
    assert_eq!(kinds(&r), vec![FindingKind::InconsistentOrientation]);
    assert!(r.summary.components.get(0).unwrap().orientable);
}

#[test]
fn an_empty_mesh_is_a_finding_and_a_point_cloud_is_not_an_empty_mesh() {
    for (text, format) in [
        ("", Format::Obj),
        ("# nothing but a comment\no empty\n", Format::Obj),
        ("OFF\n0 0 0\n", Format::Off),
    ] {
        let raw = read_bytes_raw(text.as_bytes(), format).unwrap();
        let r = check(&raw, &Options::default());
        assert_eq!(kinds(&r), vec![FindingKind::EmptyMesh], "{text:?}");
        assert!(!r.is_clean());
        assert_eq!(r.summary.counts.get("empty-mesh"), Some(&1));
    }
    let cloud = read_bytes_raw(b"v 0 0 0\nv 1 0 0\n", Format::Obj).unwrap();
    let r = check(&cloud, &Options::default());
    assert_eq!(kinds(&r), vec![FindingKind::UnusedVertex]);
}

#[test]
fn findings_name_the_faces_of_the_file_even_after_unusable_faces() {
    // Face 0 is missing a vertex, face 1 has two corners; faces 2, 3, 4 share edge (0, 1).
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n\
        f 1 2 9\nf 1 2\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
    let raw = read_bytes_raw(text.as_bytes(), Format::Obj).unwrap();
    let r = check(&raw, &Options::default());
    let edge = r
        .findings
        .iter()
        .find(|f| f.kind == FindingKind::NonManifoldEdge)
        .expect("a non-manifold edge");
    assert_eq!(
        (edge.vertices.clone(), edge.faces.clone()),
        (vec![0, 1], vec![2, 3, 4])
    );
    let missing = &r.findings[0];
    assert_eq!(
        (missing.kind, missing.faces.clone()),
        (FindingKind::MissingVertex, vec![0])
    );
    // Messages number as the file does (OBJ from 1); the ids stay the lab's.
    assert!(
        missing.message.starts_with("face 1 refers to vertices [9]"),
        "{}",
        missing.message
    );
    assert!(
        edge.message
            .starts_with("edge (1, 2) is shared by 3 faces [3, 4, 5]"),
        "{}",
        edge.message
    );
    assert_eq!(r.summary.usable_faces, 3);
}

#[test]
fn duplicate_vertices_are_found_within_the_tolerance_across_grid_cells() {
    let near = |d: f64| {
        let mut s = meshes::single_triangle();
        s.push_vertex(DVec3::new(0.99e-9, 0.0, 0.0));
        s.push_vertex(DVec3::new(0.99e-9 + d, 0.0, 0.0));
        s
    };
    let raw = |s: PolygonSoup| RawSoup {
        soup: s,
        ..RawSoup::default()
    };
    let duplicates = |r: &Report| -> Vec<Vec<u32>> {
        r.findings
            .iter()
            .filter(|f| f.kind == FindingKind::DuplicateVertices)
            .map(|f| f.vertices.clone())
            .collect()
    };
    // 0.99e-9 and 1.01e-9 sit in different cells of size 1e-9 but within the tolerance.
    let r = check(&raw(near(0.02e-9)), &Options::default());
    assert_eq!(duplicates(&r), vec![vec![0, 3, 4]]);
    let strict = Options {
        tolerance: 0.0,
        ..Options::default()
    };
    assert_eq!(
        duplicates(&check(&raw(near(0.0)), &strict)),
        vec![vec![3, 4]]
    );
    assert!(duplicates(&check(&raw(near(0.02e-9)), &strict)).is_empty());
}

#[test]
fn polygon_checks_tell_planar_convex_and_simple_apart() {
    let quad = |p: [[f64; 3]; 4]| {
        PolygonSoup::from_polygons(p.map(DVec3::from_array).to_vec(), &[[0u32, 1, 2, 3]])
    };
    let cases = [
        (
            quad([[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]]),
            vec![],
        ),
        (
            quad([[0., 0., 0.], [1., 0., 0.], [1., 1., 0.3], [0., 1., 0.]]),
            vec![FindingKind::NonPlanarFace],
        ),
        (
            quad([[0., 0., 0.], [2., 0., 0.], [1., 0.5, 0.], [1., 2., 0.]]),
            vec![FindingKind::NonConvexFace],
        ),
        (
            quad([[0., 0., 0.], [2., 2., 0.], [2., 0., 0.], [0., 1., 0.]]),
            vec![FindingKind::NonSimpleFace],
        ),
        (
            quad([[0., 0., 0.], [1., 0., 0.], [2., 0., 0.], [3., 0., 0.]]),
            vec![FindingKind::DegenerateFace],
        ),
        // A collinear corner is neither a left nor a right turn.
        (
            quad([[0., 0., 0.], [1., 0., 0.], [2., 0., 0.], [1., 1., 0.]]),
            vec![],
        ),
    ];
    for (soup, expected) in cases {
        assert_eq!(kinds(&report(&soup)), expected, "{:?}", soup.positions);
    }
    // Within a generous planarity tolerance the bent quad is planar.
    let bent = quad([[0., 0., 0.], [1., 0., 0.], [1., 1., 0.3], [0., 1., 0.]]);
    let loose = Options {
        planarity_tolerance: 0.5,
        ..Options::default()
    };
    let raw = RawSoup {
        soup: bent,
        ..RawSoup::default()
    };
    assert!(check(&raw, &loose).findings.is_empty());
}
