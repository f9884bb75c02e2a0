//! The limit of a sweep cell: the time the structure's declared access model
//! ([`MeshTopology::access`](topolab_structures::MeshTopology::access)) allows on this machine,
//! as the largest of three bounds.
//!
//! - *Bandwidth*: the bytes the sweep reads, at the probe's sequential read bandwidth for the
//!   working set of the containers it touches. A sweep in storage order reads each cache line
//!   of a container once, so a container's bytes count at most once (its size), except for
//!   scans, which read it whole for every query. The cache moves whole lines, not the bytes a
//!   query reads: where a model says its reads take part of a record (OpenMesh's halfedge:
//!   to-vertex and next, 8 of its 16 bytes), the sweep fetches the whole records it visits
//!   ([`Read::fetched`](topolab_structures::Read::fetched)). Counting only the bytes read put
//!   such a structure's bound at half of what a sweep of every record can reach.
//! - *Latency*: the dependent loads on the queries' chains, one after the other, each at the
//!   probe's load latency for the working set one query reads (an O(k) query's few lines sit
//!   in L1; a query that reads the whole mesh, such as the boundary curves, waits on memory).
//!
//! - *Checksum*: the harness's own arithmetic, one checksum term per answer at the probe's time
//!   per term: the floor of every structure's sweep, which a cheap query reaches.
//!
//! The sweep also reads what the harness's checksum asks for: the end vertices of every edge
//! it mixes in (an R10 of the structure: see [`checksum_keys`]). What the model leaves out
//! (arithmetic on the chain, branches, the structure's own bookkeeping) is what "× limit"
//! measures. One part of it is measured beside the limit, not in it: the chain when each step also
//! does the arithmetic the model declares ([`Step`]), at the probe's
//! chase of that kind ([`Limit::chain_ns_per_item`]). The CHE's `prev(h)` before each `O[]` load
//! makes a step about twice a plain load's latency in L1, the half-edges' `h ^ 1` about 1.2
//! times (the page's probe table gives this run's figures). Neither is a floor: both count one
//! query's chain after another, and a processor can overlap the chains of consecutive queries
//! (the index half-edge has run below its chain in the Targets turns). The limit
//! counts plain loads, as the model declares them, and the Targets show each sweep held to
//! its limit whose steps do arithmetic against its chain too.

pub use crate::measuring::cells::{Bound, Limit, MeshCounts};
use crate::measuring::probe::Probe;
use std::fmt::Write;
use topolab_structures::{Access, Operator, PolygonSoup, Step, Unit};

impl MeshCounts {
    /// The counts of `soup`; `None` when its edges cannot be analysed (a soup no structure with
    /// an access model stores).
    pub fn of(soup: &PolygonSoup) -> Option<Self> {
        let c = soup.connectivity().ok()?;
        Some(Self {
            vertices: soup.num_vertices(),
            edges: c.num_edges(),
            faces: soup.num_faces(),
            corners: soup.num_corners(),
            boundary_edges: c.edge_corners.iter().filter(|e| e[1] == u32::MAX).count(),
        })
    }

    /// Elements of a container of one element per `unit`.
    pub fn elements(&self, unit: Unit) -> f64 {
        (match unit {
            Unit::Vertex => self.vertices,
            Unit::Edge => self.edges,
            Unit::Face => self.faces,
            Unit::Corner => self.corners,
            Unit::HalfEdge => 2 * self.edges,
        }) as f64
    }

    /// The answers a sweep of `op` reports over the whole mesh (every structure reports the
    /// same: their checksums agree): each edge is a neighbour of both its ends (R00, R01),
    /// each corner a vertex-face incidence (R02, R12, R20, R21) and an (edge, face) query
    /// (successor, predecessor), each corner's edge but those on the boundary a face across
    /// (R22); R11 reports the other two edges of each triangle of an edge; the boundary
    /// operators report the boundary (one boundary vertex per boundary edge on a manifold).
    pub fn sweep_answers(&self, op: Operator) -> f64 {
        let (e, c, b) = (
            self.edges as f64,
            self.corners as f64,
            self.boundary_edges as f64,
        );
        match op {
            Operator::R00 | Operator::R01 | Operator::R10 => 2.0 * e,
            Operator::R02 | Operator::R12 | Operator::R20 | Operator::R21 => c,
            Operator::R11 => 2.0 * c,
            Operator::R22 => c - b,
            Operator::BoundaryVertex | Operator::BoundaryEdge | Operator::BoundaryCurves => b,
            Operator::EdgeSuccessor | Operator::EdgePredecessor => c,
        }
    }
}

/// The edge keys the harness's checksum ([`crate::measuring::kernels::run`]) reads while sweeping `op`, one
/// R10 each: (per query, per answer). Edge-valued answers enter by their end vertices; so do
/// the queried edge of R11, R12 and the (edge, face) queries, and each boundary edge found.
pub fn checksum_keys(op: Operator) -> (f64, f64) {
    match op {
        Operator::R01 | Operator::R21 | Operator::BoundaryEdge | Operator::BoundaryCurves => {
            (0.0, 1.0)
        }
        Operator::R11 | Operator::EdgeSuccessor | Operator::EdgePredecessor => (1.0, 1.0),
        Operator::R12 => (1.0, 0.0),
        _ => (0.0, 0.0),
    }
}

/// The checksum terms a sweep of `op` computes: one per answer, one per edge for R10 (whose two
/// vertices make one term).
pub fn checksum_terms(op: Operator, queries: f64, answers: f64) -> f64 {
    if op == Operator::R10 {
        queries
    } else {
        answers
    }
}

/// The limit of a sweep of `op` over `items` queries of a mesh of `counts`, for a structure
/// whose model of `op` is `access` and of R10 `r10` (for the checksum's edge keys), on the
/// machine of `probe`. `None` without queries, without probe levels, or when the checksum
/// needs edge keys and the structure has no R10 model.
pub fn limit(
    access: &Access,
    r10: Option<&Access>,
    op: Operator,
    counts: &MeshCounts,
    items: usize,
    probe: &Probe,
) -> Option<Limit> {
    if items == 0 {
        return None;
    }
    let q = items as f64;
    let answers = counts.sweep_answers(op);
    let (key_q, key_a) = checksum_keys(op);
    let keys = key_q * q + key_a * answers;
    // (container, bytes read locally, bytes scanned), each container once.
    let mut per_container: Vec<(topolab_structures::Container, f64, f64)> = Vec::new();
    let mut add = |c: topolab_structures::Container, local: f64, scanned: f64| match per_container
        .iter_mut()
        .find(|x| x.0.name == c.name)
    {
        Some(x) => {
            x.1 += local;
            x.2 += scanned;
        }
        None => per_container.push((c, local, scanned)),
    };
    for r in access.reads {
        let size = counts.elements(r.container.per) * r.container.bytes;
        let [per_query, per_answer] = r.fetched();
        add(
            r.container,
            per_query * q + per_answer * answers,
            r.scans * q * size,
        );
    }
    if keys > 0.0 {
        for r in r10?.reads {
            let size = counts.elements(r.container.per) * r.container.bytes;
            let [per_query, per_answer] = r.fetched();
            // R10 answers two vertices per query: its reads are per query.
            add(
                r.container,
                (per_query + 2.0 * per_answer) * keys,
                r.scans * keys * size,
            );
        }
    }
    let (mut bytes, mut touched, mut read_by_queries) = (0.0, 0.0, 0.0);
    for (c, local, scanned) in &per_container {
        let size = counts.elements(c.per) * c.bytes;
        bytes += local.min(size) + scanned;
        touched += size;
        read_by_queries += local + scanned;
    }
    let bandwidth_level = probe.level_for(touched)?;
    let bandwidth_ns = bytes / bandwidth_level.read_bytes_per_s * 1e9;
    let loads = access.chain_per_query * q + access.chain_per_answer * answers;
    let latency_level = probe.level_for(read_by_queries / q)?;
    let latency_ns = loads * latency_level.load_ns;
    let chain_ns = loads * latency_level.step_ns(access.step);
    let terms = checksum_terms(op, q, answers);
    let checksum_ns = terms * probe.checksum_ns;
    let (ns, bound) = [
        (bandwidth_ns, Bound::Bandwidth),
        (latency_ns, Bound::Latency),
        (checksum_ns, Bound::Checksum),
    ]
    .into_iter()
    .fold(
        (0.0, Bound::Bandwidth),
        |a, b| if b.0 > a.0 { b } else { a },
    );
    Some(Limit {
        ns_per_item: ns / q,
        bound,
        bytes_per_item: bytes / q,
        bandwidth_ns_per_item: bandwidth_ns / q,
        bandwidth_level: bandwidth_level.name.clone(),
        loads_per_item: loads / q,
        latency_ns_per_item: latency_ns / q,
        latency_level: latency_level.name.clone(),
        checksum_ns_per_item: checksum_ns / q,
        checksum_terms_per_item: terms / q,
        step: access.step,
        chain_ns_per_item: chain_ns / q,
        note: access.note.map(str::to_string),
    })
}

/// A measured cell's time as a multiple of its limit; `None` where the limit is no positive
/// time (a model that reads nothing per element, such as the boundary curves of a closed
/// torus: no ratio to it means anything, and `inf×` is not a number a reader can use).
pub(crate) fn times_limit(m: &crate::measuring::cells::Measurement) -> Option<f64> {
    let limit = m.limit.as_ref()?.ns_per_item;
    let x = m.ns_per_item? / limit;
    (limit > 0.0 && x.is_finite()).then_some(x)
}

/// How a limit was set, for a cell's tooltip and a target's reason.
pub(crate) fn limit_text(l: &crate::measuring::cells::Limit) -> String {
    let bound = match l.bound {
        crate::measuring::cells::Bound::Latency => "latency",
        crate::measuring::cells::Bound::Bandwidth => "bandwidth",
        crate::measuring::cells::Bound::Checksum => "checksum",
    };
    let mut t = format!(
        "{bound} bound; latency: {:.1} dependent loads per element at the {} latency ({}); bandwidth: {:.1} bytes per element at the {} bandwidth ({}); checksum arithmetic: {}",
        l.loads_per_item,
        l.latency_level,
        crate::format::ns(l.latency_ns_per_item),
        l.bytes_per_item,
        l.bandwidth_level,
        crate::format::ns(l.bandwidth_ns_per_item),
        crate::format::ns(l.checksum_ns_per_item)
    );
    if l.step != Step::Load && l.chain_ns_per_item > 0.0 {
        let _ = write!(
            t,
            "; the chain's arithmetic, measured: a step of {} takes {:.2}× a plain load at the {} latency, so the chain alone takes {}",
            l.step.text(),
            l.chain_ns_per_item / l.latency_ns_per_item,
            l.latency_level,
            crate::format::ns(l.chain_ns_per_item)
        );
    }
    if let Some(n) = &l.note {
        let _ = write!(t, "; not in the model: {n}");
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measuring::probe::Level;
    use topolab_structures::{meshes, Container, Read, Step};

    /// A machine of two levels, 1 MB at 100 GB/s and 2 ns a load, memory at 10 GB/s and
    /// 100 ns (a twin step 1.25 times a load, a corner step twice); half a nanosecond a
    /// checksum term.
    fn probe() -> Probe {
        Probe {
            read_bytes_per_s: 10e9,
            read_array_bytes: 1 << 30,
            chase_ns_per_hop: 100.0,
            chase_array_bytes: 1 << 30,
            levels: vec![
                Level::for_tests("L2", 1_000_000, 100.0, 2.0),
                Level::for_tests("memory", 1 << 30, 10.0, 100.0),
            ],
            checksum_ns: 0.5,
        }
    }

    /// A closed mesh of 1M vertices, 3M edges, 2M triangles.
    const TORUS: MeshCounts = MeshCounts {
        vertices: 1_000_000,
        edges: 3_000_000,
        faces: 2_000_000,
        corners: 6_000_000,
        boundary_edges: 0,
    };

    const NEXT: Container = Container::new("next", Unit::HalfEdge, 4.0);
    const VH: Container = Container::new("vh", Unit::Vertex, 4.0);

    #[test]
    fn counts_of_a_torus_and_a_grid() {
        let t = MeshCounts::of(&meshes::torus(10, 8)).unwrap();
        assert_eq!((t.vertices, t.faces, t.corners), (80, 160, 480));
        assert_eq!((t.edges, t.boundary_edges), (240, 0));
        // The sum of valences is twice the edges; every corner is one vertex-face incidence.
        assert_eq!(t.sweep_answers(Operator::R00), 480.0);
        assert_eq!(t.sweep_answers(Operator::R22), 480.0);
        let g = MeshCounts::of(&meshes::grid(4, 3, true)).unwrap();
        // 4 × 3 quads split in two: a boundary of 2 · (4 + 3) edges.
        assert_eq!(g.boundary_edges, 14);
        assert_eq!(g.sweep_answers(Operator::R22), g.corners as f64 - 14.0);
        assert_eq!(g.elements(Unit::HalfEdge), 2.0 * g.edges as f64);
    }

    #[test]
    fn a_fan_walk_is_bound_by_its_chain_and_a_scan_by_its_bytes() {
        // One vh read per vertex (not on the chain: its address is the vertex), one next per
        // answer: 6 answers per vertex on the torus.
        let walk = Access::new(
            const { &[Read::new(VH, 4.0, 0.0), Read::new(NEXT, 0.0, 4.0)] },
            0.0,
            1.0,
        );
        let l = limit(&walk, None, Operator::R00, &TORUS, 1_000_000, &probe()).unwrap();
        // 6 loads a vertex; one query reads 4 + 24 bytes, an L2 working set: 2 ns each.
        assert_eq!((l.loads_per_item, l.latency_level.as_str()), (6.0, "L2"));
        assert!((l.latency_ns_per_item - 12.0).abs() < 1e-9, "{l:?}");
        // 28 bytes a vertex from 28 MB of containers, at the memory's 10 GB/s: 2.8 ns.
        assert_eq!(l.bandwidth_level, "memory");
        assert!((l.bytes_per_item - 28.0).abs() < 1e-9);
        assert!((l.bandwidth_ns_per_item - 2.8).abs() < 1e-9);
        // 6 checksum terms a vertex: 3 ns.
        assert!((l.checksum_ns_per_item - 3.0).abs() < 1e-9);
        assert_eq!(l.checksum_terms_per_item, 6.0);
        // Declared plain loads: the chain costs what the loads cost.
        assert_eq!((l.step, l.chain_ns_per_item), (Step::Load, 12.0));
        // The same loads declared as CHE corner steps: the limit counts them as loads still,
        // the chain beside it at the corner step's latency.
        let corner = limit(
            &walk.stepping(Step::Corner),
            None,
            Operator::R00,
            &TORUS,
            1_000_000,
            &probe(),
        )
        .unwrap();
        assert_eq!(
            (corner.ns_per_item, corner.step),
            (l.ns_per_item, Step::Corner)
        );
        assert!((corner.chain_ns_per_item - 24.0).abs() < 1e-9, "{corner:?}");
        assert_eq!(
            (l.bound, l.ns_per_item),
            (Bound::Latency, l.latency_ns_per_item)
        );

        // A fifth of the dependent loads (2.4 ns): the checksum's 3 ns is the limit.
        let walk2 = Access::new(walk.reads, 0.0, 0.2);
        let l = limit(&walk2, None, Operator::R00, &TORUS, 1_000_000, &probe()).unwrap();
        assert_eq!(
            (l.bound, l.ns_per_item),
            (Bound::Checksum, l.checksum_ns_per_item)
        );

        // A scan of vh per query, nothing on a chain: the whole 4 MB each time.
        let scan = Access::new(const { &[Read::scan(VH, 1.0)] }, 0.0, 0.0);
        let l = limit(&scan, None, Operator::R00, &TORUS, 1_000_000, &probe()).unwrap();
        assert_eq!(l.bound, Bound::Bandwidth);
        assert!((l.bytes_per_item - 4e6).abs() < 1e-3, "{l:?}");
        assert!((l.ns_per_item - 4e6 / 10e9 * 1e9).abs() < 1e-6);
        assert_eq!(l.latency_ns_per_item, 0.0);
    }

    #[test]
    fn a_container_read_more_than_once_streams_once_and_keys_add_r10() {
        // R11 reads 32 bytes of next per edge: 96 MB of reads from a 24 MB container.
        let r11 = Access::new(const { &[Read::new(NEXT, 32.0, 0.0)] }, 4.0, 0.0);
        let r10 = Access::new(
            const {
                &[Read::new(
                    Container::new("vertex", Unit::HalfEdge, 4.0),
                    8.0,
                    0.0,
                )]
            },
            1.0,
            0.0,
        );
        let items = TORUS.edges;
        assert_eq!(
            limit(&r11, None, Operator::R11, &TORUS, items, &probe()),
            None,
            "the checksum needs R10"
        );
        let l = limit(&r11, Some(&r10), Operator::R11, &TORUS, items, &probe()).unwrap();
        // next: capped at its 24 MB; vertex: a key per query and per answer (five per edge),
        // 8 bytes each, capped at its 24 MB too.
        assert!((l.bytes_per_item - 48e6 / 3e6).abs() < 1e-9, "{l:?}");
        // The key reads are not on the chain.
        assert_eq!(l.loads_per_item, 4.0);
        // R12's checksum reads one key per query: the vertex array once (24 MB), beside 4
        // bytes of next per edge (12 MB, under its size).
        let r12 = Access::new(const { &[Read::new(NEXT, 4.0, 0.0)] }, 1.0, 0.0);
        let l12 = limit(&r12, Some(&r10), Operator::R12, &TORUS, items, &probe()).unwrap();
        assert!((l12.bytes_per_item - 12.0).abs() < 1e-9, "{l12:?}");
        assert_eq!(
            limit(&r12, Some(&r10), Operator::R12, &TORUS, 0, &probe()),
            None
        );
    }

    #[test]
    fn reads_that_take_part_of_a_record_fetch_the_whole_record() {
        // OpenMesh's R00: to-vertex and next, 8 bytes of a 16-byte halfedge, per answer.
        const HALFEDGES: Container = Container::new("halfedges", Unit::HalfEdge, 16.0);
        let bytes_only = Access::new(const { &[Read::new(HALFEDGES, 0.0, 8.0)] }, 0.0, 1.0);
        let records = Access::new(
            const { &[Read::new(HALFEDGES, 0.0, 8.0).in_records(0.0, 1.0)] },
            0.0,
            1.0,
        );
        let l = |a: &Access| limit(a, None, Operator::R00, &TORUS, TORUS.vertices, &probe());
        let (b, r) = (l(&bytes_only).unwrap(), l(&records).unwrap());
        // 6 answers a vertex: 48 bytes read, but 96 bytes of records brought in; the torus's 6
        // million halfedges are read whole (96 MB), not past their size.
        assert!((b.bytes_per_item - 48.0).abs() < 1e-9, "{b:?}");
        assert!((r.bytes_per_item - 96.0).abs() < 1e-9, "{r:?}");
        assert!((r.bandwidth_ns_per_item - 2.0 * b.bandwidth_ns_per_item).abs() < 1e-9);
        // A whole-record read (an array of one field) fetches what it reads.
        let next = Read::new(NEXT, 0.0, 4.0);
        assert_eq!(next.fetched(), [0.0, 4.0]);
        assert_eq!(next.in_records(0.0, 1.0).fetched(), [0.0, 4.0]);
    }
}
