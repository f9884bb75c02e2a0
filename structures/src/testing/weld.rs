//! The weld tests of the editing suite: every closed canonical mesh (and a finer torus and a
//! sphere) cut into two halves along a curve of its edges, each half built as its own mesh,
//! welded back by [`weld_meshes`], and every relation compared with the oracle of the
//! original (renumbered as the weld numbers: the first half's vertices, then the second's
//! that were not on the cut). Then the refusals: a half welded to itself (its boundary runs
//! the same way twice), to the other half turned over, and to the other half moved away.

use crate::algorithms::changing::to_soup;
use crate::algorithms::weld::weld_meshes;
use crate::core::edit::{MeshEdit, Refusal};
use crate::core::error::Error;
use crate::core::soup::PolygonSoup;
use crate::meshes;
use crate::testing::conformance::compare;
use crate::testing::oracle::canonical_face;
use glam::DVec3;

/// The closed meshes the weld tests cut.
fn closed_meshes() -> Vec<(String, PolygonSoup)> {
    let mut out: Vec<(String, PolygonSoup)> = meshes::canonical()
        .into_iter()
        .filter(|m| {
            m.soup
                .connectivity()
                .is_ok_and(|c| c.edge_corners.iter().all(|e| e[1] != u32::MAX))
        })
        .map(|m| (m.name.to_string(), m.soup))
        .collect();
    out.push(("torus-8x6".into(), meshes::torus(8, 6)));
    out.push(("sphere-4x6".into(), meshes::sphere(4, 6)));
    out
}

/// The faces of `soup` in the first half: a breadth-first walk over shared edges from face
/// 0 until half of the faces, so the cut is a curve of edges.
fn first_half(soup: &PolygonSoup) -> Vec<bool> {
    let n = soup.num_faces();
    let faces: Vec<Vec<u32>> = soup.faces().map(|f| f.to_vec()).collect();
    let mut inside = vec![false; n];
    let mut queue = std::collections::VecDeque::from([0usize]);
    inside[0] = true;
    let mut count = 1;
    while let Some(f) = queue.pop_front() {
        for g in 0..n {
            if count * 2 >= n {
                return inside;
            }
            let shares =
                !inside[g] && faces[g].iter().filter(|v| faces[f].contains(v)).count() >= 2;
            if shares {
                inside[g] = true;
                count += 1;
                queue.push_back(g);
            }
        }
    }
    inside
}

/// The faces of `soup` where `keep`, over their own vertices numbered in first use by
/// vertex id; returns the soup and, per new vertex, the old one.
fn part(soup: &PolygonSoup, keep: &[bool]) -> (PolygonSoup, Vec<u32>) {
    let mut used: Vec<u32> = soup
        .faces()
        .enumerate()
        .filter(|(f, _)| keep[*f])
        .flat_map(|(_, f)| f.to_vec())
        .collect();
    used.sort_unstable();
    used.dedup();
    let local = |v: u32| used.binary_search(&v).expect("used") as u32;
    let faces: Vec<Vec<u32>> = soup
        .faces()
        .enumerate()
        .filter(|(f, _)| keep[*f])
        .map(|(_, f)| f.iter().map(|&v| local(v)).collect())
        .collect();
    let positions = used.iter().map(|&v| soup.positions[v as usize]).collect();
    (PolygonSoup::from_polygons(positions, &faces), used)
}

fn reversed(soup: &PolygonSoup) -> PolygonSoup {
    let faces: Vec<Vec<u32>> = soup
        .faces()
        .map(|f| f.iter().rev().copied().collect())
        .collect();
    PolygonSoup::from_polygons(soup.positions.clone(), &faces)
}

fn moved(soup: &PolygonSoup) -> PolygonSoup {
    let positions = soup
        .positions
        .iter()
        .map(|&p| p + DVec3::splat(100.0))
        .collect();
    let faces: Vec<Vec<u32>> = soup.faces().map(|f| f.to_vec()).collect();
    PolygonSoup::from_polygons(positions, &faces)
}

fn refusal(got: crate::core::error::Result<impl Sized>) -> Option<Refusal> {
    match got {
        Err(Error::EditRefused { reason, .. }) => Some(reason),
        _ => None,
    }
}

/// Cuts, welds back and compares (see the module docs); returns how many meshes were cut.
pub fn weld_halves<M: MeshEdit>() -> Result<usize, String> {
    let mut cut = 0;
    for (name, soup) in closed_meshes() {
        let inside = first_half(&soup);
        let outside: Vec<bool> = inside.iter().map(|&x| !x).collect();
        let ((sa, ua), (sb, ub)) = (part(&soup, &inside), part(&soup, &outside));
        let (Ok(a), Ok(b)) = (M::from_soup(&sa), M::from_soup(&sb)) else {
            continue;
        };
        let welded = weld_meshes(&a, &b, 1e-9).map_err(|e| format!("{name}: {e}"))?;
        // The original, numbered as the weld numbers and with its faces in the weld's order.
        let mut number = vec![u32::MAX; soup.num_vertices()];
        for (i, &v) in ua.iter().enumerate() {
            number[v as usize] = i as u32;
        }
        let mut positions: Vec<DVec3> = sa.positions.clone();
        for &v in &ub {
            if number[v as usize] == u32::MAX {
                number[v as usize] = positions.len() as u32;
                positions.push(soup.positions[v as usize]);
            }
        }
        let mut faces: Vec<Vec<u32>> = Vec::new();
        for keep in [&inside, &outside] {
            faces.extend(
                soup.faces()
                    .enumerate()
                    .filter(|(f, _)| keep[*f])
                    .map(|(_, f)| f.iter().map(|&v| number[v as usize]).collect()),
            );
        }
        let original = PolygonSoup::from_polygons(positions, &faces);
        compare(&welded, &original).map_err(|e| format!("{name} welded back: {e}"))?;

        let same = refusal(weld_meshes(&a, &a, 1e-9));
        if same != Some(Refusal::Orientation) {
            return Err(format!("{name}: a half welded to itself gave {same:?}"));
        }
        if let Ok(turned) = M::from_soup(&reversed(&sb)) {
            let got = refusal(weld_meshes(&a, &turned, 1e-9));
            if got != Some(Refusal::Orientation) {
                return Err(format!("{name}: the other half turned over gave {got:?}"));
            }
        }
        let far = M::from_soup(&moved(&sb)).map_err(|e| e.to_string())?;
        let got = refusal(weld_meshes(&a, &far, 1e-9));
        if got != Some(Refusal::NothingToWeld) {
            return Err(format!("{name}: the other half moved away gave {got:?}"));
        }
        cut += 1;
    }
    Ok(cut)
}

/// A fan of triangles (centre, rim[i], rim[i + 1]) around vertex 0, the rim vertices 1.. on a
/// circle; `closed` adds the triangle from the last rim vertex back to the first.
fn fan(rim: usize, closed: bool) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let mut positions = vec![DVec3::ZERO];
    for i in 0..rim {
        let t = i as f64 / rim as f64 * std::f64::consts::TAU;
        positions.push(DVec3::new(t.cos(), t.sin(), 0.0));
    }
    let last = if closed { rim } else { rim - 1 };
    let faces = (0..last)
        .map(|i| vec![0, 1 + i as u32, 1 + ((i + 1) % rim) as u32])
        .collect();
    (positions, faces)
}

/// The open fan of `k` triangles whose last rim vertex lies on the first: welding the two
/// closes the disk (the boundary edges to the centre merge).
fn slit_fan(k: usize) -> PolygonSoup {
    let (mut positions, mut faces) = fan(k, false);
    positions.push(positions[1]);
    faces.push(vec![0, k as u32, k as u32 + 1]);
    PolygonSoup::from_polygons(positions, &faces)
}

/// A slit disk of two rings: the fan of `slit_fan(k)` and a ring of triangles around it,
/// each ring's last vertex on its first (vertices: centre 0, inner 1..=k+1, outer k+2..).
fn slit_disk(k: usize) -> PolygonSoup {
    let inner = |i: usize| 1 + i as u32;
    let outer = |i: usize| (k + 2 + i) as u32;
    let mut positions = vec![DVec3::ZERO];
    for r in [1.0, 2.0] {
        for i in 0..=k {
            let t = (i % k) as f64 / k as f64 * std::f64::consts::TAU;
            positions.push(r * DVec3::new(t.cos(), t.sin(), 0.0));
        }
    }
    let mut faces = Vec::new();
    for i in 0..k {
        faces.push(vec![0, inner(i), inner(i + 1)]);
        faces.push(vec![inner(i), outer(i), outer(i + 1)]);
        faces.push(vec![inner(i), outer(i + 1), inner(i + 1)]);
    }
    PolygonSoup::from_polygons(positions, &faces)
}

/// The 4 × 4 grid of triangles (diagonals from (i, j) to (i + 1, j + 1)), without the
/// middle square's two triangles when `hole`; vertex (i, j) is `4 * j + i`.
fn grid(hole: bool) -> PolygonSoup {
    let id = |i: u32, j: u32| 4 * j + i;
    let mut positions = Vec::new();
    for j in 0..4 {
        for i in 0..4 {
            positions.push(DVec3::new(i as f64, j as f64, 0.0));
        }
    }
    let mut faces = Vec::new();
    for j in 0..3 {
        for i in 0..3 {
            if hole && (i, j) == (1, 1) {
                continue;
            }
            faces.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push(vec![id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    PolygonSoup::from_polygons(positions, &faces)
}

/// An open band of `w` columns of squares (two triangles each) and one row, whose last
/// column of vertices lies on its first: the seam's first weld would pinch the band.
fn band(w: u32) -> PolygonSoup {
    let id = |i: u32, j: u32| j * (w + 1) + i;
    let mut positions = Vec::new();
    for j in 0..2 {
        for i in 0..=w {
            let t = (i % w) as f64 / w as f64 * std::f64::consts::TAU;
            positions.push(DVec3::new(t.cos(), t.sin(), j as f64));
        }
    }
    let mut faces = Vec::new();
    for i in 0..w {
        faces.push(vec![id(i, 0), id(i + 1, 0), id(i + 1, 1)]);
        faces.push(vec![id(i, 0), id(i + 1, 1), id(i, 1)]);
    }
    PolygonSoup::from_polygons(positions, &faces)
}

/// The faces of `soup` with `b` renamed `a`, then `b`'s slot removed (as a garbage
/// collection numbers them), canonical and sorted.
fn welded_faces(faces: &[Vec<u32>], a: u32, b: u32) -> Vec<Vec<u32>> {
    let mut out: Vec<Vec<u32>> = faces
        .iter()
        .map(|f| {
            let f: Vec<u32> = f
                .iter()
                .map(|&v| if v == b { a } else { v })
                .map(|v| if v > b { v - 1 } else { v })
                .collect();
            canonical_face(&f)
        })
        .collect();
    out.sort();
    out
}

fn soup_faces(soup: &PolygonSoup) -> Vec<Vec<u32>> {
    soup.faces().map(|f| f.to_vec()).collect()
}

/// The live faces of `m`, canonical and sorted.
fn live_faces<M: MeshEdit>(m: &M) -> Vec<Vec<u32>> {
    let faces: Vec<Vec<u32>> = (0..m.num_faces())
        .map(crate::core::ids::FaceId::new)
        .filter(|&f| !m.is_deleted_face(f))
        .map(|f| {
            let mut face = Vec::new();
            m.face_vertices(f, |v| face.push(v.0));
            canonical_face(&face)
        })
        .collect();
    let mut faces = faces;
    faces.sort();
    faces
}

/// Welds in turn the pairs `welds` (each `b` into `a`) of `soup` in `M`; each must be done.
/// Then, after garbage collection, the faces must be the original's with each pair welded and
/// every relation must agree with the oracle of those faces.
fn welds_done_as_expected<M: MeshEdit>(
    name: &str,
    soup: &PolygonSoup,
    welds: &[(u32, u32)],
) -> Result<(), String> {
    let mut m = M::from_soup(soup).map_err(|e| format!("{name}: {e}"))?;
    let mut faces = soup_faces(soup);
    for &(a, b) in welds {
        m.weld_vertices(crate::core::ids::VertexId(a), crate::core::ids::VertexId(b))
            .map_err(|e| format!("{name}: weld v{a} v{b} refused: {e}"))?;
        m.validate()
            .map_err(|e| format!("{name}: after weld v{a} v{b}: {e}"))?;
        if !m.is_deleted_vertex(crate::core::ids::VertexId(b)) {
            return Err(format!("{name}: v{b} is not deleted after its weld"));
        }
        m.garbage_collection();
        faces = welded_faces(&faces, a, b);
        let got = live_faces(&m);
        if got != faces {
            return Err(format!(
                "{name}: welded v{a} v{b}: faces {got:?}, expected {faces:?}"
            ));
        }
        compare(&m, &to_soup(&m)).map_err(|e| format!("{name} after weld v{a} v{b}: {e}"))?;
    }
    Ok(())
}

/// The weld of `b` into `a` on `soup` must be refused for one of `reasons`, and change
/// nothing. (Which manifold rule a structure names first is its own: the face rewrite checks
/// edges before fans, the half-edges fans before edges.)
fn weld_refused<M: MeshEdit>(
    name: &str,
    soup: &PolygonSoup,
    (a, b): (u32, u32),
    reasons: &[Refusal],
) -> Result<(), String> {
    let mut m = M::from_soup(soup).map_err(|e| format!("{name}: {e}"))?;
    let got =
        refusal(m.weld_vertices(crate::core::ids::VertexId(a), crate::core::ids::VertexId(b)));
    if !got.is_some_and(|r| reasons.contains(&r)) {
        return Err(format!(
            "{name}: weld v{a} v{b} gave {got:?}, not one of {reasons:?}"
        ));
    }
    let deleted =
        (0..m.num_vertices()).any(|v| m.is_deleted_vertex(crate::core::ids::VertexId::new(v)));
    if deleted || m.num_vertices() != soup.num_vertices() {
        return Err(format!(
            "{name}: the refused weld v{a} v{b} deleted a vertex"
        ));
    }
    let mut want: Vec<Vec<u32>> = soup_faces(soup).iter().map(|f| canonical_face(f)).collect();
    want.sort();
    if live_faces(&m) != want {
        return Err(format!(
            "{name}: the refused weld v{a} v{b} changed the faces"
        ));
    }
    compare(&m, soup).map_err(|e| format!("{name} after the refused weld v{a} v{b}: {e}"))
}

/// [`MeshEdit::weld_vertices`] on chosen cases: boundaries that zip by one edge (a slit fan
/// in both weld orders, a slit disk zipped vertex by vertex), a square hole closed by welding
/// two opposite corners and a slit sphere closed (both ends merge), unused vertices, and the
/// refusals (a shared face, an interior vertex, boundaries that meet at no edge, a neighbour
/// of both through interior edges, one vertex twice, used or unused ([`Refusal::SameVertex`]),
/// an id out of range, alone or twice: the ids are checked first). Returns how many cases ran.
pub fn weld_vertex_cases<M: MeshEdit>() -> Result<usize, String> {
    let mut cases = 0;
    for k in 3..=6u32 {
        let soup = slit_fan(k as usize);
        welds_done_as_expected::<M>(&format!("slit fan {k}"), &soup, &[(1, k + 1)])?;
        welds_done_as_expected::<M>(&format!("slit fan {k}, reversed"), &soup, &[(k + 1, 1)])?;
        // Zipping the slit disk: the inner ring's ends, then the outer ring's (each pair's
        // ids before the first weld's collection shifts the second).
        let disk = slit_disk(k as usize);
        welds_done_as_expected::<M>(
            &format!("slit disk {k}"),
            &disk,
            &[(1, k + 1), (k + 1, 2 * k + 1)],
        )?;
        cases += 3;
    }
    // A square hole closed by its opposite corners: both boundary edge pairs merge.
    let holed = grid(true);
    welds_done_as_expected::<M>("hole (1,1)-(2,2)", &holed, &[(5, 10)])?;
    welds_done_as_expected::<M>("hole (2,1)-(1,2)", &holed, &[(9, 6)])?;
    // A slit of two edges in a closed fan pair: welding its end closes a sphere.
    let (mut positions, mut faces) = fan(4, false);
    positions.push(positions[1]);
    faces.push(vec![0, 4, 5]);
    positions.push(DVec3::new(0.0, 0.0, 1.0));
    for i in 1..=4u32 {
        faces.push(vec![i + 1, i, 6]);
    }
    let sphere = PolygonSoup::from_polygons(positions, &faces);
    welds_done_as_expected::<M>("slit sphere", &sphere, &[(1, 5)])?;
    cases += 3;
    // Unused vertices: one welded into a used one, a used one into it.
    let mut lonely = grid(false);
    lonely.positions.push(DVec3::splat(9.0));
    welds_done_as_expected::<M>("unused into used", &lonely, &[(0, 16)])?;
    welds_done_as_expected::<M>("used into unused", &lonely, &[(16, 5)])?;
    cases += 2;

    let (p, f) = fan(4, true);
    let disk = PolygonSoup::from_polygons(p, &f);
    let manifold = [Refusal::NonManifoldVertex, Refusal::NonManifoldEdge];
    let (shared, same, none) = (
        [Refusal::BadFace],
        [Refusal::SameVertex],
        [Refusal::NoSuchElement],
    );
    for (name, soup, pair, reasons) in [
        ("a shared face", &holed, (5, 6), &shared[..]),
        ("a diagonal", &grid(false), (0, 5), &shared),
        ("an interior vertex", &grid(false), (5, 15), &manifold),
        ("two boundaries", &holed, (5, 15), &manifold),
        ("a band's seam", &band(6), (0, 6), &manifold),
        ("a centre of both", &disk, (1, 3), &manifold),
        ("one vertex twice", &holed, (3, 3), &same),
        ("one unused vertex twice", &lonely, (16, 16), &same),
        ("an id out of range", &holed, (3, 16), &none),
        ("an id out of range twice", &holed, (16, 16), &none),
    ] {
        weld_refused::<M>(name, soup, pair, reasons)?;
        cases += 1;
    }
    Ok(cases)
}

/// A closed ring of `w` columns of squares (two triangles each) and one row: [`band`] with
/// its last column of vertices made its first, built directly.
fn ring(w: u32) -> PolygonSoup {
    let id = |i: u32, j: u32| j * w + i % w;
    let band = band(w);
    let positions = (0..2)
        .flat_map(|j| (0..w).map(move |i| (i, j)))
        .map(|(i, j)| band.positions[(j * (w + 1) + i) as usize])
        .collect();
    let mut faces = Vec::new();
    for i in 0..w {
        faces.push(vec![id(i, 0), id(i + 1, 0), id(i + 1, 1)]);
        faces.push(vec![id(i, 0), id(i + 1, 1), id(i, 1)]);
    }
    PolygonSoup::from_polygons(positions, &faces)
}

/// Each case's result must be its refusal; returns how many were.
fn refused_as<M>(
    cases: [(&str, crate::core::error::Result<M>, Refusal); 3],
) -> Result<usize, String> {
    for (what, got, want) in cases.iter().map(|(w, g, r)| (w, g.as_ref().err(), r)) {
        let got = match got {
            Some(Error::EditRefused { reason, .. }) => Some(*reason),
            _ => None,
        };
        if got != Some(*want) {
            return Err(format!("{what}: {got:?}, not {want:?}"));
        }
    }
    Ok(cases.len())
}

/// The weld of edges and of faces ([`crate::algorithms::weld::weld_edges`],
/// [`crate::algorithms::weld::weld_faces`]) on structure `M`, against meshes built directly:
/// the two end edges of a band of squares welded give its ring, built closed; two far
/// faces of a torus welded give one of the k meshes their corners' k pairings make (a
/// torus with a handle: genus 2). Then the refusals: an element welded to itself, an interior
/// edge, faces sharing a corner or of different sizes, ids past the counts. Returns the
/// number of cases checked.
pub fn weld_edge_and_face_cases<M: MeshEdit>() -> Result<usize, String> {
    use crate::algorithms::weld::{weld_edges, weld_faces};
    use crate::core::ids::{FaceId, VertexId};
    let mut checked = 0;
    let w = 4;
    let band_soup = band(w);
    let m = M::from_soup(&band_soup).map_err(|e| e.to_string())?;
    let edge = |a: u32, b: u32| [VertexId(a), VertexId(b)];
    // The first column's edge (0, w + 1) and the last one's (w, 2w + 1).
    let (first, last) = (edge(0, w + 1), edge(w, 2 * w + 1));
    let welded = weld_edges(&m, first, last).map_err(|e| format!("band ends: {e}"))?;
    compare(&welded, &ring(w)).map_err(|e| format!("the band's ends welded: {e}"))?;
    checked += 1;
    let diagonal = edge(0, w + 2);
    let cases: [(&str, crate::core::error::Result<M>, Refusal); 3] = [
        (
            "an edge welded to itself",
            weld_edges(&m, first, first),
            Refusal::SameElement,
        ),
        (
            "an interior edge",
            weld_edges(&m, first, diagonal),
            Refusal::InteriorEdge,
        ),
        (
            "two vertices no edge joins",
            weld_edges(&m, first, edge(0, 2)),
            Refusal::NoSuchElement,
        ),
    ];
    checked += refused_as(cases)?;

    // Two faces of a torus: face 0 and the one whose centroid is farthest from it.
    let torus = meshes::torus(8, 6);
    let faces: Vec<Vec<u32>> = torus.faces().map(|f| f.to_vec()).collect();
    let centre = |f: &[u32]| {
        f.iter()
            .map(|&v| torus.positions[v as usize])
            .sum::<DVec3>()
    };
    let far = (1..faces.len())
        .max_by(|&a, &b| {
            let d = |g: usize| centre(&faces[g]).distance_squared(centre(&faces[0]));
            d(a).total_cmp(&d(b))
        })
        .expect("faces");
    let m = M::from_soup(&torus).map_err(|e| e.to_string())?;
    let welded =
        weld_faces(&m, FaceId(0), FaceId(far as u32)).map_err(|e| format!("torus: {e}"))?;
    let (cf, cg) = (&faces[0], &faces[far]);
    let k = cf.len();
    let pairing = |r: usize| {
        // g's corner (r − i) mod k becomes f's corner i; the others keep their order.
        let gone = |v: u32| cg.contains(&v);
        let number = |v: u32| v - (0..v).filter(|&u| gone(u)).count() as u32;
        let name = |v: u32| match cg.iter().position(|&x| x == v) {
            Some(j) => cf[(r + k - j) % k],
            None => v,
        };
        let kept: Vec<Vec<u32>> = faces
            .iter()
            .enumerate()
            .filter(|&(f, _)| f != 0 && f != far)
            .map(|(_, f)| f.iter().map(|&v| number(name(v))).collect())
            .collect();
        let positions = (0..torus.num_vertices() as u32)
            .filter(|&v| !gone(v))
            .map(|v| torus.positions[v as usize])
            .collect();
        PolygonSoup::from_polygons(positions, &kept)
    };
    let matches = (0..k)
        .filter(|&r| compare(&welded, &pairing(r)).is_ok())
        .count();
    if matches != 1 {
        return Err(format!(
            "two far faces of a torus welded: the result is {matches} of the {k} pairings"
        ));
    }
    checked += 1;
    let m = M::from_soup(&torus).map_err(|e| e.to_string())?;
    let mut neighbour = None;
    for (g, f) in faces.iter().enumerate().skip(1) {
        if f.iter().any(|v| faces[0].contains(v)) {
            neighbour = Some(g);
            break;
        }
    }
    let neighbour = neighbour.expect("a face touching face 0") as u32;
    let cases: [(&str, crate::core::error::Result<M>, Refusal); 3] = [
        (
            "a face welded to itself",
            weld_faces(&m, FaceId(0), FaceId(0)),
            Refusal::SameElement,
        ),
        (
            "faces sharing a corner",
            weld_faces(&m, FaceId(0), FaceId(neighbour)),
            Refusal::FaceMismatch,
        ),
        (
            "a face past the count",
            weld_faces(&m, FaceId(0), FaceId::new(m.num_faces())),
            Refusal::NoSuchElement,
        ),
    ];
    checked += refused_as(cases)?;
    Ok(checked)
}
