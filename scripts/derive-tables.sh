#!/usr/bin/env bash
# Re-derives tab:CPNC ab initio (issue 5): the paper's three (theta_i, F) blocks and one it
# lacks (40 deg, F = 1; and for tab:SketchBook-II, 25 deg, F = 1 and 30 deg, F = 1/2), each swept along X as one shard, merged into data/cpnc-derived.json.
# Then compares the designs of both tables, verified ab initio: docs/derived_vs_paper.csv.
# Takes about 25 s on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTREBUCHET_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build -j"$(nproc)" --target trebuchet-verify compare-tables
parts=$(mktemp -d)
trap 'rm -rf "$parts"' EXIT
for block in "30 1" "30 2/3" "40 2/3" "40 1" "25 1" "30 1/2"; do
  read -r theta F <<< "$block"
  echo "block theta $theta deg, F $F:"
  build/verify/trebuchet-verify derive-table --theta "$theta" --F "$F" --X -0.55:0.55:0.05 --shard 1/1 > "$parts/$theta-${F/\//_}.json"
done
build/verify/trebuchet-verify merge "$parts"/*.json > data/cpnc-derived.json
build/tests/compare-tables data/cpnc-derived.json > docs/derived_vs_paper.csv
grep '^#' docs/derived_vs_paper.csv
echo "wrote data/cpnc-derived.json and docs/derived_vs_paper.csv"
