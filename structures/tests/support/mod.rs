//! Test helpers shared by the reader tests: PLY files of a soup as other tools write them
//! (other scalar types and extra properties than the lab's writer uses), and ASCII STL (the lab
//! writes binary STL).

use topolab_structures::PolygonSoup;

/// A binary PLY of `soup` exercising several scalar types: vertex `x` float, an ignored
/// `uchar` property, `y` double, `z` int (the positions must be integral for that), an
/// ignored list; faces as `uchar`/`int` lists after an ignored `uint`; an extra element.
pub fn binary_ply(soup: &PolygonSoup, big_endian: bool) -> Vec<u8> {
    let order = if big_endian { "big" } else { "little" };
    let mut out = format!(
        "ply\nformat binary_{order}_endian 1.0\ncomment made by a test\n\
         element vertex {}\nproperty float x\nproperty uchar quality\nproperty double y\n\
         property int z\nproperty list uchar ushort tags\n\
         element face {}\nproperty uint flags\nproperty list uchar int vertex_indices\n\
         element material 1\nproperty list int float values\nproperty short id\nend_header\n",
        soup.num_vertices(),
        soup.num_faces()
    )
    .into_bytes();
    fn put<const N: usize>(out: &mut Vec<u8>, le: [u8; N], big_endian: bool) {
        let mut b = le;
        if big_endian {
            b.reverse();
        }
        out.extend_from_slice(&b);
    }
    for p in &soup.positions {
        put(&mut out, (p.x as f32).to_le_bytes(), big_endian);
        put(&mut out, [7u8], big_endian);
        put(&mut out, p.y.to_le_bytes(), big_endian);
        put(&mut out, (p.z as i32).to_le_bytes(), big_endian);
        put(&mut out, [2u8], big_endian);
        put(&mut out, 11u16.to_le_bytes(), big_endian);
        put(&mut out, 12u16.to_le_bytes(), big_endian);
    }
    for f in soup.faces() {
        put(&mut out, 0xdead_beef_u32.to_le_bytes(), big_endian);
        put(&mut out, [f.len() as u8], big_endian);
        for &v in f {
            put(&mut out, (v as i32).to_le_bytes(), big_endian);
        }
    }
    put(&mut out, 1i32.to_le_bytes(), big_endian);
    put(&mut out, 0.5f32.to_le_bytes(), big_endian);
    put(&mut out, 3i16.to_le_bytes(), big_endian);
    out
}

/// An ASCII PLY of `soup`: double coordinates, an ignored `uchar`, `uint` indices.
pub fn ascii_ply(soup: &PolygonSoup) -> String {
    let mut out = format!(
        "ply\nformat ascii 1.0\nelement vertex {}\nproperty double x\nproperty double y\n\
         property double z\nproperty uchar red\nelement face {}\n\
         property list uchar uint vertex_index\nend_header\n",
        soup.num_vertices(),
        soup.num_faces()
    );
    for p in &soup.positions {
        out += &format!("{} {} {} 200\n", p.x, p.y, p.z);
    }
    for f in soup.faces() {
        out += &f.len().to_string();
        for v in f {
            out += &format!(" {v}");
        }
        out += "\n";
    }
    out
}

/// An ASCII STL of the triangles of `soup` (a solid named `test`, facet normals zero), as
/// exporters write it.
pub fn ascii_stl(soup: &PolygonSoup) -> String {
    let mut out = String::from("solid test\n");
    for f in soup.faces() {
        out += "  facet normal 0 0 0\n    outer loop\n";
        for &v in f {
            let p = soup.positions[v as usize];
            out += &format!("      vertex {} {} {}\n", p.x, p.y, p.z);
        }
        out += "    endloop\n  endfacet\n";
    }
    out + "endsolid test\n"
}
