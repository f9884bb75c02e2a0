//! `topolab compare OLD/results.json NEW/results.json [--out DIR]`: two report runs side by
//! side ([`topolab_harness::compare`]): every cell measured in both, the ratio new/old, flagged
//! when outside both runs' spread, the largest change first; as text on stdout and as a
//! self-contained page, `DIR/index.html`. Exit code 0 whatever changed (it informs, it does not
//! judge); 2 when a file is not a topolab results.json, is of a format version this build does
//! not read, or the page cannot be written.

use crate::input::{input_file, Failure};
use crate::limits;
use crate::output::{check_folder, write_file};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use topolab_harness::compare;
use topolab_harness::results::Measurement;

/// Arguments of `topolab compare`.
#[derive(clap::Args, Debug)]
pub struct CompareArgs {
    /// The old run's results.json.
    pub old: PathBuf,
    /// The new run's results.json.
    pub new: PathBuf,
    /// The folder of the HTML page (index.html).
    #[arg(long, default_value = "reports/compare")]
    pub out: PathBuf,
}

/// Cells of the sample results.json the memory of a comparison is measured on.
const SAMPLE_CELLS: usize = 2000;

/// The whole comparison of two runs' texts, as [`compare`] makes it: both read, compared, the
/// page and the text drawn (`None` if one is not a results.json).
fn compare_texts(old: &[u8], new: &[u8]) -> Option<(String, String)> {
    let comparison = compare::compare(compare::read(old).ok()?, compare::read(new).ok()?);
    Some((
        compare::html(&comparison, "old", "new"),
        compare::text(&comparison, "old", "new"),
    ))
}

/// Refuses, before they are read, two files whose comparison would not fit in memory: their
/// bytes, held while parsing, plus the comparison of two sample results.json of
/// [`SAMPLE_CELLS`] cells each (read, compared, drawn) and the growth of its texts, scaled by
/// bytes.
fn admit(files: [&Path; 2]) -> Result<u64, Failure> {
    let mut bytes = 0u64;
    for f in files {
        bytes = bytes.saturating_add(input_file(f)?);
    }
    let sample = compare::sample_results(SAMPLE_CELLS);
    let (drawn, peak) = limits::peak_of(|| compare_texts(sample.as_bytes(), sample.as_bytes()));
    // The page and the text grow by appending, the runs' measurements and the compared cells
    // by pushing: a buffer that doubles peaks at up to three times its length, where in that
    // range depending on how the length falls between powers of two, so up to twice its
    // length above the sample's ([`limits::growing_text`]).
    let vectors = 2 * SAMPLE_CELLS * (2 * size_of::<Measurement>() + size_of::<compare::Cell>());
    let growth = drawn.map_or(0, |(page, text)| {
        limits::growing_text(&page) + limits::growing_text(&text) + vectors as u64
    });
    let need = bytes.saturating_add(limits::scale(peak + growth, 2 * sample.len() as u64, bytes));
    let names = files.map(|f| f.display().to_string());
    limits::admit(&format!("comparing {} and {}", names[0], names[1]), need)?;
    Ok(bytes)
}

fn read(path: &Path) -> Result<Vec<u8>, Failure> {
    std::fs::read(path).map_err(|e| Failure::usage(format!("cannot read {}: {e}", path.display())))
}

/// Compares the two runs; returns the text to print.
pub fn compare(args: &CompareArgs) -> Result<String, Failure> {
    // The page's folder is checked before the files are read.
    check_folder(&args.out, &["index.html"])?;
    admit([&args.old, &args.new])?;
    let (old, new) = (read(&args.old)?, read(&args.new)?);
    let (old_path, new_path) = (
        args.old.display().to_string(),
        args.new.display().to_string(),
    );
    let refused = |path: &str, e: compare::ReadError| Failure::usage(format!("{path}: {e}"));
    let old = compare::read(&old).map_err(|e| refused(&old_path, e))?;
    let new = compare::read(&new).map_err(|e| refused(&new_path, e))?;
    let comparison = compare::compare(old, new);
    let page = compare::html(&comparison, &old_path, &new_path);
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Failure::usage(format!("cannot write {}: {e}", args.out.display())))?;
    let index = args.out.join("index.html");
    write_file(&index, |w| w.write_all(page.as_bytes()))?;
    let mut text = compare::text(&comparison, &old_path, &new_path);
    text.push_str(&format!("wrote {}\n", index.display()));
    Ok(text)
}
