//! What the wrappers of the C++ baselines share (the `openmesh` and `cgal` modules): the status
//! codes of their shims as typed errors, the operator and workload codes of the shims' tables,
//! the checked ids of a sampled kernel's queries ([`sample_ids`]), Rust closures called back
//! from C++ with their panics carried across, the lab's checks and
//! errors for what a halfedge library refuses, the `explain` text of halfedge records, and
//! ([`edit`]) the one forwarding layer from `MeshEdit` to the shims' edit functions.
//!
//! Both shims number their statuses the same way (`openmesh/shim.h`, `cgal/shim.h`): 0 ok,
//! 1 a refused face, 2 out of memory, 3 another C++ exception, 4 an unknown code; and their
//! operators and workloads by the same tables (a test reads both headers).

/// The forwarding layer from `MeshEdit` to the shims' edit functions.
pub(crate) mod edit;
pub(crate) mod topology;

/// A C function of a shim's API with its name (for [`Error::Foreign`]).
pub(crate) struct Call<F> {
    pub(crate) name: &'static str,
    pub(crate) f: F,
}

use glam::DVec3;
use std::any::Any;
use std::ffi::c_void;
use std::fmt::Write;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use topolab_structures::{
    BoundaryCurves, BuildFacts, Connectivity, EdgeId, Element, Error, Input, Operator, PolygonSoup,
    Result, Sample, Workload,
};

// Positions go to C++ as 3 doubles per vertex, without a copy.
const _: () = assert!(std::mem::size_of::<DVec3>() == 24);

/// The status of a shim call that succeeded.
pub(crate) const OK: i32 = 0;
/// The library refused a face while building (the shim names it).
pub(crate) const REFUSED: i32 = 1;
/// `std::bad_alloc`.
pub(crate) const OUT_OF_MEMORY: i32 = 2;
/// Any other C++ exception.
pub(crate) const EXCEPTION: i32 = 3;
/// A structure, operator or workload code the shim does not know.
pub(crate) const UNKNOWN_CODE: i32 = 4;

/// A shim's callback for one answer (an index).
pub(crate) type Emit = unsafe extern "C" fn(context: *mut c_void, index: u32);
/// A shim's callback at the end of a boundary curve.
pub(crate) type EndCurve = unsafe extern "C" fn(context: *mut c_void);

/// The lab's error for status `code` of shim function `call` of `library`.
pub(crate) fn status(library: &'static str, call: &'static str, code: i32) -> Result<()> {
    let reason = match code {
        OK => return Ok(()),
        OUT_OF_MEMORY => "out of memory",
        EXCEPTION => "a C++ exception",
        UNKNOWN_CODE => "a structure, operator or workload code the shim does not know",
        REFUSED => "it refused a face",
        _ => "an unknown status",
    };
    Err(Error::Foreign {
        library,
        call,
        reason,
    })
}

/// For the trait's infallible queries (they cannot return an error): the shims' reads of a
/// built mesh allocate nothing and throw nothing, so a failure here is a broken invariant of a
/// shim, reported like Rust's own out-of-memory (which aborts).
pub(crate) fn infallible(library: &'static str, call: &'static str, code: i32) {
    if let Err(e) = status(library, call, code) {
        panic!("{e} (a query that cannot fail did)");
    }
}

/// The shims' code of operator `op`: the "Operator codes" table of `openmesh/shim.h` and
/// `cgal/shim.h` (a test reads both tables and checks this match against them).
pub(crate) const fn operator_code(op: Operator) -> i32 {
    match op {
        Operator::R00 => 0,
        Operator::R01 => 1,
        Operator::R02 => 2,
        Operator::R10 => 3,
        Operator::R11 => 4,
        Operator::R12 => 5,
        Operator::R20 => 6,
        Operator::R21 => 7,
        Operator::R22 => 8,
        Operator::BoundaryVertex => 9,
        Operator::BoundaryEdge => 10,
        Operator::BoundaryCurves => 11,
        Operator::EdgeSuccessor => 12,
        Operator::EdgePredecessor => 13,
    }
}

/// The shims' code of workload `w`: their "Workload codes" table.
pub(crate) const fn workload_code(w: Workload) -> i32 {
    match w {
        Workload::Circulators => 0,
        Workload::Barycenter => 1,
        Workload::Normals => 2,
        Workload::Smoothing => 3,
    }
}

/// The queries of `sample`, asked of operator `op` of `structure`, a mesh with `counts` =
/// [vertices, edges, faces], as both shims take a sample: one id per query, or the edge then
/// the face of each (edge, face) query of successor and predecessor (the shims' handles are
/// these indices, or are looked up from them once, before anything is timed). Checked here,
/// once, so that the shims' timed loops check nothing: an error when `op` has no sampled
/// kernel (boundary curves), when the sample is not the kind of query `op` takes, or for the
/// first id the mesh does not have.
pub(crate) fn sample_ids(
    structure: &'static str,
    op: Operator,
    sample: Sample<'_>,
    counts: [u32; 3],
) -> Result<Vec<u32>> {
    if op.input() == Input::Mesh {
        return Err(Error::Unsupported(format!(
            "{}: {} asks about the whole mesh and has no sampled kernel",
            structure,
            op.name()
        )));
    }
    if sample.input() != op.input() {
        return Err(Error::Unsupported(format!(
            "{}: {} takes {:?} queries, not {:?} ones",
            structure,
            op.name(),
            op.input(),
            sample.input()
        )));
    }
    let [vertices, edges, faces] = counts;
    let checked = |element: Element, id: u32| {
        let count = match element {
            Element::Vertex => vertices,
            Element::Edge => edges,
            Element::Face => faces,
            Element::Mesh => 0,
        };
        if id < count {
            Ok(id)
        } else {
            Err(Error::ElementOutOfRange {
                structure,
                element,
                id,
                count,
            })
        }
    };
    match sample {
        Sample::Vertices(ids) => ids.iter().map(|v| checked(Element::Vertex, v.0)).collect(),
        Sample::Edges(ids) => ids.iter().map(|e| checked(Element::Edge, e.0)).collect(),
        Sample::Faces(ids) => ids.iter().map(|f| checked(Element::Face, f.0)).collect(),
        Sample::EdgesOfFaces(pairs) => pairs
            .iter()
            .flat_map(|&(e, f)| [checked(Element::Edge, e.0), checked(Element::Face, f.0)])
            .collect(),
    }
}

/// A Rust closure called from C++, with a panic caught and carried back across the FFI
/// (unwinding through C++ frames is not allowed).
struct Callback<F> {
    f: F,
    panic: Option<Box<dyn Any + Send>>,
}

impl<F> Callback<F> {
    fn new(f: F) -> Self {
        Self { f, panic: None }
    }

    fn run(&mut self, call: impl FnOnce(&mut F)) {
        if self.panic.is_some() {
            return;
        }
        if let Err(payload) = catch_unwind(AssertUnwindSafe(|| call(&mut self.f))) {
            self.panic = Some(payload);
        }
    }

    /// Re-raises a panic of the closure, now that C++ has returned.
    fn finish(self) {
        if let Some(payload) = self.panic {
            resume_unwind(payload);
        }
    }
}

unsafe extern "C" fn emit_index<F: FnMut(u32)>(context: *mut c_void, index: u32) {
    // SAFETY: `context` is the `&mut Callback<F>` that `with_emit` passed along with this very
    // instantiation, alive and not otherwise borrowed for the C++ call.
    let callback = unsafe { &mut *context.cast::<Callback<F>>() };
    callback.run(|f| f(index));
}

unsafe extern "C" fn push_curve_edge(context: *mut c_void, index: u32) {
    // SAFETY: `context` is the `&mut Callback<&mut BoundaryCurves>` of `with_curves`.
    let callback = unsafe { &mut *context.cast::<Callback<&mut BoundaryCurves>>() };
    callback.run(|out| out.edges.push(EdgeId(index)));
}

unsafe extern "C" fn end_curve(context: *mut c_void) {
    // SAFETY: as in `push_curve_edge`.
    let callback = unsafe { &mut *context.cast::<Callback<&mut BoundaryCurves>>() };
    callback.run(|out| out.end_curve());
}

/// Runs `call(emit, context)`, a shim function that calls `emit(context, index)` per answer,
/// with `f` receiving the answers; returns the shim's status. A panic of `f` stops further
/// calls of `f` and is re-raised once C++ has returned. `call` must pass both arguments on
/// unchanged and must not keep them.
pub(crate) fn with_emit<F: FnMut(u32)>(f: F, call: impl FnOnce(Emit, *mut c_void) -> i32) -> i32 {
    let mut callback = Callback::new(f);
    let code = call(emit_index::<F>, (&mut callback as *mut Callback<F>).cast());
    callback.finish();
    code
}

/// Like [`with_emit`] for a shim function that writes boundary curves: its edges one by one,
/// then the end of each curve; `out` is cleared first.
pub(crate) fn with_curves(
    out: &mut BoundaryCurves,
    call: impl FnOnce(Emit, EndCurve, *mut c_void) -> i32,
) -> i32 {
    out.clear();
    let mut callback = Callback::new(out);
    let code = call(
        push_curve_edge,
        end_curve,
        (&mut callback as *mut Callback<&mut BoundaryCurves>).cast(),
    );
    callback.finish();
    code
}

/// The lab's error for face `face` that a library refused while building (`what`, e.g.
/// "OpenMesh's add_face"): the soup's own edge analysis names the problem the way every other
/// structure does; failing that, the non-manifold vertex of that face.
pub(crate) fn refusal(soup: &PolygonSoup, face: usize, what: &str) -> Error {
    let connectivity = match soup.connectivity() {
        Ok(c) => c,
        Err(e) => return e,
    };
    let fans = connectivity.vertex_fans(soup);
    match soup.face(face).iter().find(|&&v| fans[v as usize] > 1) {
        Some(&vertex) => Error::NonManifoldVertex {
            vertex,
            fans: fans[vertex as usize] as usize,
        },
        None => Error::Unsupported(format!(
            "{what} refused face {face} {:?} of a manifold soup",
            soup.face(face)
        )),
    }
}

/// The lab's checks of `soup` before a halfedge library builds it, and what its construction is
/// told (`SeparateConstruction::admit` of every baseline): the lab's edge analysis refuses what every
/// structure refuses, [`check_open_fans`] what these libraries refuse in some face orders
/// only, and the analysis's edge count, exact for any soup it accepts, is what the library
/// reserves for.
pub(crate) fn admit(soup: &PolygonSoup) -> Result<BuildFacts<'_>> {
    let connectivity = soup.connectivity()?;
    check_open_fans(soup, &connectivity)?;
    BuildFacts::new(soup, connectivity.num_edges())
}

/// The halfedge libraries (OpenMesh, CGAL's Surface_mesh and Polyhedron_3) store a vertex
/// with several fans by linking the fans' boundary halfedges, so every fan must be open: a
/// closed fan plus another one at the same vertex (two cones tip to tip, one closed) is
/// refused by their `add_face` ("complex vertex"). Refusing it here, before the library,
/// makes the answer independent of the face order.
///
/// Before that, a vertex of so many faces that these libraries would take time quadratic in
/// them is refused ([`Connectivity::check_star_sizes`], [`Error::StarTooLarge`]).
pub(crate) fn check_open_fans(soup: &PolygonSoup, connectivity: &Connectivity) -> Result<()> {
    connectivity.check_star_sizes(soup)?;
    let fans = connectivity.vertex_fans(soup);
    if fans.iter().all(|&n| n <= 1) {
        return Ok(());
    }
    // Each open fan has two boundary edges at its vertex (one in, one out).
    let mut boundary_sides = vec![0u32; soup.num_vertices()];
    for (face, corners) in soup.faces().enumerate() {
        let start = soup.face_start(face);
        for (i, &v) in corners.iter().enumerate() {
            if connectivity.twin_corner(start + i).is_none() {
                boundary_sides[v as usize] += 1;
                boundary_sides[corners[(i + 1) % corners.len()] as usize] += 1;
            }
        }
    }
    match (0..fans.len()).find(|&v| fans[v] > 1 && boundary_sides[v] < 2 * fans[v]) {
        Some(v) => Err(Error::NonManifoldVertex {
            vertex: v as u32,
            fans: fans[v] as usize,
        }),
        None => Ok(()),
    }
}

/// A halfedge library's records, read one by one through its shim (for `explain`). Halfedge
/// `h`'s opposite is `h ^ 1` and its edge `h / 2` in every library the lab wraps; `u32::MAX`
/// stands for "none".
pub(crate) trait HalfedgeRecords {
    /// Numbers of vertices, edges and faces.
    fn counts(&self) -> [u32; 3];
    /// The position of vertex `v`.
    fn record_position(&self, v: u32) -> DVec3;
    /// The halfedge vertex `v` keeps.
    fn vertex_halfedge(&self, v: u32) -> u32;
    /// Halfedge `h`: (to vertex, next, prev, face).
    fn halfedge(&self, h: u32) -> [u32; 4];
    /// The halfedge face `f` keeps.
    fn face_halfedge(&self, f: u32) -> u32;
}

/// Writes every record of `records` after the line `title`: vertices (position and the
/// halfedge each keeps, `vertex_halfedge` saying which one: `("outgoing", "out")` or
/// `("incoming", "in")`, long and short), halfedges, faces.
pub(crate) fn explain_halfedges(
    w: &mut dyn Write,
    records: &impl HalfedgeRecords,
    title: &str,
    vertex_halfedge: (&str, &str),
) -> std::fmt::Result {
    let (long, short) = vertex_halfedge;
    let [vertices, edges, faces] = records.counts();
    let show = |x: u32, prefix: &str| {
        if x == u32::MAX {
            "-".to_string()
        } else {
            format!("{prefix}{x}")
        }
    };
    writeln!(w, "{title}")?;
    writeln!(w, "vertices: {vertices} (position, {long} halfedge)")?;
    for v in 0..vertices {
        let p = records.record_position(v);
        let h = records.vertex_halfedge(v);
        writeln!(
            w,
            "  v{v}: ({:.3}, {:.3}, {:.3})  {short} {}",
            p.x,
            p.y,
            p.z,
            show(h, "h")
        )?;
    }
    writeln!(w, "halfedges: {} (to vertex, next, prev, face)", 2 * edges)?;
    for h in 0..2 * edges {
        let [to, next, prev, face] = records.halfedge(h);
        writeln!(
            w,
            "  h{h} (edge e{}): to v{to}, next h{next}, prev h{prev}, face {}",
            h / 2,
            show(face, "f")
        )?;
    }
    writeln!(w, "faces: {faces} (one halfedge)")?;
    for f in 0..faces {
        writeln!(w, "  f{f}: h{}", records.face_halfedge(f))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The (code, name) pairs of the table titled `title` in the header comment of `header`:
    /// the indented lines after the title.
    fn shim_table(header: &str, title: &str) -> Vec<(i32, String)> {
        let mut lines = header.lines().skip_while(|l| !l.contains(title)).skip(1);
        let mut pairs = Vec::new();
        while let Some(entries) = lines.next().and_then(|l| l.strip_prefix(" *   ")) {
            let tokens: Vec<&str> = entries.split_whitespace().collect();
            for pair in tokens.chunks(2) {
                let code = pair[0].parse().expect("a code, then a name");
                pairs.push((code, pair[1].to_string()));
            }
        }
        pairs
    }

    #[test]
    fn sample_ids_are_checked_and_laid_out_for_the_shims() {
        use topolab_structures::{FaceId, VertexId};
        let counts = [4, 6, 3];
        let ids = |op, sample| sample_ids("baseline", op, sample, counts);
        let vertices = [VertexId(3), VertexId(0), VertexId(3)];
        assert_eq!(
            ids(Operator::R00, Sample::Vertices(&vertices)).unwrap(),
            [3, 0, 3]
        );
        let pairs = [(EdgeId(5), FaceId(2)), (EdgeId(0), FaceId(1))];
        assert_eq!(
            ids(Operator::EdgeSuccessor, Sample::EdgesOfFaces(&pairs)).unwrap(),
            [5, 2, 0, 1]
        );
        // The first id past its count is named, whichever side of a pair it is on.
        for (op, sample, element, id) in [
            (Operator::R00, Sample::Vertices(&[VertexId(4)]), "vertex", 4),
            (
                Operator::R11,
                Sample::Edges(&[EdgeId(1), EdgeId(6)]),
                "edge",
                6,
            ),
            (Operator::R22, Sample::Faces(&[FaceId(9)]), "face", 9),
            (
                Operator::EdgePredecessor,
                Sample::EdgesOfFaces(&[(EdgeId(5), FaceId(3))]),
                "face",
                3,
            ),
        ] {
            let e = ids(op, sample).unwrap_err();
            assert_eq!(e.kind(), "element-out-of-range", "{e}");
            assert!(
                e.to_string().contains(&format!("no {element} {id} (")),
                "{e}"
            );
        }
        // A sample of another kind of query, or an operator without queries, is refused.
        for (op, sample) in [
            (Operator::R10, Sample::Vertices(&vertices)),
            (Operator::EdgeSuccessor, Sample::Faces(&[FaceId(0)])),
            (Operator::BoundaryCurves, Sample::Edges(&[EdgeId(0)])),
        ] {
            let e = ids(op, sample).unwrap_err();
            assert_eq!(e.kind(), "unsupported", "{e}");
            assert!(e.to_string().contains(op.name()), "{e}");
        }
    }

    #[test]
    fn codes_are_the_tables_of_both_shim_headers() {
        for header in [
            include_str!("../cpp/openmesh/shim.h"),
            include_str!("../cpp/cgal/shim.h"),
        ] {
            let ops = shim_table(header, "Operator codes");
            assert_eq!(ops.len(), Operator::ALL.len(), "{ops:?}");
            for (code, name) in &ops {
                let op = Operator::from_name(name).expect("an operator name");
                assert_eq!(operator_code(op), *code, "{name}");
            }
            let workloads = shim_table(header, "Workload codes");
            assert_eq!(workloads.len(), Workload::ALL.len(), "{workloads:?}");
            for (code, name) in &workloads {
                let w = Workload::from_name(name).expect("a workload name");
                assert_eq!(workload_code(w), *code, "{name}");
            }
        }
    }
}
