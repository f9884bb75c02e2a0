#!/usr/bin/env python3
"""Tests of third_party/fetch.py (stdlib unittest, no network): the committed manifest is
complete, an incomplete one is caught, unpacking takes only the pinned folder and refuses paths
that leave it, a verified folder is not fetched again, and a stale one is replaced whole."""

import io
import sys
import tarfile
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fetch  # noqa: E402


def archive(path: Path, files: dict[str, bytes]) -> Path:
    """A .tar.gz at `path` holding `files` (member name -> bytes)."""
    with tarfile.open(path, "w:gz") as tar:
        for name, data in files.items():
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))
    return path


class ManifestTest(unittest.TestCase):
    def test_the_committed_manifest_is_complete_and_pins_openmesh(self):
        sources = fetch.load_manifest()
        self.assertEqual(fetch.check_manifest(sources), [])
        openmesh = next(s for s in sources if s["name"] == "openmesh")
        self.assertEqual((openmesh["package"], openmesh["sdist"]), ("openmesh", True))

    def test_missing_or_wrong_fields_are_reported(self):
        broken = [dict(s) for s in fetch.load_manifest()]
        del broken[0]["sha256"]
        broken[0]["client"] = "curl"
        broken[0]["name"] = "../up"
        broken.append(dict(broken[0]))
        problems = "\n".join(fetch.check_manifest(broken))
        for expected in ("missing field 'sha256'", "sha256 must be", "client must be pip",
                         "plain folder name", "name used twice"):
            self.assertIn(expected, problems)


class UnpackTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = Path(self.tmp.name)
        self.into = self.root / "into"
        self.into.mkdir()

    def tearDown(self):
        self.tmp.cleanup()

    def test_only_the_pinned_folder_is_unpacked_without_git_entries(self):
        tar = archive(self.root / "a.tar.gz", {
            "pkg-1/Tree/a.txt": b"a",
            "pkg-1/Tree/sub/b.txt": b"bb",
            "pkg-1/Tree/.git": b"gitdir: ../.git/modules/Tree",
            "pkg-1/TreeNot/c.txt": b"c",
            "pkg-1/setup.py": b"",
        })
        self.assertEqual(fetch.unpack(tar, "pkg-1/Tree", self.into), 2)
        found = sorted(str(p.relative_to(self.into)) for p in self.into.rglob("*") if p.is_file())
        self.assertEqual(found, ["a.txt", "sub/b.txt"])
        self.assertEqual((self.into / "sub" / "b.txt").read_bytes(), b"bb")

    def test_a_path_that_leaves_the_folder_is_refused(self):
        tar = archive(self.root / "a.tar.gz", {"pkg-1/Tree/../../../evil.txt": b"x"})
        with self.assertRaisesRegex(RuntimeError, "outside the folder"):
            fetch.unpack(tar, "pkg-1/Tree", self.into)
        self.assertFalse((self.root / "evil.txt").exists())

    def test_an_archive_without_the_folder_is_refused(self):
        tar = archive(self.root / "a.tar.gz", {"pkg-1/other/a.txt": b"a"})
        with self.assertRaisesRegex(RuntimeError, "nothing under"):
            fetch.unpack(tar, "pkg-1/Tree", self.into)


class FetchTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = Path(self.tmp.name)
        self.tar = archive(self.root / "src.tar.gz", {"pkg-1/Tree/new.txt": b"new"})
        self.source = {"name": "tree", "client": "pip", "package": "pkg", "version": "1",
                       "sdist": True, "sha256": fetch.bench_data.sha256(self.tar), "path": "pkg-1/Tree"}
        self.downloads = 0
        self.saved = fetch.bench_data.download

        def fake_download(client, package, version, into, sdist=False):
            self.downloads += 1
            copy = into / self.tar.name
            copy.write_bytes(self.tar.read_bytes())
            return copy
        fetch.bench_data.download = fake_download

    def tearDown(self):
        fetch.bench_data.download = self.saved
        self.tmp.cleanup()

    def test_a_stale_folder_is_replaced_whole_and_then_left_alone(self):
        old = self.root / "tree"
        old.mkdir()
        (old / "old.txt").write_text("from another version")
        (old / fetch.STAMP).write_text('client = "pip"\n')
        self.assertTrue(fetch.fetch(self.source, self.root).startswith("ok (fetched"))
        self.assertEqual(sorted(p.name for p in old.iterdir()), [fetch.STAMP, "new.txt"])
        self.assertTrue(fetch.is_current(old, self.source))
        self.assertEqual(fetch.fetch(self.source, self.root).split()[:2], ["ok", "(already"])
        self.assertEqual(self.downloads, 1)
        # Nothing of the work folders is left beside it.
        self.assertEqual(sorted(p.name for p in self.root.iterdir()), ["src.tar.gz", "tree"])

    def test_an_archive_with_another_sha256_is_not_unpacked(self):
        self.source["sha256"] = "0" * 64
        status = fetch.fetch(self.source, self.root)
        self.assertTrue(status.startswith("MISSING:") and "sha256" in status, status)
        self.assertFalse((self.root / "tree").exists())


if __name__ == "__main__":
    unittest.main()
