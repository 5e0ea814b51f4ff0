#!/usr/bin/env bash
# run.sh BUILD_DIR SECONDS: runs the fuzz targets of BUILD_DIR at once, each for SECONDS, seeded from the
# tests' own inputs (the folders below; seeds/units holds values as users type them), under ASan
# and UBSan. Prints the executions of each; fails on any crash,
# leak, sanitizer report, timeout (10 s per input) or memory over 2 GiB, and keeps the input
# that caused it in BUILD_DIR/fuzz-artifacts for a regression case.
set -u
build=$1 seconds=$2
here=$(cd "$(dirname "$0")" && pwd)
artifacts=$build/fuzz-artifacts
mkdir -p "$artifacts"
failed=0
tests=$(dirname "$here")
seeds_units=("$here/seeds/units")
seeds_design=("$tests/cli" "$tests/robustness/inputs" "$tests/golden/expected")
seeds_batch=("$tests/cli" "$tests/robustness/inputs")
seeds_table=("$(dirname "$tests")/data" "$tests/robustness/inputs")
seeds_part=("$here/seeds/part" "$tests/robustness/inputs")
# The five targets run at once, each in the background, and are awaited in turn.
run_target() {
  local target=$1 corpus seeds max_len=4096 log status
  corpus=$(mktemp -d)
  seeds="seeds_$target[@]"
  [ "$target" = table ] || [ "$target" = part ] && max_len=16384
  log=$artifacts/$target.log
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "$build/tests/fuzz/fuzz-$target" "$corpus" "${!seeds}" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=$max_len -print_final_stats=1 \
    -artifact_prefix="$artifacts/$target-" > "$log" 2>&1
  status=$?
  rm -rf "$corpus"
  return $status
}
declare -A pid
for target in units design batch table part; do
  run_target "$target" &
  pid[$target]=$!
done
for target in units design batch table part; do
  log=$artifacts/$target.log
  if wait "${pid[$target]}"; then
    runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$')
    echo "fuzz-$target: ${runs:-?} executions in $seconds s, no crash, leak or hang"
  else
    failed=$((failed + 1))
    echo "fuzz-$target: FAILED; the input is in $artifacts, the log in $log"
    grep -E 'ERROR|SUMMARY|runtime error|terminate' "$log" | head -5
  fi
done
echo "fuzz targets: $((5 - failed)) of 5 ran clean"
[ "$failed" -eq 0 ]
