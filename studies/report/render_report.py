#!/usr/bin/python3
"""Render a granwave study results file (HDF5, "granwave-study-1") as one self-contained
HTML page: render_report.py RESULTS.h5 OUT.html

The C++ study writes every number and the report structure; this script only draws it.
Exit status: 0 on success, 2 on bad input, 1 on any other error (one line on stderr).
"""
import base64
import html
import io
import os
import re
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.colors  # noqa: E402  (after the backend is chosen)
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

FORMAT = "granwave-study-1"
REQUIRED = object()  # sentinel default: the attribute must be present
NUMERIC = re.compile(r"\s*[-+\u2212]?(\d+\.?\d*|\.\d+)([eE][-+\u2212]?\d+)?(\s*(\u00b1|\+/-)\s*"
                     r"(\d+\.?\d*|\.\d+)([eE][-+\u2212]?\d+)?)?\s*%?\s*|\s*[-+]?(nan|inf)\s*",
                     re.IGNORECASE)
CSS = """body{font-family:system-ui,"Segoe UI",Roboto,"DejaVu Sans",sans-serif;max-width:1000px;
margin:2em auto;padding:0 1em;line-height:1.5;color:#222}h2{border-bottom:1px solid #ccc}
.provenance{color:#666;font-size:.85em}ul.answers li{margin:.3em 0}
.table-title{margin:1em 0 .3em}.table-wrap{overflow-x:auto;max-width:100%;margin:0 0 1em}
table{border-collapse:collapse}th,td{border:1px solid #bbb;padding:.25em .6em;
overflow-wrap:normal;word-break:normal;hyphens:manual;vertical-align:top}th{background:#eee}
td.num{text-align:right;white-space:nowrap;font-variant-numeric:tabular-nums}.nw{white-space:nowrap}
figure{margin:1.5em 0}figure img{max-width:100%}figcaption{font-size:.92em;color:#333}"""
JS = """window.addEventListener("load", function () {
  var imgs = document.getElementsByTagName("img"), loaded = 0;
  for (var i = 0; i < imgs.length; i++) if (imgs[i].complete && imgs[i].naturalWidth > 0) loaded++;
  document.body.setAttribute("data-figures-loaded", loaded + "/" + imgs.length);
  document.body.setAttribute("data-tables", String(document.getElementsByTagName("table").length));
  var page = document.documentElement;  // a page wider than the window scrolls sideways
  document.body.setAttribute("data-page-width", page.scrollWidth + "/" + page.clientWidth);
});"""


class InputError(Exception):
    """The results file is missing, unreadable or does not follow the schema."""


def first_line(err):
    """First non-empty line of an exception message, so that errors stay one line."""
    lines = [ln.strip() for ln in str(err).splitlines() if ln.strip()]
    return lines[0] if lines else type(err).__name__


def attr(node, name, default=REQUIRED):
    """Raw attribute `name` of `node`, or `default`; InputError if required and missing."""
    if name in node.attrs:
        return node.attrs[name]
    if default is REQUIRED:
        raise InputError(f"{'root' if node.name == '/' else node.name}: "
                         f"missing attribute '{name}'")
    return default


def as_str(value):
    """str of a string attribute stored as str, bytes or a 1-element numpy array of either."""
    value = value.ravel()[0] if isinstance(value, np.ndarray) and value.size == 1 else value
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def get_nums(node, name):
    """Optional numeric attribute (scalar or array) as a 1-D float64 array, or None."""
    value = attr(node, name, None)
    try:
        return None if value is None else np.ravel(np.asarray(value, dtype=np.float64))
    except (TypeError, ValueError):
        raise InputError(f"{node.name}: attribute '{name}' is not numeric") from None


def get_float(node, name, default=None):
    """Numeric scalar attribute as float, or `default` when absent."""
    values = get_nums(node, name)
    if values is not None and len(values) > 0:
        return float(values[0])
    if default is REQUIRED:
        raise InputError(f"{node.name}: missing numeric attribute '{name}'")
    return default


def get_data(group, name, n=None, required=True, ndim=1):
    """float64 dataset `name` of `group` (None if optional and absent), shape-checked."""
    if not isinstance(group.get(name), h5py.Dataset):
        if required:
            raise InputError(f"{group.name}: missing dataset '{name}'")
        return None
    data = np.asarray(group[name][()], dtype=np.float64)
    if data.ndim != ndim or (n is not None and len(data) != n):
        size = "" if n is None else f" of length {n}"
        raise InputError(f"{group.name}/{name}: expected a {ndim}-D array{size}")
    return data


def children(group, name):
    """Sub-groups of group[name] in sorted name order (numeric names numerically)."""
    parent = group.get(name)
    if not isinstance(parent, h5py.Group):
        return []
    keys = sorted(parent.keys(), key=lambda k: (not k.isdigit(), int(k) if k.isdigit() else 0, k))
    return [parent[k] for k in keys if isinstance(parent[k], h5py.Group)]


def text_html(text):
    """Escaped text that breaks only between words: a value and its error ("1.5 ± 0.2",
    "< 2.1") stay together, and every word holding a digit or a symbol ("9.06", "0.49–0.66",
    "T~g/T0") is kept whole; words of letters may still break at their own hyphens."""
    text = re.sub(r"\s*±\s*", "\u00a0±\u00a0", text)
    text = re.sub(r"(\d)\s+%", "\\1\u00a0%", text)  # a number keeps its per cent sign
    text = re.sub(r"(^|\s)([<>≤≥])\s+", "\\1\\2\u00a0", text)
    words = []
    for word in re.split(r"( +)", text):
        escaped = html.escape(word)
        whole = word.strip() and not re.fullmatch(r"[A-Za-z\u00c0-\u024f'-]+[,;:.]?", word)
        words.append(f'<span class="nw">{escaped}</span>' if whole else escaped)
    return "".join(words)


def paragraphs(text):
    """HTML of a text whose paragraphs are separated by blank lines; a paragraph whose every
    line starts with "- " is a list, one item per line (a report's answers, one per line)."""
    parts = [p.strip() for p in re.split(r"\n\s*\n", text) if p.strip()]
    out = []
    for part in parts:
        lines = [ln.strip() for ln in part.splitlines() if ln.strip()]
        if all(ln.startswith("- ") for ln in lines):
            items = "".join(f"<li>{text_html(ln[2:].strip())}</li>\n" for ln in lines)
            out.append(f'<ul class="answers">\n{items}</ul>\n')
        else:
            out.append(f"<p>{text_html(' '.join(lines))}</p>\n")
    return "".join(out)


def bold_title(title):
    """Escaped title in bold, ending with a full stop (caption style)."""
    return f"<b>{html.escape(title)}{'' if title.endswith(('.', '?', '!')) else '.'}</b>"


def draw_series(ax, s):
    """Draw one `series/KK` group onto the axes."""
    style = as_str(attr(s, "style"))
    kw = {"label": as_str(attr(s, "label", "")) or None}
    kw.update({k: as_str(attr(s, k)) for k in ("color", "linestyle", "marker") if k in s.attrs})
    kw.update({k: get_float(s, k) for k in ("linewidth", "markersize", "alpha") if k in s.attrs})
    data = [s.get(k) for k in ("x", "y", "y_low", "y_high")]
    if not any(isinstance(d, h5py.Dataset) and d.size for d in data):
        return  # no data at all (the C++ writer omits empty vectors): nothing to draw
    x = get_data(s, "x", required=style != "hline")
    if style == "band":
        kw.pop("marker", None)
        kw.pop("markersize", None)
        ax.fill_between(x, get_data(s, "y_low", len(x)), get_data(s, "y_high", len(x)),
                        **{"alpha": 0.3, **kw})
        return
    y = get_data(s, "y", None if style == "hline" else len(x), required=style != "vline")
    yerr = get_data(s, "yerr", None if y is None else len(y), required=False)
    xerr = get_data(s, "xerr", None if x is None else len(x), required=False)
    if style in ("hline", "vline") and len(x if style == "vline" else y) == 0:
        raise InputError(f"{s.name}: {style} needs {'x' if style == 'vline' else 'y'}[0]")
    marked = {"marker": "o", "linestyle": "none", **kw}
    if style in ("hline", "vline"):  # a level, with an optional shaded +-err band
        horizontal = style == "hline"
        at, err = (y, yerr) if horizontal else (x, xerr)
        line = (ax.axhline if horizontal else ax.axvline)(at[0], **kw)
        if err is not None:
            (ax.axhspan if horizontal else ax.axvspan)(
                at[0] - err[0], at[0] + err[0], color=line.get_color(), alpha=0.15, lw=0)
    elif style in ("line", "points"):
        ax.plot(x, y, **(kw if style == "line" else marked))
    elif style == "step":
        ax.step(x, y, where="mid", **kw)
    elif style == "errorbar":
        ax.errorbar(x, y, yerr=yerr, xerr=xerr, capsize=3, **marked)
    elif style == "bar":
        kw.pop("marker", None)
        kw.pop("markersize", None)
        steps = np.diff(np.unique(x[np.isfinite(x)]))
        ax.bar(x, y, width=0.8 * (steps.min() if len(steps) else 1.0), yerr=yerr, capsize=3, **kw)
    else:
        raise InputError(f"{s.name}: unknown style '{style}'")


def strings(node, name):
    """Optional string-array attribute as a list of str (empty when absent)."""
    value = attr(node, name, None)
    return [] if value is None else [as_str(v) for v in np.atleast_1d(value).ravel()]


def draw_image(fig, ax, img):
    """Draw the optional `image` group of a figure: a colour bar for a continuous scale, one
    colour per category with a key for a discrete one (e.g. failed / reached the end)."""
    extent = [get_float(img, k, REQUIRED) for k in ("x0", "x1", "y0", "y1")]
    values = get_data(img, "values", ndim=2)
    labels, colors = strings(img, "category_labels"), strings(img, "category_colors")
    kw = {"cmap": as_str(attr(img, "cmap", "viridis")),
          "vmin": get_float(img, "vmin"), "vmax": get_float(img, "vmax")}
    if labels:
        if len(colors) != len(labels):
            raise InputError(f"{img.name}: {len(labels)} category labels, {len(colors)} colours")
        kw = {"cmap": matplotlib.colors.ListedColormap(colors),
              "norm": matplotlib.colors.BoundaryNorm(np.arange(len(labels) + 1) - 0.5,
                                                     len(labels))}
    im = ax.imshow(values, origin="lower", extent=extent, aspect="auto",
                   interpolation="nearest", **kw)
    bar = fig.colorbar(im, ax=ax, label="" if labels else as_str(attr(img, "label", "")))
    if labels:
        bar.set_ticks(np.arange(len(labels)), labels=labels)


def label_cells(ax, img):
    """The names of an image's columns and rows as tick labels at their centres (after the
    axis scales are set: setting a scale resets the ticks)."""
    extent = [get_float(img, k, REQUIRED) for k in ("x0", "x1", "y0", "y1")]
    values = get_data(img, "values", ndim=2)
    for name, count, (lo, hi), set_ticks in (
            ("x_labels", values.shape[1], extent[:2], ax.set_xticks),
            ("y_labels", values.shape[0], extent[2:], ax.set_yticks)):
        names = strings(img, name)
        if not names:
            continue
        if len(names) != count:
            raise InputError(f"{img.name}: {len(names)} {name} for {count} cells")
        set_ticks(lo + (np.arange(count) + 0.5) * (hi - lo) / count, labels=names)


def covers_data(fig, ax, legend):
    """True if the legend box hides a data point, a point along a drawn line, or an image."""
    if ax.images:
        return True
    renderer = fig.canvas.get_renderer()
    box = legend.get_window_extent(renderer).padded(2)
    points = []
    for line in ax.lines:
        xy = line.get_transform().transform(line.get_xydata())
        if len(xy) > 1 and line.get_linestyle() not in ("None", "none", ""):
            t = np.linspace(0, 1, 12)[:, None, None]  # points along every segment
            xy = (xy[:-1] * (1 - t) + xy[1:] * t).reshape(-1, 2)
        points.append(xy)
    for coll in ax.collections:
        for path in coll.get_paths():
            points.append(coll.get_transform().transform(path.vertices))
        offsets = coll.get_offsets()
        if len(offsets):
            points.append(coll.get_offset_transform().transform(offsets))
    for patch in ax.patches:  # bars
        points.append(patch.get_transform().transform(patch.get_path().vertices))
    xy = np.concatenate(points) if points else np.empty((0, 2))
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    return bool(np.any((xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) &
                       (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1)))


def place_legend(fig, ax, outside):
    """Inside the axes where it hides no data (matplotlib's "best" place), else beside them,
    or below them where a colour bar stands beside them."""
    if not outside:
        legend = ax.legend()
        fig.canvas.draw()
        if not covers_data(fig, ax, legend):
            return
        legend.remove()
    if ax.images:  # the colour bar is on the right: the legend goes under the axis label
        entries = len(ax.get_legend_handles_labels()[0])
        rows = -(-entries // 4)  # at most 4 columns, the rows filled evenly
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), borderaxespad=0.0,
                  ncol=-(-entries // rows))
    else:
        ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)


def legend_overlaps(fig, ax):
    """The other axes of the figure (colour bars) whose drawn extent, tick labels and label
    included, the legend of `ax` overlaps, as measured by the renderer after layout."""
    legend = ax.get_legend()
    if legend is None:
        return []
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    box = legend.get_window_extent(renderer)
    return [other for other in fig.axes
            if other is not ax and box.overlaps(other.get_tightbbox(renderer))]


def render_figure(item):
    """Draw a figure item with matplotlib and return its <figure> HTML (PNG inline)."""
    title, caption = (as_str(attr(item, k)) for k in ("title", "caption"))
    fig = Figure(figsize=(7, 4.2), dpi=110, layout="tight")
    FigureCanvasAgg(fig)  # a canvas to measure the legend against the data
    ax = fig.add_subplot()
    ax.set_xlabel(as_str(attr(item, "xlabel")))
    ax.set_ylabel(as_str(attr(item, "ylabel")))
    if isinstance(item.get("image"), h5py.Group):
        draw_image(fig, ax, item["image"])
    for series in children(item, "series"):
        draw_series(ax, series)
    ax.set_xscale(as_str(attr(item, "xscale", "linear")))
    ax.set_yscale(as_str(attr(item, "yscale", "linear")))
    if isinstance(item.get("image"), h5py.Group):
        label_cells(ax, item["image"])
    for name, set_lim in (("xlim", ax.set_xlim), ("ylim", ax.set_ylim)):
        lim = get_nums(item, name)
        if lim is not None and len(lim) != 2:
            raise InputError(f"{item.name}: attribute '{name}' must have 2 elements")
        if lim is not None:
            set_lim(lim[0], lim[1])
    if get_float(item, "invert_y", 0):
        ax.invert_yaxis()
    if not isinstance(item.get("image"), h5py.Group):
        ax.grid(True, alpha=0.3)
    if get_float(item, "legend", 1) and ax.get_legend_handles_labels()[0]:
        place_legend(fig, ax, get_float(item, "legend_outside", 0))
        if legend_overlaps(fig, ax):  # a legend on a colour bar hides its scale: never draw it
            raise RuntimeError(f"{item.name}: the legend overlaps the colour bar")
    buf = io.BytesIO()
    # A colour bar's tick labels (category names) can reach past the tight layout: keep them.
    extra = {"bbox_inches": "tight", "pad_inches": 0.05} if ax.images else {}
    fig.savefig(buf, format="png", dpi=110, **extra)
    png = base64.b64encode(buf.getvalue()).decode("ascii")
    return (f'<figure><img src="data:image/png;base64,{png}" alt="{html.escape(title)}">\n'
            f"<figcaption>{bold_title(title)} {text_html(caption)}</figcaption></figure>\n")


def render_table(item):
    """Return the HTML of a table item: its title and caption above it, the table in a box
    that scrolls sideways when the table is wider than the page; numeric cells right-aligned."""
    columns, cells = ([as_str(v) for v in np.atleast_1d(attr(item, k)).ravel()]
                      for k in ("columns", "cells"))
    if not columns or len(cells) % len(columns):
        raise InputError(f"{item.name}: {len(cells)} cells do not fill rows of "
                         f"{len(columns)} columns")
    caption = (bold_title(as_str(attr(item, "title"))) + " "
               + text_html(as_str(attr(item, "caption", ""))))
    head = "".join(f"<th>{text_html(c)}</th>" for c in columns)
    rows = ["<tr>" + "".join(f'<td class="num">{html.escape(c)}</td>' if NUMERIC.fullmatch(c)
                             else f"<td>{text_html(c)}</td>" for c in cells[i:i + len(columns)])
            + "</tr>\n" for i in range(0, len(cells), len(columns))]
    return (f'<p class="table-title">{caption}</p>\n<div class="table-wrap"><table>\n'
            f"<thead><tr>{head}</tr></thead>\n<tbody>\n{''.join(rows)}</tbody></table></div>\n")


def render_item(item):
    """Return the HTML of one `items/MM` group."""
    kind = as_str(attr(item, "type"))
    if kind == "figure":
        try:
            return render_figure(item)
        except (ValueError, TypeError) as err:  # bad colour, cmap, scale, mathtext...
            raise InputError(f"{item.name}: cannot draw: {first_line(err)}") from None
    if kind == "table":
        return render_table(item)
    if kind == "text":
        return paragraphs(as_str(attr(item, "text")))
    raise InputError(f"{item.name}: unknown item type '{kind}'")


def source_line(h5):
    """The commit the program was built from, and whether its working tree was clean."""
    commit = html.escape(as_str(attr(h5, "source_commit", "unknown")))
    tree = as_str(attr(h5, "source_tree", "unknown"))
    if commit == "unknown":
        return "source commit unknown"
    note = {"clean": "", "with uncommitted changes": " (built with uncommitted changes)"}
    return f"source commit <code>{commit}</code>" + note.get(tree, " (working tree unknown)")


def render_page(h5):
    """Return the complete HTML page for an open results file."""
    fmt = as_str(attr(h5, "format", ""))
    if fmt != FORMAT:
        raise InputError(f"format is '{fmt}', expected '{FORMAT}'")
    title, study, version = (html.escape(as_str(attr(h5, k))) for k in
                             ("title", "study", "granwave_version"))
    source = source_line(h5)
    if not isinstance(h5.get("report/sections"), h5py.Group):
        raise InputError("missing group /report/sections")
    toc, body = [], []
    for sec in children(h5, "report/sections"):
        anchor = "sec-" + sec.name.rsplit("/", 1)[-1]
        name = html.escape(as_str(attr(sec, "title")))
        toc.append(f'<li><a href="#{anchor}">{name}</a></li>\n')
        body.append(f'<section><h2 id="{anchor}">{name}</h2>\n'
                    + paragraphs(as_str(attr(sec, "text", "")))
                    + "".join(render_item(item) for item in children(sec, "items"))
                    + "</section>\n")
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">\n'
            f"<title>{title}</title>\n<style>{CSS}</style></head>\n<body>\n<h1>{title}</h1>\n"
            + paragraphs(as_str(attr(h5, "summary", "")))
            + f'<p class="provenance">Study <code>{study}</code> &middot; granwave {version}'
            f" &middot; {source}</p>\n<nav><h3>Contents</h3><ol>\n{''.join(toc)}</ol></nav>\n"
            + "".join(body) + f"<script>\n{JS}\n</script>\n</body></html>\n")


def write_atomically(path, text):
    """Write `text` as UTF-8 to `path` via a temporary file in the same directory."""
    tmp = os.path.join(os.path.dirname(os.path.abspath(path)),
                       f"{os.path.basename(path)}.tmp-{os.getpid()}")
    try:
        with open(tmp, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def main(argv):
    """Command-line entry point; returns the exit status."""
    if len(argv) != 3:
        print("usage: render_report.py RESULTS.h5 OUT.html", file=sys.stderr)
        return 2
    src, out = argv[1], argv[2]
    try:
        if not os.path.isfile(src):
            raise InputError("no such file")
        if not h5py.is_hdf5(src):
            raise InputError("not an HDF5 file")
        with h5py.File(src, "r") as h5:
            page = render_page(h5)
    except InputError as err:
        print(f"render_report: {src}: {err}", file=sys.stderr)
        return 2
    except Exception as err:  # noqa: BLE001  (one line, never a traceback)
        print(f"render_report: {src}: {type(err).__name__}: {first_line(err)}", file=sys.stderr)
        return 1
    try:
        write_atomically(out, page)
    except OSError as err:
        print(f"render_report: {out}: cannot write: {err.strerror or err}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
