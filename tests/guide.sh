#!/usr/bin/env bash
# guide.sh [--update] GUIDE BIN...: runs a walkthrough (docs/guide.md, docs/historians.md) so that its commands
# cannot rot. Every ```console block is a session: a line "$ command" is run (by bash, in one
# scratch folder for the whole guide, with the BIN folders first on PATH), and the lines after
# it, up to the next "$ " or the block's end, are its expected output, stdout and stderr
# together, compared line by line without trailing blanks (and without a Monte Carlo run's
# time and threads). With --update the guide is
# rewritten with the outputs of now (review the diff before committing it).
set -u
update=0
if [ "${1:-}" = --update ]; then update=1; shift; fi
guide=$(realpath "$1")
shift
for bin in "$@"; do PATH=$(realpath "$bin"):$PATH; done
export PATH
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$work/guide.md
failures=0 commands=0 in_block=0
expected=() command=""

# Compares the expected lines of the last command with what it printed.
finish_command() {
  [ -n "$command" ] || return 0
  local actual
  actual=$(cd "$work/run" && bash -c "$command" 2>&1 | sed 's/[[:space:]]*$//')
  # A Monte Carlo report says how long it took and on how many threads: not compared.
  local timing='s/, [0-9.e+-]* s on [0-9]* thread(s)$/, (time) on (threads)/'

  commands=$((commands + 1))
  if [ "$update" = 1 ]; then
    [ -z "$actual" ] || printf '%s\n' "$actual" >> "$out"
  else
    local want
    want=$(printf '%s\n' "${expected[@]+"${expected[@]}"}" | sed 's/[[:space:]]*$//' | sed "$timing")
    actual=$(printf '%s\n' "$actual" | sed "$timing")
    if [ "$actual" != "$want" ]; then
      failures=$((failures + 1))
      echo "FAIL: \$ $command"
      diff <(printf '%s\n' "$want") <(printf '%s\n' "$actual") | head -20
    fi
  fi
  command="" expected=()
}

mkdir -p "$work/run"
: > "$out"
while IFS= read -r line || [ -n "$line" ]; do
  if [ "$in_block" = 0 ]; then
    printf '%s\n' "$line" >> "$out"
    [ "$line" = '```console' ] && in_block=1
    continue
  fi
  if [ "$line" = '```' ]; then
    finish_command
    printf '%s\n' "$line" >> "$out"
    in_block=0
    continue
  fi
  if [ "${line:0:2}" = '$ ' ]; then
    finish_command
    printf '%s\n' "$line" >> "$out"
    command=${line:2}
  else
    expected+=("$line")
  fi
done < "$guide"

if [ "$update" = 1 ]; then
  cp "$out" "$guide"
  echo "guide.sh: $commands commands run, $guide rewritten"
  exit 0
fi
echo "guide.sh: $commands commands, $failures differ from the guide"
[ "$failures" -eq 0 ] && [ "$commands" -gt 0 ]
