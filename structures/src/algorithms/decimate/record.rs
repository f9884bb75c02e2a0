//! The collapse record as a file: what `topolab decimate --levels` writes beside the coarse
//! mesh and `topolab reconstruct` reads back, so that "first a coarse representation is
//! transmitted, then refined by further transmissions" and "reconstruction must be possible
//! again" (the lecture on polygon-mesh data structures, on thinning meshes for compression and
//! level of detail) hold across files.
//!
//! ## The format, version 1
//!
//! Text, one item a line, fields separated by single spaces; a line that starts with `#` is a
//! comment, anywhere:
//!
//! ```text
//! topolab-collapses 1
//! original V F FINGERPRINT
//! coarse V' F' FINGERPRINT
//! levels K
//! level FACES COLLAPSES FINGERPRINT        (K lines, in decimation order)
//! collapses N
//! FROM TO LEFT RIGHT X Y Z ERROR           (N lines, in decimation order)
//! end
//! ```
//!
//! - `original`: the input's vertex and face counts; `coarse`: the coarsest mesh's
//!   (`V' = V − N`, `F' = F − 2N`); `level`: each level's face count and the number of
//!   collapses done when it was reached (`FACES = F − 2 COLLAPSES`; the last level is the
//!   coarse mesh).
//! - FINGERPRINT: 16 hexadecimal digits, [`fingerprint`] of the mesh in the canonical form of
//!   [`live_soup`](super::live_soup) (its vertex numbering and face order, below), so that a
//!   coarse mesh that is not the one the record was made with is refused, and a
//!   reconstruction is checked.
//! - One line per collapse, in the order done: collapse `i` moved vertex `FROM`, at
//!   `(X, Y, Z)`, onto `TO` and deleted the triangles (`FROM`, `TO`, `LEFT`) and (`TO`,
//!   `FROM`, `RIGHT`) ([`Collapses`]); `ERROR` its quadric error. Vertices are named by their
//!   id in the original mesh. The numbers are written as Rust writes an `f64` (the shortest
//!   decimal that reads back as the same `f64`) and read with Rust's parser, so a position
//!   comes back bit for bit (the test `positions_round_trip_bit_for_bit` tries random bit
//!   patterns); the OBJ and OFF writers write positions the same way.
//! - `end` closes the file: a record cut short is refused, even one cut inside a number.
//!
//! ## Vertex numbering and face order of the meshes beside it
//!
//! The coarse mesh (and every level) holds the vertices of the original that are still
//! there, in increasing original id, numbered from 0 in that order; the original id of the
//! coarse mesh's vertex `k` is the `k`-th smallest id no collapse removed. Faces are each
//! rotated to start at their smallest vertex, and sorted: the original's face order cannot be
//! recovered from the collapses, so both commands write this order, the original included.

use super::Collapses;
use crate::core::soup::PolygonSoup;
use glam::DVec3;
use std::io::Write;

/// The first word of a record file.
pub const MAGIC: &str = "topolab-collapses";

/// The version of the format this code writes and reads.
pub const VERSION: u32 = 1;

/// A mesh's counts and [`fingerprint`], as the record states them.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Vertices.
    pub vertices: usize,
    /// Faces.
    pub faces: usize,
    /// [`fingerprint`] of the mesh in canonical form.
    pub fingerprint: u64,
}

/// One level of detail: the state after the first `collapses` collapses.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Level {
    /// Its face count.
    pub faces: usize,
    /// The collapses done when it was reached.
    pub collapses: usize,
    /// [`fingerprint`] of the level's mesh in canonical form.
    pub fingerprint: u64,
}

/// A collapse record: the original and coarse meshes' counts, the levels, the collapses.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Record {
    /// The mesh before any collapse.
    pub original: Counts,
    /// The mesh after all of them.
    pub coarse: Counts,
    /// The levels, in decimation order.
    pub levels: Vec<Level>,
    /// The collapses, in the order done.
    pub collapses: Collapses,
}

/// Why a record was refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum RecordError {
    /// The first line is not `topolab-collapses VERSION`.
    #[error("not a topolab collapse record: it must start with `{MAGIC} {VERSION}`")]
    NotARecord,
    /// A record of another version.
    #[error("a record of version {found}; this topolab reads version {VERSION}")]
    Version {
        /// The version the file states.
        found: String,
    },
    /// A line that does not read as the format says.
    #[error("line {line}: {message}")]
    Syntax {
        /// 1-based.
        line: usize,
        /// What was expected.
        message: String,
    },
    /// The file ends before `end`.
    #[error("the record ends early (cut short?): {expected} expected")]
    Truncated {
        /// What the next line should have been.
        expected: String,
    },
    /// Lines that read but do not fit together (counts that do not add up, an id past the
    /// original's vertices, a vertex removed twice or named after its removal).
    #[error("the record contradicts itself: {0}")]
    Inconsistent(String),
    /// A mesh that is not the one the record was made with.
    #[error("the record does not match {what}: {message}")]
    Mismatch {
        /// The mesh compared ("the coarse mesh").
        what: String,
        /// How it differs.
        message: String,
    },
}

/// A 64-bit FNV-1a hash of `soup`: its counts, every position's bits and every face's corners,
/// in order. Not a cryptographic hash: it tells a wrong file from the right one, not an
/// adversary's forgery.
pub fn fingerprint(soup: &PolygonSoup) -> u64 {
    const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01b3;
    let mut h = OFFSET;
    let mut eat = |x: u64| {
        for b in x.to_le_bytes() {
            h = (h ^ b as u64).wrapping_mul(PRIME);
        }
    };
    eat(soup.num_vertices() as u64);
    for p in &soup.positions {
        for c in p.to_array() {
            eat(c.to_bits());
        }
    }
    eat(soup.num_faces() as u64);
    for f in soup.faces() {
        eat(f.len() as u64);
        for &v in f {
            eat(v as u64);
        }
    }
    h
}

impl Counts {
    /// The counts and fingerprint of `soup`.
    pub fn of(soup: &PolygonSoup) -> Self {
        Self {
            vertices: soup.num_vertices(),
            faces: soup.num_faces(),
            fingerprint: fingerprint(soup),
        }
    }

    /// Does `soup` have these counts and fingerprint? What differs, if not.
    pub fn check(&self, what: &str, soup: &PolygonSoup) -> Result<(), RecordError> {
        let found = Counts::of(soup);
        let message = if (found.vertices, found.faces) != (self.vertices, self.faces) {
            format!(
                "it has {} vertices and {} faces, the record says {} and {}",
                found.vertices, found.faces, self.vertices, self.faces
            )
        } else if found.fingerprint != self.fingerprint {
            format!(
                "its fingerprint is {:016x}, the record says {:016x} (the same counts, other positions or faces)",
                found.fingerprint, self.fingerprint
            )
        } else {
            return Ok(());
        };
        Err(RecordError::Mismatch {
            what: what.to_string(),
            message,
        })
    }
}

impl Record {
    /// Writes the record in the format of the module docs.
    pub fn write(&self, w: &mut impl Write) -> std::io::Result<()> {
        let c = &self.collapses;
        writeln!(w, "{MAGIC} {VERSION}")?;
        writeln!(
            w,
            "# quadric-error decimation by topolab; vertices by their original id; see docs/level-of-detail.md"
        )?;
        for (name, k) in [("original", &self.original), ("coarse", &self.coarse)] {
            writeln!(
                w,
                "{name} {} {} {:016x}",
                k.vertices, k.faces, k.fingerprint
            )?;
        }
        writeln!(w, "levels {}", self.levels.len())?;
        for l in &self.levels {
            writeln!(
                w,
                "level {} {} {:016x}",
                l.faces, l.collapses, l.fingerprint
            )?;
        }
        writeln!(w, "collapses {}", c.len())?;
        writeln!(w, "# from to left right x y z error")?;
        for i in 0..c.len() {
            let p = c.position[i];
            writeln!(
                w,
                "{} {} {} {} {} {} {} {}",
                c.from[i], c.to[i], c.left[i], c.right[i], p.x, p.y, p.z, c.error[i]
            )?;
        }
        writeln!(w, "end")
    }

    /// The record as text ([`Record::write`]).
    pub fn to_text(&self) -> String {
        let mut out = Vec::new();
        self.write(&mut out).expect("writing to memory");
        String::from_utf8(out).expect("the record is ASCII")
    }

    /// Reads a record written by [`Record::write`] and checks that it holds together
    /// ([`Record::validate`]).
    pub fn parse(text: &str) -> Result<Record, RecordError> {
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l))
            .filter(|(_, l)| !l.starts_with('#'));
        let mut next = |expected: &str| {
            lines.next().ok_or_else(|| RecordError::Truncated {
                expected: expected.to_string(),
            })
        };
        let (_, first) = next("the first line")?;
        match first.split(' ').collect::<Vec<_>>()[..] {
            [MAGIC, v] if v == VERSION.to_string() => {}
            [MAGIC, v] => {
                return Err(RecordError::Version {
                    found: v.to_string(),
                })
            }
            _ => return Err(RecordError::NotARecord),
        }
        let mut record = Record::default();
        for (name, slot) in [
            ("original", &mut record.original),
            ("coarse", &mut record.coarse),
        ] {
            let (line, text) = next(name)?;
            let [v, f, h] = fields(line, text, name)?;
            *slot = Counts {
                vertices: number(line, v, "a vertex count")?,
                faces: number(line, f, "a face count")?,
                fingerprint: hex(line, h)?,
            };
        }
        let (line, text) = next("levels")?;
        let [k] = fields(line, text, "levels")?;
        let k: usize = number(line, k, "a level count")?;
        for _ in 0..k {
            let (line, text) = next("a level")?;
            let [f, c, h] = fields(line, text, "level")?;
            record.levels.push(Level {
                faces: number(line, f, "a face count")?,
                collapses: number(line, c, "a collapse count")?,
                fingerprint: hex(line, h)?,
            });
        }
        let (line, text) = next("collapses")?;
        let [n] = fields(line, text, "collapses")?;
        let n: usize = number(line, n, "a collapse count")?;
        if n > record.original.vertices {
            return Err(RecordError::Inconsistent(format!(
                "{n} collapses of {} vertices",
                record.original.vertices
            )));
        }
        let c = &mut record.collapses;
        for _ in 0..n {
            let (line, text) = next("a collapse")?;
            let words: Vec<&str> = text.split(' ').collect();
            let [from, to, left, right, x, y, z, error] = words[..] else {
                return Err(syntax(
                    line,
                    "a collapse is 8 numbers: from to left right x y z error",
                ));
            };
            c.from.push(number(line, from, "a vertex id")?);
            c.to.push(number(line, to, "a vertex id")?);
            c.left.push(number(line, left, "a vertex id")?);
            c.right.push(number(line, right, "a vertex id")?);
            c.position
                .push(DVec3::new(real(line, x)?, real(line, y)?, real(line, z)?));
            c.error.push(real(line, error)?);
        }
        let (line, text) = next("end")?;
        if text != "end" {
            return Err(syntax(
                line,
                format!("`end` expected after the {n} collapses"),
            ));
        }
        if let Some((line, _)) = lines.next() {
            return Err(syntax(line, "nothing may follow `end`"));
        }
        record.validate()?;
        Ok(record)
    }

    /// Checks that the record holds together: the counts add up (`V' = V − N`, `F' = F − 2N`,
    /// each level's faces `F − 2 COLLAPSES`, the levels' collapses not decreasing and the last
    /// `N`), every id is below `V`, no collapse's four vertices repeat, no vertex is removed
    /// twice, positions are finite, and undone last first, every collapse names vertices then
    /// present (the survivors and those re-created by later collapses).
    pub fn validate(&self) -> Result<(), RecordError> {
        let bad = |m: String| Err(RecordError::Inconsistent(m));
        let (v, f) = (self.original.vertices, self.original.faces);
        let c = &self.collapses;
        let n = c.len();
        let sizes = [c.to.len(), c.left.len(), c.right.len(), c.position.len()];
        if sizes.iter().any(|&s| s != n) || c.error.len() != n {
            return bad("the collapse arrays differ in length".into());
        }
        if n > v || 2 * n > f {
            return bad(format!("{n} collapses of {v} vertices and {f} faces"));
        }
        if (self.coarse.vertices, self.coarse.faces) != (v - n, f - 2 * n) {
            return bad(format!(
                "the coarse mesh has {} vertices and {} faces, but {v} and {f} less {n} collapses leave {} and {}",
                self.coarse.vertices,
                self.coarse.faces,
                v - n,
                f - 2 * n
            ));
        }
        let mut before = 0;
        for (i, l) in self.levels.iter().enumerate() {
            if l.collapses < before || l.collapses > n || l.faces != f - 2 * l.collapses {
                return bad(format!(
                    "level {} ({} faces after {} collapses) does not follow from {f} faces, {n} collapses and the level before",
                    i + 1,
                    l.faces,
                    l.collapses
                ));
            }
            before = l.collapses;
        }
        if self.levels.last().is_some_and(|l| l.collapses != n) {
            return bad("the last level is not the coarse mesh".into());
        }
        // Sets of the removed vertices, not arrays of the original's: `V` is only what the
        // file says until a mesh is compared with it.
        let mut removed = std::collections::HashSet::with_capacity(n);
        for i in 0..n {
            let ids = [c.from[i], c.to[i], c.left[i], c.right[i]];
            if let Some(&id) = ids.iter().find(|&&x| x as usize >= v) {
                return bad(format!(
                    "collapse {i} names vertex {id}, but the original has {v} vertices"
                ));
            }
            if (1..4).any(|a| ids[..a].contains(&ids[a])) {
                return bad(format!("collapse {i} names a vertex twice: {ids:?}"));
            }
            if !removed.insert(c.from[i]) {
                return bad(format!("vertex {} is removed twice", c.from[i]));
            }
            if !c.position[i].is_finite() {
                return bad(format!("collapse {i} has a non-finite position"));
            }
        }
        // Undone last first, `from` comes back after the split: the others must be there.
        for i in (0..n).rev() {
            if let Some(&id) = [c.to[i], c.left[i], c.right[i]]
                .iter()
                .find(|x| removed.contains(x))
            {
                return bad(format!(
                    "collapse {i} names vertex {id}, which an earlier collapse removed"
                ));
            }
            removed.remove(&c.from[i]);
        }
        Ok(())
    }

    /// Per original vertex, its id in the coarse mesh: the survivors numbered in increasing
    /// original id ([`u32::MAX`] for a removed vertex). What
    /// [`reconstruct_from`](super::reconstruct_from) starts from.
    pub fn coarse_ids(&self) -> Vec<u32> {
        let mut live = vec![0u32; self.original.vertices];
        for &v in &self.collapses.from {
            live[v as usize] = u32::MAX;
        }
        let mut k = 0;
        for slot in &mut live {
            if *slot == 0 {
                *slot = k;
                k += 1;
            }
        }
        live
    }

    /// How many of the collapses the first state with at least `faces` faces keeps, going
    /// from the coarse mesh towards the original (each vertex split adds two faces); `None`
    /// when `faces` is below the coarse mesh's or above the original's.
    pub fn keep_for(&self, faces: usize) -> Option<usize> {
        let (coarse, original) = (self.coarse.faces, self.original.faces);
        (coarse..=original)
            .contains(&faces)
            .then(|| (original - faces) / 2)
    }

    /// The level whose state keeps the first `keep` collapses, if one does.
    pub fn level_keeping(&self, keep: usize) -> Option<&Level> {
        self.levels.iter().find(|l| l.collapses == keep)
    }
}

fn syntax(line: usize, message: impl Into<String>) -> RecordError {
    RecordError::Syntax {
        line,
        message: message.into(),
    }
}

/// The fields after the keyword `name` of a line, exactly `K` of them.
fn fields<'a, const K: usize>(
    line: usize,
    text: &'a str,
    name: &str,
) -> Result<[&'a str; K], RecordError> {
    let mut words = text.split(' ');
    let fields: Vec<&str> = match words.next() {
        Some(w) if w == name => words.collect(),
        _ => return Err(syntax(line, format!("`{name}` expected"))),
    };
    fields
        .try_into()
        .map_err(|_| syntax(line, format!("`{name}` takes {K} numbers")))
}

fn number<T: std::str::FromStr>(line: usize, word: &str, what: &str) -> Result<T, RecordError> {
    word.parse()
        .map_err(|_| syntax(line, format!("{word:?} is not {what}")))
}

fn hex(line: usize, word: &str) -> Result<u64, RecordError> {
    if word.len() != 16 {
        return Err(syntax(
            line,
            format!("{word:?} is not a fingerprint of 16 hexadecimal digits"),
        ));
    }
    u64::from_str_radix(word, 16).map_err(|_| {
        syntax(
            line,
            format!("{word:?} is not a fingerprint of 16 hexadecimal digits"),
        )
    })
}

fn real(line: usize, word: &str) -> Result<f64, RecordError> {
    number(line, word, "a number")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithms::decimate::{
        canonical_input, decimate_levels, live_soup, reconstruct_from, Strategy,
    };
    use crate::core::topology::MeshTopology;
    use crate::families::half_edge::index::IndexHalfEdge;
    use crate::meshes;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn positions_round_trip_bit_for_bit() {
        // Every finite f64 the record may hold: random bit patterns (all exponents, subnormals
        // included) and the edge cases.
        let mut rng = ChaCha8Rng::seed_from_u64(36);
        let mut values: Vec<f64> = (0..200_000)
            .map(|_| f64::from_bits(rng.random::<u64>()))
            .filter(|x| x.is_finite())
            .collect();
        values.extend([
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            f64::from_bits(1),
            -f64::from_bits(1),
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            0.1,
            1.0 / 3.0,
        ]);
        for chunk in values.chunks(3) {
            let [x, y, z] = [chunk[0], chunk[chunk.len() / 2], chunk[chunk.len() - 1]];
            let record = Record {
                original: Counts {
                    vertices: 4,
                    faces: 4,
                    fingerprint: 1,
                },
                coarse: Counts {
                    vertices: 3,
                    faces: 2,
                    fingerprint: u64::MAX,
                },
                levels: vec![],
                collapses: Collapses {
                    from: vec![3],
                    to: vec![0],
                    left: vec![1],
                    right: vec![2],
                    position: vec![DVec3::new(x, y, z)],
                    error: vec![x.abs()],
                },
            };
            let back = Record::parse(&record.to_text()).expect("reads back");
            let bits = |r: &Record| r.collapses.position[0].to_array().map(f64::to_bits);
            assert_eq!(bits(&back), bits(&record), "{x:e} {y:e} {z:e}");
            assert_eq!(back.collapses.error[0].to_bits(), x.abs().to_bits());
        }
    }

    /// A real record: a torus decimated through two levels.
    fn torus_record() -> (Record, Vec<PolygonSoup>) {
        let soup = meshes::perturb(&meshes::torus(12, 8), 0.02, 7);
        let mut m = IndexHalfEdge::from_soup(&soup).expect("manifold");
        let identity: Vec<u32> = (0..soup.num_vertices() as u32).collect();
        let mut soups = Vec::new();
        let d = decimate_levels(&mut m, &[96, 40], Strategy::Lazy, |m, _| {
            soups.push(live_soup(m, &identity))
        })
        .expect("decimates");
        let record = Record {
            original: Counts::of(&canonical_input(&soup)),
            coarse: Counts::of(soups.last().expect("two levels")),
            levels: d
                .levels
                .iter()
                .zip(&soups)
                .map(|(&collapses, s)| Level {
                    faces: s.num_faces(),
                    collapses,
                    fingerprint: fingerprint(s),
                })
                .collect(),
            collapses: d.collapses,
        };
        (record, soups)
    }

    #[test]
    fn a_record_reads_back_as_written_and_rebuilds_each_level() {
        let (record, soups) = torus_record();
        record.validate().expect("holds together");
        let text = record.to_text();
        let back = Record::parse(&text).expect("reads back");
        assert_eq!(back, record);
        assert_eq!(back.to_text(), text);
        let coarse = soups.last().unwrap();
        for (l, level) in record.levels.iter().zip(&soups) {
            let mut m = IndexHalfEdge::from_soup(coarse).expect("manifold");
            let keep = record.keep_for(l.faces).expect("in range");
            assert_eq!(keep, l.collapses);
            let r = reconstruct_from(&mut m, &record.collapses, keep, record.coarse_ids())
                .expect("rebuilds");
            assert_eq!(&live_soup(&m, &r.original), level);
        }
    }

    #[test]
    fn what_does_not_hold_together_is_refused() {
        let (record, _) = torus_record();
        let text = record.to_text();
        let lines: Vec<&str> = text.lines().collect();
        let first_collapse = lines.iter().position(|l| l.starts_with("# from")).unwrap() + 1;
        let with = |i: usize, line: &str| {
            let mut l = lines.clone();
            l[i] = line;
            l.join("\n")
        };
        let levels = lines.iter().position(|l| l.starts_with("levels ")).unwrap();
        let n = record.collapses.len();
        let (v, f) = (record.original.vertices, record.original.faces);
        let out_of_range = format!("{v} 0 1 2 0 0 0 0");
        let twice = {
            let c = &record.collapses;
            format!(
                "{} {} {} {} 0 0 0 0",
                c.from[0], c.to[1], c.left[1], c.right[1]
            )
        };
        let cases: Vec<(String, &str)> = vec![
            (String::new(), "ends early"),
            (
                text.replacen(&format!("{MAGIC} 1"), &format!("{MAGIC} 2"), 1),
                "version 2",
            ),
            ("OFF\n".into(), "not a topolab collapse record"),
            // Cut inside the last collapse's numbers: `end` is missing.
            (
                text[..text.len() - "end\n".len() - 3].to_string(),
                "ends early",
            ),
            (text.replace("\nend", "\nend\nmore"), "nothing may follow"),
            (with(first_collapse, "1 2 3"), "a collapse is 8 numbers"),
            (with(first_collapse, &out_of_range), "original has"),
            (with(first_collapse + 1, &twice), "removed twice"),
            (
                text.replace(
                    &format!("original {v} {f}"),
                    &format!("original {v} {}", f + 2),
                ),
                "the coarse mesh has",
            ),
            (
                text.replace(&format!("collapses {n}"), &format!("collapses {}", n - 1)),
                "`end` expected",
            ),
            (with(levels, "levels x"), "is not a level count"),
            (with(levels, "level 1 2"), "`levels` expected"),
        ];
        for (bad, says) in cases {
            let e = Record::parse(&bad).expect_err(says).to_string();
            assert!(e.contains(says), "{says}: {e}");
        }
    }

    #[test]
    fn a_collapse_that_names_a_removed_vertex_is_refused() {
        // Vertex 3 is removed by collapse 0, then named by collapse 1 as `to`.
        let record = Record {
            original: Counts {
                vertices: 6,
                faces: 8,
                fingerprint: 0,
            },
            coarse: Counts {
                vertices: 4,
                faces: 4,
                fingerprint: 0,
            },
            levels: vec![],
            collapses: Collapses {
                from: vec![3, 4],
                to: vec![0, 3],
                left: vec![1, 1],
                right: vec![2, 2],
                position: vec![DVec3::ZERO; 2],
                error: vec![0.0; 2],
            },
        };
        let e = record.validate().unwrap_err().to_string();
        assert!(e.contains("which an earlier collapse removed"), "{e}");
    }

    #[test]
    fn the_coarse_ids_number_the_survivors_in_original_order() {
        let record = Record {
            original: Counts {
                vertices: 5,
                ..Counts::default()
            },
            collapses: Collapses {
                from: vec![3, 0],
                ..Collapses::default()
            },
            ..Record::default()
        };
        assert_eq!(
            record.coarse_ids(),
            [u32::MAX, 0, 1, u32::MAX, 2],
            "survivors 1, 2, 4"
        );
    }
}
