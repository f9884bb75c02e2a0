//! What the report says of each outside library it ran ("How the baselines are run"): the
//! facts of this build (versions, sources, flags) and of how the lab calls each library. One
//! function per library, each listed only when it is compiled in and the run used it.

use super::BaselineRun;
use topolab_registry as registry;

/// How the C++ baselines' heap is counted, the same sentence for each.
const CPP_HEAP: &str = "in one untimed build of its own, by the lab's global operator new and delete (baselines/cpp/heap/heap.cpp), each block for its malloc_usable_size, as the Rust structures' blocks are counted by the lab's global allocator; peak and held bytes of that build";

/// What the report's run used: the structures it measured, and whether its hull, decimation
/// and libigl sections ran.
#[derive(Clone, Copy, Debug)]
pub struct Used<'a> {
    /// The structures measured (their names).
    pub structures: &'a [&'a str],
    /// Whether the hull section ran.
    pub hull: bool,
    /// Whether the decimation section ran.
    pub decimate: bool,
    /// libigl's version, when its section ran.
    pub libigl: Option<&'a str>,
}

/// Every outside library this build has and the run used, in page order.
pub fn runs(used: Used<'_>) -> Vec<BaselineRun> {
    let mut runs = Vec::new();
    let measured = |name: &str| used.structures.contains(&name);
    if let Some(build) = topolab_baselines::OPENMESH_BUILD {
        if measured(registry::OPENMESH) || used.decimate {
            runs.push(openmesh(build));
        }
    }
    #[cfg(has_cgal)]
    {
        let version = topolab_baselines::cgal::version();
        if measured(registry::CGAL_SURFACE_MESH) || measured(registry::CGAL_POLYHEDRON) {
            runs.push(cgal_structures(&version));
        }
        if used.hull {
            runs.push(cgal_hull(&version));
        }
    }
    #[cfg(has_qhull)]
    if used.hull {
        runs.push(qhull());
    }
    if let Some(version) = used.libigl {
        runs.push(libigl(version));
    }
    #[cfg(feature = "peers")]
    for c in &registry::PEER_CRATES {
        if c.structures.iter().any(|s| measured(s)) {
            runs.push(peer(c));
        }
    }
    runs
}

/// A Rust crate of `topolab-peers`: the same for each, but its version, use and differences.
#[cfg(feature = "peers")]
fn peer(c: &registry::PeerCrate) -> BaselineRun {
    BaselineRun {
        name: c.structures.join(", "),
        library: format!("{} {} (Rust, crates.io)", c.name, c.version),
        build: "from crates.io at this exact version (its checksum in Cargo.lock), compiled in the lab's workspace with the lab's release profile, as the lab's own structures".into(),
        used_as: c.used_as.into(),
        timed: "construction: the crate's own build alone (the lab's checks before the clock, the adapter's id tables after it, as CGAL's); every sweep, sampled kernel and workload by the lab's generic Rust kernels, the adapter's calls inlined into them as the lab's structures' are (no FFI, so no native loops)".into(),
        counted: "by the lab's global allocator, as the lab's own structures: every block allocated during one untimed build, for its malloc_usable_size; peak and held bytes of that build".into(),
        differences: c.differences.iter().map(|d| d.to_string()).collect(),
    }
}

fn openmesh(build: &str) -> BaselineRun {
    BaselineRun {
        name: registry::OPENMESH.into(),
        library: build.split(',').next().unwrap_or(build).trim().into(),
        build: build.into(),
        used_as: "TriMesh_ArrayKernelT (PolyMesh_ArrayKernelT for polygons) with double-precision points; built with reserve, add_vertex, add_face; queried with its circulators (vv, ve, vf, fv, fe, ff ranges) and handle steps; the changing workloads with its split, flip, collapse and garbage_collection; decimation with DecimaterT and ModQuadricT".into(),
        timed: "construction: the reserve, add_vertex and add_face calls alone (the lab's checks and the exact counts before the clock, freeing after); every sweep, sampled kernel and workload as one C++ loop; decimation: initialize() and decimate_to_faces(), the mesh built before and compacted after".into(),
        counted: CPP_HEAP.into(),
        differences: vec![
            "OpenMesh's functions are called in a static library, out of line from the lab's C++ loops (no link-time optimisation across them), as an application linking OpenMesh calls them; the Rust structures are inlined into their loops.".into(),
            "The collapse test collapses without a legality test, as the Surface_mesh benchmark runs OpenMesh; the lab's structures run their own test before every collapse.".into(),
            "Decimation: the lab's eager strategy asks each structure's own collapse test with a vertex pair, which finds the half-edge and compares the two 1-rings (O(k²) on the index half-edge), where OpenMesh's is_collapse_ok starts from the half-edge and tags the 1-ring (O(k)): work on the lab's side.".into(),
            "Decimation: OpenMesh slides boundary vertices along the boundary; the lab's decimater keeps them, so that every collapse can be undone by a vertex split (the Targets' tori have no boundary).".into(),
        ],
    }
}

#[cfg(has_cgal)]
fn cgal_structures(version: &str) -> BaselineRun {
    BaselineRun {
        name: format!("{}, {}", registry::CGAL_SURFACE_MESH, registry::CGAL_POLYHEDRON),
        library: format!("CGAL {version} (header-only)"),
        build: "Debian's libcgal-dev headers, compiled here into the shim at -O3 -DNDEBUG (baselines/cpp/cgal/*.cpp)".into(),
        used_as: "Surface_mesh<Point_3> built with reserve, add_vertex, add_face; Polyhedron_3 (HalfedgeDS_list, Polyhedron_items_with_id_3) built with Polyhedron_incremental_builder_3; both queried with CGAL's circulators and halfedge functions, and changed with its Euler operations".into(),
        timed: "construction: the library's build calls alone (Polyhedron_3's id tables made after the clock); every sweep, sampled kernel (its queries turned into CGAL's descriptors before the clock) and workload as one C++ loop".into(),
        counted: CPP_HEAP.into(),
        differences: vec![
            "Polyhedron_3 stores an id per element and the lab keeps tables from id to handle (8 bytes per element), so that the lab's integer ids reach it; both are in its bytes.".into(),
            "CGAL's Euler::collapse_edge is called without a legality test in the collapse test, as the Surface_mesh benchmark does.".into(),
        ],
    }
}

#[cfg(has_cgal)]
fn cgal_hull(version: &str) -> BaselineRun {
    BaselineRun {
        name: topolab_baselines::hulls::HullLibrary::CgalConvexHull3.name().into(),
        library: format!("CGAL {version} convex_hull_3"),
        build: "Debian's libcgal-dev headers, compiled here at -O3 -DNDEBUG (baselines/cpp/cgal/hull.cpp), linked with GMP".into(),
        used_as: "convex_hull_3 with the Exact_predicates_inexact_constructions_kernel into a Surface_mesh".into(),
        timed: "the convex_hull_3 call alone, warm: a run to warm up, then the median of the timed runs, as every hull of the section".into(),
        counted: "not counted (GMP allocates with its own malloc)".into(),
        differences: Vec::new(),
    }
}

#[cfg(has_qhull)]
fn qhull() -> BaselineRun {
    BaselineRun {
        name: topolab_baselines::hulls::HullLibrary::Qhull.name().into(),
        library: format!("Qhull {} (libqhull_r)", topolab_baselines::qhull::version()),
        build: "Debian's libqhull-dev, linked; the C shim baselines/c/qhull/shim.c compiled here at -O3 -DNDEBUG".into(),
        used_as: topolab_baselines::qhull::description(),
        timed: "qh_new_qhull and collecting the hull's vertex ids, in-process, warm: a run to warm up, then the median of the timed runs; copying the points, the volume and freeing are outside the clock".into(),
        counted: "not counted".into(),
        differences: vec![
            "Qhull triangulates merged facets (option Qt) and reports its own facets; the lab's algorithms build a winged-edge hull. Both report the same vertices, which the report checks.".into(),
        ],
    }
}

fn libigl(version: &str) -> BaselineRun {
    BaselineRun {
        name: "libigl".into(),
        library: format!("libigl {version} (Python bindings)"),
        build: "PyPI's libigl wheel, in the repository's .venv".into(),
        used_as: "its adjacency functions (adjacency_list, vertex_triangle_adjacency, edges, triangle_triangle_adjacency, boundary_loop_all, per_vertex_normals) on the tori, one thread (IGL_NUM_THREADS=1)".into(),
        timed: "each function call alone, in the Python process (python/libigl_reference.py); its answers are checked against the lab's sweeps".into(),
        counted: "not counted".into(),
        differences: vec![
            "libigl answers whole-mesh questions (every vertex's neighbours at once, into arrays), not one query at a time, and runs behind Python: its times are a reference beside the lab's sweeps, not a structure in the tables.".into(),
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_baseline_is_listed_only_when_the_run_used_it() {
        let none = runs(Used {
            structures: &["vertex-list"],
            hull: false,
            decimate: false,
            libigl: None,
        });
        assert!(none.is_empty(), "{none:?}");
        let with_libigl = runs(Used {
            structures: &[],
            hull: false,
            decimate: false,
            libigl: Some("2.6.1"),
        });
        assert_eq!(with_libigl.len(), 1);
        assert_eq!(with_libigl[0].library, "libigl 2.6.1 (Python bindings)");
    }

    /// Each crate is listed once when one of its structures was measured, by its version.
    #[cfg(feature = "peers")]
    #[test]
    fn a_rust_crate_is_listed_when_one_of_its_structures_ran() {
        let runs = runs(Used {
            structures: &["lox-directed-edge", "tri-mesh"],
            hull: false,
            decimate: false,
            libigl: None,
        });
        let libraries: Vec<&str> = runs.iter().map(|r| r.library.as_str()).collect();
        assert_eq!(
            libraries,
            [
                "lox 0.1.1 (Rust, crates.io)",
                "tri-mesh 0.6.1 (Rust, crates.io)"
            ]
        );
        assert_eq!(runs[0].name, "lox-half-edge, lox-directed-edge");
        assert!(runs.iter().all(|r| !r.differences.is_empty()));
    }

    #[test]
    fn openmesh_is_described_by_its_build() {
        let Some(build) = topolab_baselines::OPENMESH_BUILD else {
            eprintln!("SKIPPED: OpenMesh is not compiled in");
            return;
        };
        let runs = runs(Used {
            structures: &[registry::OPENMESH],
            hull: false,
            decimate: false,
            libigl: None,
        });
        assert_eq!(runs[0].name, registry::OPENMESH);
        assert_eq!(runs[0].build, build);
        assert!(
            runs[0].library.starts_with("OpenMesh "),
            "{}",
            runs[0].library
        );
    }

    #[cfg(has_cgal)]
    #[test]
    fn cgal_names_the_version_of_its_headers() {
        let v = topolab_baselines::cgal::version();
        assert!(
            v.split('.').all(|p| p.parse::<u32>().is_ok()),
            "a dotted version: {v}"
        );
    }
}
