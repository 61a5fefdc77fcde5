#!/usr/bin/python3
"""`granwave export` writes what the field's readers open: a short run of the paper's dry
scene is exported to extended XYZ and read back by READER:
  ase          ase.io.read: every frame's positions, velocities, angular velocities, cell
               and time are the run file's, bit for bit (read with h5py);
  mdanalysis   MDAnalysis's XYZ reader: every frame's positions are the run file's to its
               single precision (MDAnalysis keeps float32 coordinates).
Usage: export_in_readers.py READER GRANWAVE SCENE.toml
Exit 0 if all agree, 77 (skipped) if the reader's Debian package is not installed, else 1."""
import os
import subprocess
import sys
import tempfile
import warnings

import h5py
import numpy as np

reader, granwave, scene = sys.argv[1:4]
package = {"ase": "python3-ase", "mdanalysis": "python3-mdanalysis"}[reader]
try:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        __import__("ase.io" if reader == "ase" else "MDAnalysis")
except ImportError:
    print(f"export_in_readers: skipped: {reader} is not installed (apt-get install {package})")
    sys.exit(77)


def check_ase(path, f, want):
    import ase
    import ase.io
    frames = ase.io.read(path, index=":")
    problems = [] if len(frames) == len(want) else [f"{len(frames)} frames, {len(want)} expected"]
    g = "/particles/all/"
    for atoms, k in zip(frames, want):
        for name, got, expected in (
                ("positions", atoms.positions, f[g + "position/value"][k]),
                ("velocities", atoms.arrays.get("velocities"), f[g + "velocity/value"][k]),
                ("angular velocities", atoms.arrays.get("angular_velocity"),
                 f[g + "angular_velocity/value"][k]),
                ("cell", atoms.cell.lengths(), np.diag(f[g + "box/edges/value"][k]))):
            if got is None or not np.array_equal(got, expected):
                problems.append(f"frame {k}: {name} differ")
        if atoms.info.get("Time") != f[g + "position/time"][k]:
            problems.append(f"frame {k}: time {atoms.info.get('Time')}")
    return problems, f"{len(frames)} frames, ASE {ase.__version__}"


def check_mdanalysis(path, f, want):
    import MDAnalysis
    u = MDAnalysis.Universe(path, format="XYZ", topology_format="XYZ")
    frames = len(u.trajectory)
    problems = [] if frames == len(want) else [f"{frames} frames, {len(want)} expected"]
    for _, k in zip(u.trajectory, want):
        expected = f["/particles/all/position/value"][k].astype(np.float32)
        if not np.array_equal(u.atoms.positions, expected):
            problems.append(f"frame {k}: positions differ")
    return problems, f"{frames} frames, MDAnalysis {MDAnalysis.__version__}"


with tempfile.TemporaryDirectory(prefix="granwave-export-") as tmp:
    run = os.path.join(tmp, "run.h5")
    subprocess.run([granwave, "simulate", scene, "--set", "run.duration=0.5", "-o", run, "-q"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run([granwave, "export", run, "--every", "10"], check=True,
                   stdout=subprocess.DEVNULL)
    with h5py.File(run, "r") as f, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        want = range(0, f["/particles/all/position/value"].shape[0], 10)
        check = check_ase if reader == "ase" else check_mdanalysis
        problems, what = check(os.path.join(tmp, "run.extxyz"), f, want)
if problems:
    print("export_in_readers: " + "; ".join(problems[:5]))
    sys.exit(1)
print(f"export_in_readers: ok ({what})")
