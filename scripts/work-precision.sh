#!/usr/bin/env bash
# Builds the benchmarks and charts the verifier's speed against its accuracy (issue 4):
# docs/work_precision.csv, docs/work_precision.svg and docs/cost_stiffness.svg. Runs on one
# core (taskset) so that timings are comparable; takes about a minute.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTREBUCHET_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build -j"$(nproc)" --target bench-shot
taskset -c 1 build/tests/bench-shot "${1:-0.2}" > docs/work_precision.csv
gnuplot docs/work_precision.gp
echo "wrote docs/work_precision.csv, docs/work_precision.svg, docs/cost_stiffness.svg"
