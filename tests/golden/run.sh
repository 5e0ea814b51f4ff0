#!/usr/bin/env bash
# run.sh [--old] CALC VERIFY OUTDIR: runs every case of cases.txt and writes, per case,
# OUTDIR/NAME.out (stdout), NAME.err (stderr) and NAME.code (exit code). --old runs the
# verifier of before issue 10, whose modes were flags: `verify fit ARGS` becomes
# `verify ARGS --fit`, `verify optimize ARGS` becomes `verify --optimize ARGS`, and so on.
set -u
old=0
if [ "$1" = --old ]; then old=1; shift; fi
CALC=$(realpath "$1") VERIFY=$(realpath "$2") out=$(realpath -m "$3")
here=$(cd "$(dirname "$0")" && pwd)
CLI=$here/../cli
GOLDEN=$here
mkdir -p "$out"
calc() { "$CALC" "$@"; }
verify() {
  if [ "$old" = 0 ]; then "$VERIFY" "$@"; return; fi
  case "${1:-}" in
    shot) shift; "$VERIFY" "$@" ;;
    fit) shift; "$VERIFY" "$@" --fit ;;
    optimize|derive-table|merge) local mode=--$1; shift; "$VERIFY" "$mode" "$@" ;;
    *) "$VERIFY" "$@" ;;
  esac
}
while read -r name command; do
  case "$name" in ''|'#'*) continue ;; esac
  TMP=$(mktemp -d)
  (cd "$TMP" && eval "$command") > "$out/$name.out" 2> "$out/$name.err" < /dev/null
  echo $? > "$out/$name.code"
  rm -rf "$TMP"
done < "$here/cases.txt"
