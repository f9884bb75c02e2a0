//! `topolab info FILE.che`: a `.che` file described as the CHE level its containers hold. It
//! is mapped ([`CheFile::open`]: its header and length, O(1)), verified as `topolab check`
//! verifies it ([`CheFile::check`], one pass), and then asked every question `info` asks of a
//! mesh, so that the answers are those `info` gives for the mesh the file was converted from:
//! levels 2 and 3 through the mapped containers themselves, levels 0 and 1 (whose vertex star
//! scans `V[]`, O(n) a vertex) through level 2 built from the file's `G[]` and `V[]`.

use super::info_text::summary_lines;
use crate::input::Failure;
use crate::limits;
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;
use topolab_structures::che::file::Container;
use topolab_structures::che::{CheFile, MappedChe};
use topolab_structures::summary::{summarize, Summary};
use topolab_structures::{CheL2, MeshTopology, PolygonSoup};

/// The refusal of a file whose check failed (`e`).
fn unsound(spec: &str, e: topolab_structures::Error) -> Failure {
    Failure {
        message: format!(
            "{e} (`topolab check {spec}` reports it; `info` describes sound files only)"
        ),
        code: 1,
    }
}

/// The summary of a file of level `L` (2 or 3) through its mapped containers, once verified
/// ([`MappedChe::verify`], which is [`CheFile::check`]).
fn mapped_summary<const L: u8>(file: CheFile, spec: &str) -> Result<Summary, Failure>
where
    MappedChe<L>: MeshTopology,
{
    let mut m = MappedChe::<L>::from_file(file).map_err(|e| Failure::usage(e.to_string()))?;
    m.verify().map_err(|e| unsound(spec, e))?;
    Ok(summarize(&m))
}

/// The summary of a verified file of level 0 or 1: level 2 built from its `G[]` and `V[]`
/// (what `info` builds for a mesh: the same answers), refused first when it would not fit.
fn rebuilt_summary(file: &CheFile) -> Result<Summary, Failure> {
    let sample = limits::sample_mesh();
    let ((), peak) = limits::peak_of(|| {
        drop(CheL2::from_soup(&sample));
    });
    let triangles = file.header().triangles;
    let bytes =
        file.file_bytes()
            .saturating_add(limits::scale(peak, sample.num_faces() as u64, triangles));
    limits::admit(&format!("info {}", file.path().display()), bytes)?;
    let soup =
        PolygonSoup::from_triangles(file.geometry().to_vec(), file.start_vertices().to_vec());
    let level2 = CheL2::from_soup(&soup).map_err(|e| Failure {
        message: format!("{}: {e}", file.path().display()),
        code: 1,
    })?;
    drop(soup);
    Ok(summarize(&level2))
}

/// The text of `topolab info FILE.che`; `structure` is what `--structure` named, if anything.
pub(super) fn che_info(spec: &str, structure: Option<&str>, json: bool) -> Result<String, Failure> {
    let started = Instant::now();
    // The error names the file.
    let file = CheFile::open(Path::new(spec)).map_err(|e| Failure {
        message: e.to_string(),
        code: 2,
    })?;
    let opened_ms = started.elapsed().as_secs_f64() * 1e3;
    let h = file.header();
    let level_name = format!("che-l{}", h.level);
    if let Some(asked) = structure.filter(|s| *s != level_name) {
        crate::output::say(&format!(
            "note: --structure {asked} ignored: {spec} holds the containers of CHE level {} and is described as {level_name}",
            h.level
        ));
    }
    let verifying = Instant::now();
    let bytes = file.file_bytes();
    let stored: Vec<Container> = Container::ALL
        .into_iter()
        .filter(|c| c.first_level() <= h.level)
        .collect();
    let containers: Vec<(&str, u64, u64)> = stored
        .iter()
        .map(|&c| (c.name(), h.count(c), c.element_bytes()))
        .collect();
    let summary = match h.level {
        0 | 1 => {
            file.check().map_err(|e| unsound(spec, e))?;
            rebuilt_summary(&file)?
        }
        2 => mapped_summary::<2>(file, spec)?,
        _ => mapped_summary::<3>(file, spec)?,
    };
    let verified_ms = verifying.elapsed().as_secs_f64() * 1e3;
    if json {
        let mut v = serde_json::to_value(&summary).expect("serialisable");
        let containers: serde_json::Map<String, serde_json::Value> = containers
            .iter()
            .map(|&(name, elements, element_bytes)| {
                (
                    name.to_string(),
                    serde_json::json!({ "elements": elements, "element_bytes": element_bytes }),
                )
            })
            .collect();
        v["mesh"] = spec.into();
        v["computed_through"] = summary.structure.into();
        v["structure"] = level_name.into();
        v["format"] = "che".into();
        v["format_version"] = topolab_structures::che::file::VERSION.into();
        v["level"] = h.level.into();
        v["bytes"] = bytes.into();
        v["containers"] = containers.into();
        v["memory_mapped"] = true.into();
        v["open_ms"] = opened_ms.into();
        v["verified"] = true.into();
        v["verify_ms"] = verified_ms.into();
        return Ok(serde_json::to_string_pretty(&v).expect("serialisable") + "\n");
    }
    let names: Vec<&str> = containers.iter().map(|c| c.0).collect();
    let mut out = String::new();
    let _ = writeln!(out, "mesh:                 {spec}");
    let _ = writeln!(
        out,
        "format:               .che version {} (the CHE's containers, little-endian)",
        topolab_structures::che::file::VERSION
    );
    let _ = writeln!(
        out,
        "structure:            {level_name} (CHE level {}: {}; answered through {})",
        h.level,
        names.join(", "),
        summary.structure
    );
    summary_lines(&mut out, &summary);
    let _ = writeln!(out, "bytes:                {bytes}");
    let _ = writeln!(
        out,
        "memory-mapped:        yes, opened in {opened_ms:.3} ms (header and length), verified and answered in {verified_ms:.1} ms"
    );
    Ok(out)
}
