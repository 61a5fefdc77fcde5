#!/bin/sh
# The XDMF sidecar of a 2D hydro run file loads in ParaView (pvpython, Debian's paraview and
# python3-paraview): a short 2D run of the paper's dry scene (periodic in x, 20 cells per
# column, the shortest run: 8 cycles), then fields_in_paraview.py (the fields file's check, the
# same names: cell arrays area_fraction, temperature, velocity; /xdmf/pNNNN groups) reads the
# arrays through ParaView and checks one value against the HDF5 file. Exit 77 (skipped) if
# pvpython is not installed.
# Usage: hydro2d_in_paraview.sh GRANWAVE SCENE.toml
set -eu
if ! command -v pvpython > /dev/null; then
  echo "hydro2d_in_paraview: skipped: pvpython is not installed (apt-get install paraview python3-paraview)"
  exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/granwave-paraview-XXXXXX")
"$1" hydro "$2" --set hydro.dimensions=2 --set hydro.columns=4 --set hydro.cells=20 --set container.periodic_x=true \
  --set run.duration=0.3 -o "$work/hydro.h5" -q > /dev/null
test -f "$work/hydro.xdmf"
pvpython "$(dirname "$0")/fields_in_paraview.py" "$work/hydro.xdmf" "$work/hydro.h5" \
  > "$work/paraview.log" 2>&1 || {
  grep "fields_in_paraview" "$work/paraview.log" >&2 || tail -n 5 "$work/paraview.log" >&2
  exit 1
}
grep "fields_in_paraview" "$work/paraview.log"
rm -rf "$work"
