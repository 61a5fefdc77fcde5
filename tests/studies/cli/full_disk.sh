#!/bin/bash
# A full disk: every command that writes HDF5 (simulate, simulate --fields, hydro, fields)
# exits 74 with one line naming the cause ("No space left on device"), a checkpointed run
# exits 74 or, when its checkpoint is the file that could not be written, 75 with the same
# cause (docs/commands.md), crashes
# neither in the error path nor at exit (an HDF5 file whose flush failed must be closed before
# the library shuts down), and leaves nothing in the full directory. The full file system is a
# small tmpfs this test mounts, so it needs root (or CAP_SYS_ADMIN); skipped (77) otherwise.
# Usage: full_disk.sh GRANWAVE SCENE_DIR WORKDIR
set -u
granwave=$1 scenes=$2 work=$3
fail() { echo "full_disk: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/full" || fail "cannot make $work"
if [ "$(id -u)" -ne 0 ] || ! mount -t tmpfs -o size=48k granwave-full "$work/full" 2>/dev/null; then
  echo "full_disk: skipped: mounting a small tmpfs needs root (uid $(id -u))"
  rm -rf "$work"
  exit 77
fi
trap 'umount "$work/full" 2>/dev/null' EXIT
dry=$scenes/paper-dry.toml

# A run file outside the full disk, for `fields`.
"$granwave" simulate "$dry" --set run.duration=2 -q -o "$work/run.h5" > /dev/null ||
  fail "cannot make the input run"

expect_full() {
  local name=$1 expected=$2
  shift 2
  local code=0
  "$@" > "$work/$name.out" 2> "$work/$name.err" || code=$?
  [[ " $expected " == *" $code "* ]] ||
    fail "$name: exit $code, expected $expected: $(head -c 600 "$work/$name.err")"
  grep -q "No space left on device" "$work/$name.err" ||
    fail "$name: the cause is not named: $(cat "$work/$name.err")"
  [ "$(wc -l < "$work/$name.err")" -eq 1 ] || fail "$name: more than one line: $(cat "$work/$name.err")"
  [ -z "$(ls -A "$work/full")" ] || fail "$name: left $(ls -A "$work/full" | tr '\n' ' ')"
}

expect_full simulate 74 "$granwave" simulate "$dry" --set run.duration=1 -q -o "$work/full/run.h5"
# Which file meets the full disk first depends on the sizes written: the run file (74) or the
# checkpoint (75).
expect_full simulate_checkpointed "74 75" "$granwave" simulate "$dry" --set run.duration=1 -q \
  -o "$work/full/run.h5" --checkpoint-every 0.05
expect_full simulate_fields 74 "$granwave" simulate "$dry" --set run.duration=2 -q \
  --no-output --fields "$work/full/fields.h5"
expect_full hydro 74 "$granwave" hydro "$dry" -q -o "$work/full/hydro.h5"
expect_full fields 74 "$granwave" fields "$work/run.h5" -o "$work/full/fields.h5"
umount "$work/full" && rm -rf "$work"
echo "full_disk: ok (simulate, simulate --checkpoint-every, simulate --fields, hydro, fields)"
