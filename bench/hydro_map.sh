#!/usr/bin/env bash
# The map of docs/hydro.md ("Where it holds: the map") beyond the stability grid: deep and wide
# layers, the wet law's extremes, both closure sets, grids of 100-800 cells, rtol 1e-3 to 1e-6.
# Usage: bench/hydro_map.sh GRANWAVE SCENE_DIR OUT_DIR  (one line per case on stdout)
set -u
granwave=$1 scenes=$2 out=$3
mkdir -p "$out"
run() {  # law, label, overrides...
  local law=$1 label=$2
  shift 2
  local sets=() o
  for o in "$@"; do sets+=(--set "$o"); done
  local log="$out/$law-${label// /_}.txt"
  "$granwave" hydro -q "$scenes/paper-$law.toml" -o "$out/$law-${label// /_}.h5" "${sets[@]}" \
    >"$log" 2>&1
  local code=$?
  local period regime cost
  period=$(grep -o "centre-of-mass period .*" "$log" | head -1)
  regime=$(grep "^layer" "$log" | sed 's/^layer *//')
  cost=$(grep -o "cost .* CPU-s ([0-9.]* per cycle)" "$log" | sed 's/^cost *//')
  echo "$law | $label | exit $code | ${period:-$(tail -1 "$log")} | ${regime:-} | ${cost:-}"
}
for law in dry wet; do
  for n in 150 450 600; do
    for g in 2 4; do run $law "N=$n Gamma=$g" particles.count=$n drive.gamma=$g; done
  done
  run $law "N=1200 60 d high" particles.count=1200 container.height=0.12
  run $law "N=1200 60 d wide" particles.count=1200 container.width=0.12
  for cells in 200 400 800; do run $law "$cells cells" hydro.cells=$cells; done
  for rtol in 1e-3 1e-5 1e-6; do run $law "rtol $rtol" hydro.rtol=$rtol; done
  for f in 10 20; do
    for g in 2 4 6 8; do
      run $law "GD f=$f Gamma=$g" 'hydro.transport="garzo-dufty"' drive.frequency=$f drive.gamma=$g
      run $law "rough f=$f Gamma=$g" 'hydro.particles="rough"' drive.frequency=$f drive.gamma=$g
    done
  done
done
for stc in 20 80; do
  for einf in 0.8 0.95; do
    run wet "St_c=$stc e_inf=$einf" contact.stokes_critical=$stc contact.e_inf=$einf
  done
done
