//! The changing workloads (√3 subdivision, the collapse test) on a torus, index half-edge and
//! pointer half-edge against OpenMesh in turns: the median of the within-round ratios.
//!
//! ```sh
//! cargo run --release --example changing_vs             # 1M triangles, 7 rounds
//! cargo run --release --example changing_vs -- 200000 5
//! ```

#[cfg(not(has_openmesh))]
fn main() -> std::process::ExitCode {
    eprintln!("changing_vs: {}", topolab::OPENMESH_MISSING);
    std::process::ExitCode::FAILURE
}

#[cfg(has_openmesh)]
fn main() -> std::process::ExitCode {
    use std::time::Instant;
    use topolab::openmesh::OpenMesh;
    use topolab_harness::changing::mesh_checksum;
    use topolab_harness::timing::median;
    use topolab_structures::algorithms::changing::Changing;
    use topolab_structures::{meshes, IndexHalfEdge, MeshTopology, PointerHalfEdge};

    let mut args = std::env::args().skip(1);
    let triangles: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let rounds: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(7);
    let soup = meshes::torus_with_triangles(triangles);
    println!("torus of {} faces, {rounds} rounds", soup.num_faces());
    for w in Changing::ALL {
        let (mut index, mut pointer, mut om) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..rounds {
            let mut m = OpenMesh::from_soup(&soup).expect("manifold");
            m.prepare_changing().expect("a TriMesh");
            let t = Instant::now();
            m.native_changing(w).expect("runs");
            let t_om = t.elapsed().as_secs_f64();
            let expected = mesh_checksum(&m);
            drop(m);
            let mut m = IndexHalfEdge::from_soup(&soup).expect("manifold");
            let t = Instant::now();
            w.run(&mut m).expect("runs");
            let t_index = t.elapsed().as_secs_f64();
            assert_eq!(mesh_checksum(&m), expected, "index-half-edge disagrees");
            drop(m);
            let mut m = PointerHalfEdge::from_soup(&soup).expect("manifold");
            let t = Instant::now();
            w.run(&mut m).expect("runs");
            let t_pointer = t.elapsed().as_secs_f64();
            assert_eq!(mesh_checksum(&m), expected, "pointer-half-edge disagrees");
            index.push(t_index / t_om);
            pointer.push(t_pointer / t_om);
            om.push(t_om);
        }
        for v in [&mut index, &mut pointer, &mut om] {
            v.sort_by(f64::total_cmp);
        }
        println!(
            "{:>13}: OpenMesh {:.1} ms ({:.1} ns/face); index-half-edge {:.2}× OpenMesh, pointer-half-edge {:.2}× (medians of round ratios)",
            w.name(),
            median(&om) * 1e3,
            median(&om) * 1e9 / soup.num_faces() as f64,
            median(&index),
            median(&pointer)
        );
    }
    std::process::ExitCode::SUCCESS
}
