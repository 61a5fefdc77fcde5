#!/bin/sh
# Runs a study and checks its report in headless Chromium (tests/studies/report/check_report.py).
# Usage: report_in_chromium.sh GRANWAVE STUDY.toml OUTDIR
# OUTDIR is emptied first, so that the runs and the report are made by this build.
set -eu
if [ "$#" -ne 3 ]; then
  echo "usage: $0 GRANWAVE STUDY.toml OUTDIR" >&2
  exit 2
fi
granwave=$1
study=$2
outdir=$3
here=$(dirname "$0")
rm -rf "$outdir"
"$granwave" study "$study" -o "$outdir" -q -j 2
exec /usr/bin/python3 "$here/../report/check_report.py" "$outdir/report.html"
