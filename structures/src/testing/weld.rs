//! The weld tests of the editing suite: every closed canonical mesh (and a finer torus and a
//! sphere) cut into two halves along a curve of its edges, each half built as its own mesh,
//! welded back by [`weld_meshes`], and every relation compared with the oracle of the
//! original (renumbered as the weld numbers: the first half's vertices, then the second's
//! that were not on the cut). Then the refusals: a half welded to itself (its boundary runs
//! the same way twice), to the other half turned over, and to the other half moved away.

use crate::algorithms::weld::weld_meshes;
use crate::core::edit::{MeshEdit, Refusal};
use crate::core::error::Error;
use crate::core::soup::PolygonSoup;
use crate::testing::conformance::compare;
use crate::testing::meshes;
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

fn refusal(got: crate::Result<impl Sized>) -> Option<Refusal> {
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
