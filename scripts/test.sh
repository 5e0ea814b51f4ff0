#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs the whole test suite (Catch2 unit
# tests and the command-line tests) through CTest -- twice: once in the Release build, once
# built with AddressSanitizer and UndefinedBehaviorSanitizer (build-sanitize/), where any
# memory error or undefined behaviour aborts the test that hit it. In between, it fuzzes each
# reader of user text for a minute with libFuzzer under the same sanitizers (build-fuzz/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "== fuzzing: libFuzzer under AddressSanitizer and UndefinedBehaviorSanitizer, ${TREBUCHET_FUZZ_SECONDS:-60} s per target =="
CXX=clang++-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTREBUCHET_FUZZ=ON -DTREBUCHET_BUILD_TESTS=OFF \
  -DTREBUCHET_BUILD_PROGRAMS=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)"
bash tests/fuzz/run.sh build-fuzz "${TREBUCHET_FUZZ_SECONDS:-60}"
echo "== the same suite under AddressSanitizer and UndefinedBehaviorSanitizer =="
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTREBUCHET_SANITIZE=ON >/dev/null
cmake --build build-sanitize -j"$(nproc)" --target unit-tests trebuchet-calc trebuchet-verify golden-compare check-spreadsheet
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)"
