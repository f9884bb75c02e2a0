#!/usr/bin/env python3
"""Qhull's 3D convex hull (scipy.spatial.ConvexHull) of a point file, as JSON.

Usage: qhull_reference.py POINTS_FILE --out JSON [--repeat R]

POINTS_FILE: one point per line, either an OBJ `v x y z` line or three numbers `x y z`;
other lines (comments, faces) are ignored, so an OBJ mesh works too (its vertices only).
Point i is the i-th point line, as in topolab (`topolab hull`).

JSON: {"n": points, "vertices": sorted indices of the hull vertices, "volume": enclosed
volume, "simplices": triangles Qhull reports (its facets triangulated), "seconds": the best
of R timings of the ConvexHull call alone (reading the file not included), "qhull_options":
the options used}. Qhull merges coplanar facets by default, so its vertices are the extreme
points, the set topolab's algorithms return.
"""
import argparse
import json
import time

import numpy as np
from scipy.spatial import ConvexHull


def read_points(path):
    points = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if fields and fields[0] == "v":
                fields = fields[1:4]
            elif len(fields) != 3:
                continue
            try:
                points.append([float(x) for x in fields[:3]])
            except ValueError:
                continue
    return np.array(points, dtype=np.float64).reshape(-1, 3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("points")
    parser.add_argument("--out", required=True)
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    points = read_points(args.points)
    best = float("inf")
    hull = None
    for _ in range(max(1, args.repeat)):
        start = time.perf_counter()
        hull = ConvexHull(points)
        best = min(best, time.perf_counter() - start)
    result = {
        "n": int(len(points)),
        "vertices": sorted(int(v) for v in hull.vertices),
        "volume": float(hull.volume),
        "simplices": int(len(hull.simplices)),
        "seconds": best,
        "qhull_options": "SciPy's default for 3D: the command 'qhull i Qt' (mode i, Qt always on)",
    }
    with open(args.out, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main()
