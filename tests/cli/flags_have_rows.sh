#!/usr/bin/env bash
# flags_have_rows.sh CALC VERIFY INPUTS_MD: every flag of every subcommand, and of the calculator,
# has its row in the table of inputs or the table of settings (issue 51). docs/inputs.md is
# written from both tables (the test docs.inputs holds it to them), so a flag the page lists as
# `--flag` has its row; a flag declared by hand beside the tables would be missing there.
set -u
calc=$1 verify=$2 page=$3
status=0
flags_of() { "$@" --help | grep -oE '^\s+--[A-Za-z0-9-]+' | tr -d ' ' | grep -vxE -- '--help|--version'; }
check() {
  local where=$1; shift
  local flags
  flags=$(flags_of "$@")
  [ -n "$flags" ] || { echo "FAIL: $where lists no flags"; status=1; }
  for flag in $flags; do
    grep -qF -- "\`$flag\`" "$page" || { echo "FAIL: $where's $flag has no row in $page"; status=1; }
  done
  echo "$where: $(echo "$flags" | wc -l) flags, each with its row"
}
check trebuchet-calc "$calc"
for sub in shot fit optimize derive-table merge complete calibrate compare contest sweep; do
  [ "$sub" = merge ] && continue  # its one argument is the parts' files
  check "verify $sub" "$verify" "$sub"
done
exit $status
