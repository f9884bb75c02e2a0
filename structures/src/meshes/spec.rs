//! The grammar of the built-in meshes the command line names (`torus:N`, `genus:G:N`, ...).
//!
//! [`parse_spec`] reads a name into a [`MeshSpec`] without generating anything, so that a caller
//! can see its [`MeshSize`] (and the memory it takes) first; [`MeshSpec::generate`] builds it.
//! A name is either not a built-in mesh ([`SpecError::Unknown`]) or one too large for `u32` ids
//! ([`SpecError::TooLarge`]): the two are different mistakes and say so.

use super::canonical::{canonical_by_name, CanonicalMesh};
use super::generators::{
    grid, mixed_counts, mixed_grid, mixed_pairs, perforated_plate, sphere, torus, torus_sides,
    PlateLayout,
};
use crate::core::soup::PolygonSoup;

/// The largest face count [`from_spec`] generates: sizes past what `u32` handles number (a
/// triangle mesh of this many faces has 3·2³⁰ corners, under `u32::MAX`) are refused, not
/// attempted.
pub const MAX_FACES: usize = 1 << 30;

/// The most tunnels and openings (`genus:G:N`, `holes:K:N`, `surface:G:K:N`) a spec may ask for:
/// each takes a tile of at least 4 × 4 cells (64 triangles), so 2^20 of them already make a
/// plate of 2^26 triangles; more are refused before any arithmetic on them.
pub const MAX_SLOTS: usize = 1 << 20;

/// Why a name is not a built-in mesh that can be generated.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SpecError {
    /// Neither a canonical mesh name nor a generator with its numbers.
    #[error("not a built-in mesh")]
    Unknown,
    /// A well-formed name asking for more than a built-in mesh may have.
    #[error("too large: {count} {what}, more than the {max} a built-in mesh may have ({why})")]
    TooLarge {
        /// What there are too many of: `faces`, `corners`, `vertices`, or `tunnels and openings`.
        what: &'static str,
        /// How many the name asks for (saturated at `u128::MAX` for longer numbers).
        count: u128,
        /// The most there may be.
        max: u64,
        /// Why that is the most.
        why: &'static str,
    },
}

/// The element counts of a built-in mesh, known before it is generated.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct MeshSize {
    /// Vertices.
    pub vertices: u64,
    /// Faces.
    pub faces: u64,
    /// Corners (the sum of the face sizes).
    pub corners: u64,
}

impl MeshSize {
    /// The counts of `soup`.
    pub fn of(soup: &PolygonSoup) -> Self {
        Self {
            vertices: soup.num_vertices() as u64,
            faces: soup.num_faces() as u64,
            corners: soup.num_corners() as u64,
        }
    }

    /// Heap bytes of a [`PolygonSoup`] of this size: a position is three `f64` (24 bytes), a
    /// corner one `u32` vertex index, a face one `u32` offset (plus the leading 0). The
    /// generators reserve exactly this.
    pub fn soup_bytes(&self) -> u64 {
        24 * self.vertices + 4 * self.corners + 4 * (self.faces + 1)
    }

    /// The first count that `u32` ids cannot number ([`PolygonSoup::check`]'s limit: each
    /// below `u32::MAX`), as the name of the count and the count.
    pub fn beyond_u32(&self) -> Option<(&'static str, u64)> {
        [
            ("vertices", self.vertices),
            ("faces", self.faces),
            ("corners", self.corners),
        ]
        .into_iter()
        .find(|&(_, n)| n >= u32::MAX as u64)
    }
}

/// A built-in mesh, parsed but not generated.
#[derive(Clone, Debug)]
pub enum MeshSpec {
    /// A canonical mesh (tiny, already built).
    Canonical(CanonicalMesh),
    /// A closed torus of `nu` × `nv` vertices.
    Torus {
        /// Rings.
        nu: usize,
        /// Vertices per ring.
        nv: usize,
    },
    /// A closed UV sphere of `side` rings and `side` segments.
    Sphere {
        /// Rings and segments.
        side: usize,
    },
    /// An open `side` × `side` grid of cells, each two triangles or a quad.
    Grid {
        /// Cells per side.
        side: usize,
        /// Two triangles per cell (a quad otherwise).
        triangulated: bool,
    },
    /// The mixed-polygon grid of about `faces` faces.
    Mixed {
        /// The face count asked for.
        faces: usize,
    },
    /// A perforated plate of about `triangles` triangles.
    Plate {
        /// Tunnels.
        genus: usize,
        /// Openings.
        holes: usize,
        /// The triangle count asked for.
        triangles: usize,
    },
}

impl MeshSpec {
    /// The counts of the mesh [`MeshSpec::generate`] makes, exactly.
    pub fn size(&self) -> MeshSize {
        let (v, f, c) = match *self {
            MeshSpec::Canonical(ref m) => {
                let s = &m.soup;
                (s.num_vertices(), s.num_faces(), s.num_corners())
            }
            MeshSpec::Torus { nu, nv } => (nu * nv, 2 * nu * nv, 6 * nu * nv),
            MeshSpec::Sphere { side } => {
                let faces = 2 * side * (side - 1);
                (2 + (side - 1) * side, faces, 3 * faces)
            }
            MeshSpec::Grid { side, triangulated } => {
                let (per, corners) = if triangulated { (2, 6) } else { (1, 4) };
                (
                    (side + 1) * (side + 1),
                    per * side * side,
                    corners * side * side,
                )
            }
            MeshSpec::Mixed { faces } => {
                let n = mixed_pairs(faces);
                let (f, c) = mixed_counts(n);
                ((2 * n + 1) * (2 * n + 1), f, c)
            }
            MeshSpec::Plate {
                genus,
                holes,
                triangles,
            } => {
                let (v, f) = PlateLayout::new(genus, holes, triangles).counts();
                (v, f, 3 * f)
            }
        };
        MeshSize {
            vertices: v as u64,
            faces: f as u64,
            corners: c as u64,
        }
    }

    /// Builds the mesh.
    pub fn generate(self) -> PolygonSoup {
        match self {
            MeshSpec::Canonical(m) => m.soup,
            MeshSpec::Torus { nu, nv } => torus(nu, nv),
            MeshSpec::Sphere { side } => sphere(side, side),
            MeshSpec::Grid { side, triangulated } => grid(side, side, triangulated),
            MeshSpec::Mixed { faces } => mixed_grid(faces),
            MeshSpec::Plate {
                genus,
                holes,
                triangles,
            } => perforated_plate(genus, holes, triangles),
        }
    }
}

/// A count of a spec: digits, `_` allowed between them; `None` if not a number. Numbers past
/// `u128` saturate: they are too large, not malformed.
fn count(text: &str) -> Option<u128> {
    let digits = text.replace('_', "");
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some(digits.parse().unwrap_or(u128::MAX))
}

/// A built-in mesh named on the command line: a canonical mesh name, or a generator with a
/// face count for about N faces:
///
/// | spec | mesh |
/// |---|---|
/// | `torus:N` | closed torus, genus 1, ordered ring by ring |
/// | `sphere:N` | closed UV sphere |
/// | `grid:N`, `quad-grid:N` | open grid of triangles or quads |
/// | `mixed:N` | open grid of triangles, quads, pentagons and hexagons ([`mixed_grid`]) |
/// | `genus:G:N` | closed surface of genus G ([`perforated_plate`]) |
/// | `holes:K:N` | genus-0 surface with K boundary curves ([`perforated_plate`]) |
/// | `surface:G:K:N` | genus G and K boundary curves |
///
/// `_` may separate digits (`torus:1_000_000`). [`SpecError::Unknown`] for anything else;
/// [`SpecError::TooLarge`] for more than [`MAX_FACES`] faces, more than [`MAX_SLOTS`] tunnels
/// and openings, or a mesh whose vertices or corners `u32` ids cannot number (4 corners per
/// face: `quad-grid:1073741824` has 2³² corners).
pub fn parse_spec(spec: &str) -> Result<MeshSpec, SpecError> {
    if let Some(m) = canonical_by_name(spec) {
        return Ok(MeshSpec::Canonical(m));
    }
    let mut parts = spec.split(':');
    let kind = parts.next().ok_or(SpecError::Unknown)?;
    let numbers: Vec<u128> = parts
        .map(count)
        .collect::<Option<_>>()
        .ok_or(SpecError::Unknown)?;
    let arity = match kind {
        "torus" | "sphere" | "grid" | "quad-grid" | "mixed" => 1,
        "genus" | "holes" => 2,
        "surface" => 3,
        _ => return Err(SpecError::Unknown),
    };
    let Some((&n, slots)) = numbers.split_last().filter(|_| numbers.len() == arity) else {
        return Err(SpecError::Unknown);
    };
    // Refused before any arithmetic on them: with n ≤ 2^30 and 2^20 slots, the counts below
    // fit a usize with room to spare.
    if n > MAX_FACES as u128 {
        return Err(SpecError::TooLarge {
            what: "faces",
            count: n,
            max: MAX_FACES as u64,
            why: "u32 ids number 3 corners per face",
        });
    }
    let slot_count = slots.iter().fold(0u128, |a, &b| a.saturating_add(b));
    if slot_count > MAX_SLOTS as u128 {
        return Err(SpecError::TooLarge {
            what: "tunnels and openings",
            count: slot_count,
            max: MAX_SLOTS as u64,
            why: "each takes a tile of at least 64 triangles",
        });
    }
    let n = n as usize;
    let slots: Vec<usize> = slots.iter().map(|&k| k as usize).collect();
    let side = |cells: usize| ((cells as f64).sqrt().round() as usize).max(1);
    let parsed = match (kind, slots.as_slice()) {
        ("torus", []) => {
            let (nu, nv) = torus_sides(n.max(2));
            MeshSpec::Torus { nu, nv }
        }
        ("sphere", []) => MeshSpec::Sphere {
            side: side(n / 2).max(3),
        },
        ("grid", []) => MeshSpec::Grid {
            side: side(n / 2),
            triangulated: true,
        },
        ("quad-grid", []) => MeshSpec::Grid {
            side: side(n),
            triangulated: false,
        },
        ("mixed", []) => MeshSpec::Mixed { faces: n },
        ("genus", &[genus]) => MeshSpec::Plate {
            genus,
            holes: 0,
            triangles: n,
        },
        ("holes", &[holes]) => MeshSpec::Plate {
            genus: 0,
            holes,
            triangles: n,
        },
        ("surface", &[genus, holes]) => MeshSpec::Plate {
            genus,
            holes,
            triangles: n,
        },
        _ => return Err(SpecError::Unknown),
    };
    if let Some((what, count)) = parsed.size().beyond_u32() {
        return Err(SpecError::TooLarge {
            what,
            count: count.into(),
            max: u32::MAX as u64 - 1,
            why: "u32 ids",
        });
    }
    Ok(parsed)
}

/// The mesh [`parse_spec`] names, generated.
pub fn from_spec(spec: &str) -> Result<PolygonSoup, SpecError> {
    parse_spec(spec).map(MeshSpec::generate)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_past_u32_ids_are_too_large_not_unknown() {
        let too_large = |spec: &str| match parse_spec(spec) {
            Err(SpecError::TooLarge { what, .. }) => what,
            other => panic!("{spec}: {other:?}"),
        };
        assert_eq!(too_large("torus:99999999999"), "faces");
        assert_eq!(
            too_large("torus:999999999999999999999999999999999999999999"),
            "faces"
        );
        assert_eq!(too_large("genus:99999999999:10"), "tunnels and openings");
        // 2^30 quads have 2^32 corners: within MAX_FACES, past what u32 offsets number.
        assert_eq!(too_large("quad-grid:1073741824"), "corners");
        assert_eq!(too_large("mixed:1073741824"), "corners");
        // 2^30 triangles are within every limit (3 · 2^30 corners).
        assert!(parse_spec("torus:1073741824").is_ok());
    }

    #[test]
    fn sizes_are_the_generated_counts() {
        let specs = [
            "torus:1000",
            "torus:0",
            "torus:77777",
            "sphere:5000",
            "sphere:1",
            "grid:5000",
            "grid:1",
            "quad-grid:999",
            "mixed:500",
            "mixed:12345",
            "mixed:1",
            "genus:3:20000",
            "holes:5:20000",
            "surface:2:3:20000",
            "genus:40:10",
            "holes:1:1",
            "open-tetrahedron",
        ];
        for spec in specs {
            let parsed = parse_spec(spec).unwrap();
            let size = parsed.size();
            let canonical = matches!(parsed, MeshSpec::Canonical(_));
            let soup = parsed.generate();
            assert_eq!(size, MeshSize::of(&soup), "{spec}");
            // The generators reserve what they use: no buffer grows (and doubles) on the way.
            if !canonical {
                assert_eq!(size.soup_bytes(), soup.heap_bytes() as u64, "{spec}");
            }
        }
    }
}
