//! `topolab explain che`: the Compact Half-Edge for teaching. Without `--trace`, every
//! container of every level (`G`, `V`, `O`, `VH`, `EH`, `CH`) with its indices, as the
//! chapter's Figure 4.10 draws them; with `--trace r00 --vertex N`, the reads each level's
//! vertex-star algorithm makes (Algorithms 5, 6, 7) to answer the 1-ring of vertex N, and the
//! `V[]` read R00 adds per neighbour; the count at the end is all of them.

use crate::input::{mesh_or_tetrahedron, Failure};
use crate::limits;
use std::fmt::Write as _;
use topolab_structures::che::{next, triangle, CheLevel, StarRead};
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, MeshTopology, Operator, PolygonSoup, VertexId,
};

/// The name `explain` accepts for the four levels at once.
pub const NAME: &str = "che";

/// The text of `topolab explain che [--mesh M] [--trace OP --vertex N]`.
pub fn explain_che(
    mesh: Option<&str>,
    trace: Option<&str>,
    vertex: Option<u32>,
) -> Result<String, Failure> {
    // Measured on a sample: the text of every container, or the levels a trace builds.
    let (soup, label) = mesh_or_tetrahedron(mesh, false, |sample| {
        let mut text = String::new();
        let _ = match trace {
            None => all_containers(sample, &mut text),
            Some(_) => all_traces(sample, 0, &mut text),
        };
        limits::growing_text(&text)
    })?;
    let mut out = format!("Compact Half-Edge (CHE), levels 0-3, for {label}\n");
    let traced = trace.map(|name| (name, Operator::from_name(name)));
    match (traced, vertex) {
        (None, _) => {
            out.push_str(
                "Triangle t owns half-edges 3t, 3t+1, 3t+2; half-edge 3t+i leaves corner i of face t.\n",
            );
            all_containers(&soup, &mut out)?;
        }
        (Some((_, Some(Operator::R00 | Operator::R01 | Operator::R02))), Some(v)) => {
            if v as usize >= soup.num_vertices() {
                return Err(Failure::usage(format!(
                    "--vertex {v}: the mesh has {} vertices",
                    soup.num_vertices()
                )));
            }
            let _ = writeln!(
                out,
                "The vertex star of v{v} (R00, R01 and R02 all walk it), read by read:"
            );
            all_traces(&soup, v, &mut out)?;
        }
        (Some((name, _)), Some(_)) => {
            return Err(Failure::usage(format!(
                "--trace {name}: only the vertex star (r00, r01, r02) can be traced"
            )))
        }
        (Some(_), None) => return Err(Failure::usage("--trace needs --vertex N".into())),
    }
    Ok(out)
}

fn all_containers(soup: &PolygonSoup, out: &mut String) -> Result<(), Failure> {
    containers::<CheL0>(soup, out)?;
    containers::<CheL1>(soup, out)?;
    containers::<CheL2>(soup, out)?;
    containers::<CheL3>(soup, out)
}

fn all_traces(soup: &PolygonSoup, v: u32, out: &mut String) -> Result<(), Failure> {
    star_trace::<CheL0>(soup, v, out)?;
    star_trace::<CheL1>(soup, v, out)?;
    star_trace::<CheL2>(soup, v, out)?;
    star_trace::<CheL3>(soup, v, out)
}

fn build<L: MeshTopology>(soup: &PolygonSoup) -> Result<L, Failure> {
    L::from_soup(soup).map_err(|e| Failure {
        message: format!("{} cannot store this mesh: {e}", L::NAME),
        code: 1,
    })
}

fn containers<L: MeshTopology + CheLevel>(
    soup: &PolygonSoup,
    out: &mut String,
) -> Result<(), Failure> {
    let level = build::<L>(soup)?;
    let _ = writeln!(
        out,
        "\n== level {} ({}): {} bytes ==",
        L::LEVEL,
        L::NAME,
        level.heap_bytes()
    );
    level.explain(out).expect("writing to a String cannot fail");
    Ok(())
}

fn star_trace<L: MeshTopology + CheLevel>(
    soup: &PolygonSoup,
    v: u32,
    out: &mut String,
) -> Result<(), Failure> {
    let level = build::<L>(soup)?;
    let starts = level.start_vertices();
    let _ = writeln!(
        out,
        "\n== level {} ({}): {} ==",
        L::LEVEL,
        L::NAME,
        L::STAR_ALGORITHM
    );
    let mut reads = 0;
    // The 1-ring as the traced walk meets it (Algorithm 7's order at levels 2 and 3, whose
    // timed R00 walks the star from both ends and answers in another order).
    let mut ring = Vec::new();
    level.vertex_star(
        VertexId(v),
        |read| {
            let line = match read {
                StarRead::Vertex { he, vertex } => {
                    reads += 1;
                    format!("read V[{}] = {}", he.0, vertex.0)
                }
                StarRead::Opposite { he, opposite } => {
                    reads += 1;
                    format!("read O[{}] = {opposite}", he.0)
                }
                StarRead::VertexHalfEdge { vertex, he } => {
                    reads += 1;
                    format!("read VH[{}] = {he}", vertex.0)
                }
                // R00 reads each neighbour from V[] on top of the star's own reads.
                StarRead::Corner { he } => {
                    reads += 1;
                    ring.push(starts[next(he).index()]);
                    format!(
                        "triangle {} through half-edge {} (leaves v{v}): R00 reads neighbour V[{}] = {}",
                        triangle(he).0,
                        he.0,
                        next(he).0,
                        starts[next(he).index()]
                    )
                }
                StarRead::Closing { he } => {
                    reads += 1;
                    ring.push(starts[he.index()]);
                    format!(
                        "boundary half-edge {} enters v{v}: R00 reads neighbour V[{}] = {}",
                        he.0,
                        he.0,
                        starts[he.index()]
                    )
                }
            };
            let _ = writeln!(out, "  {line}");
        },
        |_| {},
    );
    let _ = writeln!(out, "  R00(v{v}) = {ring:?} after {reads} container reads");
    Ok(())
}
