#!/bin/sh
# Install and move: `cmake --install` into a temporary prefix, the prefix moved elsewhere, and
# a tiny wave-fronts study run from the moved copy while the source and build trees are hidden
# (a private mount namespace binds an empty directory over each; the running ctest sees none
# of it). The program must find its report renderer, LAMMPS deck, scenes and source commit
# relative to itself (share/granwave; docs/commands.md, "Install"), and name no path of the
# trees it was built in (source file names recorded by a sanitizer build aside).
# Usage: install_and_move.sh SOURCE_DIR BUILD_DIR
set -eu
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/granwave-install-XXXXXX")
fail() {
  echo "install_and_move: $*" >&2
  exit 1
}
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" || fail "cmake --install failed"
mv "$work/prefix" "$work/moved"
prefix=$work/moved
# Sanitizer builds record source file names for their reports (GCC ignores -ffile-prefix-map
# there); those are labels, not files the program opens, so only other paths count.
for tree in "$src" "$build"; do
  named=$(strings "$prefix/bin/granwave" | grep -F "$tree" | grep -v -E '\.(cpp|hpp|h)$' | head -n 1)
  [ -z "$named" ] || fail "the installed program names $named"
done
[ -s "$prefix/share/doc/granwave/LICENSE" ] && [ -s "$prefix/share/doc/granwave/CITATION.cff" ] ||
  fail "no LICENSE or CITATION.cff in share/doc/granwave"
# The tiny study copied out of the prefix, naming the scenes as the shipped study files do
# (../scenes/paper-*.toml, which is not beside the copy): they are found among the installed
# ones (docs/studies.md). LAMMPS "auto" with a program that does not exist: the study checks
# the installed deck and leaves LAMMPS out.
mkdir -p "$work/copied"
study=$work/copied/tiny-wave-fronts.toml
sed -e 's|\.\./\.\./\.\./scenes/|../scenes/|' \
    -e 's|^run = "no".*|run = "auto"\nexecutable = "granwave-test-no-such-lammps"|' \
    "$src/tests/studies/data/tiny-wave-fronts.toml" > "$study"
cd "$work"
run="'$prefix/bin/granwave' study '$study' -o '$work/out' -q -j 2"
if unshare --mount true 2> /dev/null; then
  mkdir -p "$work/empty"
  unshare --mount sh -c "mount --bind '$work/empty' '$build' && mount --bind '$work/empty' \
'$src' && exec $run" > "$work/study.log" 2>&1 || fail "the study failed: $(tail -n 3 "$work/study.log")"
  hidden="source and build trees hidden"
else
  sh -c "exec $run" > "$work/study.log" 2>&1 || fail "the study failed: $(tail -n 3 "$work/study.log")"
  hidden="trees not hidden: unshare --mount is not permitted here"
fi
[ -s "$work/out/results.h5" ] || fail "no results.h5"
[ -s "$work/out/report.html" ] || fail "no report.html (renderer not found?)"
/usr/bin/python3 - "$work/out/results.h5" "$build/share/granwave/source-commit" << 'PY' || fail "the results do not name the source commit"
import sys, h5py
recorded = open(sys.argv[2]).read().split()
with h5py.File(sys.argv[1], "r") as f:
    commit = f.attrs["source_commit"]
    commit = commit.decode() if isinstance(commit, bytes) else str(commit)
sys.exit(0 if commit.split()[0] == recorded[0] else 1)
PY
echo "install_and_move: ok ($hidden)"
rm -rf "$work"
