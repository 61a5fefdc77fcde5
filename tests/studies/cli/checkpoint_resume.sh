#!/bin/sh
# A particle run killed with SIGKILL and run again with the same command continues from its
# last checkpoint and ends bit-identical to the same command never stopped: the run file
# (trajectories, observables, the pair-impact histogram, scene, provenance) and the fields
# file. Checkpointing itself changes nothing but the command line recorded in the provenance. Also: a checkpoint of
# another scene is refused by name, a damaged one too (exit 75, kept), and nothing is left
# behind.
# Usage: checkpoint_resume.sh GRANWAVE SCENE.toml WORKDIR
set -eu
granwave=$1
scene=$2
work=$3
identical="$(dirname "$0")/../../tools/h5_identical.py"
rm -rf "$work"
mkdir -p "$work/plain" "$work/whole" "$work/killed"
fail() { echo "checkpoint_resume: $*" >&2; exit 1; }

# The same relative command line in both directories: the provenance must match too.
run() { "$granwave" simulate "$scene" --set run.duration=4 -o run.h5 --fields run.fields.h5 -q "$@"; }

(cd "$work/plain" && run > summary.txt)
(cd "$work/whole" && run --checkpoint-every 0.2 > summary.txt)
"$identical" "$work/plain/run.h5" "$work/whole/run.h5" --exclude /parameters/provenance ||
  fail "checkpoints changed the run"
# The pair-impact histogram is in the run file, so the comparisons below cover it too.
impacts=$(h5dump -a /granwave/pair_impacts/total "$work/whole/run.h5" | sed -n 's/^ *(0): *//p')
[ "${impacts:-0}" -gt 0 ] || fail "no pair impacts recorded in run.h5"

cd "$work/killed"
# Not through run(): $! must be granwave itself, not a subshell.
"$granwave" simulate "$scene" --set run.duration=4 -o run.h5 --fields run.fields.h5 -q \
  --checkpoint-every 0.2 > /dev/null &
pid=$!
i=0
until [ -e run.h5.checkpoint ]; do
  sleep 0.02
  i=$((i + 1))
  [ "$i" -lt 3000 ] || fail "no checkpoint within 60 s"
done
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
[ ! -e run.h5 ] || fail "the run finished before it was killed; nothing was tested"

# A checkpoint is continued only by the run it belongs to; refusing it is not the run's result
# (exit 75: a study tries the run again) and leaves the checkpoint alone.
code=0
run --checkpoint-every 0.2 --set drive.gamma=3.5 > /dev/null 2> other.log || code=$?
[ "$code" -eq 75 ] || fail "a checkpoint of another scene: exit $code, not 75"
[ -e run.h5.checkpoint ] || fail "refusing a foreign checkpoint removed it"
grep -q "run.h5.checkpoint: saved by a run of another scene" other.log ||
  fail "unclear error for a foreign checkpoint: $(cat other.log)"

run --checkpoint-every 0.2 > summary.txt 2> resume.log
grep -q "continuing from run.h5.checkpoint at t = " resume.log ||
  fail "the run did not continue from its checkpoint: $(cat resume.log)"
"$identical" ../whole/run.h5 run.h5 || fail "the continued run file differs"
"$identical" ../whole/run.fields.h5 run.fields.h5 || fail "the continued fields file differs"
# The summary differs only in its wall-clock lines (time, rates, checkpoints written).
grep -v -e "^wall time" -e "^events" -e "^checkpoints" summary.txt > a.txt
grep -v -e "^wall time" -e "^events" -e "^checkpoints" ../whole/summary.txt > b.txt
diff a.txt b.txt > /dev/null || fail "the summaries differ: $(diff a.txt b.txt)"
leftovers=$(ls | grep -e checkpoint -e '\.tmp-' -e '\.lock' || true)
[ -z "$leftovers" ] || fail "left behind after the run: $leftovers"

# A damaged checkpoint: one line naming it, no output.
echo "not HDF5" > run.h5.checkpoint
rm -f run.h5 run.fields.h5
code=0
run --checkpoint-every 0.2 > /dev/null 2> damaged.log || code=$?
[ "$code" -eq 75 ] || fail "a damaged checkpoint: exit $code, not 75"
[ -e run.h5.checkpoint ] || fail "a damaged checkpoint was removed"
grep -q "run.h5.checkpoint" damaged.log || fail "the error does not name the checkpoint: $(cat damaged.log)"
[ "$(wc -l < damaged.log)" -eq 1 ] || fail "more than one error line: $(cat damaged.log)"
[ ! -e run.h5 ] || fail "a damaged checkpoint left a run file"
echo "checkpoint_resume: ok (continued from $(sed -n 's/.*at t = \([0-9.]*\) s.*/\1/p' resume.log) s)"
rm -rf "$work"  # passed: nothing left behind (a failure keeps WORKDIR for a look)
