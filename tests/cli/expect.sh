#!/usr/bin/env bash
# expect.sh EXIT_CODE REGEX COMMAND [ARGS...]
# Runs COMMAND (stdin from $STDIN_FILE, default /dev/null) and passes when it exits with
# EXIT_CODE and its combined stdout and stderr matches the extended regular expression REGEX.
# Fails when any output contains nan or inf as a number.
set -u
expected_code=$1
regex=$2
shift 2
output=$("$@" 2>&1 < "${STDIN_FILE:-/dev/null}")
code=$?
printf '%s\n' "$output"
if [ "$code" -ne "$expected_code" ]; then
  echo "expect.sh: exit code $code, expected $expected_code" >&2
  exit 1
fi
if ! printf '%s\n' "$output" | grep -Eq -- "$regex"; then
  echo "expect.sh: output does not match: $regex" >&2
  exit 1
fi
if printf '%s\n' "$output" | grep -Eiq -- '(^|[^a-z])(-?nan|-?inf(inity)?)([^a-z]|$)'; then
  echo "expect.sh: output contains nan or inf" >&2
  exit 1
fi
