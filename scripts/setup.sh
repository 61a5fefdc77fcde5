#!/usr/bin/env bash
# Installs the Debian 12 packages granwave needs (only those missing), configures and
# builds. Used by main.sh and test.sh; safe to run again (incremental).
#   GRANWAVE_BUILD_DIR  build tree (default: build)
#   GRANWAVE_SANITIZE   1 = address + undefined-behaviour sanitizer build
#   GRANWAVE_BUILD_BENCH 0 = do not build the benchmark programs (default 1)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config
          libeigen3-dev libsundials-dev libfftw3-dev libhdf5-dev hdf5-tools
          libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libtomlplusplus-dev libfmt-dev
          python3-matplotlib python3-h5py python3-numpy chromium libopenmpi-dev openmpi-bin
          git clang-format python3-clang-14)
# Used only by the tests, never by the program: the field's readers that open granwave's files
# (docs/commands.md, "Viewers") and YAML for the citation file's check.
test_packages=(paraview python3-paraview python3-mdanalysis python3-ase python3-gsd python3-yaml)
packages+=("${test_packages[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "granwave setup: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

build="${GRANWAVE_BUILD_DIR:-build}"
sanitize="${GRANWAVE_SANITIZE:-0}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DGRANWAVE_SANITIZE="$([ "$sanitize" = 1 ] && echo ON || echo OFF)" \
  -DGRANWAVE_BUILD_BENCH="$([ "$sanitize" = 1 ] || [ "${GRANWAVE_BUILD_BENCH:-1}" = 0 ] && echo OFF || echo ON)" >&2
cmake --build "$build" -j"$(nproc)" >&2
