#!/bin/sh
# The same study under `mpirun -n 2` (rank 0 coordinating and running, rank 1 working) gives
# the same results as without MPI (REFERENCE: the tiny-study fixture's results.h5, made by
# child processes on one machine), run costs aside.
# Usage: mpi_matches_serial.sh MPIRUN GRANWAVE STUDY.toml REFERENCE.h5 WORKDIR
set -eu
mpirun=$1
granwave=$2
study=$3
reference=$4
work=$5
[ -f "$reference" ] || { echo "mpi_matches_serial: no $reference (the tiny-study fixture makes it)" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
"$mpirun" --allow-run-as-root --oversubscribe -n 2 "$granwave" study "$study" \
  -o "$work/mpi" -q --no-report
# Bit for bit (h5diff would pass datasets of different shapes as "not comparable").
"$(dirname "$0")/../../tools/h5_identical.py" "$reference" "$work/mpi/results.h5" \
  --only /results --exclude /results/wave_fronts/cost
echo "mpi_matches_serial: ok"
rm -rf "$work"  # passed: nothing left behind (a failure keeps WORKDIR for a look)
