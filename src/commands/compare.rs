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
use topolab_harness::compare::{self, Run};

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

/// Cells of the sample results.json that reading one is measured on.
const SAMPLE_CELLS: usize = 2000;

/// Reads a run, refusing first what is not a regular file, or a file whose reading would not
/// fit in memory: its bytes, held while parsing, plus the parse, measured on a sample of
/// [`SAMPLE_CELLS`] cells and scaled by bytes.
fn read(path: &Path) -> Result<Run, Failure> {
    let name = path.display().to_string();
    let bytes = input_file(path)?;
    let sample = compare::sample_results(SAMPLE_CELLS);
    let (_, peak) =
        limits::peak_of(|| compare::read(sample.as_bytes()).map(|r| r.measurements.len()));
    let need = bytes.saturating_add(limits::scale(peak, sample.len() as u64, bytes));
    limits::admit(&format!("reading {name}"), need)?;
    let text =
        std::fs::read(path).map_err(|e| Failure::usage(format!("cannot read {name}: {e}")))?;
    compare::read(&text).map_err(|e| Failure::usage(format!("{name}: {e}")))
}

/// Compares the two runs; returns the text to print.
pub fn compare(args: &CompareArgs) -> Result<String, Failure> {
    // The page's folder is checked before the files are read.
    check_folder(&args.out, &["index.html"])?;
    let old = read(&args.old)?;
    let new = read(&args.new)?;
    let (old_path, new_path) = (
        args.old.display().to_string(),
        args.new.display().to_string(),
    );
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
