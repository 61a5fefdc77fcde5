#!/usr/bin/python3
"""Cost per answer of the two models against the size of the layer (docs/performance.md).

usage: cost_per_answer.py GRANWAVE SCENE OUTDIR [--quick]

An answer is the layer's periodic state at the paper's drive (10 Hz, Gamma 4) with its
centre-of-mass period and impact front. Its cost:
  - particles: the study's run of 15 s (150 cycles; the wave-fronts study's particle runs)
    at the engine's CPU cost per cycle, measured on a 3 s run (30 cycles, the first 10 not
    counted: the layer settles);
  - continuum: `granwave hydro` from the settled layer to its periodic state, CPU seconds of
    the whole process, with cells in proportion to the depth (10 per row of particles, at
    least 100) so that the resolution per particle diameter is that of the paper's layer.
Two families: deep layers (width 30 d, N = 150 ... 2400, the box tall enough for the layer)
and wide boxes at the paper's depth (10 rows, width 30 ... 240 d).
Prints CSV (family, N, width_d, height_d, particle_cpu_per_cycle, particle_cpu_per_answer,
hydro_cells, hydro_cycles, hydro_cpu_per_answer, hydro_period, ratio) and the crossover.
"""
import os
import subprocess
import sys

import h5py


def cpu_of(args):
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        sys.exit(f"failed: {' '.join(args)}: {proc.stderr.read().decode()[-300:]}")
    return usage.ru_utime + usage.ru_stime


def scene_sets(n, width_d, height_d):
    d = 0.002
    return ["--set", f"particles.count={n}", "--set", f"container.width={width_d * d}",
            "--set", f"container.height={height_d * d}"]


def particles(g, scene, n, width_d, height_d):
    base = scene_sets(n, width_d, height_d) + ["--no-output", "-q"]
    short = cpu_of([g, "simulate", scene, "--set", "run.duration=1.0"] + base)
    long = cpu_of([g, "simulate", scene, "--set", "run.duration=3.0"] + base)
    return (long - short) / 20.0  # CPU per cycle, cycles 10..30


def hydro(g, scene, n, width_d, height_d, cells, out):
    path = os.path.join(out, f"hydro-{n}-{width_d}.h5")
    cpu = cpu_of([g, "hydro", scene, "-o", path, "-q", "--set", f"hydro.cells={cells}",
                  "--set", "hydro.rtol=1e-3"] + scene_sets(n, width_d, height_d))
    with h5py.File(path, "r") as f:
        cycles = int(f["/solver"].attrs["cycles"])
        period = int(f["/solver"].attrs["period"])
    os.remove(path)
    return cpu, cycles, period


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    g, scene, out = sys.argv[1:4]
    quick = "--quick" in sys.argv
    os.makedirs(out, exist_ok=True)
    deep = [150, 300, 600, 1200] + ([] if quick else [2400])
    wide = [30, 60, 120] + ([] if quick else [240])
    cases = [("deep", n, 30, max(30, round(1.6 * n / 30) + 14)) for n in deep]
    cases += [("wide", 10 * w, w, 30) for w in wide if w != 30]
    print("family,N,width_d,height_d,particle_cpu_per_cycle,particle_cpu_per_answer,"
          "hydro_cells,hydro_cycles,hydro_cpu_per_answer,hydro_period,ratio", flush=True)
    rows = []
    for family, n, width_d, height_d in cases:
        per_cycle = particles(g, scene, n, width_d, height_d)
        cells = max(100, n * 10 // width_d)
        cpu, cycles, period = hydro(g, scene, n, width_d, height_d, cells, out)
        answer = 150 * per_cycle
        rows.append((family, n, width_d, answer, cpu))
        print(f"{family},{n},{width_d},{height_d},{per_cycle:.4f},{answer:.2f},{cells},{cycles},"
              f"{cpu:.2f},{period},{answer / cpu:.2f}", flush=True)
    for family in ("deep", "wide"):
        pts = [(n, a, h) for f, n, w, a, h in rows if f == family]
        cross = next((n for n, a, h in pts if a > h), None)
        print(f"{family}: continuum cheaper per answer from N = {cross}" if cross
              else f"{family}: particles cheaper per answer up to N = {pts[-1][0]}")


if __name__ == "__main__":
    main()
