#!/bin/bash
# Studies sharing one run cache at once (docs/studies.md, "Runs, reuse and resume"): two
# studies with the default settings, then four with --checkpoint-every 0, all started together
# on one cache, each finish; their results.h5 equal each other and those of the same study made
# alone (REFERENCE, the tiny-study fixture's results.h5 beside its runs/) in every number but the measured cost
# of the runs (wall and CPU seconds of whoever made them), failure reasons and collapse times
# included; the cache holds one record per run and no temporaries.
# Usage: shared_cache.sh GRANWAVE STUDY.toml REFERENCE_RESULTS.h5 WORKDIR
set -u
granwave=$1 study=$2 reference=$3 work=$4
fail() { echo "shared_cache: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
[ -f "$reference" ] || fail "no reference $reference (the tiny-study fixture makes it)"
records=$(ls "$(dirname "$reference")/runs" | grep -c '\.done$')

# The report is left out: it says which runs each study found made ("ok (reused)").
same_results() {
  h5diff --exclude-path /report "$@" > "$work/diff.txt" 2>&1
}
same_as_alone() {
  same_results --exclude-path /runs/wall_seconds --exclude-path /runs/cpu_seconds \
    --exclude-path /results/wave_fronts/cost "$reference" "$1"
}

together() {
  local name=$1 n=$2
  shift 2
  local pids=() i
  for i in $(seq 1 "$n"); do
    "$granwave" study "$study" -o "$work/$name-$i" --cache "$work/$name-cache" -q -j 1 \
      --no-report "$@" > /dev/null 2> "$work/$name-$i.err" &
    pids+=($!)
  done
  for i in $(seq 1 "$n"); do
    wait "${pids[$((i - 1))]}" || fail "$name: study $i of $n failed: $(cat "$work/$name-$i.err")"
    same_as_alone "$work/$name-$i/results.h5" ||
      fail "$name: study $i of $n differs from the study made alone: $(head -20 "$work/diff.txt")"
    same_results "$work/$name-1/results.h5" "$work/$name-$i/results.h5" ||
      fail "$name: study $i of $n differs from study 1: $(head -20 "$work/diff.txt")"
  done
  local done_now
  done_now=$(ls "$work/$name-cache" | grep -c '\.done$')
  [ "$done_now" -eq "$records" ] || fail "$name: $done_now records, expected $records"
  ! ls "$work/$name-cache" | grep -q '\.tmp' ||
    fail "$name: temporaries left: $(ls "$work/$name-cache" | grep '\.tmp')"
}

together two 2
together four 4 --checkpoint-every 0
rm -rf "$work"
echo "shared_cache: ok (2 and 4 studies on one cache; $records runs each recorded once)"
