#!/usr/bin/env bash
# Set up, build and run the whole test suite through ctest (unit, integration and
# validation tiers). With --sanitize: an address + undefined-behaviour sanitizer build in
# build-asan, running the same tests but the labels `grid` (the stability grid's 240 particle
# runs, about 650 CPU-s in Release and several times that under the sanitizers) and `repeat`
# (three whole studies run again end to end, 750 CPU-s under the sanitizers), both on code
# paths that the other tests already take.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--sanitize" ]; then
  export GRANWAVE_BUILD_DIR="${GRANWAVE_BUILD_DIR:-build-asan}" GRANWAVE_SANITIZE=1
fi
# The tests do not need the benchmark programs: skip building them here.
GRANWAVE_BUILD_BENCH=0 bash scripts/setup.sh
build="${GRANWAVE_BUILD_DIR:-build}"
skip=()
[ "${GRANWAVE_SANITIZE:-0}" = 1 ] && skip=(-LE '^(grid|repeat)$')
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" ${skip[@]+"${skip[@]}"}
