#!/usr/bin/python3
"""Cost of the hydro solver at equal error, two builds side by side (docs/performance.md).

usage: hydro_equal_error.py OLD_GRANWAVE OLD_SCENE NEW_GRANWAVE NEW_SCENE OUTDIR

Runs `granwave hydro SCENE` of each build over a grid of (cells, rtol) and once more at its
finest setting (each build's own reference), then measures for every run
  - the error of the centre-of-mass trajectory over the periodic window, phase by phase: the
    largest deviation from the reference relative to the reference's excursion;
  - the process CPU time (user + system, from wait4) per drive cycle integrated.
Prints one CSV row per run, and for the old build's default (400 cells, rtol 1e-4) the
cheapest new run with no larger error and the ratio of their costs per cycle.
Runs whose period differs from the reference's count as failures of accuracy (error inf).
"""
import csv
import os
import subprocess
import sys

import h5py
import numpy as np


def run(binary, scene, cells, rtol, out):
    path = os.path.join(out, f"{os.path.basename(binary)}-{cells}-{rtol:g}.h5")
    args = [binary, "hydro", scene, "-o", path, "-q", "--set", f"hydro.cells={cells}",
            "--set", f"hydro.rtol={rtol:g}"]
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode().strip()
    cpu = usage.ru_utime + usage.ru_stime
    if status != 0:
        return {"ok": False, "cpu": cpu, "why": err.splitlines()[-1] if err else "failed"}
    with h5py.File(path, "r") as f:
        com = f["/phases/center_of_mass_height"][()]
        cycles = int(f["/solver"].attrs["cycles"])
        period = int(f["/solver"].attrs["period"])
    os.remove(path)
    return {"ok": True, "cpu": cpu, "cycles": cycles, "period": period, "com": com}


def com_error(r, ref):
    if not r["ok"] or r["period"] != ref["period"] or len(r["com"]) != len(ref["com"]):
        return float("inf")
    span = ref["com"].max() - ref["com"].min()
    return float(np.abs(r["com"] - ref["com"]).max() / span)


def sweep(label, binary, scene, grid, reference, out, rows):
    ref = run(binary, scene, *reference, out)
    if not ref["ok"]:
        sys.exit(f"{label} reference failed: {ref['why']}")
    results = {}
    for cells, rtol in grid:
        r = run(binary, scene, cells, rtol, out)
        e = com_error(r, ref)
        per_cycle = r["cpu"] / r["cycles"] if r["ok"] else float("nan")
        rows.append([label, cells, rtol, f"{e:.3e}", f"{per_cycle:.4f}",
                     r.get("period", 0), "ok" if r["ok"] else r["why"]])
        print(",".join(map(str, rows[-1])), flush=True)
        results[(cells, rtol)] = (e, per_cycle)
    return results


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    old_bin, old_scene, new_bin, new_scene, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    rows = []
    print("solver,cells,rtol,com_error,cpu_s_per_cycle,period,status", flush=True)
    old = sweep("old", old_bin, old_scene,
                [(c, r) for c in (100, 200, 400, 800) for r in (1e-3, 1e-4, 1e-5)],
                (1600, 1e-6), out, rows)
    new = sweep("new", new_bin, new_scene,
                [(c, r) for c in (25, 50, 100, 200, 400) for r in (1e-3, 1e-4, 1e-5)],
                (800, 1e-7), out, rows)
    with open(os.path.join(out, "equal_error.csv"), "w", newline="") as f:
        csv.writer(f).writerows(
            [["solver", "cells", "rtol", "com_error", "cpu_s_per_cycle", "period", "status"]]
            + rows)
    e0, c0 = old[(400, 1e-4)]
    better = [(c, k) for k, (e, c) in new.items() if e <= e0 and c == c]
    if not better:
        print(f"old default: error {e0:.3e}, {c0:.4f} CPU-s/cycle; no new run reaches it")
        return
    c1, k1 = min(better)
    print(f"old default (400 cells, rtol 1e-4): error {e0:.3e}, {c0:.4f} CPU-s/cycle")
    print(f"cheapest new run with no larger error: {k1[0]} cells, rtol {k1[1]:g}, "
          f"error {new[k1][0]:.3e}, {c1:.4f} CPU-s/cycle: {c0 / c1:.1f}x cheaper")


if __name__ == "__main__":
    main()
