#!/usr/bin/env bash
# The quick tier, for work in progress (docs/testing.md): run it at every commit, and the whole
# suite (scripts/test.sh) before you stop. It builds what changed in build/ (Release, through
# ccache) and, where the page's build folder exists, the page; then runs the entries labelled
# quick: the unit tier but its heavy contests (the paper's tables, the physics, the readers), the
# programs' doors (cli), the golden outputs, the Python package under pytest, the page's load in
# Chromium, and every tenth case of the hostile corpus. At most 3 minutes after a build on a
# 2-core machine.
#   bash scripts/quick.sh            build, then the quick tier
#   bash scripts/quick.sh --no-build the quick tier over the builds as they are
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
start=$SECONDS
source scripts/ccache.sh
source scripts/stages.sh

build() {
  [ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTREBUCHET_BUILD_BENCHMARKS=ON \
    -DTREBUCHET_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  cmake --build build -j"$jobs"
  # The page is rebuilt where it was built before (scripts/build-web.sh); else its test says so.
  if [ -f build-web/CMakeCache.txt ]; then bash scripts/build-web.sh build-web; fi
}
quick_tier() {
  run_ctest build --output-on-failure -j"$jobs" --timeout 300 -L "^(unit|cli|quick)$" -LE "^slow$"
}

[ "${1:-}" = --no-build ] || stage "build (Release, and the page where it was built)" build
stage "the quick tier" quick_tier
stages_table
