#!/bin/sh
# The short wet run (4 s = 40 cycles) that the `granwave fields` tests read (FieldsCliTest.cpp),
# made once per test run as a ctest fixture instead of once per test process: each test copies
# it into a directory of its own.
# Usage: fields_cli_run.sh GRANWAVE DIR
set -eu
if [ "$#" -ne 2 ]; then
  echo "usage: $0 GRANWAVE DIR" >&2
  exit 2
fi
rm -rf "$2"
mkdir -p "$2"
cd "$2"
printf '[contact]\nrestitution = "wet"\n[run]\nduration = 4\n' > wet.toml
"$1" simulate -q wet.toml -o wet.h5 > simulate.txt
