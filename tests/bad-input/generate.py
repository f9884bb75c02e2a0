#!/usr/bin/env python3
"""Writes the bad-input corpus: small OBJ, OFF, PLY and STL files (ASCII and binary), each broken
in one way. The files are committed; run this again only to change them:

    python3 tests/bad-input/generate.py

What each file must produce is in tests/bad_input.rs (the table `CORPUS`)."""

import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"


def obj(vertices, faces):
    out = "".join(f"v {x} {y} {z}\n" for x, y, z in vertices)
    return out + "".join("f " + " ".join(str(v + 1) for v in f) + "\n" for f in faces)


def mobius(n=6):
    """A triangulated Moebius strip: n quads around a half twist, two triangles each."""
    vertices, faces = [], []
    for i in range(n):
        t = 2 * math.pi * i / n
        for s in (-0.3, 0.3):
            r = 1 + s * math.cos(t / 2)
            vertices.append((r * math.cos(t), r * math.sin(t), s * math.sin(t / 2)))
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        c, d = (2 * i + 2, 2 * i + 3) if i < n - 1 else (1, 0)
        faces += [(a, c, d), (a, d, b)]
    return obj(vertices, faces)


def ply_binary(order, vertices, faces, index_type="i", count_type="B"):
    """`order` is '<' or '>'; vertices as float xyz, faces as lists of `index_type`."""
    name = {"<": "binary_little_endian", ">": "binary_big_endian"}[order]
    ply_types = {"i": "int", "I": "uint", "B": "uchar", "b": "char"}
    header = (
        f"ply\nformat {name} 1.0\nelement vertex {len(vertices)}\n"
        "property float x\nproperty float y\nproperty float z\n"
        f"element face {len(faces)}\n"
        f"property list {ply_types[count_type]} {ply_types[index_type]} vertex_indices\nend_header\n"
    ).encode()
    body = b"".join(struct.pack(order + "fff", *v) for v in vertices)
    for f in faces:
        body += struct.pack(order + count_type, len(f))
        body += struct.pack(order + index_type * len(f), *f)
    return header + body


SQUARE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
PLY_ASCII_HEAD = (
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
)

# OBJ
write("empty.obj", "")
write("obj-bad-token.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n")
write("obj-unknown-statement.obj", TRIANGLE + "face 1 2 3\n")
write("obj-short-vertex.obj", "v 0 0 0\nv 1 0\nv 0 1 0\n")
write("obj-truncated.obj", "v 0 0 0\nv 1 0 0\nv 0 1")
write("obj-index-out-of-range.obj", TRIANGLE + "f 1 2 7\n")
write("obj-negative-out-of-range.obj", TRIANGLE + "f 1 2 -9\n")
write("obj-index-zero.obj", TRIANGLE + "f 0 1 2\n")
write("obj-index-overflows-u32.obj", TRIANGLE + "f 1 2 4294967297\n")
write("obj-index-overflows-i64.obj", TRIANGLE + "f 1 2 99999999999999999999999\n")
write("obj-nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")
write("obj-inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n")
write("obj-one-vertex-face.obj", TRIANGLE + "f 1 2 3\nf 1\n")
write("obj-two-vertex-face.obj", TRIANGLE + "f 1 2 3\nf 1 2\n")
write("obj-repeated-vertex.obj", obj(SQUARE, [(0, 1, 2, 1)]))
write("non-manifold-edge.obj",
      obj([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1)], [(0, 1, 2), (1, 0, 3), (0, 1, 4)]))
write("non-manifold-vertex.obj",
      obj([(0, 0, 0), (1, 0, 0), (1, 1, 0), (-1, 0, 0), (-1, -1, 0)], [(0, 1, 2), (0, 3, 4)]))
write("inconsistent-orientation.obj", obj(SQUARE, [(0, 1, 2), (0, 2, 3)[::-1]]))
write("mobius.obj", mobius())
write("duplicate-face.obj", obj(SQUARE[:3], [(0, 1, 2), (0, 1, 2)]))
write("geometric-duplicate-face.obj", obj(SQUARE[:3] + SQUARE[:3], [(0, 1, 2), (3, 4, 5)]))
write("duplicate-vertices.obj", obj(SQUARE + [(1, 1, 0)], [(0, 1, 2), (0, 4, 3)]))
write("unused-vertex.obj", obj(SQUARE, [(0, 1, 2)]))
write("degenerate-face.obj", obj([(0, 0, 0), (1, 0, 0), (2, 0, 0)], [(0, 1, 2)]))
write("non-planar-face.obj", obj([(0, 0, 0), (1, 0, 0), (1, 1, 0.5), (0, 1, 0)], [(0, 1, 2, 3)]))
write("non-convex-face.obj", obj([(0, 0, 0), (2, 0, 0), (1, 0.5, 0), (1, 2, 0)], [(0, 1, 2, 3)]))
# A pentagram: every turn has the same sign, but its edges cross (simple before convex).
STAR = [(math.cos(a), math.sin(a), 0) for a in (2 * math.pi * k * 2 / 5 for k in range(5))]
write("non-simple-face.obj", obj(STAR, [(0, 1, 2, 3, 4)]))
write("point-cloud.obj", "v 0 0 0\nv 1 0 0\n")
write("obj-comments-only.obj", "# exported with nothing selected\no empty\ng\n")

# OFF
write("empty.off", "")
write("off-no-elements.off", "OFF\n0 0 0\n")
write("off-no-header.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("off-bad-count.off", "OFF\n3 one 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("off-huge-vertex-count.off", "OFF\n1000000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("off-huge-face-count.off", "OFF 3 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("off-truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n")
write("off-truncated-in-face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1")
write("off-negative-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n")
write("off-index-overflows-u32.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967296\n")
write("off-nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\nNaN 1 0\n3 0 1 2\n")
write("off-two-vertex-face.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1\n")

# PLY
write("empty.ply", "")
write("ply-no-elements.ply", ply_binary("<", [], []))
write("ply-no-end-header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n")
write("ply-bad-format.ply", "ply\nformat utf16 1.0\nend_header\n")
write("ply-missing-z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nend_header\n0 0\n")
write("ply-ascii-bad-token.ply", PLY_ASCII_HEAD + "0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n")
write("ply-ascii-nan.ply", PLY_ASCII_HEAD + "0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n")
write("ply-ascii-truncated.ply", PLY_ASCII_HEAD + "0 0 0\n1 0 0\n0 1 0\n3 0 1")
write("ply-ascii-huge-header.ply", PLY_ASCII_HEAD.replace("vertex 3", "vertex 1000000000000")
      + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
valid_le = ply_binary("<", SQUARE[:3], [(0, 1, 2)])
valid_be = ply_binary(">", SQUARE[:3], [(0, 1, 2)])
write("ply-binary-huge-header.ply",
      valid_le.replace(b"element vertex 3", b"element vertex 1000000000000"))
write("ply-binary-too-short.ply", valid_le[:-3])
write("ply-binary-big-endian-too-short.ply", valid_be[:-7])
write("ply-binary-too-long.ply", valid_le + b"\0\0\0\0")
write("ply-binary-negative-index.ply", ply_binary("<", SQUARE[:3], [(0, 1, -1)]))
write("ply-binary-index-overflows-u32.ply",
      ply_binary(">", SQUARE[:3], [(0, 1, 4294967295)], index_type="I"))
write("ply-binary-negative-list-count.ply",
      ply_binary("<", SQUARE[:3], [(0, 1, 2)], count_type="b").replace(b"\x03\x00\x00\x00\x00", b"\xff\x00\x00\x00\x00", 1))
write("ply-binary-one-vertex-face.ply", ply_binary("<", SQUARE[:3], [(0, 1, 2), (2,)]))


def stl_binary(triangles, count=None):
    out = b"binary STL of the bad-input corpus".ljust(80, b" ")
    out += struct.pack("<I", len(triangles) if count is None else count)
    for t in triangles:
        out += struct.pack("<3f", 0, 0, 0)
        for p in t:
            out += struct.pack("<3f", *p)
        out += struct.pack("<H", 0)
    return out


def stl_ascii(triangles):
    out = "solid corpus\n"
    for t in triangles:
        out += "facet normal 0 0 0\nouter loop\n"
        out += "".join(f"vertex {x} {y} {z}\n" for x, y, z in t)
        out += "endloop\nendfacet\n"
    return out + "endsolid corpus\n"


STL_TRIANGLE = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
write("stl-binary-count-too-large.stl", stl_binary([STL_TRIANGLE], count=2))
write("stl-binary-bytes-after-count.stl", stl_binary([STL_TRIANGLE]) + b"\0\0")
write("stl-ascii-truncated.stl", stl_ascii([STL_TRIANGLE])[:-30])
write("stl-ascii-four-vertices.stl",
      stl_ascii([STL_TRIANGLE]).replace("endloop", "vertex 1 1 0\nendloop", 1))
write("stl-degenerate-facet.stl", stl_binary([STL_TRIANGLE, [(0, 0, 0), (1, 0, 0), (0, 0, 0)]]))

# Issue 52's hostile cases, small: each once made a reader or a check slow, large or wrong.
# Separate triangles with coordinates of 1e10 and more (the duplicate search's cells saturated).
write("obj-far-coordinates.obj",
      obj([(1e10 + 1e5 * t + 1000 * (k == 1), 2e10 + 1000 * (k == 2), 3e10)
           for t in range(10) for k in range(3)],
          [(i, i + 1, i + 2) for i in range(0, 30, 3)]))
# Distinct vertices a few ulps apart: near duplicates, all within the tolerance.
ULPS = [1.0]
for _ in range(11):
    ULPS.append(math.nextafter(ULPS[-1], 2.0))
write("obj-ulps-apart.obj",
      obj([(x, (i % 3) * 1.0, (i % 2) * 1.0) for i, x in enumerate(ULPS)],
          [(i, i + 1, i + 2) for i in range(0, 12, 3)]))
# A grid 1e-50 across: distinct doubles, one float (STL cannot hold it).
write("obj-underflows-a-float.obj",
      obj([(i * 1e-50, j * 1e-50, 0) for i in range(3) for j in range(3)],
          [(0, 1, 3), (1, 4, 3), (1, 2, 4), (2, 5, 4), (3, 4, 6), (4, 7, 6), (4, 5, 7), (5, 8, 7)]))
# 200 triangles around vertex 1, each a fan of its own.
write("obj-many-fans.obj",
      obj([(0, 0, 0)] + [(1 + i, k, 0) for i in range(200) for k in (1, 2)],
          [(0, 2 * i + 1, 2 * i + 2) for i in range(200)]))
# Distinct unknown statement kinds: listed up to 8, the others counted.
write("obj-unknown-kinds.obj", TRIANGLE + "f 1 2 3\n" + "".join(f"kind{i} 1\n" for i in range(20)))
# An index past the vertices, to be reported as the file numbers it (from 1).
write("obj-index-one-based.obj", "v 0 0 0\nf 1 2 1\n")
# Not OBJ at all: an OFF file and a file of zeros, named .obj (an empty mesh).
write("obj-holds-off.obj", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
write("obj-zeros.obj", bytes(4096))
# One long token: echoed 60 characters and its length.
write("off-nul-bytes.off", bytes(4096))
# A count of u64::MAX, reported as written.
write("ply-count-u64-max.ply",
      PLY_ASCII_HEAD.replace("element vertex 3", "element vertex 18446744073709551615")
      + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
# Faces without corners: each a finding, counted, a few kept.
write("ply-binary-faces-without-corners.ply", ply_binary("<", [], [()] * 1000))
