#!/usr/bin/python3
"""scripts/check_citation.py passes the project's CITATION.cff and fails a citation file that
breaks the Citation File Format 1.2.0 or disagrees with the project (run by ctest:
citation_check_rejects_invalid_files)."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
CHECK = os.path.join(ROOT, "scripts", "check_citation.py")
with open(os.path.join(ROOT, "CITATION.cff")) as f:
    GOOD = f.read()


def run(text):
    with tempfile.NamedTemporaryFile("w", suffix=".cff") as f:
        f.write(text)
        f.flush()
        p = subprocess.run([sys.executable, CHECK, "--root", ROOT, "--file", f.name],
                           capture_output=True, text=True)
        return p.returncode, p.stdout


class CitationCheck(unittest.TestCase):
    def assertRejected(self, text, words):
        code, out = run(text)
        self.assertEqual(code, 1, out)
        self.assertIn(words, out)

    def test_the_projects_file_passes(self):
        self.assertEqual(run(GOOD), (0, ""))

    def test_a_missing_required_key_fails(self):
        self.assertRejected(GOOD.replace("\ntitle:", "\ntitel:"), "missing required key 'title'")

    def test_a_key_the_format_does_not_define_fails(self):
        self.assertRejected(GOOD + "homepage: https://example.org\n", "unknown key 'homepage'")

    def test_another_cff_version_fails(self):
        self.assertRejected(GOOD.replace("cff-version: 1.2.0", "cff-version: 1.1.0"),
                            "cff-version")

    def test_a_version_other_than_the_projects_fails(self):
        self.assertRejected(GOOD.replace('version: "0.1.0"', 'version: "9.9"'), "version: '9.9'")

    def test_a_reference_without_authors_fails(self):
        self.assertRejected(GOOD.replace("    authors:\n      - family-names: Huang",
                                         "    editors:\n      - family-names: Huang"),
                            "missing required key 'authors'")


if __name__ == "__main__":
    unittest.main()
