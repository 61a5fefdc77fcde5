#!/usr/bin/env bash
# clang-format --dry-run --Werror (the repository's .clang-format, Debian's clang-format) on the
# C++ files changed since a base commit, so formatting is checked where code changes.
# The base, in this order:
#   1. $GRANWAVE_FORMAT_BASE, if set (a commit, branch or tag);
#   2. the merge base with origin/main, if that is not HEAD itself (a branch being merged);
#   3. HEAD^ (on main itself: the last commit's changes);
#   4. none: every C++ file (a repository of one commit).
# Uncommitted changes count too (the diff is taken against the working tree).
set -euo pipefail
cd "$(dirname "$0")/.."
base="${GRANWAVE_FORMAT_BASE:-}"
if [ -z "$base" ] && git rev-parse -q --verify origin/main > /dev/null; then
  merge_base=$(git merge-base HEAD origin/main)
  [ "$merge_base" = "$(git rev-parse HEAD)" ] || base=$merge_base
fi
if [ -z "$base" ] && git rev-parse -q --verify HEAD^ > /dev/null; then
  base=HEAD^
fi
if [ -n "$base" ]; then
  mapfile -t files < <(git diff --name-only --diff-filter=ACMR "$base" -- '*.cpp' '*.hpp' '*.h')
  what="changed since $(git rev-parse --short "$base")"
else
  mapfile -t files < <(git ls-files -- '*.cpp' '*.hpp' '*.h')
  what="all"
fi
echo "check_format: $(clang-format --version | head -n 1); ${#files[@]} C++ file(s), $what"
((${#files[@]} == 0)) || clang-format --dry-run --Werror "${files[@]}"
