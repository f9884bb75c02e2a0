//! A benchmark-style check (not a test) of the OpenMesh baseline on a 1M-triangle torus:
//! construction and the native sweeps and workloads, median of 7 runs, with checksums.
//!
//! ```sh
//! cargo run --release --example openmesh_vs            # 1M triangles
//! cargo run --release --example openmesh_vs -- 200000  # another size
//! ```
//!
//! Our `vertex-list` answers R00 by scanning every face (O(n) per query, O(n²) per sweep),
//! so it is not run at this size; the lab's own structures are timed by the harness.

#[cfg(not(has_openmesh))]
fn main() -> std::process::ExitCode {
    eprintln!("openmesh_vs: {}", topolab::OPENMESH_MISSING);
    std::process::ExitCode::FAILURE
}

#[cfg(has_openmesh)]
fn main() -> std::process::ExitCode {
    use std::time::{Duration, Instant};
    use topolab::openmesh::OpenMesh;
    use topolab_structures::{meshes, Input, MeshTopology, Operator, Workload};

    const RUNS: usize = 7;
    /// The median time of `RUNS` runs of `f`, and its last result.
    fn median<T>(mut f: impl FnMut() -> T) -> (Duration, T) {
        let mut times = Vec::with_capacity(RUNS);
        let mut last = None;
        for _ in 0..RUNS {
            let start = Instant::now();
            let out = std::hint::black_box(f());
            times.push(start.elapsed());
            last = Some(out);
        }
        times.sort_unstable();
        (times[RUNS / 2], last.expect("RUNS > 0"))
    }
    let ns = |d: Duration, n: usize| d.as_nanos() as f64 / n as f64;

    let triangles = match std::env::args().nth(1).map(|a| a.parse::<usize>()) {
        None => 1_000_000,
        Some(Ok(n)) if n >= 18 => n,
        Some(_) => {
            eprintln!("usage: openmesh_vs [TRIANGLES >= 18]");
            return std::process::ExitCode::from(2);
        }
    };
    let soup = meshes::torus_with_triangles(triangles);
    let (nv, nf) = (soup.num_vertices(), soup.num_faces());
    let edges = soup.num_corners() / 2; // closed triangle mesh: every edge has two corners
                                        // The heap at the peak of a build of its own (OpenMesh's construction alone), counted as
                                        // the report counts it.
    let (mesh, heap) = topolab::ALLOCATOR.measure(|| OpenMesh::build_native(&soup, edges));
    let mesh = mesh.expect("a torus builds");
    println!(
        "OpenMesh {} on a torus: {nv} vertices, {nf} triangles; median of {RUNS} runs\n",
        if soup.is_triangle_mesh() {
            "TriMesh_ArrayKernelT"
        } else {
            "PolyMesh_ArrayKernelT"
        }
    );

    // Times on a busy machine are inflated: say how busy it was.
    if let Ok(load) = std::fs::read_to_string("/proc/loadavg") {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        println!(
            "load average {} on {cores} cores\n",
            load.split(' ').take(3).collect::<Vec<_>>().join(" ")
        );
    }
    let (t, _) = median(|| OpenMesh::build_native(&soup, edges).expect("a torus builds"));
    println!(
        "construction (reserve + add_vertex + add_face, one C++ call): {:8.1} ns/face  {:7.1} ms",
        ns(t, nf),
        t.as_secs_f64() * 1e3
    );
    let (t, _) = median(|| OpenMesh::from_soup(&soup).expect("a torus builds"));
    println!(
        "from_soup (the lab's manifold checks + construction):        {:8.1} ns/face  {:7.1} ms",
        ns(t, nf),
        t.as_secs_f64() * 1e3
    );
    println!(
        "heap: {:.1} bytes/face at the build's peak ({:.1} MB), {:.1} declared by the records\n",
        heap as f64 / nf as f64,
        heap as f64 / 1e6,
        mesh.heap_bytes() as f64 / nf as f64,
    );

    println!("{:<18} {:>14} {:>22}", "sweep", "ns/element", "checksum");
    for op in Operator::ALL {
        let per = match op.input() {
            Input::Vertex => nv,
            Input::Edge => mesh.num_edges(),
            Input::Face | Input::EdgeOfFace | Input::Mesh => nf,
        };
        let (t, sum) = median(|| mesh.native_sweep(op).expect("OpenMesh failed"));
        println!("{:<18} {:>14.2} {:>22}", op.name(), ns(t, per), sum);
    }
    println!("(ns per vertex for r00 r01 r02 boundary-vertex, per edge for r10 r11 r12 boundary-edge, per face otherwise)\n");

    println!("{:<18} {:>14} {:>22}", "workload", "ns/vertex", "result");
    let mut mesh = mesh;
    for workload in Workload::ALL {
        if let Err(e) = mesh.prepare_workload(workload) {
            eprintln!("OpenMesh failed: {e}");
            return std::process::ExitCode::FAILURE;
        }
        let (t, value) = median(|| mesh.native_workload(workload).expect("OpenMesh failed"));
        println!(
            "{:<18} {:>14.2} {:>22.9}",
            workload.name(),
            ns(t, nv),
            value
        );
    }
    println!("(smoothing runs 7 steps in a row; its result is after the 7th)");
    std::process::ExitCode::SUCCESS
}
