//! What the subcommands share: reading a mesh named on the command line, and the
//! [`Failure`] a command returns (its message and exit code).

pub use crate::failure::Failure;
use crate::{limits, registry};
use std::path::Path;
use topolab_structures::io::echo;
use topolab_structures::meshes::{self, MeshSize, SpecError};
use topolab_structures::{Error, PolygonSoup};

/// Refuses an input path that is not a regular file: a directory cannot be read as a mesh, and
/// a device or pipe (`/dev/zero`) may never end. Returns the file's size in bytes.
pub fn input_file(path: &Path) -> Result<u64, Failure> {
    let meta = std::fs::metadata(path).map_err(|e| Failure {
        message: format!("cannot read {}: {e}", path.display()),
        code: 2,
    })?;
    if meta.is_dir() {
        return Err(Failure::usage(format!(
            "cannot read {}: it is a directory, not a mesh file",
            path.display()
        )));
    }
    if !meta.is_file() {
        return Err(Failure::usage(format!(
            "cannot read {}: it is not a regular file (a device or a pipe)",
            path.display()
        )));
    }
    Ok(meta.len())
}

/// Reads a mesh file for a command, refusing before reading one whose reading would exceed the
/// available memory ([`limits::read_mesh_bytes`]). What the reader skipped (it does not change the
/// mesh: an unknown OBJ statement, bytes after a binary PLY's last element) is one warning line
/// on stderr per kind; the STL corners it welded into shared vertices, one note line.
fn read_file(spec: &str, path: &Path) -> Result<PolygonSoup, Failure> {
    let bytes = input_file(path)?;
    limits::admit(
        &format!("reading {spec}"),
        limits::read_mesh_bytes(path, bytes),
    )?;
    let (soup, notes) = topolab_structures::io::read_with_notes(path).map_err(|e| {
        let mut failure = Failure::unreadable(spec, &e);
        failure.message += &invalid_mesh_hint(spec, &e);
        failure
    })?;
    warn_skipped(spec, &notes.skipped);
    if notes.welded_corners > 0 {
        crate::output::say(&format!(
            "note: {spec}: {} of {} STL corners welded to an earlier corner at exactly the same position ({} vertices)",
            notes.welded_corners,
            soup.num_corners(),
            soup.num_vertices()
        ));
    }
    Ok(soup)
}

/// One warning line on stderr per kind of thing the reader skipped in `spec`: a few lines at
/// most, since the readers list a bounded number of kinds (an OBJ's unknown statements past
/// [`topolab_structures::io::LISTED_UNKNOWN_KINDS`] kinds counted together on one line).
pub fn warn_skipped(spec: &str, skipped: &[topolab_structures::io::Skipped]) {
    for s in skipped {
        crate::output::say(&format!("warning: {spec}: {s}"));
    }
}

/// Where to go next when `spec` reads but is not a mesh the command can use (`e` says why): an
/// empty string unless `spec` is a file and `e` a problem of the mesh itself (a face repeating
/// a vertex, a non-manifold edge or vertex, faces that disagree on orientation), which
/// `topolab check` lists in full and, for the manifold problems, `topolab repair` fixes.
pub fn invalid_mesh_hint(spec: &str, e: &Error) -> String {
    if !Path::new(spec).is_file() {
        return String::new();
    }
    if e.is_non_manifold() {
        format!(
            " (`topolab check {spec}` lists every problem; `topolab repair {spec} --out FIXED.obj` repairs it)"
        )
    } else if matches!(
        e,
        Error::RepeatedVertex { .. } | Error::TooFewCorners { .. } | Error::IndexOutOfRange { .. }
    ) {
        format!(" (`topolab check {spec}` lists every problem of the file)")
    } else {
        String::new()
    }
}

/// The failure for a name that is no file and no built-in mesh it can generate.
fn not_a_mesh(spec: &str, e: SpecError) -> Failure {
    match e {
        SpecError::Unknown => {
            let names: Vec<&str> = meshes::canonical().iter().map(|m| m.name).collect();
            Failure::usage(format!(
                "no file {}, and it is not a built-in mesh ({}, or torus:N, sphere:N, grid:N, quad-grid:N, mixed:N, genus:G:N, holes:K:N, surface:G:K:N)",
                echo::quoted(spec.as_bytes()),
                names.join(", ")
            ))
        }
        too_large @ SpecError::TooLarge { .. } => Failure::usage(format!("{spec}: {too_large}")),
    }
}

/// Loads a mesh named on the command line, a file or a built-in mesh, for `work`: what the
/// command will do with it. Refused (exit code 2) before it is read or generated when its ids
/// or the memory of reading it, generating it and running `work` on it would not fit
/// ([`crate::limits`]: `work` is measured on a sample mesh and scaled to this one's corners;
/// it returns bytes to add to its measured peak, usually 0: a text's growth,
/// [`limits::growing_text`]).
pub fn load_mesh(spec: &str, work: impl Fn(&PolygonSoup) -> u64) -> Result<PolygonSoup, Failure> {
    load_for(spec, true, false, work)
}

/// [`load_mesh`] and [`load_mesh_consumed`]: `count_soup` says whether a generated mesh's soup
/// is counted besides `work` (not when `work` holds it already); `separate`, whether `work` is
/// measured on [`limits::separate_triangles`] besides [`limits::sample_mesh`] (the larger
/// peak per element is scaled).
fn load_for(
    spec: &str,
    count_soup: bool,
    separate: bool,
    work: impl Fn(&PolygonSoup) -> u64,
) -> Result<PolygonSoup, Failure> {
    let path = Path::new(spec);
    if path.exists() {
        let soup = read_file(spec, path)?;
        // The mesh read stays alive during the work: counted with it, unless the work holds
        // it (and its measured peak counts it).
        let size = MeshSize::of(&soup);
        let base = if count_soup { size.soup_bytes() } else { 0 };
        admit_work(spec, &size, base, separate, work)?;
        return Ok(soup);
    }
    let parsed = meshes::parse_spec(spec).map_err(|e| not_a_mesh(spec, e))?;
    let size = parsed.size();
    let soup = if count_soup { size.soup_bytes() } else { 0 };
    admit_work(spec, &size, soup, separate, work)?;
    Ok(parsed.generate())
}

/// [`load_mesh`] for work that consumes the mesh (its arrays become the result's, as
/// `convert --to che` builds the CHE): `work` takes a copy of the sample by value and is
/// measured with it, so the mesh is counted once, in the work's peak, and not again as the
/// soup it is generated into. The mesh is then most of the peak, so the work is measured on
/// [`limits::separate_triangles`] too (more bytes of mesh an element than the sample mesh's).
pub fn load_mesh_consumed(
    spec: &str,
    work: impl Fn(PolygonSoup) -> u64,
) -> Result<PolygonSoup, Failure> {
    load_for(spec, false, true, |sample| work(sample.clone()))
}

/// The size of the built-in mesh `spec` names, when it names one and no file (`None` for a
/// file, or a name that is not a built-in mesh: [`load_mesh`] says why).
pub fn built_in_size(spec: &str) -> Option<MeshSize> {
    if Path::new(spec).exists() {
        return None;
    }
    meshes::parse_spec(spec).ok().map(|m| m.size())
}

/// Refuses a mesh of `size` when `base` bytes (its soup, if not yet built) and `work` on it,
/// measured on [`limits::sample_mesh`] (and on [`limits::separate_triangles`] when
/// `separate`: made here, once the mesh is read, not held while it is) and scaled by elements
/// ([`limits::elements`]; the largest of the samples' scaled peaks), exceed the available
/// memory. Meshes no larger than the sample pass unmeasured.
fn admit_work(
    spec: &str,
    size: &MeshSize,
    base: u64,
    separate: bool,
    work: impl Fn(&PolygonSoup) -> u64,
) -> Result<(), Failure> {
    let sample = limits::sample_mesh();
    let sample_elements = limits::elements(&MeshSize::of(&sample));
    let elements = limits::elements(size);
    if elements <= sample_elements {
        return Ok(());
    }
    let measured = |s: &PolygonSoup| {
        let (extra, peak) = limits::peak_of(|| work(s));
        limits::scale(peak + extra, limits::elements(&MeshSize::of(s)), elements)
    };
    let mut work = measured(&sample);
    drop(sample);
    if separate {
        work = work.max(measured(&limits::separate_triangles()));
    }
    limits::admit(spec, base.saturating_add(work))
}

/// Refuses a mesh with no vertex and no face (exit code 1): every count of it would be 0 and
/// "manifold" or "genus" would be vacuous; `topolab check` reports it as `empty-mesh`.
pub fn refuse_empty(spec: &str, soup: &PolygonSoup) -> Result<(), Failure> {
    if soup.num_vertices() == 0 && soup.num_faces() == 0 {
        return Err(Failure {
            message: format!(
                "{spec} is an empty mesh: it has no vertices and no faces (`topolab check` reports it as empty-mesh)"
            ),
            code: 1,
        });
    }
    Ok(())
}

/// The mesh `explain` shows: the one named (loaded for `work`, see [`load_mesh`]), or the open
/// tetrahedron (a 2x2 grid for grid-only structures, which cannot store it); with a label.
pub fn mesh_or_tetrahedron(
    mesh: Option<&str>,
    grids_only: bool,
    work: impl Fn(&PolygonSoup) -> u64,
) -> Result<(PolygonSoup, String), Failure> {
    Ok(match mesh {
        Some(spec) => {
            let soup = load_mesh(spec, work)?;
            refuse_empty(spec, &soup)?;
            (soup, spec.to_string())
        }
        // The tetrahedron is not a grid: grid-only structures explain a 2x2 grid instead.
        None if grids_only => (
            meshes::grid(2, 2, true),
            "a 2x2 triangulated grid (the open tetrahedron is not a grid)".to_string(),
        ),
        None => (
            meshes::open_tetrahedron(),
            "the open tetrahedron of the CHE thesis chapter's Figure 4.10 (apex 3, triangle t = (t, t+1 mod 3, 3))".to_string(),
        ),
    })
}

/// The failure for a structure name that is not in this build (a C++ baseline left out says
/// how to get it).
pub fn unknown_structure(name: &str) -> Failure {
    if let Some(why) = registry::missing_baseline(name) {
        return Failure::usage(format!("{name}: {why}"));
    }
    Failure::usage(format!(
        "unknown structure {}; known: {}",
        echo::quoted(name.as_bytes()),
        registry::NAMES.join(", ")
    ))
}

/// Does `path` end in `.che` (any case)?
pub fn has_che_extension(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("che"))
}

/// Is `path` a `.che` file (docs/che-format.md): a regular file named `.che`, or one that
/// starts with the `.che` magic whatever its name? Reads at most the magic's 8 bytes.
pub fn is_che_file(path: &Path) -> bool {
    use std::io::Read;
    if !path.is_file() {
        return false;
    }
    if has_che_extension(path) {
        return true;
    }
    let mut start = [0u8; 8];
    std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut start))
        .is_ok_and(|()| start == topolab_structures::che::file::MAGIC)
}
