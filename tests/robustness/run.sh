#!/usr/bin/env bash
# run.sh CALC VERIFY [K/N]: runs every case of corpus.tsv (with K/N, the K-th of every N cases, so
# that N tests share the corpus and run side by side) and checks it. A case passes when:
#  - it exits with its expected code (never a signal, never the time limit);
#  - its output (stdout and stderr together) matches its regular expression;
#  - no output holds nan or inf outside a quoted echo of the user's own text.
# Prints one line per failure and a count of crashes, hangs and nan/inf; exits 1 on any failure.
set -u
CALC=$(realpath "$1") VERIFY=$(realpath "$2") shard=${3:-1/1}
shard_k=${shard%/*} shard_n=${shard#*/}
IN=$(cd "$(dirname "$0")" && pwd)/inputs
export CALC VERIFY IN
passed=0 failed=0 crashes=0 hangs=0 nonfinite=0
index=0
while IFS=$'\t' read -r name code regex command; do
  case "$name" in '#'*|'') continue ;; esac
  index=$((index + 1))
  [ $(((index - 1) % shard_n + 1)) -eq "$shard_k" ] || continue
  work=$(mktemp -d)
  output=$(cd "$work" && timeout 60 bash -c "$command" 2>&1)
  status=$?
  rm -rf "$work"
  problem=""
  if [ "$status" -eq 124 ]; then hangs=$((hangs + 1)); problem="did not finish within 60 s"
  elif [ "$status" -ge 128 ]; then crashes=$((crashes + 1)); problem="ended by signal $((status - 128))"
  elif [ "$status" -ne "$code" ]; then problem="exit $status, expected $code"
  elif ! printf '%s\n' "$output" | grep -Eq -- "$regex"; then problem="output does not match: $regex"
  fi
  # Quoted text and CLI11's list of unexpected arguments echo the user's input; computed numbers are never quoted.
  if printf '%s\n' "$output" | sed -E "s/'[^']*'//g; s/\"[^\"]*\"//g; s/(was|were) not expected: .*//" |
       grep -Eiq -- '(^|[^a-z])(-?nan|-?inf(inity)?)([^a-z]|$)'; then
    nonfinite=$((nonfinite + 1)); problem="${problem:+$problem; }prints nan or inf"
  fi
  if [ -z "$problem" ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    printf 'FAILED %s: %s\n  %s\n  %s\n' "$name" "$problem" "$command" "$(printf '%s' "$output" | head -c 400)"
  fi
done < "$(dirname "$0")/corpus.tsv"
echo "robustness corpus ($shard): $((passed + failed)) cases; crashes $crashes, hangs $hangs, nan/inf $nonfinite"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
