//! What the writers refuse before they write: a mesh whose file the lab's own readers would
//! refuse, or read back as another mesh. [`writable`] answers, for one format, without writing.

use crate::core::error::{Error, Format, Result};
use crate::core::soup::PolygonSoup;
use std::collections::HashMap;

/// Refuses ([`Error::NotWritable`]) a mesh that, written as `format`, would not read back:
///
/// - an empty mesh (no vertex, no face) in any format: every reader makes nothing of it,
///   which `check` reports as `empty-mesh` and the other commands refuse;
/// - a soup [`PolygonSoup::check`] refuses (an index out of range, a face of fewer than three
///   corners or repeating a vertex, a coordinate that is not finite);
/// - in STL, which stores triangles (a polygon becomes a fan) with `float` positions and whose
///   reader welds corners at one position: a mesh without faces (it would read back empty), a
///   coordinate beyond `float`'s range (infinite once written), and a triangle two of whose
///   corners become one position as `float` (distinct doubles a `float` cannot tell apart,
///   a value that underflows to 0): welded, it repeats a vertex.
///
/// OBJ, OFF and PLY write coordinates exactly (shortest round-trip decimals, PLY `double`),
/// so a checked soup reads back as itself. O(n), with a hash of the STL positions.
pub fn writable(soup: &PolygonSoup, format: Format) -> Result<()> {
    let refuse = |reason: String| Err(Error::NotWritable { format, reason });
    if soup.num_vertices() == 0 && soup.num_faces() == 0 {
        return refuse(
            "the mesh is empty (no vertices, no faces): the file would read back as nothing".into(),
        );
    }
    soup.check()?;
    if format != Format::Stl {
        return Ok(());
    }
    if soup.num_faces() == 0 {
        return refuse(format!(
            "STL stores triangles only, and the mesh has {} vertices and no face: the file would read back empty",
            soup.num_vertices()
        ));
    }
    let triangles: u64 = soup.faces().map(|f| f.len() as u64 - 2).sum();
    if triangles > u64::from(u32::MAX) {
        return refuse(format!(
            "{triangles} triangles, more than a binary STL's count holds"
        ));
    }
    for (v, p) in soup.positions.iter().enumerate() {
        for x in p.to_array() {
            if !(x as f32).is_finite() {
                return refuse(format!(
                    "vertex {v} has the coordinate {x:e}, beyond the largest STL float ({:e})",
                    f32::MAX
                ));
            }
        }
    }
    // The vertex each position becomes once written as floats and welded by the reader.
    let mut welded: HashMap<[u32; 3], u32> = HashMap::with_capacity(soup.num_vertices());
    let place: Vec<u32> = soup
        .positions
        .iter()
        .enumerate()
        .map(|(v, p)| {
            let key = p.to_array().map(|x| ((x as f32) + 0.0).to_bits());
            *welded.entry(key).or_insert(v as u32)
        })
        .collect();
    for (j, face) in soup.faces().enumerate() {
        for k in 1..face.len() - 1 {
            let t = [face[0], face[k], face[k + 1]];
            let p = t.map(|v| place[v as usize]);
            if p[0] == p[1] || p[1] == p[2] || p[0] == p[2] {
                let (a, b) = match () {
                    _ if p[0] == p[1] => (t[0], t[1]),
                    _ if p[1] == p[2] => (t[1], t[2]),
                    _ => (t[0], t[2]),
                };
                return refuse(format!(
                    "face {j} has vertices {a} and {b} at positions STL's floats cannot tell apart ({} and {}): read back, the triangle would repeat a vertex",
                    fmt(soup, a),
                    fmt(soup, b)
                ));
            }
        }
    }
    Ok(())
}

fn fmt(soup: &PolygonSoup, v: u32) -> String {
    let p = soup.positions[v as usize];
    format!("({}, {}, {})", p.x, p.y, p.z)
}
