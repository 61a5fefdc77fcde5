#!/usr/bin/python3
"""What studies/report/render_report.py draws besides the numbers: text that breaks only
between words, the headline's list of answers, and its refusal to draw a legend over a colour
bar (run by ctest: studies_report_renderer_*)."""
import importlib.util
import os
import sys
import unittest

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "..", "studies", "report", "render_report.py")
SPEC = importlib.util.spec_from_file_location("render_report", SCRIPT)
render_report = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(render_report)


def image_with_legend():
    """A figure like a space-time plot: an image with its colour bar and two labelled lines."""
    fig = Figure(figsize=(7, 4.2), dpi=110, layout="tight")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    im = ax.imshow(np.random.default_rng(1).random((10, 20)), aspect="auto",
                   extent=[0, 1, 0, 30], origin="lower")
    fig.colorbar(im, ax=ax, label="area fraction")
    ax.plot([0, 1], [5, 5], label="plate")
    ax.plot([0, 1], [25, 25], label="lid")
    return fig, ax


class LegendAndColourBar(unittest.TestCase):
    def test_a_legend_placed_on_the_colour_bar_is_found(self):
        fig, ax = image_with_legend()
        bar = fig.axes[1]
        fig.canvas.draw()
        box = bar.get_position()  # figure coordinates of the colour bar
        ax.legend(loc="center", bbox_to_anchor=(box.x0 + box.width / 2, box.y0 + box.height / 2),
                  bbox_transform=fig.transFigure)
        self.assertEqual(render_report.legend_overlaps(fig, ax), [bar])

    def test_the_renderers_placement_keeps_the_legend_off_the_colour_bar(self):
        fig, ax = image_with_legend()
        render_report.place_legend(fig, ax, outside=False)
        self.assertEqual(render_report.legend_overlaps(fig, ax), [])


class Text(unittest.TestCase):
    def test_numbers_values_with_errors_and_symbols_stay_whole(self):
        html = render_report.text_html(
            "front 1.55 ± 0.10 m/s, share 0.49–0.66 of 95 % and T~g/T0")
        self.assertIn('<span class="nw">1.55\u00a0±\u00a00.10</span>', html)
        self.assertIn('<span class="nw">0.49–0.66</span>', html)
        self.assertIn('<span class="nw">95\u00a0%</span>', html)
        self.assertIn('<span class="nw">T~g/T0</span>', html)
        self.assertIn("front ", html)  # a plain word may break at its hyphens: no span
        self.assertNotIn('<span class="nw">front</span>', html)

    def test_a_bound_keeps_its_sign(self):
        self.assertIn('<span class="nw">&lt;\u00a02.1</span>',
                      render_report.text_html("< 2.1 (not resolved: error ≥ value)"))

    def test_a_paragraph_of_dash_lines_is_a_list_of_answers(self):
        html = render_report.paragraphs("- Wet layer: 1.2 m/s.\n- Dry layer: none.\n\nMore.")
        self.assertTrue(html.startswith('<ul class="answers">\n<li>Wet layer: '))
        self.assertEqual(html.count("<li>"), 2)
        self.assertIn("<p>More.</p>", html)


if __name__ == "__main__":
    unittest.main(verbosity=2)
