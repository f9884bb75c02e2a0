//! `topolab hull`: the 3D convex hull of a point file or of random points, by one of the
//! algorithms of the lecture on 3D convex hulls, built on the winged-edge; prints counts, the
//! work the lecture's analysis counts, and time, optionally writes the hull as OBJ (outward
//! triangles, the hull's vertices only).

use crate::input::{load_mesh, Failure};
use crate::limits;
use crate::output::{check_mesh_out, write_mesh};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;
use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};
use topolab_structures::MeshTopology;

/// Options of `topolab hull`.
#[derive(clap::Args, Debug, Clone)]
pub struct HullArgs {
    /// A mesh or point file (.obj, .off, .ply, .stl): only its vertices are used; an OBJ of `v`
    /// lines only (a point cloud) works.
    #[arg(required_unless_present = "random", conflicts_with = "random")]
    pub file: Option<String>,
    /// Instead of a file: this many random points.
    #[arg(long)]
    pub random: Option<usize>,
    /// Where the random points come from: cube, ball or sphere.
    #[arg(long, default_value = "cube")]
    pub shape: String,
    /// The algorithm: gift (wrapping), incremental, randomized (incremental).
    #[arg(long, default_value = "randomized")]
    pub algo: String,
    /// Write the hull here (.obj, .off or .stl).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Seed of the random points and of the randomized algorithm's insertion order.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

/// A hull the algorithms refuse: exit code 1 for a property of the point set (too few
/// distinct points, all coplanar), 2 for points the request cannot take at all (coordinates
/// past the exact predicates' range, counts past `u32` ids), like the other requests that
/// cannot fit.
fn refused(e: topolab_structures::Error) -> Failure {
    let cannot_fit = matches!(
        e,
        topolab_structures::Error::CoordinateOutOfRange { .. }
            | topolab_structures::Error::TooLarge { .. }
    );
    Failure {
        message: format!("no hull ({}): {e}", e.kind()),
        code: if cannot_fit { 2 } else { 1 },
    }
}

/// The sample the randomized algorithm's memory is measured on: its conflict pool collects
/// garbage only once 2^16 entries (1 MB) are garbage, a fixed cost that made the peak per
/// point of 2,048 points 1.8 to 4.5 times that of 200k (measured: 714 against 157 bytes per
/// point in a ball, 806 against 441 on a sphere); at 32k points it is within 15% of the
/// larger sets' (163 against 157 to 165 bytes in a ball from 65k to 1M points, 382 against
/// 390 to 445 on a sphere). A randomized hull of 32k points takes milliseconds.
const RANDOMIZED_SAMPLE_POINTS: usize = 32_768;

/// The hull's memory on a sample of `shape` ([`limits::SAMPLE_POINTS`] points, or
/// [`RANDOMIZED_SAMPLE_POINTS`] for the randomized algorithm, at most `n`), scaled to `n`
/// points: the points, the hull and the soup `--out` writes. Doubled: the arrays grow as faces
/// are created, doubling their buffers, so where a sample's and a full run's sizes fall
/// between powers of two changes the peak per point (the plain scaling came out at 0.85 to
/// 1.12 times the measured peak on 50k to 200k points in a ball and on a sphere).
fn hull_bytes(shape: Shape, n: usize, algorithm: Algorithm) -> u64 {
    let sample = match algorithm {
        Algorithm::Randomized { .. } => RANDOMIZED_SAMPLE_POINTS.min(n),
        _ => limits::SAMPLE_POINTS,
    };
    let ((), peak) = limits::peak_of(|| {
        let points = random_points(shape, sample, 1);
        if let Ok(hull) = convex_hull(&points, algorithm) {
            hull.to_compact_soup();
        }
    });
    limits::scale(2 * peak, sample as u64, n as u64)
}

/// Runs `topolab hull`; returns the text to print.
pub fn hull(args: &HullArgs) -> Result<String, Failure> {
    let algorithm =
        Algorithm::from_name(&args.algo, args.seed).map_err(|e| Failure::usage(e.to_string()))?;
    if let Some(out) = &args.out {
        check_mesh_out(out, args.file.as_deref().unwrap_or(""))?;
    }
    let (points, source) = match (&args.file, args.random) {
        (_, Some(n)) => {
            let what = format!("--random {n}");
            // Hull vertices are u32 ids; more points would panic or abort in the allocation.
            limits::within_u32(&what, &[("points", n as u128)])?;
            let shape = Shape::from_name(&args.shape).map_err(|e| Failure::usage(e.to_string()))?;
            if n > limits::SAMPLE_POINTS {
                limits::admit(&what, hull_bytes(shape, n, algorithm))?;
            }
            let source = format!("{n} random points in {} (seed {})", args.shape, args.seed);
            (random_points(shape, n, args.seed), source)
        }
        (Some(file), None) => {
            let points = load_mesh(file, |_| 0)?.positions;
            // Measured on a sphere, where every point is a hull vertex: the most a hull holds.
            let n = points.len();
            if n > limits::SAMPLE_POINTS {
                let need = hull_bytes(Shape::Sphere, n, algorithm);
                limits::admit(&format!("the hull of {file}"), need)?;
            }
            (points, file.clone())
        }
        (None, None) => return Err(Failure::usage("give a FILE or --random N".into())),
    };
    let start = Instant::now();
    let hull = convex_hull(&points, algorithm).map_err(refused)?;
    let seconds = start.elapsed().as_secs_f64();
    let n = points.len();
    let mut text = String::new();
    let _ = writeln!(text, "points:        {n} ({source})");
    let _ = writeln!(text, "algorithm:     {}", algorithm.name());
    let _ = writeln!(text, "hull vertices: {}", hull.vertices().len());
    let _ = writeln!(text, "hull edges:    {}", hull.mesh.num_edges());
    let _ = writeln!(text, "hull faces:    {}", hull.mesh.num_faces());
    let _ = writeln!(
        text,
        "faces created: {} ({:.3} of the lecture's bound 6n - 20 = {})",
        hull.faces_created,
        hull.faces_created as f64 / (6.0 * n as f64 - 20.0),
        6 * n as i64 - 20
    );
    let w = hull.work;
    let n_lg_n = n as f64 * (n as f64).log2();
    let _ = writeln!(
        text,
        "Volume6 tests: {} ({} exact after the floating-point filter)",
        w.volume6_tests, w.exact_tests
    );
    if w.conflict_work > 0 {
        let _ = writeln!(
            text,
            "conflict work: {} (sum of |P(e)|; {:.3} of n lg n = {:.0})",
            w.conflict_work,
            w.conflict_work as f64 / n_lg_n,
            n_lg_n
        );
    }
    let _ = writeln!(text, "volume:        {}", hull.volume());
    let _ = writeln!(text, "time:          {:.6} s", seconds);
    if let Some(out) = &args.out {
        write_mesh(out, &hull.to_compact_soup())?;
        let _ = writeln!(text, "written:       {}", out.display());
    }
    Ok(text)
}
