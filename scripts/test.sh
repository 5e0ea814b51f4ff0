#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs the whole test suite (Catch2 unit
# tests and the command-line tests) through CTest -- twice: once in the Release build, once
# built with AddressSanitizer and UndefinedBehaviorSanitizer (build-sanitize/), where any
# memory error or undefined behaviour aborts the test that hit it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "== the same suite under AddressSanitizer and UndefinedBehaviorSanitizer =="
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTREBUCHET_SANITIZE=ON >/dev/null
cmake --build build-sanitize -j"$(nproc)" --target unit-tests trebuchet-calc trebuchet-verify golden-compare
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)"
