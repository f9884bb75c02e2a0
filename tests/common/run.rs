//! Running the `topolab` binary from a test: a scratch folder, a run, its output as text.

use std::path::PathBuf;
use std::process::{Command, Output};

/// An empty folder for test `name` of this process, in the system's temporary folder.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topolab-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the binary with `args`, to the end.
pub fn topolab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Output bytes as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The lines of an `explain --op` text that change a record (`  key.field: old -> new` or
/// `  key: old -> new`).
pub fn changed(text: &str) -> Vec<&str> {
    text.lines()
        .filter(|l| l.starts_with("  ") && l.contains(" -> "))
        .map(str::trim)
        .collect()
}
