#!/usr/bin/python3
"""scripts/check_includes.py fails on each kind of include across the dependency rule and
passes a tree that follows it (run by ctest: include_check_rejects_includes_across_the_rule)."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CHECK = os.path.join(HERE, "..", "..", "scripts", "check_includes.py")
RULES = os.path.join(HERE, "..", "..", "scripts", "include-rules.toml")


def run(files):
    """Writes `files` (path -> text) into a fresh tree and runs the checker on it."""
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as f:
                f.write(text)
        p = subprocess.run([sys.executable, CHECK, "--root", root, "--rules", RULES],
                           capture_output=True, text=True)
        return p.returncode, p.stdout


class IncludeRule(unittest.TestCase):
    def assertRejected(self, path, include, words):
        code, out = run({path: f'#include "{include}"\n'})
        self.assertEqual(code, 1, out)
        self.assertIn(path + ":1:", out)
        for w in words:
            self.assertIn(w, out)

    def test_a_tree_that_follows_the_rule_passes(self):
        code, out = run({
            "particles/Engine.cpp": '#include "scene/Scene.hpp"\n#include "h5/File.hpp"\n',
            "coarse_grain/Fields.cpp": '#include "particles/Snapshot.hpp"\n#include "scene/S.hpp"\n',
            "studies/hydro_run/Model.cpp": '#include "hydro/Closure.hpp"\n',
            "studies/stability/Vote.cpp": '#include "studies/contract/Study.hpp"\n'
                                          '#include "coarse_grain/Fields.hpp"\n#include "Vote.hpp"\n',
            "studies/cli/main.cpp": '#include "studies/stability/Vote.hpp"\n',
            "tests/studies/stability/VoteTest.cpp": '#include "studies/stability/Vote.hpp"\n'
                                                    '#include "tests/h5/ScratchDir.hpp"\n',
        })
        self.assertEqual(code, 0, out)

    def test_particles_including_hydro_or_studies_is_rejected(self):
        self.assertRejected("particles/A.cpp", "hydro/B.hpp", ["particles may not include hydro"])
        self.assertRejected("particles/A.cpp", "studies/contract/S.hpp",
                            ["particles may not include studies/contract"])

    def test_hydro_including_particles_or_scene_is_rejected(self):
        self.assertRejected("hydro/A.hpp", "particles/B.hpp", ["hydro may not include particles"])
        self.assertRejected("hydro/A.hpp", "studies/cli/C.hpp", ["hydro may not include studies/cli"])

    def test_coarse_grain_including_hydro_is_rejected(self):
        self.assertRejected("coarse_grain/A.cpp", "hydro/B.hpp",
                            ["coarse_grain may not include hydro"])

    def test_a_study_including_another_study_or_the_cli_is_rejected(self):
        self.assertRejected("studies/wave_fronts/A.cpp", "studies/stability/B.hpp",
                            ["studies/wave_fronts may not include studies/stability"])
        self.assertRejected("studies/sound_speed/A.cpp", "studies/cli/B.hpp",
                            ["studies/sound_speed may not include studies/cli"])

    def test_the_runner_and_the_report_stay_below_the_study_contract(self):
        self.assertRejected("studies/runner/A.cpp", "studies/run_files/B.hpp",
                            ["studies/runner may not include studies/run_files"])
        self.assertRejected("studies/report/A.cpp", "studies/contract/B.hpp",
                            ["studies/report may not include studies/contract"])

    def test_the_methods_comparison_does_not_include_the_study_it_is_part_of(self):
        self.assertRejected("studies/method_comparison/A.cpp", "studies/wave_fronts/B.hpp",
                            ["studies/method_comparison may not include studies/wave_fronts"])
        self.assertRejected("studies/method_comparison/A.cpp", "studies/stability/B.hpp",
                            ["studies/method_comparison may not include studies/stability"])

    def test_a_test_follows_the_rule_of_the_folder_it_tests(self):
        self.assertRejected("tests/hydro/ATest.cpp", "particles/B.hpp",
                            ["tests/hydro may not include particles"])

    def test_a_folder_the_rule_does_not_name_is_rejected(self):
        code, out = run({"newroom/A.cpp": "int x;\n"})
        self.assertEqual(code, 1, out)
        self.assertIn("not in the dependency rule", out)
        code, out = run({"scene/A.cpp": '#include "newroom/B.hpp"\n'})
        self.assertEqual(code, 1, out)
        self.assertIn("does not name", out)


if __name__ == "__main__":
    unittest.main()
