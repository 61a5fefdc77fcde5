#!/usr/bin/env python3
"""Paired runs of two builds of the continuum's cycle benchmark (bench/HydroCycleBenchmark.cpp).

    bench/pair_hydro_bench.py OLD_BENCH NEW_BENCH [--pairs 5] [--filter REGEX]

For each benchmark, OLD and NEW run in turn (old, new, old, new, ...), one process each, and
the ratio NEW/OLD of the thread CPU per drive cycle is taken pair by pair, so a drift of the
shared machine's speed cancels. Prints, per benchmark, the median CPU-s per cycle of each build,
the median and range of the paired ratios, and NEW's CVODE counters per cycle.
"""
import argparse
import json
import statistics
import subprocess
import sys


def run(binary, name):
    out = subprocess.run(
        [binary, f"--benchmark_filter=^{name}$", "--benchmark_format=json"],
        check=True, capture_output=True, text=True).stdout
    bench = json.loads(out)["benchmarks"]
    if len(bench) != 1 or "error_message" in bench[0]:
        sys.exit(f"{binary}: {name}: {bench}")
    return bench[0]


def names(binary, pattern):
    out = subprocess.run([binary, "--benchmark_list_tests", f"--benchmark_filter={pattern}"],
                         check=True, capture_output=True, text=True).stdout
    return [line.strip() for line in out.splitlines() if line.strip()]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("--pairs", type=int, default=5)
    p.add_argument("--filter", default=".")
    a = p.parse_args()
    counters = ["steps_per_cycle", "rhs_per_cycle", "jac_per_cycle", "ncf_per_cycle",
                "etf_per_cycle"]
    print("benchmark,old_cpu_s_per_cycle,new_cpu_s_per_cycle,ratio_median,ratio_min,ratio_max,"
          + ",".join(counters))
    for name in names(a.new, a.filter):
        old, new, ratios, last = [], [], [], None
        for _ in range(a.pairs):
            o = run(a.old, name)["cpu_s_per_cycle"]
            last = run(a.new, name)
            n = last["cpu_s_per_cycle"]
            old.append(o)
            new.append(n)
            ratios.append(n / o)
        print(f"{name},{statistics.median(old):.4f},{statistics.median(new):.4f},"
              f"{statistics.median(ratios):.3f},{min(ratios):.3f},{max(ratios):.3f},"
              + ",".join(f"{last[c]:.1f}" for c in counters), flush=True)


if __name__ == "__main__":
    main()
