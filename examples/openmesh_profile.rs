//! One OpenMesh kernel on a torus, once, for `valgrind --tool=callgrind`: what the report times
//! of OpenMesh (its construction, or a changing workload after an untimed build), through the
//! same shim calls, so instruction counts (repeatable under load, unlike times) say where
//! OpenMesh's instructions go.
//!
//! ```sh
//! cargo build --release --example openmesh_profile
//! valgrind --tool=callgrind --toggle-collect=topolab_om_build \
//!     target/release/examples/openmesh_profile build 65536
//! valgrind --tool=callgrind --toggle-collect=topolab_om_changing \
//!     target/release/examples/openmesh_profile sqrt3 65536      # or collapse
//! valgrind --tool=callgrind --toggle-collect='*timed_decimation*' \
//!     target/release/examples/openmesh_profile decimate 16384
//! callgrind_annotate --inclusive=yes callgrind.out.<pid>
//! ```
//!
//! `--toggle-collect` counts only inside the named call: the build (`add_vertex` and
//! `add_face` per element, as the report's construction), the workload alone, or the
//! Decimater's `initialize()` and `decimate_to_faces()` to 10% of the faces (what the report's
//! decimation section times).

#[cfg(not(has_openmesh))]
fn main() -> std::process::ExitCode {
    eprintln!("openmesh_profile: {}", topolab::OPENMESH_MISSING);
    std::process::ExitCode::FAILURE
}

#[cfg(has_openmesh)]
fn main() -> std::process::ExitCode {
    use topolab::openmesh::OpenMesh;
    use topolab_structures::algorithms::changing::Changing;
    use topolab_structures::{meshes, MeshTopology};

    let mut args = std::env::args().skip(1);
    let kernel = args.next();
    let triangles = args.next().map(|a| a.parse::<usize>());
    const KERNELS: [&str; 4] = ["build", "sqrt3", "collapse", "decimate"];
    let (kernel, triangles) = match (kernel.as_deref(), triangles) {
        (Some(k), None) if KERNELS.contains(&k) => (k.to_string(), 65_536),
        (Some(k), Some(Ok(n))) if KERNELS.contains(&k) && n >= 18 => (k.to_string(), n),
        _ => {
            eprintln!(
                "usage: openmesh_profile {} [TRIANGLES >= 18]",
                KERNELS.join("|")
            );
            return std::process::ExitCode::from(2);
        }
    };
    let soup = meshes::torus_with_triangles(triangles);
    if kernel == "decimate" {
        // The report's decimation: to 10% of the faces, the whole of it in C++.
        let target = soup.num_faces() / 10;
        let got = topolab::native_decimate::NativeDecimater::OpenMesh
            .decimate(&soup, target)
            .expect("decimates");
        println!(
            "{kernel} on a torus of {} faces to {target}: {} vertices, {} faces after, {:.3} s",
            soup.num_faces(),
            got.result.num_vertices(),
            got.result.num_faces(),
            got.seconds
        );
        return std::process::ExitCode::SUCCESS;
    }
    // The report's timed construction (`OpenMesh::construct`, told the exact counts by the
    // lab's checks before it), then its finishing step.
    let separate = OpenMesh::separate_construction().expect("OpenMesh builds separately");
    let facts = separate.admit(&soup).expect("a torus is manifold");
    let mut m = separate
        .construction(&facts)
        .and_then(|built| built.finish(&soup))
        .expect("a torus builds");
    let workload = match kernel.as_str() {
        "sqrt3" => Some(Changing::Sqrt3),
        "collapse" => Some(Changing::Collapse),
        _ => None,
    };
    if let Some(w) = workload {
        m.prepare_changing().expect("a TriMesh");
        m.native_changing(w).expect("runs");
    }
    println!(
        "{kernel} on a torus of {} faces: {} vertices, {} faces after",
        soup.num_faces(),
        m.num_vertices(),
        m.num_faces()
    );
    std::process::ExitCode::SUCCESS
}
