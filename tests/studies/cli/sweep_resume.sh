#!/bin/sh
# A sweep killed with SIGKILL half way and run again gives the same results as an
# uninterrupted one (REFERENCE: the tiny-study fixture's output directory, made without
# checkpoints): the same /results numbers (run costs aside) and bit-identical particle runs;
# no run of the killed study survives it (its children get SIGTERM, checkpoint and stop), and
# the particle run it was making continues from its checkpoint.
# Usage: sweep_resume.sh GRANWAVE STUDY.toml REFERENCE WORKDIR
set -eu
granwave=$1
study=$2
reference=$3
work=$4
identical="$(dirname "$0")/../../tools/h5_identical.py"
[ -f "$reference/results.h5" ] || {
  echo "sweep_resume: no $reference/results.h5 (the tiny-study fixture makes it)" >&2
  exit 1
}
rm -rf "$work"
mkdir -p "$work"

# A particle run still going with a checkpoint (its record not yet written): the run whose
# checkpoint the resumed study must continue from.
unfinished_checkpoint() {
  for c in "$work"/killed/runs/particles-*.h5.checkpoint; do
    [ -e "$c" ] || continue
    [ -e "${c%.h5.checkpoint}.done" ] || return 0
  done
  return 1
}
# Kill once some but not all runs are recorded and a particle run has saved a checkpoint. Runs
# of a small sweep last a second or less, so the run can finish between the look and the kill:
# then the killed study is started again (it resumes) and killed again, up to five times.
attempt=0
while :; do
  "$granwave" study "$study" -o "$work/killed" -q -j 2 --no-report --checkpoint-every 0.2 &
  pid=$!
  i=0
  while [ "$(ls "$work/killed/runs" 2>/dev/null | grep -c '\.done$')" -lt 4 ] ||
    ! unfinished_checkpoint; do
    kill -0 "$pid" 2>/dev/null || {
      echo "sweep_resume: the study ended before a run could be cut half way" >&2
      exit 1
    }
    sleep 0.05
    i=$((i + 1))
    [ "$i" -lt 6000 ] || {
      kill -9 "$pid" 2>/dev/null || true
      echo "sweep_resume: no run checkpointed within 300 s" >&2
      exit 1
    }
  done
  kill -9 "$pid"
  wait "$pid" 2>/dev/null || true
  if [ -e "$work/killed/results.h5" ]; then
    echo "sweep_resume: a killed study left results.h5" >&2
    exit 1
  fi
  # Its runs get SIGTERM, checkpoint and stop; on a loaded machine that can take seconds, and
  # the finished runs are counted only once none is left.
  j=0
  while pgrep -f "$work/killed/runs" >/dev/null; do
    sleep 0.1
    j=$((j + 1))
    [ "$j" -lt 600 ] || {
      echo "sweep_resume: runs of the killed study are still running 60 s after the kill" >&2
      exit 1
    }
  done
  unfinished_checkpoint && break
  attempt=$((attempt + 1))
  [ "$attempt" -lt 5 ] || { echo "sweep_resume: every checkpointed run finished before the kill" >&2; exit 1; }
done
done_before=$(ls "$work/killed/runs" | grep -c '\.done$')
"$granwave" study "$study" -o "$work/killed" -j 2 --no-report --checkpoint-every 0.2 2> "$work/resume.log" >/dev/null
grep -Eq "(^|[^0-9])$done_before reused" "$work/resume.log" || {
  echo "sweep_resume: the resumed study did not reuse the $done_before finished runs:" >&2
  head -1 "$work/resume.log" >&2
  exit 1
}
# Same numbers; the cost chart's CPU times are measurements of this machine, not results.
"$identical" "$reference/results.h5" "$work/killed/results.h5" --only /results \
  --exclude /results/wave_fronts/cost
grep -l "continuing from" "$work"/killed/runs/particles-*.log > /dev/null 2>&1 || {
  echo "sweep_resume: no particle run continued from a checkpoint" >&2
  exit 1
}
# Particle runs: bit-identical trajectories, observables and fields; only the provenance
# differs (it names the output directory of each study).
for f in "$reference"/runs/particles-*.h5; do
  g="$work/killed/runs/$(basename "$f")"
  case "$f" in
    *.fields.h5) "$identical" "$f" "$g" --exclude /parameters ;;
    *) "$identical" "$f" "$g" --only /particles --only /observables ;;
  esac || {
    echo "sweep_resume: $(basename "$f") differs after the resume" >&2
    exit 1
  }
done
leftovers=$(ls "$work/killed/runs" | grep -e checkpoint -e '\.tmp-' -e '\.lock$' || true)
[ -z "$leftovers" ] || { echo "sweep_resume: left in the cache: $leftovers" >&2; exit 1; }
echo "sweep_resume: ok ($done_before runs kept across SIGKILL, $attempt extra kill(s); continued:" \
  "$(grep -h "continuing from" "$work"/killed/runs/particles-*.log | sed 's/.* at t = //' | tr '\n' ' '))"
rm -rf "$work"  # passed: nothing left behind (a failure keeps WORKDIR for a look)
