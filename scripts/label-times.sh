#!/usr/bin/env bash
# label-times.sh [BUILD...]: for each tier (CTest label) of the suite, its entries (ctest -N) and
# the sum of their wall times in the last run_ctest output of each BUILD (scripts/stages.sh keeps
# it in BUILD/ctest-output.log), as the Markdown rows of docs/testing.md's table of labels.
# Default: build (the Release tiers) and build-sanitize (the sanitizer pass).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/stages.sh
builds=("$@")
[ ${#builds[@]} -gt 0 ] || builds=(build build-sanitize)
labels=(unit heavy cli robustness golden docs package python physics external web scale quick slow)
printf '| label |'; for b in "${builds[@]}"; do printf ' entries in %s | seconds in %s |' "$b" "$b"; done; echo
printf '|---|'; for _ in "${builds[@]}"; do printf -- '---|---|'; done; echo
for label in "${labels[@]}"; do
  printf '| `%s` |' "$label"
  for b in "${builds[@]}"; do
    if [ ! -f "$b/CTestTestfile.cmake" ]; then printf ' | |'; continue; fi
    names=$(ctest --test-dir "$b" -N -L "^$label\$" | sed -nE 's/^ *Test +#[0-9]+: (.*)$/\1/p')
    entries=$(printf '%s' "$names" | grep -c . || true)
    seconds=$( { printf '%s\n' "$names" | sed 's/^/N\t/'; [ -f "$b/ctest-output.log" ] &&
      test_seconds "$b/ctest-output.log" | sed 's/^/T\t/'; } |
      awk -F'\t' '$1 == "N" { want[$2] = 1 } $1 == "T" && ($3 in want) { s += $2; n++ } END { printf n ? "%.0f" : "", s }')
    printf ' %s | %s |' "$entries" "${seconds:-not run}"
  done
  echo
done
