#!/bin/sh
# The XDMF sidecar of a fields file loads in ParaView (pvpython, Debian's paraview and
# python3-paraview): a short run of the paper's dry scene with live fields, then
# fields_in_paraview.py reads the arrays through ParaView and checks one value against the
# HDF5 file. Exit 77 (skipped) if pvpython is not installed.
# Usage: fields_in_paraview.sh GRANWAVE SCENE.toml
set -eu
if ! command -v pvpython > /dev/null; then
  echo "fields_in_paraview: skipped: pvpython is not installed (apt-get install paraview python3-paraview)"
  exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/granwave-paraview-XXXXXX")
"$1" simulate "$2" --set run.duration=2 -o "$work/run.h5" --fields "$work/fields.h5" -q > /dev/null
# ParaView 5.11 joins a sidecar's relative HDF5 path to the XDMF path as given: pass a path
# with its directory (as the GUI's file dialog does).
pvpython "$(dirname "$0")/fields_in_paraview.py" "$work/fields.xdmf" "$work/fields.h5" \
  > "$work/paraview.log" 2>&1 || {
  grep "fields_in_paraview" "$work/paraview.log" >&2 || tail -n 5 "$work/paraview.log" >&2
  exit 1
}
grep "fields_in_paraview" "$work/paraview.log"
rm -rf "$work"
