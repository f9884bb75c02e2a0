#!/usr/bin/env python3
"""libigl as the lab's outside reference.

    .venv/bin/python python/libigl_reference.py MESH --out JSON

Loads a triangle mesh with libigl, computes the relations the lab computes with libigl's own
functions, and writes for each one the checksum of harness/src/checksum.rs (same `mix` and
`edge_key`, in numpy uint64 wrapping arithmetic) and the time of the libigl call alone (median
of 5 after a warm-up run, one thread: IGL_NUM_THREADS=1):

    {"mesh": ..., "vertices": n, "triangles": m, "libigl_version": "2.6.1",
     "results": [{"operator": "r00", "function": "adjacency_list",
                  "checksum": "<u64 as decimal string>", "seconds": ...}, ...]}

| libigl function              | lab operator    |
|------------------------------|-----------------|
| adjacency_list               | r00             |
| vertex_triangle_adjacency    | r02             |
| edges                        | r10             |
| triangle_triangle_adjacency  | r22             |
| boundary_loop_all            | boundary-curves |
| per_vertex_normals (uniform) | normals         |

libigl's reader triangulates polygons, so on a polygon file the checksums are those of its
triangulation, not the lab's polygon mesh. `normals` is the Surface_mesh benchmark workload (normalised sum of unit face normals): it
has a "value" (the sum of all vertex normal coordinates) instead of a checksum.
"""

import argparse
import json
import os
import statistics
import sys
import time

# libigl reads its thread count from the environment: one thread, like the lab's kernels.
os.environ["IGL_NUM_THREADS"] = "1"

import numpy as np  # noqa: E402

try:
    import igl  # noqa: E402
except ImportError:
    sys.exit("libigl is missing: run `bash .ci/install-deps` (or `.venv/bin/pip install libigl numpy scipy`)")

U64 = np.uint64
MIX_A = U64(0x9E3779B97F4A7C15)
MIX_B = U64(0xBF58476D1CE4E5B9)


def mix(a, b):
    """harness/src/checksum.rs `mix`, elementwise on uint64 arrays (wrapping)."""
    a = np.asarray(a, dtype=U64)
    b = np.asarray(b, dtype=U64)
    with np.errstate(over="ignore"):
        h = (a * MIX_A + b) * MIX_B
    return h ^ (h >> U64(31))


def edge_key(a, b):
    """harness/src/checksum.rs `edge_key`: smaller end vertex in the high half."""
    a = np.asarray(a, dtype=U64)
    b = np.asarray(b, dtype=U64)
    return (np.minimum(a, b) << U64(32)) | np.maximum(a, b)


def wrapping_sum(x):
    return int(np.sum(np.asarray(x, dtype=U64), dtype=U64))


def median_of(call, repeats=5):
    """The result of `call` and the median of its times in seconds, after one run to warm up
    (the lab's timings are medians of warm runs too)."""
    result = call()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        times.append(time.perf_counter() - start)
    return result, statistics.median(times)


def r00(adjacency):
    v = np.repeat(np.arange(len(adjacency)), [len(a) for a in adjacency])
    w = np.fromiter((x for a in adjacency for x in a), dtype=np.int64, count=len(v))
    return wrapping_sum(mix(v, w))


def r02(vf_ni, n):
    vf, ni = vf_ni
    v = np.repeat(np.arange(n), np.diff(ni))
    return wrapping_sum(mix(v, vf))


def r10(edges):
    return wrapping_sum(mix(edges.min(axis=1), edges.max(axis=1)))


def r22(tt_tti):
    tt = tt_tti[0]
    f = np.repeat(np.arange(tt.shape[0]), tt.shape[1]).reshape(tt.shape)
    across = tt >= 0
    return wrapping_sum(mix(f[across], tt[across]))


def boundary_curves(loops):
    total = 0
    for loop in loops:
        loop = np.asarray(loop, dtype=np.int64)
        keys = edge_key(loop, np.roll(loop, -1))
        total += wrapping_sum(mix(np.full(len(loop), len(loop)), keys))
    return total % (1 << 64)


def libigl_version():
    """The installed libigl package's version, or "unknown"."""
    try:
        from importlib.metadata import version
        return version("libigl")
    except Exception:  # noqa: BLE001 - any failure only loses the version string
        return "unknown"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", help="a triangle mesh file libigl reads (.obj, .off, ...)")
    parser.add_argument("--out", required=True, help="where to write the JSON")
    args = parser.parse_args()

    V, F = igl.read_triangle_mesh(args.mesh)
    if F.shape[0] == 0 or F.shape[1] != 3:
        sys.exit(f"{args.mesh}: libigl needs a non-empty triangle mesh, got faces of shape {F.shape}")
    F = np.ascontiguousarray(F, dtype=np.int64)
    n = V.shape[0]

    runs = [
        ("r00", "adjacency_list", lambda: igl.adjacency_list(F), r00),
        ("r02", "vertex_triangle_adjacency", lambda: igl.vertex_triangle_adjacency(F, n),
         lambda out: r02(out, n)),
        ("r10", "edges", lambda: igl.edges(F), r10),
        ("r22", "triangle_triangle_adjacency", lambda: igl.triangle_triangle_adjacency(F), r22),
        ("boundary-curves", "boundary_loop_all", lambda: igl.boundary_loop_all(F), boundary_curves),
    ]
    results = []
    for operator, function, call, checksum in runs:
        output, seconds = median_of(call)
        results.append({"operator": operator, "function": function,
                        "checksum": str(checksum(output)), "seconds": seconds})
    uniform = igl.PER_VERTEX_NORMALS_WEIGHTING_TYPE_UNIFORM
    normals, seconds = median_of(lambda: igl.per_vertex_normals(V, F, uniform))
    results.append({"operator": "normals", "function": "per_vertex_normals",
                    "value": float(np.sum(normals)), "seconds": seconds})

    report = {"mesh": args.mesh, "vertices": int(n), "triangles": int(F.shape[0]),
              "threads": 1, "libigl_version": libigl_version(), "results": results}
    with open(args.out, "w") as out:
        json.dump(report, out, indent=2)
        out.write("\n")


if __name__ == "__main__":
    main()
