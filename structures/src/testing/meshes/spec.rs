//! The grammar of the built-in meshes the command line names (`torus:N`, `genus:G:N`, ...).

use super::canonical::canonical_by_name;
use super::generators::{grid, mixed_grid, perforated_plate, sphere, torus_with_triangles};
use crate::core::soup::PolygonSoup;

/// The largest face count [`from_spec`] generates: sizes past what `u32` handles number (a
/// triangle mesh of this many faces has 3·2³⁰ corners, under `u32::MAX`) are refused, not
/// attempted.
pub const MAX_FACES: usize = 1 << 30;

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
/// `_` may separate digits (`torus:1_000_000`). `None` for anything else, and for more than
/// [`MAX_FACES`] faces or 2^20 tunnels and openings.
pub fn from_spec(spec: &str) -> Option<PolygonSoup> {
    if let Some(m) = canonical_by_name(spec) {
        return Some(m.soup);
    }
    let mut parts = spec.split(':');
    let kind = parts.next()?;
    let numbers: Vec<usize> = parts
        .map(|n| n.replace('_', "").parse().ok())
        .collect::<Option<_>>()?;
    // Sizes past u32 handles (and slot counts that would need more) are refused, not attempted.
    // Like sizes past MAX_FACES, more tunnels and openings than this are refused, not attempted.
    const MAX_SLOTS: usize = 1 << 20;
    let (&n, counts) = numbers.split_last()?;
    if n > MAX_FACES || counts.iter().sum::<usize>() > MAX_SLOTS {
        return None;
    }
    let side = |cells: usize| ((cells as f64).sqrt().round() as usize).max(1);
    match (kind, numbers.as_slice()) {
        ("torus", &[n]) => Some(torus_with_triangles(n.max(2))),
        ("sphere", &[n]) => {
            let s = side(n / 2).max(3);
            Some(sphere(s, s))
        }
        ("grid", &[n]) => {
            let s = side(n / 2);
            Some(grid(s, s, true))
        }
        ("quad-grid", &[n]) => {
            let s = side(n);
            Some(grid(s, s, false))
        }
        ("mixed", &[n]) => Some(mixed_grid(n)),
        ("genus", &[g, n]) => Some(perforated_plate(g, 0, n)),
        ("holes", &[k, n]) => Some(perforated_plate(0, k, n)),
        ("surface", &[g, k, n]) => Some(perforated_plate(g, k, n)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::super::euler_and_curves;
    use super::*;

    #[test]
    fn specs_name_the_generators() {
        let g = from_spec("genus:2:1_000").unwrap();
        assert_eq!(euler_and_curves(&g), (-2, 0));
        let h = from_spec("holes:4:1000").unwrap();
        assert_eq!(euler_and_curves(&h), (-2, 4));
        let m = from_spec("surface:1:2:1000").unwrap();
        assert_eq!(euler_and_curves(&m), (-2, 2));
        assert_eq!(from_spec("mixed:500").unwrap(), mixed_grid(500));
        assert!(from_spec("genus:2").is_none());
        assert!(from_spec("holes:x:10").is_none());
        assert!(from_spec("torus:100:3").is_none());
        assert!(from_spec("genus:99999999999:10").is_none());
        assert!(from_spec("torus:99999999999").is_none());
    }
}
