#!/usr/bin/python3
"""tests/studies/report/check_report.py passes a page drawn by render_report.py and fails each
defect it is meant to catch, on a copy of that page broken on purpose: a console error, an
image that does not load, words and numbers broken across lines, a value parted from its
error, a table wider than the page without a box that scrolls, a cell whose content is wider
than the cell (run by ctest: studies_report_check_fails_broken_pages; skipped, code 77,
without chromium)."""
import importlib.util
import os
import re
import shutil
import sys
import tempfile
import unittest

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..", "..")


def load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


check_report = load("check_report", os.path.join(HERE, "check_report.py"))
render_report = load("render_report", os.path.join(ROOT, "studies", "report", "render_report.py"))
CHROMIUM = shutil.which("chromium")

# A table wider than the page: twelve columns of values with their errors.
COLUMNS = ["model"] + [f"front speed {k} (m/s)" for k in range(1, 12)]
ROW = ["hydro, velocity-dependent closure"] + ["1.550 ± 0.095"] * 11
NARROW = ["layer", "share of seeds", "status"]
NARROW_ROW = ["wet", "0.58 (0.49–0.66)", "particles reached the end"]


def write_results(path):
    """A results file with one section: a wide table, a narrow one and a figure."""
    with h5py.File(path, "w") as h5:
        for key, value in (("format", render_report.FORMAT), ("study", "test"),
                           ("title", "A test report"), ("granwave_version", "0"),
                           ("summary", "- Wet layer: 1.72 ± 0.20 m/s.\n- Dry layer: none.")):
            h5.attrs[key] = value
        sec = h5.create_group("report/sections/00")
        sec.attrs["title"], sec.attrs["text"] = "Fronts", "Front speeds of 95 % of the runs."
        for k, (columns, row) in enumerate(((COLUMNS, ROW), (NARROW, NARROW_ROW))):
            table = sec.create_group(f"items/{k:02d}")
            table.attrs.update({"type": "table", "title": "Fronts", "caption": "One sigma.",
                                "columns": columns, "cells": row * 2})
        fig = sec.create_group("items/02")
        fig.attrs.update({"type": "figure", "title": "Fronts", "caption": "Heights.",
                          "xlabel": "t / T", "ylabel": "z / d"})
        series = fig.create_group("series/00")
        series.attrs.update({"style": "line", "label": "front"})
        series["x"], series["y"] = np.linspace(0, 1, 5), np.linspace(0, 3, 5)


class CheckReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="check_report_test-")
        results = os.path.join(cls.tmp, "results.h5")
        write_results(results)
        with h5py.File(results, "r") as h5:
            cls.page = render_report.render_page(h5)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def failures(self, page):
        path = os.path.join(self.tmp, "report.html")
        with open(path, "w", encoding="utf-8") as f:
            f.write(page)
        return "\n".join(check_report.check(path, CHROMIUM))

    def broken(self, old, new):
        self.assertIn(old, self.page)
        return self.page.replace(old, new)

    def test_the_drawn_page_passes(self):
        self.assertEqual(self.failures(self.page), "")

    def test_a_console_error_fails(self):
        page = self.broken("</body>", '<script>console.error("boom")</script></body>')
        self.assertIn("console: console error: boom", self.failures(page))

    def test_an_uncaught_exception_fails(self):
        page = self.broken("</body>", "<script>undefinedFunction()</script></body>")
        self.assertIn("console: uncaught exception", self.failures(page))

    def test_an_image_that_does_not_load_fails(self):
        page = self.broken("</section>", '<figure><img src="missing.png"></figure></section>')
        self.assertIn("console: failed to load <img>", self.failures(page))

    def test_words_and_numbers_broken_inside_fail(self):
        # The renderer's style before: any word broken anywhere to fit a narrow column.
        page = self.broken("overflow-wrap:normal", "overflow-wrap:anywhere")
        page = page.replace(".table-wrap{overflow-x:auto", ".table-wrap{overflow-x:visible")
        page = page.replace('class="nw"', "").replace("td.num{", "td.num{white-space:normal;")
        found = self.failures(page)
        self.assertRegex(found, r"table 1: '[^']+' is broken across lines")

    def test_a_value_parted_from_its_error_fails(self):
        page = self.broken("td.num{text-align:right;white-space:nowrap;",
                           "td.num{text-align:right;white-space:normal;max-width:4em;")
        page = page.replace("\u00a0±\u00a0", " ± ")
        self.assertIn("'1.550 ± 0.095' is broken across lines", self.failures(page))

    def test_a_wide_table_without_a_scroll_box_fails(self):
        page = self.broken(".table-wrap{overflow-x:auto", ".table-wrap{overflow-x:visible")
        found = self.failures(page)
        self.assertRegex(found, r"table 1 is \d+ px wide in a \d+ px column without a box")
        self.assertIn("it scrolls sideways", found)

    def test_a_headline_in_one_paragraph_fails(self):
        self.assertIn('<ul class="answers">', self.page)
        page = re.sub(r'<ul class="answers">.*?</ul>', "<p>Wet layer: 1.72. Dry layer: none.</p>",
                      self.page, count=1, flags=re.S)
        self.assertIn("the headline is not only a list of answers: it has <p>", self.failures(page))

    def test_a_paragraph_beside_the_answers_fails(self):
        page = self.broken("</ul>", "</ul>\n<p>Seeds 1-3.</p>")
        self.assertIn("the headline is not only a list of answers: it has <p>", self.failures(page))

    def test_a_page_without_a_headline_fails(self):
        self.assertIn('<ul class="answers">', self.page)
        page = re.sub(r'<ul class="answers">.*?</ul>', "", self.page, count=1, flags=re.S)
        self.assertIn("the page has no list of answers under its title", self.failures(page))

    def test_a_cell_content_wider_than_its_cell_fails(self):
        page = self.broken("th,td{", "td{max-width:5em;overflow:hidden}th,td{")
        self.assertIn("is wider than the cell", self.failures(page))


if __name__ == "__main__":
    if CHROMIUM is None:
        print("check_report_test: chromium not installed: skipped", file=sys.stderr)
        sys.exit(77)
    unittest.main(verbosity=2)
