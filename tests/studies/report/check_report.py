#!/usr/bin/python3
"""Render a granwave HTML report in headless Chromium and check what it shows.

Usage: check_report.py REPORT.html

Checks the DOM after scripts ran: every figure image decoded, every table has
body rows each holding a number (or the reason a run failed), no empty cell or
figure, at least one <h2>, a headline under the title that is a list of answers
and nothing else (<ul class="answers">: the summary's "- " lines), and no
sideways scrolling in a 1280 px wide window; and that a screenshot shows
something.  A copy of the page with two scripts of
this checker added (PROBE) also fails on: any console error, uncaught exception
or resource that failed to load; a table wider than its column without a box
that scrolls sideways, or such a box wider than the page; a cell whose content
is wider than the cell; a number or a word broken across two lines (in tables,
lists, paragraphs and captions; a word of letters may break at its own hyphen).
Legends inside the figures' images are not in the DOM: render_report.py itself
refuses to draw a legend that overlaps a colour bar.  Exit 0 if all good, else
1 with one line per failure on stderr.
"""
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
from html.parser import HTMLParser

NUMBER = re.compile(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?")
TIMEOUT_S = 120
WINDOW = (1280, 1000)  # px, a laptop screen
MIN_SCREENSHOT_BYTES = 10 * 1024
MAX_LAYOUT_FAILURES = 20  # listed; the rest counted

# Added at the start of <head>: records console errors, uncaught exceptions and resources that
# failed to load, before any script of the page runs.
PROBE_HEAD = """<script>(function () {
  var errors = window.__checkReportErrors = [];
  var consoleError = console.error;
  console.error = function () {
    errors.push("console error: " + Array.prototype.join.call(arguments, " "));
    return consoleError.apply(console, arguments);
  };
  window.addEventListener("error", function (e) {
    var el = e.target;
    errors.push(el && el !== window && el.tagName
                ? "failed to load <" + el.tagName.toLowerCase() + ">"
                : "uncaught exception: " + e.message);
  }, true);
  window.addEventListener("unhandledrejection", function (e) {
    errors.push("unhandled promise rejection: " + e.reason);
  });
})();</script>"""

# Added at the end of <body>: after the page loaded and laid out, measures every table and
# text and writes the findings into <body data-check-errors> and <body data-check-layout>.
PROBE_BODY = """<script>(function () {
  function scroller(el) {
    for (var p = el.parentElement; p && p !== document.body; p = p.parentElement) {
      var ox = getComputedStyle(p).overflowX;
      if (ox === "auto" || ox === "scroll") return p;
    }
    return null;
  }
  // Words between spaces (not no-break spaces; a value, "±" and its error are one word), split
  // after the hyphen of letters-hyphen-letters.
  function pieces(text) {
    var out = [], re = /[^ \\t\\n\\r\\f]+(?:[ \\u00a0]*\\u00b1[ \\u00a0]*[^ \\t\\n\\r\\f]+)*/g, m;
    while ((m = re.exec(text)) !== null) {
      var start = m.index, word = m[0], cut = /[A-Za-z]-(?=[A-Za-z])/g, h;
      while ((h = cut.exec(word)) !== null) {
        out.push([start, m.index + h.index + 2]);
        start = m.index + h.index + 2;
      }
      out.push([start, m.index + word.length]);
    }
    return out;
  }
  function brokenWords(root, where, found) {
    var walk = document.createTreeWalker(root, NodeFilter.SHOW_TEXT), node;
    var range = document.createRange();
    while ((node = walk.nextNode())) {
      pieces(node.data).forEach(function (p) {
        range.setStart(node, p[0]);
        range.setEnd(node, p[1]);
        var tops = Array.prototype.map.call(range.getClientRects(), function (r) {
          return r.top;
        });
        if (tops.length > 1 && Math.max.apply(null, tops) - Math.min.apply(null, tops) > 2)
          found.push(where + ": '" + node.data.slice(p[0], p[1]) + "' is broken across lines");
      });
    }
  }
  function measure() {
    var found = [], page = document.documentElement.clientWidth;
    var tables = document.getElementsByTagName("table");
    for (var t = 0; t < tables.length; t++) {
      var table = tables[t], name = "table " + (t + 1), box = scroller(table);
      var width = table.getBoundingClientRect().width;
      var column = table.parentElement.getBoundingClientRect().width;
      if (!box && width > column + 1)
        found.push(name + " is " + Math.round(width) + " px wide in a " + Math.round(column) +
                   " px column without a box that scrolls sideways");
      if (box && box.getBoundingClientRect().right > page + 1)
        found.push(name + ": its scroll box reaches past the page");
      var cells = table.querySelectorAll("td, th");
      for (var c = 0; c < cells.length; c++) {
        if (cells[c].scrollWidth > cells[c].clientWidth + 1)
          found.push(name + ": the content of cell '" + cells[c].textContent.slice(0, 40) +
                     "' is wider than the cell");
        brokenWords(cells[c], name, found);
      }
    }
    var texts = document.querySelectorAll("body > p, section > p, li, figcaption, p.table-title");
    for (var i = 0; i < texts.length; i++)
      brokenWords(texts[i], texts[i].tagName.toLowerCase(), found);
    document.body.setAttribute("data-check-layout", JSON.stringify(found));
    document.body.setAttribute("data-check-errors", JSON.stringify(window.__checkReportErrors));
  }
  window.addEventListener("load", function () { setTimeout(measure, 0); });
})();</script>"""


# Block elements that may stand between the title and the provenance line: the headline
# (render_report.py's paragraphs() of the summary) must be lists of answers only.
HEADLINE_BLOCKS = ("p", "ul", "ol", "div", "table", "h2", "h3", "section", "nav")


class ReportDom(HTMLParser):
    """Collects what the checks need from a dumped DOM."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.body_attrs = {}
        self.img_srcs = []
        self.h2_count = 0
        self.tables = []      # per table: list of (in_thead, [cell texts]) rows
        self.figures = []     # per figure: list of img srcs inside it
        self.headline = []    # blocks between <h1> and the provenance line: (tag, class)
        self.answers = 0      # <li> items of the headline
        self._headline = None  # None before <h1>, True inside the headline, False after it
        self._tables = []     # stack of open tables: [rows, section]
        self._cell = None     # text pieces of the open <td>/<th>
        self._figure = None   # img srcs of the open <figure>

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if self._headline and tag == "p" and attrs.get("class") == "provenance":
            self._headline = False
        elif self._headline and tag in HEADLINE_BLOCKS:
            self.headline.append((tag, attrs.get("class") or ""))
        elif self._headline and tag == "li":
            self.answers += 1
        if tag == "body":
            self.body_attrs = attrs
        elif tag == "img":
            self.img_srcs.append(attrs.get("src") or "")
            if self._figure is not None:
                self._figure.append(attrs.get("src") or "")
        elif tag == "h2":
            self.h2_count += 1
        elif tag == "figure":
            self._figure = []
            self.figures.append(self._figure)
        elif tag == "table":
            self._tables.append([[], "tbody"])
        elif self._tables and tag in ("thead", "tbody", "tfoot"):
            self._tables[-1][1] = tag
        elif self._tables and tag == "tr":
            self._tables[-1][0].append((self._tables[-1][1] == "thead", []))
        elif self._tables and tag in ("td", "th"):
            self._cell = []

    def handle_endtag(self, tag):
        if tag == "h1" and self._headline is None:
            self._headline = True
        elif tag == "figure":
            self._figure = None
        elif tag == "table" and self._tables:
            self.tables.append(self._tables.pop()[0])
        elif tag in ("thead", "tbody", "tfoot") and self._tables:
            self._tables[-1][1] = "tbody"
        elif tag in ("td", "th") and self._cell is not None:
            rows = self._tables[-1][0] if self._tables else []
            if rows:
                rows[-1][1].append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def run_chromium(chromium, tmp, name, output_arg, url):
    """Run headless Chromium once with a fresh profile; return its stdout text."""
    profile = tempfile.mkdtemp(prefix=f"profile-{name}-", dir=tmp)
    cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
           "--no-first-run", "--disable-background-networking", "--disable-component-update",
           "--disable-sync", f"--user-data-dir={profile}", "--virtual-time-budget=5000",
           f"--window-size={WINDOW[0]},{WINDOW[1]}",
           output_arg, url]
    proc = subprocess.run(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, timeout=TIMEOUT_S, check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"chromium ({name}) exited with status {proc.returncode}")
    return proc.stdout.decode("utf-8", errors="replace")


def check_dom(dom):
    """Return the list of failures found in the dumped DOM."""
    failures = []
    loaded = dom.body_attrs.get("data-figures-loaded")
    n_img = len(dom.img_srcs)
    if loaded is None:
        failures.append("<body> has no data-figures-loaded attribute (page script did not run)")
    else:
        match = re.fullmatch(r"(\d+)/(\d+)", loaded)
        if not match:
            failures.append(f'malformed data-figures-loaded="{loaded}"')
        elif int(match[2]) < 1:
            failures.append("the page has no figures")
        elif match[1] != match[2]:
            failures.append(f"only {match[1]} of {match[2]} figure images loaded")
        elif int(match[2]) != n_img:
            failures.append(f'data-figures-loaded="{loaded}" but the DOM has {n_img} <img>')
    width = dom.body_attrs.get("data-page-width")
    match = re.fullmatch(r"(\d+)/(\d+)", width or "")
    if not match:
        failures.append(f'<body> has no usable data-page-width ("{width}")')
    elif int(match[1]) > int(match[2]):
        failures.append(f"the page is {match[1]} px wide in a {match[2]} px window: "
                        "it scrolls sideways")
    tables_attr = dom.body_attrs.get("data-tables")
    if tables_attr is not None and tables_attr != str(len(dom.tables)):
        failures.append(f'data-tables="{tables_attr}" but the DOM has {len(dom.tables)} tables')
    for t, rows in enumerate(dom.tables, 1):
        if any(in_head and not all(cells) for in_head, cells in rows):
            failures.append(f"table {t} has an empty header cell")
        body = [cells for in_head, cells in rows if not in_head]
        if not body:
            failures.append(f"table {t} has no body rows")
        for r, cells in enumerate(body, 1):
            if not cells or not all(cells):
                failures.append(f"table {t} body row {r} has an empty cell")
            # A row without any number must say why: a run that failed is a result
            # (where a method breaks down), reported with its reason.
            if not any(NUMBER.search(c) for c in cells) and not any("fail" in c for c in cells):
                failures.append(f"table {t} body row {r} has no number: "
                                f"{' | '.join(cells)[:80]!r}")
    for f, srcs in enumerate(dom.figures, 1):
        if not any(srcs):
            failures.append(f"figure {f} has no image")
    if dom.h2_count < 1:
        failures.append("the page has no <h2> section heading")
    failures += check_headline(dom)
    return failures + check_probe(dom)


def check_headline(dom):
    """The summary under the title is a list of answers, one per line ("- " lines)."""
    others = [f"<{tag}>" for tag, cls in dom.headline if (tag, cls) != ("ul", "answers")]
    if others:
        return [f"the headline is not only a list of answers: it has {', '.join(others)}"]
    if dom.answers < 1:
        return ["the page has no list of answers under its title"]
    return []


def check_probe(dom):
    """Failures the probe scripts recorded (console errors, layout), or that they did not run."""
    failures = []
    for name, what in (("data-check-errors", "console"), ("data-check-layout", "layout")):
        try:
            found = json.loads(dom.body_attrs[name])
        except (KeyError, TypeError, ValueError):
            failures.append(f"the checker's {what} probe did not run (no <body {name}>)")
            continue
        failures += [f"{what}: {f}" for f in found[:MAX_LAYOUT_FAILURES]]
        if len(found) > MAX_LAYOUT_FAILURES:
            failures.append(f"{what}: {len(found) - MAX_LAYOUT_FAILURES} more")
    return failures


def probed_copy(path, tmp):
    """A copy of the page in `tmp` with the probe scripts added; its file:// URL."""
    with open(path, encoding="utf-8") as f:
        page = f.read()
    head, body = page.find("<head>"), page.rfind("</body>")
    if head < 0 or body < 0:
        raise RuntimeError("the page has no <head> or no </body>")
    page = (page[:head + 6] + PROBE_HEAD + page[head + 6:body] + PROBE_BODY + page[body:])
    copy = os.path.join(tmp, "probed.html")
    with open(copy, "w", encoding="utf-8") as f:
        f.write(page)
    return pathlib.Path(copy).as_uri()


def check(path, chromium):
    """Render `path` and return the list of failures (empty if all good)."""
    tmp = tempfile.mkdtemp(prefix="check_report-")
    try:
        url = probed_copy(path, tmp)  # file:///abs/path, percent-encoded
        dom = ReportDom()
        dom.feed(run_chromium(chromium, tmp, "dom", "--dump-dom", url))
        dom.close()
        failures = check_dom(dom)
        shot = os.path.join(tmp, "shot.png")
        run_chromium(chromium, tmp, "shot", f"--screenshot={shot}", url)
        if not os.path.isfile(shot):
            failures.append("chromium wrote no screenshot")
        elif os.path.getsize(shot) <= MIN_SCREENSHOT_BYTES:
            failures.append(f"screenshot is only {os.path.getsize(shot)} bytes: page looks blank")
        return failures
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main(argv):
    """Command-line entry point; returns the exit status."""
    if len(argv) != 2:
        print("usage: check_report.py REPORT.html", file=sys.stderr)
        return 1
    path = argv[1]
    chromium = shutil.which("chromium")
    if chromium is None:
        print("check_report: chromium not installed (apt-get install chromium)", file=sys.stderr)
        return 1
    if not os.path.isfile(path):
        print(f"check_report: {path}: no such file", file=sys.stderr)
        return 1
    try:
        failures = check(path, chromium)
    except (OSError, RuntimeError, subprocess.TimeoutExpired) as err:
        failures = [str(err).splitlines()[0] if str(err) else type(err).__name__]
    for failure in failures:
        print(f"check_report: {path}: {failure}", file=sys.stderr)
    if not failures:
        print(f"check_report: {path}: ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
