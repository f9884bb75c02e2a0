//! The files a command writes, checked before the work starts: a run that would only fail at
//! the end (an unwritable folder, a directory or a device where a file goes) fails at once.
//! The writing itself goes through [`topolab_structures::io::write_atomically`]: a temporary
//! file in the same folder, renamed over the target once complete, so a failed or interrupted
//! run never leaves a half-written file under the target's name.

use crate::failure::Failure;
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use topolab_structures::io::PlyEncoding;
use topolab_structures::io::{create_temporary, echo, write_atomically};
use topolab_structures::{Error, Format, PolygonSoup};

fn cannot(path: &Path, why: impl std::fmt::Display) -> Failure {
    Failure::usage(format!("cannot write {}: {why}", echo::path(path)))
}

/// The folder a file goes in (`.` for a bare file name).
fn folder_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Refuses what is at `path` if it is not a regular file: writing renames a finished file over
/// it, which must not replace a directory or a device (`/dev/null`).
fn refuse_non_file(path: &Path) -> Result<(), Failure> {
    match std::fs::metadata(path) {
        Ok(m) if m.is_dir() => Err(cannot(path, "it is a directory")),
        Ok(m) if !m.is_file() => Err(cannot(
            path,
            "it is not a regular file (a device or a pipe); give a file name",
        )),
        _ => Ok(()),
    }
}

/// Creates and removes a temporary file such as a write of `path` would fill
/// ([`create_temporary`]: a new random name, never an existing file or link): the one sure test
/// of "creatable and writable" (permission bits do not tell, for root or on read-only mounts).
/// Nothing that was there before is opened, so nothing is truncated.
fn probe(path: &Path) -> Result<(), Failure> {
    let (file, tmp) = create_temporary(path).map_err(|e| cannot(path, e))?;
    drop(file);
    let _ = std::fs::remove_file(&tmp);
    Ok(())
}

/// Checks, before the work, that the file `path` can be written: its folder exists, nothing but
/// a regular file is in its place, and a file can be created next to it.
pub fn check_file(path: &Path) -> Result<(), Failure> {
    if path.file_name().is_none() {
        return Err(cannot(path, "it names a folder, not a file"));
    }
    refuse_non_file(path)?;
    let folder = folder_of(path);
    if !folder.is_dir() {
        return Err(cannot(
            path,
            format!("the folder {} does not exist", folder.display()),
        ));
    }
    probe(path)
}

/// Checks, before the work, that the folder `dir` can receive `files`: it is a folder (or can
/// be created: its nearest existing ancestor is a writable folder), and each file can be
/// written in it. Creates nothing that stays.
pub fn check_folder(dir: &Path, files: &[&str]) -> Result<(), Failure> {
    if dir.exists() {
        if !dir.is_dir() {
            return Err(cannot(dir, "it is not a folder"));
        }
        for f in files {
            let path = dir.join(f);
            refuse_non_file(&path)?;
            probe(&path)?;
        }
        return Ok(());
    }
    // Created at the end: its nearest existing ancestor must take a new entry.
    let mut ancestor = folder_of(dir);
    while !ancestor.exists() {
        let up = folder_of(&ancestor);
        if up == ancestor {
            // `.` itself is gone (the working directory was removed).
            return Err(cannot(dir, "no existing folder above it"));
        }
        ancestor = up;
    }
    if !ancestor.is_dir() {
        return Err(cannot(
            dir,
            format!("{} is not a folder", ancestor.display()),
        ));
    }
    probe(&ancestor.join("topolab-out")).map_err(|_| {
        cannot(
            dir,
            format!("cannot create a folder in {}", ancestor.display()),
        )
    })
}

/// Refuses (exit code 2) an output that is the input `input` (a file named on the command
/// line, or a built-in mesh's name, which is no file): the command would replace its own
/// source. The same file under another name (a hard or symbolic link) counts as the same.
/// No command of the lab works in place.
pub fn check_not_input(input: &str, out: &Path) -> Result<(), Failure> {
    use std::os::unix::fs::MetadataExt;
    let (Ok(a), Ok(b)) = (std::fs::metadata(input), std::fs::metadata(out)) else {
        return Ok(());
    };
    if a.dev() == b.dev() && a.ino() == b.ino() {
        return Err(Failure::usage(format!(
            "cannot write {}: it is the input {}; write to another file (no command works in place)",
            echo::path(out),
            echo::path(Path::new(input))
        )));
    }
    Ok(())
}

/// Checks, before the work, an output mesh file: a format the lab writes (.obj, .off, .ply or
/// .stl), not the input `input` ([`check_not_input`]), then [`check_file`].
pub fn check_mesh_out(path: &Path, input: &str) -> Result<(), Failure> {
    match topolab_structures::io::format_of(path) {
        Ok(_) => {}
        Err(e) => return Err(Failure::usage(format!("cannot write: {e}"))),
    }
    check_not_input(input, path)?;
    check_file(path)
}

/// Writes a mesh file (by extension, atomically: [`topolab_structures::io::write`]); a failure
/// names the file (exit code 2; 1 for a mesh the format cannot hold, see [`write_mesh_as`]).
pub fn write_mesh(path: &Path, soup: &PolygonSoup) -> Result<(), Failure> {
    let format = topolab_structures::io::format_of(path).map_err(|e| cannot(path, e))?;
    write_mesh_as(path, soup, format, PlyEncoding::Binary)
}

/// Writes a mesh file in `format` (PLY in `ply`), whatever its extension
/// ([`topolab_structures::io::write_encoded`]). A mesh the file would not hold as it is (empty,
/// or, in STL, beyond `float` or with corners `float` cannot tell apart:
/// [`topolab_structures::io::writable`]) is refused with exit code 1 and nothing is written;
/// a file that cannot be written, exit code 2.
pub fn write_mesh_as(
    path: &Path,
    soup: &PolygonSoup,
    format: Format,
    ply: PlyEncoding,
) -> Result<(), Failure> {
    topolab_structures::io::write_encoded(path, soup, format, ply).map_err(|e| match e {
        Error::Io { source, .. } => cannot(path, source),
        Error::NotWritable { .. } => Failure {
            message: format!("{} not written: {e}", echo::path(path)),
            code: 1,
        },
        e => cannot(path, e),
    })
}

/// Writes `path` atomically ([`write_atomically`]); a failure names the file (exit code 2).
pub fn write_file(
    path: &Path,
    fill: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>,
) -> Result<(), Failure> {
    write_atomically(path, fill).map_err(|e| cannot(path, e))
}

/// What fills one file of [`write_files_together`].
pub type Fill<'a> = Box<dyn FnOnce(&mut BufWriter<File>) -> std::io::Result<()> + 'a>;

/// Writes the files `files` (name, filler) into the folder `dir` (created if missing) so that
/// either all of them are there or none: each is filled as a temporary file first
/// ([`create_temporary`]), and
/// only when every one is complete are they renamed over their names. When a fill fails (a
/// full disk), the temporary files are removed, and so is the folder if this call created it.
/// A rename within one folder needs no space and does not fail on a folder it could create
/// files in; if one fails anyway, the files renamed before it stay (in a folder this call
/// created, they go with it). A failure names the file (exit code 2).
pub fn write_files_together(dir: &Path, files: Vec<(String, Fill<'_>)>) -> Result<(), Failure> {
    // The highest folder this call creates, to remove if a file cannot be written.
    let mut created = None;
    let mut up = dir.to_path_buf();
    while !up.as_os_str().is_empty() && !up.exists() {
        created = Some(up.clone());
        up = folder_of(&up);
    }
    std::fs::create_dir_all(dir).map_err(|e| cannot(dir, e))?;
    let mut filled: Vec<(PathBuf, PathBuf)> = Vec::new();
    let undo = |filled: &[(PathBuf, PathBuf)]| {
        for (tmp, _) in filled {
            let _ = std::fs::remove_file(tmp);
        }
        if let Some(top) = &created {
            let _ = std::fs::remove_dir_all(top);
        }
    };
    for (name, fill) in files {
        let path = dir.join(&name);
        let (file, tmp) = match create_temporary(&path) {
            Ok(created) => created,
            Err(e) => {
                undo(&filled);
                return Err(cannot(&path, e));
            }
        };
        let mut w = BufWriter::new(file);
        let written = fill(&mut w).and_then(|()| std::io::Write::flush(&mut w));
        filled.push((tmp, path.clone()));
        if let Err(e) = written {
            undo(&filled);
            return Err(cannot(&path, e));
        }
    }
    for (i, (tmp, path)) in filled.iter().enumerate() {
        if let Err(e) = std::fs::rename(tmp, path) {
            undo(&filled[i..]);
            return Err(cannot(path, e));
        }
    }
    Ok(())
}

/// Writes one line to standard error, `topolab: ` first, with control characters escaped
/// ([`echo::escape_controls`]): a message may hold a file name or a token of a file, and
/// neither may reach the terminal raw.
pub fn say(message: &str) {
    eprintln!("topolab: {}", echo::escape_controls(message));
}

/// Writes a command's text to standard output, control characters but newlines and tabs
/// escaped ([`echo::escape_controls`]). A reader that stops reading (`topolab ... |
/// head`) closes the pipe: that ends the output without an error, as for the other Unix
/// tools, instead of the panic of `print!`. Any other failure to write is reported on stderr
/// and turns the exit code into 2.
pub fn print(text: &str) -> Result<(), Failure> {
    use std::io::Write as _;
    let mut out = std::io::stdout().lock();
    let text = echo::escape_controls(text);
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(Failure {
            message: format!("cannot write to standard output: {e}"),
            code: 2,
        }),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn what_cannot_be_written_is_refused_before_the_work() {
        let dir = std::env::temp_dir().join(format!("topolab-output-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert!(check_file(&dir.join("ok.obj")).is_ok());
        assert!(!dir.join("ok.obj").exists(), "the check leaves no file");
        for bad in [
            dir.clone(),
            dir.join("missing/x.obj"),
            PathBuf::from("/dev/null"),
        ] {
            let e = check_file(&bad).unwrap_err();
            assert_eq!(e.code, 2, "{}", bad.display());
            assert!(e.message.starts_with("cannot write"), "{}", e.message);
        }
        assert!(check_folder(&dir.join("new/deeper"), &["results.json"]).is_ok());
        assert!(!dir.join("new").exists(), "the check creates no folder");
        std::fs::create_dir_all(dir.join("taken/results.json")).unwrap();
        assert!(check_folder(&dir.join("taken"), &["results.json"]).is_err());
        std::fs::write(dir.join("file"), "").unwrap();
        assert!(check_folder(&dir.join("file"), &[]).is_err());
        assert!(check_folder(&dir.join("file/below"), &[]).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
