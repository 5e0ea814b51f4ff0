#!/usr/bin/env bash
# derive_shards.sh VERIFY: a sweep run whole and run as three shards merged in another order
# gives the same table, byte for byte, and the calculator reads that table.
set -eu
verify=$1
calc=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
grid=(derive-table --theta 30 --F 1 --X -0.1:0.1:0.05)
"$verify" "${grid[@]}" --threads 2 > "$dir/whole.json"
for k in 1 2 3; do "$verify" "${grid[@]}" --threads 1 --shard "$k/3" > "$dir/part$k.json"; done
"$verify" merge "$dir/part3.json" "$dir/part1.json" "$dir/part2.json" > "$dir/merged.json"
cmp "$dir/whole.json" "$dir/merged.json"
"$calc" --table "$dir/whole.json" --R 250m --T 26kJ --theta 30 --F 1 | grep -E "L1 = [0-9.]+ m"
echo "whole and merged shards agree"
