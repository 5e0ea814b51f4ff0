#!/usr/bin/env bash
# run.sh LABELS_SH FIXTURES: labels.sh passes a table that agrees with the code it describes, and
# fails, naming the label, a table with two rows for one label and a table lacking a cited label
# (tab:Bar-I, which also shows that a label with a hyphen is read whole).
set -u
labels=$1 fixtures=$2 failures=0
expect() {  # expect FIXTURE EXIT_WANTED MESSAGE
  out=$(bash "$labels" "$fixtures/$1" 2>&1); rc=$?
  if [ "$2" = pass ] && [ $rc -ne 0 ]; then echo "FAIL $1: labels.sh failed: $out"; failures=$((failures + 1)); return; fi
  if [ "$2" = fail ] && [ $rc -eq 0 ]; then echo "FAIL $1: labels.sh passed: $out"; failures=$((failures + 1)); return; fi
  if ! grep -qF -- "$3" <<< "$out"; then echo "FAIL $1: the output lacks '$3': $out"; failures=$((failures + 1)); return; fi
  echo "ok $1: $3"
}
expect agrees pass "2 rows, 0 problems"
expect cited_twice fail "eq:Foo has 2 rows"
expect no_row fail "tab:Bar-I has 0 rows"
[ $failures -eq 0 ]
