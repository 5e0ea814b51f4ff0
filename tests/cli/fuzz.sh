#!/usr/bin/env bash
# fuzz.sh CALC VERIFY [RUNS]: runs both programs with random, mostly malformed command lines
# and JSON (fixed seed), and complete and shot with random ranges, spreads, air, series and
# pictures; none may leave a temporary output behind. Passes when every run exits with one of the program's documented
# codes (never a signal or an unknown code) and no output holds nan or inf outside the quoted
# echo of the user's own input.
set -u
calc=$(realpath "$1")
verify=$(realpath "$2")
runs=${3:-300}
RANDOM=2026
words=(150m 3.1t 40kJ -5kg 0 1e400 nan inf 2/3 1/0 abc 12xyz 30deg 95 "" " " 1e-300 0.5 7 -0 1e6t 3..1m 4.13 50kg)
calc_flags=(--R --T --L1 --L2 --L4 --D --M --m --mb --Lb --l --theta --F --branch --beta2 --g --scale --format --foo)
verify_flags=(--L1 --L2 --L3 --F --L4 --M --m --mb --theta --g --R --T --tol --target-level --quality --n --stepper --rtol --format --fit)
# The surface added since: complete, ranges and spreads, air, series and pictures, their numbers.
spread_words=(2t..3t 3..4t 4t..3t 9m±1m 9m+-1m "3t±1e308t" 1e308t..1e309t 50kg..60 -1m..1m 0..0 1e-320m..1m 2/3..1 150m 50kg 5t 9.5m 40 -10 1e-12s 1e308s 5ms 1e-300 1e5m/s stone iron Re 1 0 abc)
complete_flags=(--Lb --L1 --L2 --H --L4 --M --m --mb --D --l --theta --F --samples --seed --air-density --wind --projectile --cd --quality --rtol --atol --target-level --beta2 --wood-density --g --format)
shot_flags=(--L4 --M --m --mb --theta --psi-i --series-dt --samples --seed --wind --projectile --cd --air-density --target-level --quality --n --rtol --atol --tol --format --digits)
pick() { local -n list=$1; printf '%s' "${list[RANDOM % ${#list[@]}]}"; }
failures=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() {  # check PROGRAM ALLOWED_CODES OUTPUT CODE ARGS...
  local program=$1 allowed=$2 output=$3 code=$4
  shift 4
  if [[ " $allowed " != *" $code "* ]]; then
    echo "fuzz.sh: $program exited $code for: $*" >&2
    failures=$((failures + 1))
  fi
  # Quoted text, and CLI11's list of unexpected arguments, echo the user's own input; numbers
  # the program computed are never quoted.
  if printf '%s\n' "$output" | sed -E "s/'[^']*'//g; s/\"[^\"]*\"//g; s/(was|were) not expected: .*//" | grep -Eiq -- '(^|[^a-z])(-?nan|-?inf(inity)?)([^a-z]|$)'; then
    echo "fuzz.sh: $program printed nan or inf for: $*" >&2
    failures=$((failures + 1))
  fi
}
for ((k = 0; k < runs; k++)); do
  args=()
  for ((n = RANDOM % 4; n >= 0; n--)); do args+=("$(pick calc_flags)" "$(pick words)"); done
  output=$("$calc" "${args[@]}" 2>&1 </dev/null)
  check trebuchet-calc "0 2 3 4 5 6 7 8 9" "$output" $? "${args[@]}"

  args=()
  for ((n = RANDOM % 9; n >= 0; n--)); do args+=("$(pick verify_flags)" "$(pick words)"); done
  output=$(timeout 20 "$verify" "${args[@]}" 2>&1 </dev/null)
  check trebuchet-verify "0 1 2 3" "$output" $? "${args[@]}"

  # complete with random attested values, ranges and spreads, air (few samples: a run is a check, not a study).
  args=(complete --samples 20)
  [ $((RANDOM % 2)) -eq 0 ] && args+=(--Lb 9.5m --m 50kg)  # half the runs from an engine that completes
  [ $((RANDOM % 3)) -eq 0 ] && args+=(--air)
  for ((n = RANDOM % 6; n >= 0; n--)); do args+=("$(pick complete_flags)" "$(pick spread_words)"); done
  output=$(cd "$work" && timeout 60 "$verify" "${args[@]}" 2>&1 </dev/null)
  check trebuchet-verify "0 1 2 3" "$output" $? "${args[@]}"

  # A shot with random spreads, air, series and pictures in a scratch folder.
  args=(shot --L1 6.13m --L2 1.52m --L3 2m --L4 5.1m --M 14.3t --m 100kg --mb 2t --samples 50 --series s.csv)
  [ $((RANDOM % 3)) -eq 0 ] && args+=(--air)
  [ $((RANDOM % 4)) -eq 0 ] && args+=(--plot pictures)
  for ((n = RANDOM % 6; n >= 0; n--)); do args+=("$(pick shot_flags)" "$(pick spread_words)"); done
  output=$(cd "$work" && timeout 60 "$verify" "${args[@]}" 2>&1 </dev/null)
  check trebuchet-verify "0 1 2 3" "$output" $? "${args[@]}"
  # No output is left half-written: nothing under a temporary name.
  if compgen -G "$work/*.part-*" > /dev/null; then
    echo "fuzz.sh: a temporary output was left behind by: ${args[*]}" >&2
    failures=$((failures + 1))
  fi
  rm -rf "${work:?}"/*

  # A JSON design with one value replaced by a random word (or a random JSON type).
  values=('"6.13m"' 6.13 '"x"' null '[1]' '{}' true -1 0 1e308 '"1e400m"')
  json="{\"L1\": $(pick values), \"L2\": 1.08, \"F\": 1, \"L4\": 5.8, \"M\": \"14.3t\", \"m\": 100, \"mb\": 660, \"R\": 450, \"T\": $(pick values)}"
  [ $((RANDOM % 5)) -eq 0 ] && json="${json:0:$((RANDOM % ${#json}))}"  # truncated
  output=$(printf '%s' "$json" | timeout 20 "$verify" - --format json 2>&1)
  check trebuchet-verify "0 1 2 3" "$output" $? "stdin: $json"
done
echo "fuzz.sh: $((5 * runs)) runs, $failures failures"
[ "$failures" -eq 0 ]
