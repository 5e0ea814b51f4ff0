#!/usr/bin/env bash
# fuzz.sh CALC VERIFY [RUNS]: runs both programs with random, mostly malformed command lines
# and JSON (fixed seed). Passes when every run exits with one of the program's documented
# codes (never a signal or an unknown code) and no output holds nan or inf outside the quoted
# echo of the user's own input.
set -u
calc=$1
verify=$2
runs=${3:-300}
RANDOM=2026
words=(150m 3.1t 40kJ -5kg 0 1e400 nan inf 2/3 1/0 abc 12xyz 30deg 95 "" " " 1e-300 0.5 7 -0 1e6t 3..1m 4.13 50kg)
calc_flags=(--R --T --L1 --L2 --L4 --D --M --m --mb --Lb --l --theta --F --branch --beta2 --g --scale --format --foo)
verify_flags=(--L1 --L2 --L3 --F --L4 --M --m --mb --theta --g --R --T --tol --target-level --quality --n --stepper --rtol --format --fit)
pick() { local -n list=$1; printf '%s' "${list[RANDOM % ${#list[@]}]}"; }
failures=0
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

  # A JSON design with one value replaced by a random word (or a random JSON type).
  values=('"6.13m"' 6.13 '"x"' null '[1]' '{}' true -1 0 1e308 '"1e400m"')
  json="{\"L1\": $(pick values), \"L2\": 1.08, \"F\": 1, \"L4\": 5.8, \"M\": \"14.3t\", \"m\": 100, \"mb\": 660, \"R\": 450, \"T\": $(pick values)}"
  [ $((RANDOM % 5)) -eq 0 ] && json="${json:0:$((RANDOM % ${#json}))}"  # truncated
  output=$(printf '%s' "$json" | timeout 20 "$verify" - --format json 2>&1)
  check trebuchet-verify "0 1 2 3" "$output" $? "stdin: $json"
done
echo "fuzz.sh: $((3 * runs)) runs, $failures failures"
[ "$failures" -eq 0 ]
