#!/usr/bin/env bash
# Installs the Debian 12 packages granwave needs (only those missing), configures and
# builds. Used by main.sh and test.sh; safe to run again (incremental).
#   setup.sh            the program, the tests and the benchmarks, with what they need
#   setup.sh --program  only the program (`granwave`) and what building and running it needs
#   GRANWAVE_BUILD_DIR  build tree (default: build)
#   GRANWAVE_SANITIZE   1 = address + undefined-behaviour sanitizer build (with clang 14)
#   GRANWAVE_BUILD_BENCH 0 = do not build the benchmark programs (default 1)
set -euo pipefail
cd "$(dirname "$0")/.."
program_only=0
[ "${1:-}" = "--program" ] && program_only=1

# The program: compilers, the libraries it links, OpenMPI (studies over MPI ranks), git (the
# source commit in every output's provenance) and what the study report is drawn with.
packages=(build-essential cmake ninja-build pkg-config git
          libeigen3-dev libsundials-dev libfftw3-dev libhdf5-dev
          libcli11-dev libtomlplusplus-dev libfmt-dev libopenmpi-dev openmpi-bin
          python3-matplotlib python3-h5py python3-numpy)
# The tests and benchmarks: GoogleTest, Google Benchmark, the format and include checks,
# headless Chromium for the reports, h5ls, the field's readers that open granwave's files
# (docs/commands.md, "Viewers") and YAML for the citation file's check.
test_packages=(libgtest-dev libgmock-dev libbenchmark-dev hdf5-tools chromium
               clang-format python3-clang-14 clang-14 libclang-rt-14-dev
               paraview python3-paraview python3-mdanalysis python3-ase python3-gsd python3-yaml)
((program_only)) || packages+=("${test_packages[@]}")
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
options=(-DCMAKE_BUILD_TYPE=Release
         -DGRANWAVE_SANITIZE="$([ "$sanitize" = 1 ] && echo ON || echo OFF)")
if ((program_only)); then
  # A build tree made for the tests keeps its tests (only the program is rebuilt); a new one
  # configures without them, so that GoogleTest and Google Benchmark need not be installed.
  [ -f "$build/CMakeCache.txt" ] || options+=(-DGRANWAVE_BUILD_TESTS=OFF -DGRANWAVE_BUILD_BENCH=OFF)
else
  options+=(-DGRANWAVE_BUILD_TESTS=ON
            -DGRANWAVE_BUILD_BENCH="$([ "$sanitize" = 1 ] || [ "${GRANWAVE_BUILD_BENCH:-1}" = 0 ] && echo OFF || echo ON)")
fi
if [ "$sanitize" = 1 ]; then
  # The sanitizer build uses clang 14: it compiles the instrumented code in about a third of
  # GCC's time on the heaviest files (docs/performance.md, "CI"), and is a second compiler's
  # warnings. A tree configured with another compiler is configured afresh.
  if [ -f "$build/CMakeCache.txt" ] &&
     ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$' "$build/CMakeCache.txt"; then
    rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
  fi
  options+=(-DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14)
fi
# A new tree is generated for Ninja, which starts a file as soon as its own inputs are ready
# (Make waits for every library a target links before compiling the target's files, and
# leaves a core idle at each such step); a tree made earlier keeps its generator.
[ -f "$build/CMakeCache.txt" ] || options+=(-G Ninja)
cmake -S . -B "$build" "${options[@]}" >&2
if ((program_only)); then
  cmake --build "$build" -j"$(nproc)" --target granwave >&2
else
  cmake --build "$build" -j"$(nproc)" >&2
fi
