#!/usr/bin/python3
"""Every HDF5 file a study writes names its format, and every numeric dataset in it has a
"unit" attribute: the tiny study's results.h5 and the run files, fields files and hydro files
in its run cache. Exceptions, by the format's own definition: H5MD's "step" datasets (record
indices; H5MD gives them no unit) and the report model under /report (figure and table data
for the page, whose units are in the axis labels and column heads).
Usage: units_and_formats.py OUTDIR
Exit 0 if all agree, else 1 with the first offenders."""
import glob
import os
import sys

import h5py

outdir = sys.argv[1]
files = [os.path.join(outdir, "results.h5")] + sorted(glob.glob(os.path.join(outdir, "runs", "*.h5")))
problems, kinds = [], set()


def format_of(f, path):
    if "h5md" in f:
        kinds.add("H5MD " + ".".join(str(v) for v in f["h5md"].attrs["version"]))
        return f["h5md/creator"].attrs["name"]
    for where in ("/", "/parameters"):
        if where in f and "format" in f[where].attrs:
            value = f[where].attrs["format"]
            kinds.add(value.decode() if isinstance(value, bytes) else value)
            return value
    problems.append(f"{path}: no format (neither /h5md nor a 'format' attribute)")
    return None


for path in files:
    with h5py.File(path, "r") as f:
        format_of(f, path)

        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset) or obj.dtype.kind not in "fiub":
                return
            if name.startswith("report/") or (name.endswith("/step") and "h5md" in f):
                return
            if "unit" not in obj.attrs:
                problems.append(f"{os.path.basename(path)}: /{name} has no unit")
        f.visititems(visit)
if len(files) < 2:
    problems.append(f"{outdir}: expected results.h5 and the run cache's files")
if problems:
    print("units_and_formats: " + "; ".join(problems[:8]) +
          (f" (and {len(problems) - 8} more)" if len(problems) > 8 else ""))
    sys.exit(1)
print(f"units_and_formats: ok ({len(files)} files: {', '.join(sorted(kinds))})")
