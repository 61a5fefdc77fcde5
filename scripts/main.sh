#!/usr/bin/env bash
# The main job: set up, build, then simulate the paper's default scene (N = 300, f = 10 Hz,
# Gamma = 4, 15 s), dry and wet, writing out/paper-{dry,wet}.h5 and printing summaries.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build="${GRANWAVE_BUILD_DIR:-build}"
mkdir -p out
for law in dry wet; do
  echo "== paper scene, $law =="
  "$build/studies/granwave" simulate "scenes/paper-$law.toml" -o "out/paper-$law.h5"
done
