#!/bin/sh
# The same study under `mpirun -n 2` (rank 0 coordinating and running, rank 1 working) gives
# the same results as the serial run (run costs aside).
# Usage: mpi_matches_serial.sh MPIRUN GRANWAVE STUDY.toml WORKDIR
set -eu
mpirun=$1
granwave=$2
study=$3
work=$4
rm -rf "$work"
mkdir -p "$work"
"$granwave" study "$study" -o "$work/serial" -q -j 1 --no-report
"$mpirun" --allow-run-as-root --oversubscribe -n 2 "$granwave" study "$study" \
  -o "$work/mpi" -q --no-report
# Bit for bit (h5diff would pass datasets of different shapes as "not comparable").
"$(dirname "$0")/../../tools/h5_identical.py" "$work/serial/results.h5" "$work/mpi/results.h5" \
  --only /results --exclude /results/wave_fronts/cost
echo "mpi_matches_serial: ok"
rm -rf "$work"  # passed: nothing left behind (a failure keeps WORKDIR for a look)
