//! Adaptive refinement by longest-edge bisection
//! ([`topolab_structures::algorithms::adaptive`]) on every editable structure of the registry:
//! the structures are enrolled from `registry::editable_names()` through
//! `registry::visit_editable`, so a structure marked `[editable]` is tested here without a
//! line of its own.
//!
//! On random triangle meshes (grids with holes, and tori) and random requests (a longest edge
//! between a fifth of the mesh's longest edge and all of it, a box or none), after the
//! refinement: `validate()` holds; `topolab check` finds no kind of problem the input did not
//! have; the topology is the input's (Euler characteristic, boundary curves, components,
//! genus); no edge inside the box is longer than `max_edge`; every input edge not to be split
//! is still an edge and every input vertex where it was; the rounds are within
//! `round_bound` and the faces at least `fewest_faces`; and every structure ends with the
//! same faces (the order is the mesh's, not a structure's).

use proptest::prelude::*;
use std::collections::{BTreeSet, HashSet};
use topolab_structures::algorithms::adaptive::{
    fewest_faces, refine_adaptive, round_bound, AdaptiveReport, Region, Request,
};
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::algorithms::checks::{self, FindingKind};
use topolab_structures::glam::DVec3;
use topolab_structures::io::RawSoup;
use topolab_structures::meshes::{random_mesh, torus, RandomMeshParams};
use topolab_structures::registry::{editable_names, visit_editable, EditVisitor};
use topolab_structures::summary::summarize;
use topolab_structures::{MeshEdit, MeshTopology, PolygonSoup, VertexId};

/// An edge as its two end vertices, the smaller first.
fn key(a: VertexId, b: VertexId) -> (u32, u32) {
    (a.0.min(b.0), a.0.max(b.0))
}

/// The edges of `m` by their end vertices.
fn edges<M: MeshTopology>(m: &M) -> HashSet<(u32, u32)> {
    let mut out = HashSet::new();
    m.for_each_edge(|e| {
        let [a, b] = m.edge_vertices(e);
        out.insert(key(a, b));
    });
    out
}

/// The faces of a soup, each rotated to start at its smallest vertex: the same set whatever
/// the face numbering.
fn face_set(soup: &PolygonSoup) -> BTreeSet<Vec<u32>> {
    (0..soup.num_faces())
        .map(|f| {
            let face = soup.face(f);
            let start = (0..face.len()).min_by_key(|&i| face[i]).unwrap_or(0);
            face.iter()
                .cycle()
                .skip(start)
                .take(face.len())
                .copied()
                .collect()
        })
        .collect()
}

/// The kinds of problem `topolab check` finds in `soup`.
fn problems(soup: &PolygonSoup) -> BTreeSet<FindingKind> {
    let raw = RawSoup {
        soup: soup.clone(),
        ..RawSoup::default()
    };
    checks::check(&raw, &checks::Options::default())
        .findings
        .iter()
        .map(|f| f.kind)
        .collect()
}

/// What one structure made of the input.
struct Outcome {
    name: &'static str,
    report: AdaptiveReport,
    faces: BTreeSet<Vec<u32>>,
}

/// Refines the input on one structure and checks everything that structure alone can show;
/// `Ok(None)` when the structure does not store the input.
struct Refine<'a> {
    soup: &'a PolygonSoup,
    request: &'a Request,
}

impl EditVisitor for Refine<'_> {
    type Output = Result<Option<Outcome>, String>;

    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        let Ok(mut m) = M::from_soup(self.soup) else {
            return Ok(None);
        };
        let (request, name) = (self.request, M::NAME);
        let before = summarize(&m);
        let input_edges = edges(&m);
        let fewest = fewest_faces(&m, request).map_err(|e| format!("{name}: {e}"))?;
        let report =
            refine_adaptive(&mut m, request, usize::MAX).map_err(|e| format!("{name}: {e}"))?;
        m.validate().map_err(|e| format!("{name}: {e}"))?;
        let after = summarize(&m);
        let same_topology = (
            before.euler_characteristic,
            before.boundary_curves,
            before.components,
            before.genus,
        ) == (
            after.euler_characteristic,
            after.boundary_curves,
            after.components,
            after.genus,
        );
        if !same_topology {
            return Err(format!("{name}: topology {before:?} became {after:?}"));
        }
        if report.faces_after != m.num_faces() || (report.faces_after as u128) < fewest {
            return Err(format!(
                "{name}: {report:?}, {} faces, at least {fewest} expected",
                m.num_faces()
            ));
        }
        let bound = round_bound(report.longest, request.max_edge());
        if report.rounds > bound {
            return Err(format!(
                "{name}: {report:?}, past the bound of {bound} rounds"
            ));
        }
        let position = |v: u32| m.position(VertexId(v));
        for &(a, b) in &edges(&m) {
            let (pa, pb) = (position(a), position(b));
            if request.inside(pa, pb) && pa.distance(pb) > request.max_edge() {
                return Err(format!(
                    "{name}: edge {a} - {b} inside, of length {} > {}",
                    pa.distance(pb),
                    request.max_edge()
                ));
            }
        }
        let after_edges = edges(&m);
        for &(a, b) in &input_edges {
            let (pa, pb) = (position(a), position(b));
            let to_split = request.inside(pa, pb) && pa.distance(pb) > request.max_edge();
            if !to_split && !after_edges.contains(&(a, b)) {
                return Err(format!(
                    "{name}: edge {a} - {b} was not to split, but it is gone"
                ));
            }
        }
        if (0..self.soup.num_vertices()).any(|v| position(v as u32) != self.soup.positions[v]) {
            return Err(format!("{name}: an input vertex moved"));
        }
        let out = to_soup(&m);
        let (had, has) = (problems(self.soup), problems(&out));
        if !has.is_subset(&had) {
            return Err(format!(
                "{name}: check found {has:?}, the input had {had:?}"
            ));
        }
        Ok(Some(Outcome {
            name,
            report,
            faces: face_set(&out),
        }))
    }
}

/// The input of a case: a random grid with holes (triangles only) or a small torus.
fn input(seed: u64) -> PolygonSoup {
    if seed.is_multiple_of(4) {
        torus(3 + (seed / 4 % 4) as usize, 3 + (seed / 16 % 3) as usize)
    } else {
        random_mesh(
            seed,
            RandomMeshParams {
                triangles_only: true,
                max_side: 6,
                keep: 0.85,
            },
        )
    }
}

/// Runs every editable structure on one case: how many stored the input, and what the first
/// did (all did the same); `Err` describes the first failure.
fn run_case(
    seed: u64,
    fraction: f64,
    region: Option<[f64; 6]>,
) -> Result<(usize, Option<AdaptiveReport>), String> {
    let soup = input(seed);
    let mut longest = 0f64;
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for f in 0..soup.num_faces() {
        let face = soup.face(f);
        for (i, &v) in face.iter().enumerate() {
            let (p, q) = (
                soup.positions[v as usize],
                soup.positions[face[(i + 1) % face.len()] as usize],
            );
            longest = longest.max(p.distance(q));
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    let region = region.map(|[x0, y0, z0, x1, y1, z1]| {
        // A box in the mesh's bounding box: from the point at fractions (x0, y0, z0) of it to
        // the point at fractions (x1, y1, z1) of what is left beyond.
        let min = lo + (hi - lo) * DVec3::new(x0, y0, z0);
        let max = min + (hi - min) * DVec3::new(x1, y1, z1);
        Region::new(min, max).expect("min <= max by construction")
    });
    let request = Request::new(longest * fraction, region).map_err(|e| e.to_string())?;
    let mut outcomes: Vec<Outcome> = Vec::new();
    for name in editable_names() {
        let visit = Refine {
            soup: &soup,
            request: &request,
        };
        let outcome = visit_editable(name, visit).expect("an editable structure")?;
        outcomes.extend(outcome);
    }
    if let Some((first, rest)) = outcomes.split_first() {
        for other in rest {
            if other.faces != first.faces || other.report != first.report {
                return Err(format!(
                    "{} made {} faces ({:?}), {} made {} ({:?})",
                    first.name,
                    first.faces.len(),
                    first.report,
                    other.name,
                    other.faces.len(),
                    other.report
                ));
            }
        }
    }
    let first = outcomes.first().map(|o| o.report);
    Ok((outcomes.len(), first))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn refinement_is_conforming_local_and_the_same_on_every_structure(
        seed in any::<u64>(),
        fraction in 0.15f64..1.1,
        // Boxes from the first half of the bounding box to at least halfway beyond, so that
        // they hold edges (both ends inside) of these small meshes.
        region in proptest::option::of(
            (proptest::array::uniform3(0.0f64..0.5), proptest::array::uniform3(0.5f64..1.0))
                .prop_map(|([x0, y0, z0], [x1, y1, z1])| [x0, y0, z0, x1, y1, z1]),
        ),
    ) {
        if let Err(msg) = run_case(seed, fraction, region) {
            panic!("seed {seed}, fraction {fraction}, region {region:?}: {msg}");
        }
    }
}

#[test]
fn every_editable_structure_refines_and_a_box_refines_less() {
    // A torus every structure stores, refined to under half its longest edge: every
    // editable structure took part, and the refinement did split.
    let (structures, whole) = run_case(4, 0.45, None).unwrap();
    assert_eq!(structures, editable_names().len());
    let whole = whole.unwrap();
    assert!(whole.edges_split > 0 && whole.faces_after > whole.faces_before);
    // The half of it with x >= its middle: fewer faces, still some split.
    let (_, half) = run_case(4, 0.45, Some([0.5, 0.0, 0.0, 1.0, 1.0, 1.0])).unwrap();
    let half = half.unwrap();
    assert!(
        half.edges_split > 0 && half.faces_after < whole.faces_after,
        "{half:?} {whole:?}"
    );
    // Finer: more rounds, within the bound.
    let (_, fine) = run_case(4, 0.05, None).unwrap();
    let fine = fine.unwrap();
    assert!(fine.rounds > whole.rounds, "{fine:?} {whole:?}");
}
