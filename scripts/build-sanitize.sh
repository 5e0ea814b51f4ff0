#!/usr/bin/env bash
# Builds the sanitizer pass of scripts/test.sh: clang under AddressSanitizer and
# UndefinedBehaviorSanitizer, instrumented for libFuzzer, into build-sanitize/ (the unit tests,
# both programs and the five fuzz targets). Line tables only: a sanitizer's report still names
# file and line, and the build skips the rest of the debug information (issue 33).
#   bash scripts/build-sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache.sh
CXX=clang++-14 cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DTREBUCHET_SANITIZE=ON -DTREBUCHET_FUZZ=ON >/dev/null
cmake --build build-sanitize -j"$(nproc)" --target unit-tests trebuchet-calc trebuchet-verify fuzz-units fuzz-design fuzz-batch fuzz-table fuzz-part
