#!/usr/bin/env python3
"""Tests of bench-data/fetch.py (stdlib unittest): the committed manifest is complete, an
incomplete one is caught, and the naive counting and the npm conversion are right."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fetch  # noqa: E402


class ManifestTest(unittest.TestCase):
    def test_the_committed_manifest_is_complete(self):
        meshes = fetch.load_manifest()
        self.assertEqual(fetch.check_manifest(meshes), [])
        self.assertGreaterEqual(len({m["package"] for m in meshes}), 3)

    def test_missing_or_wrong_fields_are_reported(self):
        meshes = fetch.load_manifest()
        broken = [dict(m) for m in meshes]
        del broken[0]["sha256"]
        broken[1]["genus"] = "maybe"
        broken[2]["client"] = "curl"
        broken[3]["closed"] = True
        broken[3]["boundary_curves"] = 2
        problems = "\n".join(fetch.check_manifest(broken))
        for expected in ("missing field 'sha256'", "genus is a number", "client must be",
                         "closed but has boundary curves"):
            self.assertIn(expected, problems)
        self.assertTrue(fetch.check_manifest(meshes[:4]))


class MeasureTest(unittest.TestCase):
    def measure(self, name, text):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / name
            path.write_text(text)
            return fetch.measure(path)

    def test_an_open_tetrahedron_in_off(self):
        m = self.measure("t.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n")
        self.assertEqual((m["vertices"], m["faces"], m["closed"]), (4, 3, False))
        self.assertEqual((m["boundary_curves"], m["genus"], m["dirty"]), (1, 0, "no"))

    def test_a_closed_cube_of_quads_in_obj_and_a_dirty_flip(self):
        cube = "".join(f"v {i & 1} {i >> 1 & 1} {i >> 2 & 1}\n" for i in range(8))
        faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
        obj = cube + "".join("f " + " ".join(f"{v + 1}/1" for v in f) + "\n" for f in faces)
        m = self.measure("c.obj", obj)
        self.assertEqual((m["faces"], m["face_sizes"], m["closed"], m["genus"]), (6, "polygons of 4", True, 0))
        flipped = obj.replace("f 1/1 3/1 4/1 2/1", "f 2/1 4/1 3/1 1/1")
        self.assertEqual(self.measure("f.obj", flipped)["dirty"], "4 edges with inconsistent orientation")

    def test_npm_bunny_arrays_become_obj(self):
        js = b"exports.positions=[[0,0,0],[1,0,0],[0,1,0]]\nexports.cells=[[0,1,2]]\n"
        self.assertEqual(fetch.js_arrays_to_obj(js), b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")


if __name__ == "__main__":
    unittest.main()
