#!/usr/bin/env bash
# threads_same_output.sh VERIFY MIXED_ARRAY: an array of 60 designs (tests/cli/mixed_array.json
# twenty times: good ones, one without a sling, one that cannot turn) gives the same stdout,
# stderr and exit code on one thread and on two, in table and in JSON (issue 12).
set -u
verify=$1 mixed=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
body=$(sed -e '1d' -e '$d' "$mixed")
{
  echo "["
  for k in $(seq 1 20); do
    echo "$body"
    [ "$k" -lt 20 ] && echo ","
  done
  echo "]"
} > "$dir/array.json"
status=0
for format in table json; do
  for threads in 1 2; do
    "$verify" "$dir/array.json" --format "$format" --threads "$threads" > "$dir/$format.$threads.out" 2> "$dir/$format.$threads.err"
    echo $? > "$dir/$format.$threads.code"
  done
  for part in out err code; do
    if ! cmp -s "$dir/$format.1.$part" "$dir/$format.2.$part"; then
      echo "FAIL: $format $part differs between 1 and 2 threads"
      status=1
    fi
  done
done
[ "$(grep -c '"error"' "$dir/json.1.out")" = 40 ] || { echo "FAIL: expected 40 failed designs in place"; status=1; }
[ "$status" = 0 ] && echo "same output on 1 and 2 threads: $(wc -c < "$dir/json.1.out") bytes of JSON, exit $(cat "$dir/json.1.code")"
exit $status
