//! "Decimation by quadric error, and reconstruction": the lab's decimater on the editable
//! structures beside OpenMesh's and CGAL's, each result's error, and the reconstruction.

use crate::decimate::DecimateRow;
use crate::phases::Phase;
use crate::report::section::{Needs, Page, Section};
use std::fmt::Write;

/// The report section.
fn render(h: &mut String, rows: &[DecimateRow]) {
    if rows.is_empty() {
        return;
    }
    h.push_str("<h2>Decimation by quadric error, and reconstruction</h2><div class=read><b>How to read it.</b> Thinning for level of detail, as the lecture on polygon-mesh data structures asks, with reconstruction possible again. Each mesh is decimated to 10% of its faces by Garland and Heckbert's quadric error. The lab's decimater runs on the editable structures with two strategies, both with OpenMesh's area-weighted plane quadrics, a heap of vertices keyed by their best half-edge collapse (the error rounded to <code>f32</code>), the removed vertex collapsed onto its neighbour (no optimal placement), the link condition of the structure's collapse test, and boundary vertices kept. <b>eager</b> rows run OpenMesh's <code>DecimaterT</code> with <code>ModQuadricT</code> step for step: every neighbour of a vertex tested for legality (<code>MeshEdit::check_collapse</code>, the structure's own test) before it is priced, only legal collapses heaped, one refused when it leaves the heap dropped, every neighbour of the removed vertex heaped again, no geometric test. They and OpenMesh's Decimater run one algorithm, so their time ratio compares the structures: the Targets row is the index half-edge's eager decimation against OpenMesh. <b>lazy</b> rows run the lab's own variant: collapses priced without a legality test and tested when they leave the heap (a refused vertex heaped again with its next-best neighbour), and a collapse that would flip or flatten a face skipped (OpenMesh's <code>ModNormalFlippingT</code> at 90°, which OpenMesh's row does not run): another algorithm, with fewer legality tests, shown beside but not a structure comparison. OpenMesh's own Decimater and CGAL's <code>edge_collapse</code> with the Garland–Heckbert plane policies on a <code>Surface_mesh</code> (edges keyed, the new vertex at the quadric's minimiser) run in C++. Time: the decimation alone, median of fresh builds (the build not timed); on the run's largest torus the index half-edge (eager) and OpenMesh take turns, round by round, and must give the same mesh, triangle for triangle, in every round (the report stops otherwise); the Targets table gives the median of their per-round ratios. The library functions OpenMesh's Decimater calls (its legality test <code>is_collapse_ok</code>, <code>find_halfedge</code>, <code>valence</code>, and <code>collapse</code>) are compiled with the report's shim, in release: Debian's library has its assertions compiled in, which cost 90% of the Decimater's instructions (callgrind, 16k torus: 2.71 G as shipped, 0.28 G so), with the same result mesh. Error, computed by the lab on every result the same way: the distance from each vertex of the original to the decimated surface, its maximum (one-sided Hausdorff at the vertices) and mean, in % of the bounding-box diagonal. Reconstruction: the recorded collapses replayed backwards by vertex splits, and the result compared with the original (positions bit for bit, the same oriented faces through the id mapping).</div>");
    h.push_str("<table><tr><th class=l>mesh</th><th>faces</th><th>target</th><th class=l>decimater</th><th>ms</th><th>× OpenMesh</th><th>faces after</th><th>max error %</th><th>mean error %</th><th>reconstruction ms</th><th>exact</th></tr>");
    for r in rows {
        let om = rows
            .iter()
            .find(|o| o.mesh == r.mesh && o.structure == "openmesh")
            .map(|o| format!("{:.2}", r.seconds / o.seconds))
            .unwrap_or_else(|| "–".into());
        let (rec, exact) = match r.reconstruction {
            Some((s, ok)) => (format!("{:.1}", s * 1e3), if ok { "yes" } else { "NO" }),
            None => ("–".into(), "–"),
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td>{}</td><td class=l>{}</td><td>{:.1}</td><td>{om}</td><td>{}</td><td>{:.4}</td><td>{:.4}</td><td>{rec}</td><td>{exact}</td></tr>",
            r.mesh,
            r.faces,
            r.target,
            r.decimater(),
            r.seconds * 1e3,
            r.faces_after,
            r.error.max * 100.0,
            r.error.mean * 100.0,
        );
    }
    h.push_str("</table>");
}

/// Decimation by quadric error against OpenMesh's and CGAL's decimaters, and the
/// reconstruction by vertex splits, on the generated tori.
pub struct Decimate;

impl Section for Decimate {
    fn name(&self) -> &'static str {
        "decimate"
    }

    fn needs(&self) -> Needs {
        Needs::GENERATED
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("decimate", "decimation"))
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, &page.r.decimate);
    }
}
