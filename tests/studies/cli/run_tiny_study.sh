#!/bin/sh
# Runs a study afresh (OUTDIR emptied first, so the runs and the report are made by this
# build): the set-up of the tiny-study fixtures of tests/studies/CMakeLists.txt, whose tests
# then check OUTDIR/report.html and OUTDIR/results.h5.
# Usage: run_tiny_study.sh GRANWAVE STUDY.toml OUTDIR
set -eu
if [ "$#" -ne 3 ]; then
  echo "usage: $0 GRANWAVE STUDY.toml OUTDIR" >&2
  exit 2
fi
rm -rf "$3"
exec "$1" study "$2" -o "$3" -q -j 2
