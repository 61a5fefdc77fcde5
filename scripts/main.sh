#!/usr/bin/env bash
# The main job: set up and build the program only, then run the wave-fronts study (the
# paper's wave-propagation section from the particles and the continuum; docs/studies.md) and
# write its report, out/wave-fronts/report.html. Runs are cached in out/runs: a second call, or
# a call after an interruption, reuses every finished run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --program
build="${GRANWAVE_BUILD_DIR:-build}"
mkdir -p out
"$build/studies/granwave" study studies/wave-fronts.toml -o out/wave-fronts --cache out/runs
echo "open out/wave-fronts/report.html"
