//! "Memory per triangle": heap bytes of each built structure and the peak while building it.

use crate::measuring::kernels::Kernel;
use crate::page::plot::Style;
use crate::page::svg;
use crate::report::cells::largest;
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{Measurement, Results, Status};
use std::fmt::Write;

/// One bar per structure built on `mesh`, per triangle of its `tri`: `bar` gives a construction
/// cell's bytes and, where it has one, its tick.
fn construction_bars(
    r: &Results,
    mesh: &str,
    tri: usize,
    ci: &dyn Fn(&str) -> Style,
    bar: impl Fn(&Measurement) -> Option<(u64, Option<u64>)>,
) -> Vec<(String, Style, f64, Option<f64>)> {
    let per = |b: u64| b as f64 / tri as f64;
    r.measurements
        .iter()
        .filter(|m| {
            m.mesh == mesh && m.kernel == Kernel::Construction && m.status == Status::Measured
        })
        .filter_map(|m| {
            let (bytes, tick) = bar(m)?;
            Some((
                m.structure.clone(),
                ci(&m.structure),
                per(bytes),
                tick.map(per),
            ))
        })
        .collect()
}

fn memory(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let rows = construction_bars(r, mesh, tri, ci, |m| m.bytes.map(|b| (b, m.declared_bytes)));
    let _ = write!(h, "<h2>Memory per triangle ({mesh})</h2><div class=read><b>How to read it.</b> Bars: heap bytes the built structure holds, divided by the number of triangles, geometry included, counted in a build of its own by one rule for every structure: each block counts for the bytes glibc's <code>malloc_usable_size</code> gives it (the request rounded up to glibc's 16-byte steps, at least 24; not the 8-byte size field glibc keeps in front of each block). The Rust structures' blocks are counted by the lab's global allocator, the C++ baselines' (OpenMesh, CGAL) by the lab's global <code>operator new</code> and <code>delete</code>, each counting the measuring thread's blocks only. Black tick: the bytes its containers should take by their lengths (<code>heap_bytes()</code>; for a C++ baseline, its records as the library lays them out); a gap between bar and tick is the allocator's rounding or memory not accounted. The second chart: the peak during that build, the structure's own construction (for a C++ baseline, the library's, without the lab's checks before it).</div>{}", svg::bars("bytes per triangle", "B", &rows));
    let peak = construction_bars(r, mesh, tri, ci, |m| m.peak_bytes.map(|b| (b, None)));
    h.push_str(&svg::bars(
        "peak bytes per triangle during construction",
        "B",
        &peak,
    ));
}

/// Heap bytes per triangle.
pub struct Memory;

impl Section for Memory {
    fn name(&self) -> &'static str {
        "memory"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Light)
    }

    fn render(&self, h: &mut String, page: &Page) {
        memory(h, page.r, &|s| page.style(s));
    }
}
