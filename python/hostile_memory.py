#!/usr/bin/env python3
"""Peak resident memory of the lab's commands on the hostile files of issue 52.

Writes the hostile files (a few MB each) into a folder, then runs each command on each file
with the release binary, one process at a time, and prints a table: the file, its size, the
command, its exit code, its peak RSS (GNU time's "Maximum resident set size", `%M`: the
command's own, where a child forked by this script would count the script's pages it was
forked with), and the peak above the fixed part over the file's size.
The binary's own RSS on a tiny mesh (its code and libraries) is printed first: the fixed part
of every peak.

    cargo build --release
    python3 python/hostile_memory.py target/release/topolab /tmp/hostile

Memory, not time: the numbers do not depend on the machine's load (docs/limits.md).
"""
import math
import os
import struct
import subprocess
import sys
import tempfile


def write_files(folder):
    def w(name, data):
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data.encode() if isinstance(data, str) else data)

    def triangles(n):
        return "".join("f %d %d %d\n" % (3 * t + 1, 3 * t + 2, 3 * t + 3) for t in range(n))

    def ply(vertices, faces, body):
        return ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
                "property float y\nproperty float z\nelement face %d\n"
                "property list uchar int vertex_indices\nend_header\n"
                % (vertices, faces)).encode() + body

    n = 150_000
    # Distinct vertices with coordinates of 1e10 and more, in separate triangles.
    w("far.obj", "".join("v %r %r %r\n" % (1e10 + i * 4096.0, 1e10 + (i % 7) * 1e6, 3e12 + i)
                         for i in range(n)) + triangles(n // 3))
    # Distinct vertices a few ulps apart, in separate triangles.
    one = struct.unpack("<Q", struct.pack("<d", 1.0))[0]
    w("ulps.obj", "".join("v %r 1 %d\n" % (struct.unpack("<d", struct.pack("<Q", one + 2 * i))[0],
                                           i % 3) for i in range(n)) + triangles(n // 3))
    # Triangles sharing one vertex: each a fan of its own, and one fan listed shuffled.
    m = 100_000
    w("fans.obj", "v 0 0 0\n" + "".join("v %d 1 0\nv %d 2 0\n" % (i + 1, i + 1) for i in range(m))
      + "".join("f 1 %d %d\n" % (2 * i + 2, 2 * i + 3) for i in range(m)))
    w("disk.obj", "v 0 0 0\n"
      + "".join("v %.9f %.9f 0\n" % (math.cos(2 * math.pi * i / m), math.sin(2 * math.pi * i / m))
                for i in range(m))
      + "".join("f 1 %d %d\n" % (i * 7919 % m + 2, (i * 7919 % m + 1) % m + 2) for i in range(m)))
    # Distinct unknown OBJ statement kinds.
    w("unknown.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
      + "".join("kind%d 1\n" % i for i in range(300_000)))
    # A binary PLY announcing 4.88 million faces of 0 corners.
    w("zerofaces.ply", ply(0, 4_880_000, bytes(4_880_000)))
    # Separate triangles, as OBJ and as binary PLY (49 bytes a triangle).
    t = 100_000
    w("separate.obj", "".join("v %d 0 0\nv %d 1 0\nv %d 0 1\n" % (i, i, i) for i in range(t))
      + triangles(t))
    body = b"".join(struct.pack("<9f", i, 0, 0, i, 1, 0, i, 0, 1) for i in range(t))
    body += b"".join(struct.pack("<B3i", 3, 3 * i, 3 * i + 1, 3 * i + 2) for i in range(t))
    w("separate.ply", ply(3 * t, t, body))
    # Files of NUL bytes, read as each format.
    for ext in ["off", "obj", "ply", "stl"]:
        w("zeros." + ext, bytes(4_000_000))


def peak(binary, args):
    """Exit code and peak RSS in bytes of `binary args`, its output discarded."""
    with tempfile.NamedTemporaryFile("r") as report:
        code = subprocess.call(["/usr/bin/time", "-f", "%M", "-o", report.name, binary] + args,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return code, int(report.read().split()[-1]) * 1024


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    binary, folder = sys.argv[1], sys.argv[2]
    os.makedirs(folder, exist_ok=True)
    write_files(folder)
    out = tempfile.mkdtemp()
    _, base = peak(binary, ["info", "tetrahedron"])
    print("fixed part (info tetrahedron): %.1f MB" % (base / 1e6))
    print("%-14s %8s  %-24s %4s %10s %14s"
          % ("file", "MB", "command", "exit", "peak MB", "(peak-fixed)/file"))
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        size = os.path.getsize(path)
        for label, args in [("info", ["info", path]),
                            ("info --structure che-l2", ["info", path, "--structure", "che-l2"]),
                            ("check", ["check", path]),
                            ("convert .obj", ["convert", path, os.path.join(out, "o.obj")]),
                            ("convert .che", ["convert", path, os.path.join(out, "o.che")]),
                            ("repair", ["repair", path, "--out", os.path.join(out, "r.obj")])]:
            code, rss = peak(binary, args)
            for f in os.listdir(out):
                os.remove(os.path.join(out, f))
            print("%-14s %8.2f  %-24s %4d %10.1f %14.2f"
                  % (name, size / 1e6, label, code, rss / 1e6, (rss - base) / size))
    os.rmdir(out)


if __name__ == "__main__":
    main()
