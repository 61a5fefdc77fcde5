#!/usr/bin/env bash
# Set up, build and run the whole test suite through ctest in a Release build: every label
# (unit, integration, study, validation, long, grid; tests/CMakeLists.txt). With --sanitize:
# an address + undefined-behaviour sanitizer build in build-asan (at -O1), running the unit
# and integration tiers: every piece of code and every program path, on small inputs. The
# whole studies, the physics validations, the gently shaken layers and the stability grid
# run the same code at a larger scale and are left to the Release build (under the sanitizers
# they took most of CI's time; docs/performance.md, "CI").
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--sanitize" ]; then
  export GRANWAVE_BUILD_DIR="${GRANWAVE_BUILD_DIR:-build-asan}" GRANWAVE_SANITIZE=1
fi
# The tests do not need the benchmark programs: skip building them here.
GRANWAVE_BUILD_BENCH=0 bash scripts/setup.sh
build="${GRANWAVE_BUILD_DIR:-build}"
tiers=()
[ "${GRANWAVE_SANITIZE:-0}" = 1 ] && tiers=(-L '^(unit|integration)$')
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" ${tiers[@]+"${tiers[@]}"}
