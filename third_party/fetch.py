#!/usr/bin/env python3
"""Fetches the C++ sources of third_party/sources.toml into third_party/<name>/ (Python 3.11+,
stdlib only): OpenMesh's C++ tree, which build.rs compiles (a build script has no network).

Each source ships in a package of a registry: PyPI's `openmesh` sdist carries OpenMesh's
complete C++ tree. The package is downloaded with its own client (bench-data/fetch.py's
`download`, the one the real meshes use) into a temporary folder, its sha256 checked against
the manifest, and only the manifest's `path` inside the archive unpacked. The folder is
replaced whole, and only once it is complete; its stamp (`.topolab-source`, the package, its
version and sha256) is written in it before. A folder whose stamp matches the manifest is
skipped, so running this again is cheap and needs no network.

    python3 third_party/fetch.py          # fetch, verify and unpack (what .ci/install-deps runs)
    python3 third_party/fetch.py --check  # only check that the manifest is complete (a test)

Exit code: 0 when every source is in place (or --check passes), 1 otherwise.
"""

from __future__ import annotations

import importlib.util
import re
import shutil
import sys
import tarfile
import tempfile
import tomllib
from pathlib import Path, PurePosixPath

HERE = Path(__file__).resolve().parent
MANIFEST = HERE / "sources.toml"
# The stamp in each unpacked folder: what it was unpacked from. build.rs reads it to say how
# the library it compiles was obtained.
STAMP = ".topolab-source"
# What the stamp records, in this order (the manifest's own values).
STAMPED = ("client", "package", "version", "sha256")

# bench-data/fetch.py, loaded by path: it is a script of that folder, and has this one's name.
_spec = importlib.util.spec_from_file_location("bench_data_fetch", HERE.parent / "bench-data" / "fetch.py")
bench_data = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bench_data)

FIELDS = {
    "name": str,
    "client": str,
    "package": str,
    "version": str,
    "sdist": bool,
    "sha256": str,
    "path": str,
    "licence": str,
    "what": str,
}


def load_manifest(path: Path = MANIFEST) -> list[dict]:
    with open(path, "rb") as f:
        return tomllib.load(f)["source"]


def check_manifest(sources: list[dict]) -> list[str]:
    """Every problem of the manifest, as sentences (empty when it is complete)."""
    problems = []
    names = set()
    for i, s in enumerate(sources):
        label = s.get("name", f"entry {i}")
        for field, kind in FIELDS.items():
            if field not in s:
                problems.append(f"{label}: missing field {field!r}")
            elif not isinstance(s[field], kind) or (isinstance(s[field], str) and not s[field]):
                problems.append(f"{label}: field {field!r} is empty or not a {kind.__name__}")
        if not re.fullmatch(r"[a-z0-9][a-z0-9_-]*", str(s.get("name", ""))):
            problems.append(f"{label}: name must be a plain folder name (lowercase, digits, - or _)")
        if s.get("client") != "pip":
            problems.append(f"{label}: client must be pip (the only one whose sources this unpacks)")
        if not re.fullmatch(r"[0-9a-f]{64}", str(s.get("sha256", ""))):
            problems.append(f"{label}: sha256 must be 64 lowercase hex digits")
        if label in names:
            problems.append(f"{label}: name used twice")
        names.add(label)
    return problems


def stamp_text(source: dict) -> str:
    """The stamp of a folder unpacked from `source`, one `key = "value"` line per field."""
    return "".join(f'{key} = "{source[key]}"\n' for key in STAMPED)


def is_current(folder: Path, source: dict) -> bool:
    """Whether `folder` holds `source` as the manifest pins it (its stamp says so)."""
    stamp = folder / STAMP
    return stamp.is_file() and stamp.read_text() == stamp_text(source)


def unpack(archive: Path, inner: str, into: Path) -> int:
    """Writes the files under `inner/` of the tar archive into `into` (which must exist),
    `inner/` stripped; returns how many. Raises RuntimeError for a member that would land
    outside `into` or is neither a file nor a folder (the pinned archive has neither), and
    when nothing is under `inner`. Git's `.git` entries are left out: the tree is not a
    repository of its own."""
    prefix = PurePosixPath(inner)
    written = 0
    with tarfile.open(archive) as tar:
        for member in tar:
            name = PurePosixPath(member.name)
            if name == prefix or prefix not in name.parents:
                continue
            relative = name.relative_to(prefix)
            if name.is_absolute() or ".." in relative.parts:
                raise RuntimeError(f"{member.name}: a path outside the folder")
            if ".git" in relative.parts:
                continue
            target = into.joinpath(*relative.parts)
            if member.isdir():
                target.mkdir(parents=True, exist_ok=True)
            elif member.isfile():
                target.parent.mkdir(parents=True, exist_ok=True)
                with tar.extractfile(member) as data, open(target, "wb") as out:
                    shutil.copyfileobj(data, out)
                written += 1
            else:
                raise RuntimeError(f"{member.name}: neither a file nor a folder")
    if not written:
        raise RuntimeError(f"nothing under {inner}/ in {archive.name}")
    return written


def install(source: dict, archive: Path, root: Path) -> int:
    """Unpacks `source` from `archive` into root/<name>, replacing what was there only once
    the new folder is complete (stamp included); returns the number of files."""
    work = Path(tempfile.mkdtemp(prefix=f".fetch-{source['name']}-", dir=root))
    try:
        fresh = work / "tree"
        fresh.mkdir()
        count = unpack(archive, source["path"], fresh)
        (fresh / STAMP).write_text(stamp_text(source))
        target = root / source["name"]
        if target.exists():
            target.rename(work / "old")
        fresh.rename(target)
        return count
    finally:
        shutil.rmtree(work, ignore_errors=True)


def fetch(source: dict, root: Path = HERE) -> str:
    """Makes root/<name> hold `source`; returns its status line (`ok ...` or `MISSING: why`)."""
    folder = root / source["name"]
    if is_current(folder, source):
        return f"ok (already verified) in {folder}"
    package, version = source["package"], source["version"]
    with tempfile.TemporaryDirectory(prefix="topolab-fetch-") as tmp:
        kind = " (sdist)" if source["sdist"] else ""
        print(f"fetch: {source['client']} {package} {version}{kind} ...", flush=True)
        try:
            archive = bench_data.download(source["client"], package, version, Path(tmp), sdist=source["sdist"])
        except RuntimeError as e:
            return f"MISSING: cannot download {package} {version}: {e}"
        digest = bench_data.sha256(archive)
        if digest != source["sha256"]:
            return (f"MISSING: {archive.name} has sha256 {digest}, not the manifest's "
                    f"(the package changed?); not unpacked")
        try:
            count = install(source, archive, root)
        except (RuntimeError, OSError, tarfile.TarError) as e:
            return f"MISSING: cannot unpack {source['path']} from {archive.name}: {e}"
    return f"ok (fetched, sha256 verified, {count} files) in {folder}"


def main() -> int:
    sources = load_manifest()
    problems = check_manifest(sources)
    if "--check" in sys.argv:
        for p in problems:
            print(f"sources: {p}")
        print(f"sources: {len(sources)} sources, {len(problems)} problems")
        return 1 if problems else 0
    if problems:
        print("fetch: the manifest is incomplete:\n  " + "\n  ".join(problems))
        return 1
    missing = 0
    for source in sources:
        status = fetch(source)
        missing += status.startswith("MISSING")
        print(f"  {source['name']}  {status}")
    if missing:
        print(f"fetch: {missing} source(s) missing (reasons above; a failed download usually "
              "means no network); the build leaves out what needs them; run again to retry")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
