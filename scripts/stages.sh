# Sourced by scripts/test.sh and scripts/quick.sh: a run in named stages, each timed.
#   stage NAME FUNCTION   runs FUNCTION, then prints its wall time and the CPU time (user and
#                         system) of everything it started
#   run_ctest BUILD ARGS  ctest over BUILD, then its ten slowest tests (wall seconds)
#   stages_table          every stage's times, and the whole run's
#   beside NAME NICE SCRIPT [ARGS]  starts `bash SCRIPT ARGS` in the background at niceness NICE,
#                         in its own process group, its output kept aside
#   joined NAME           waits for it, prints its output, and fails where it failed
# A run that ends before it joins them (a failed stage) stops what still runs beside it.
# The caller sets start=$SECONDS first.
stage_rows=()

# The CPU seconds the shell's finished children have used, user plus system, into
# children_cpu: bash's `times`, run in this shell (in a command substitution it would be a child
# whose own children have used nothing).
children_cpu=0
read_children_cpu() {
  local file
  file=$(mktemp)
  times >"$file"
  children_cpu=$(awk 'NR == 2 { split($1, u, "m"); split($2, s, "m"); sub("s", "", u[2]); sub("s", "", s[2]);
                                printf "%.0f\n", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$file")
  rm -f "$file"
}

stage() {
  local name=$1 run=$2 wall0=$SECONDS cpu0 cpu wall
  echo "== $name (at $((SECONDS - start)) s) =="
  read_children_cpu
  cpu0=$children_cpu
  "$run"
  wall=$((SECONDS - wall0))
  read_children_cpu
  cpu=$((children_cpu - cpu0))
  echo "== $name: ${wall} s wall, ${cpu} s CPU =="
  stage_rows+=("$(printf '%6d s %7d s  %s' "$wall" "$cpu" "$name")")
}

# ctest's ten slowest tests, read from its output (a line "N/M Test #K: NAME .... Passed 1.23
# sec" a test): run_ctest BUILD ARGS... runs ctest on BUILD with ARGS and keeps the output in
# BUILD/ctest-output.log. (Its own CTestCostData.txt cuts a name at its first space.)
# Each test's wall seconds in a ctest output LOG, a line "SECONDS<tab>NAME" a test.
test_seconds() {
  sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: (.*[^ .]) \.+ *\**[A-Za-z ]+ +([0-9.]+) sec$/\2\t\1/p' "$1"
}

run_ctest() {
  local build=$1 status=0
  shift
  ctest --test-dir "$build" "$@" | tee "$build/ctest-output.log" || status=$?
  echo "-- the ten slowest tests of $build (wall seconds, each beside the others ctest ran at once):"
  test_seconds "$build/ctest-output.log" |
    sort -g -r | awk -F'\t' 'NR <= 10 { printf "%8.1f  %s\n", $1, $2 }'  # no head: it would end sort by SIGPIPE, and pipefail the script
  return "$status"
}

stages_table() {
  echo "== done at $((SECONDS - start)) s =="
  echo "  wall      CPU  stage"
  printf '%s\n' "${stage_rows[@]}"
}

declare -A beside_pid beside_log
stop_beside() {
  local name
  for name in "${!beside_pid[@]}"; do kill -- -"${beside_pid[$name]}" 2>/dev/null || true; done
}
beside() {
  local name=$1 niceness=$2
  shift 2
  beside_log[$name]=$(mktemp)
  # Started with &, setsid is no group's leader, so it makes its own session without a fork: $! is
  # the group to stop.
  setsid nice -n "$niceness" bash "$@" >"${beside_log[$name]}" 2>&1 &
  beside_pid[$name]=$!
  trap stop_beside EXIT
}
joined() {
  local name=$1 status=0
  wait "${beside_pid[$name]}" || status=$?
  cat "${beside_log[$name]}"
  rm -f "${beside_log[$name]}"
  unset "beside_pid[$name]" "beside_log[$name]"
  return "$status"
}
