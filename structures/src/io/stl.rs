//! STL, ASCII and binary: the triangle format of scanning and 3D printing.
//!
//! An STL file stores each triangle's three corners as positions, with no vertex list. The
//! reader makes the soup's vertices by **welding by exact position**: corners whose three
//! coordinates are bit-for-bit equal (as read: `f32` in binary, the parsed number in ASCII)
//! are one vertex, numbered in order of first appearance, so triangle j of the file is face j.
//! Nothing within a tolerance is merged (that would change the mesh; `topolab repair` and
//! `check --tolerance` are where near-coincident vertices are found). How many corners were
//! welded is kept in [`RawSoup::welded_corners`] (`topolab` prints it).
//!
//! Which encoding is told by content, not by the extension alone: a file is binary when its
//! length is exactly what the triangle count at byte 80 announces (84 + 50 per triangle),
//! ASCII when it starts with `solid` and is not such a binary file (binary headers may start
//! with `solid` too), and otherwise it is refused: a binary file whose length disagrees with
//! its count is truncated (shorter) or a syntax error (longer). Facet normals are read past
//! (the structures compute what they need from positions); the attribute bytes of binary
//! facets are skipped.

use super::echo::quoted;
use super::text::{lines, position, short_line, strip_comment, syntax, tokens};
use super::{RawSoup, SoupBuilder};
use crate::core::error::{Error, Format, Location, Result};
use glam::DVec3;

const STL: Format = Format::Stl;

/// Bytes of a binary STL's header and triangle count.
const HEADER: usize = 84;
/// Bytes of one binary facet: normal, three corners (12 `f32`), attribute (`u16`).
const FACET: usize = 50;

pub(super) fn read(bytes: &[u8]) -> Result<RawSoup> {
    let count = binary_count(bytes);
    let expected = count.map(|n| HEADER as u64 + FACET as u64 * n as u64);
    if let (Some(count), Some(expected)) = (count, expected) {
        if expected == bytes.len() as u64 {
            return read_binary(bytes, count as usize);
        }
    }
    if bytes.trim_ascii_start().starts_with(b"solid") {
        return read_ascii(bytes);
    }
    match count.zip(expected) {
        Some((count, expected)) => {
            let location = Location::Byte(bytes.len() as u64);
            if (bytes.len() as u64) < expected {
                Err(Error::Truncated {
                    format: STL,
                    location,
                    message: format!(
                        "the binary header announces {count} triangles ({expected} bytes), the file has {} bytes",
                        bytes.len()
                    ),
                })
            } else {
                Err(Error::Syntax {
                    format: STL,
                    location: Location::Byte(expected),
                    message: format!(
                        "{} bytes after the {count} triangles the binary header announces",
                        bytes.len() as u64 - expected
                    ),
                })
            }
        }
        None => Err(Error::Truncated {
            format: STL,
            location: Location::Byte(bytes.len() as u64),
            message: "neither an ASCII STL (it does not start with \"solid\") nor a binary one (shorter than its 84-byte header)".into(),
        }),
    }
}

/// The triangle count of a binary header (little-endian `u32` at byte 80), if the file is
/// long enough to have one.
fn binary_count(bytes: &[u8]) -> Option<u32> {
    let count = bytes.get(80..HEADER)?;
    Some(u32::from_le_bytes(count.try_into().expect("four bytes")))
}

/// Corners welded into vertices by exact position, as the soup is built.
struct Welder {
    out: SoupBuilder,
    /// The vertices by position: an open-addressing table of vertex ids (the positions are
    /// the soup's), 4 bytes a slot, at most half full: 8 to 16 bytes a vertex where a map of
    /// positions to ids took 33 to 75, the largest part of reading an STL file.
    slots: Vec<u32>,
    /// Keyed at random per process: no file makes positions collide.
    hasher: std::collections::hash_map::RandomState,
    corners: usize,
}

/// An empty slot of [`Welder::slots`].
const EMPTY: u32 = u32::MAX;

impl Welder {
    fn with_capacity(triangles: usize) -> Self {
        // About half as many vertices as triangles on a closed mesh.
        Self {
            out: SoupBuilder::with_capacity(triangles / 2, triangles, triangles * 3),
            slots: vec![EMPTY; (triangles + 16).next_power_of_two()],
            hasher: std::collections::hash_map::RandomState::new(),
            corners: 0,
        }
    }

    /// The bits a position is welded by: -0.0 and 0.0 are one place.
    fn key(p: DVec3) -> [u64; 3] {
        p.to_array().map(|x| (x + 0.0).to_bits())
    }

    /// The slot of position `key`: the one holding its vertex, or the empty one where it goes.
    fn slot(&self, key: [u64; 3]) -> usize {
        use std::hash::BuildHasher;
        let mask = self.slots.len() - 1;
        let mut i = self.hasher.hash_one(key) as usize & mask;
        loop {
            let v = self.slots[i];
            if v == EMPTY || Self::key(self.out.raw.soup.positions[v as usize]) == key {
                return i;
            }
            i = (i + 1) & mask;
        }
    }

    fn corner(&mut self, p: DVec3) {
        let i = self.slot(Self::key(p));
        let v = match self.slots[i] {
            EMPTY => {
                let v = self.out.raw.soup.push_vertex(p).0;
                self.slots[i] = v;
                if 2 * (v as usize + 1) > self.slots.len() {
                    self.grow();
                }
                v
            }
            v => v,
        };
        self.out.corner(v as i64);
        self.corners += 1;
    }

    /// Doubles the table, placing every vertex again.
    fn grow(&mut self) {
        self.slots = vec![EMPTY; 2 * self.slots.len()];
        for v in 0..self.out.raw.soup.num_vertices() {
            let i = self.slot(Self::key(self.out.raw.soup.positions[v]));
            self.slots[i] = v as u32;
        }
    }

    fn finish(mut self) -> RawSoup {
        self.out.raw.welded_corners = self.corners - self.out.raw.soup.num_vertices();
        self.out.finish()
    }
}

fn read_binary(bytes: &[u8], count: usize) -> Result<RawSoup> {
    let mut welder = Welder::with_capacity(count);
    let f32_at = |at: usize| f32::from_le_bytes(bytes[at..at + 4].try_into().expect("4 bytes"));
    for t in 0..count {
        let facet = HEADER + t * FACET;
        for corner in 0..3 {
            let at = facet + 12 + 12 * corner;
            let p = DVec3::new(
                f32_at(at) as f64,
                f32_at(at + 4) as f64,
                f32_at(at + 8) as f64,
            );
            welder.corner(p);
        }
        welder.out.end_face();
    }
    Ok(welder.finish())
}

fn read_ascii(bytes: &[u8]) -> Result<RawSoup> {
    let mut welder = Welder::with_capacity(bytes.len() / 256);
    let mut in_facet = false;
    let mut corners_in_facet = 0;
    let mut ended = false;
    let mut last_line = 1;
    for line in lines(bytes, 1) {
        last_line = line.number;
        let mut words = tokens(strip_comment(line.content));
        let Some(keyword) = words.next() else {
            continue;
        };
        if ended {
            // Several solids in one file: each `solid` starts the next.
            if keyword == b"solid" {
                ended = false;
                continue;
            }
            return Err(syntax(STL, line.number, "text after \"endsolid\""));
        }
        match keyword {
            b"solid" if line.number == 1 || !in_facet => {}
            b"facet" => {
                if in_facet {
                    return Err(syntax(STL, line.number, "\"facet\" inside a facet"));
                }
                in_facet = true;
                corners_in_facet = 0;
            }
            b"outer" | b"endloop" if in_facet => {}
            b"vertex" if in_facet => {
                if corners_in_facet == 3 {
                    return Err(syntax(
                        STL,
                        line.number,
                        "a facet with more than three vertices",
                    ));
                }
                let p = position(STL, &line, &mut words)?;
                welder.corner(p);
                corners_in_facet += 1;
            }
            b"endfacet" if in_facet => {
                if corners_in_facet != 3 {
                    return Err(short_line(
                        STL,
                        &line,
                        format!("a facet with {corners_in_facet} of 3 vertices"),
                    ));
                }
                welder.out.end_face();
                in_facet = false;
            }
            b"endsolid" if !in_facet => ended = true,
            // A keyword cut short by the end of the file.
            other if !line.terminated => {
                return Err(short_line(
                    STL,
                    &line,
                    format!("the file ends in {}", quoted(other)),
                ))
            }
            other => {
                return Err(syntax(
                    STL,
                    line.number,
                    format!("unexpected {}", quoted(other)),
                ))
            }
        }
    }
    if in_facet {
        return Err(Error::Truncated {
            format: STL,
            location: Location::Line(last_line),
            message: "the file ends inside a facet".into(),
        });
    }
    Ok(welder.finish())
}

/// Writes `soup` as binary STL (little endian): a header naming the lab, the triangle count,
/// then per triangle its unit normal (zero for a degenerate one) and corners as `f32`. A face
/// of more than three corners is written as a fan of triangles from its first corner, so STL
/// (triangles only) receives every face; positions become `f32`, as the format has them.
pub(super) fn write_binary(
    w: &mut impl std::io::Write,
    soup: &super::PolygonSoup,
) -> std::io::Result<()> {
    let triangles: usize = soup.faces().map(|f| f.len() - 2).sum();
    let count = u32::try_from(triangles).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("{triangles} triangles: more than a binary STL's u32 count holds"),
        )
    })?;
    let mut header = [b' '; 80];
    let name = b"binary STL written by topolab";
    header[..name.len()].copy_from_slice(name);
    w.write_all(&header)?;
    w.write_all(&count.to_le_bytes())?;
    let mut facet = [0u8; FACET];
    for face in soup.faces() {
        let p = |i: usize| soup.positions[face[i] as usize];
        for k in 1..face.len() - 1 {
            let corners = [p(0), p(k), p(k + 1)];
            let normal = (corners[1] - corners[0])
                .cross(corners[2] - corners[0])
                .normalize_or_zero();
            for (i, v) in std::iter::once(normal).chain(corners).enumerate() {
                for (axis, x) in v.to_array().into_iter().enumerate() {
                    let at = 12 * i + 4 * axis;
                    facet[at..at + 4].copy_from_slice(&(x as f32).to_le_bytes());
                }
            }
            w.write_all(&facet)?;
        }
    }
    Ok(())
}
