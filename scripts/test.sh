#!/usr/bin/env bash
# The README's test command, and CI's (.ci/run): installs what is missing, then
#   1. the Release build with the benchmarks, warnings as errors, and beside it the browser page
#      (WebAssembly, scripts/build-web.sh); then every tier of the suite (docs/testing.md) but the
#      hostile corpus and the command-line fuzzer, which stage 2 runs;
#   2. one clang build under AddressSanitizer and UndefinedBehaviorSanitizer, instrumented for
#      libFuzzer (scripts/build-sanitize.sh), begun beside the suite at the lowest priority (nice
#      19): it takes the cores where the suite's tests wait on LibreOffice, Chromium or gnuplot.
#      (At nice 10 it took a tenth of them from the suite, which then ran 411 s where it had
#      run 330 s without it.) The five fuzz
#      targets run at once for a minute each, then the tiers that run the code on inputs (unit,
#      cli, robustness; every 10th reference design, the contests of the label heavy in part) run
#      again under the sanitizers, where any memory error or undefined behaviour aborts the test
#      that hit it; the corpus and the command-line fuzzer run here only.
# First the formatters (scripts/lint.sh). Every build compiles through ccache (scripts/ccache.sh).
# Each stage prints its wall and CPU time (a stage that joins work begun beside an earlier one
# counts that work's CPU), each ctest run its slowest tests, and the end a table of the stages.
# TREBUCHET_FUZZ_SECONDS changes the fuzzing time.
# The quick tier for work in progress is scripts/quick.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
start=$SECONDS
source scripts/stages.sh

installing() { bash scripts/install-deps.sh; }
formatters() { bash scripts/lint.sh; }
release_build() {
  # With the Python module for Debian's own interpreter (docs/python.md).
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTREBUCHET_WERROR=ON -DTREBUCHET_BUILD_BENCHMARKS=ON \
    -DTREBUCHET_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  cmake --build build -j"$jobs"
}
release_build_and_page() {
  beside page 0 scripts/build-web.sh build-web
  release_build
  joined page
}
every_tier() {
  # The hostile-input corpus and the command-line fuzzer run once, in the sanitizer stage: there
  # every case is checked for its exit code, its message and no nan or inf as here, and for
  # memory errors and undefined behaviour besides. One test more than the cores: many here wait
  # on LibreOffice, Chromium or gnuplot (464 s of CPU in 291 s on two cores at -j2), and a third
  # fills those waits.
  beside sanitizer 19 scripts/build-sanitize.sh
  run_ctest build --output-on-failure -j"$((jobs + 1))" --timeout 600 -E '^(robustness_corpus_[0-9]+of[0-9]+|cli\.fuzz)$'
}
sanitizer_build() { joined sanitizer; }
fuzzing() { bash tests/fuzz/run.sh build-sanitize "${TREBUCHET_FUZZ_SECONDS:-60}"; }
sanitized_tiers() {
  # TREBUCHET_REFERENCE_STRIDE and TREBUCHET_HEAVY_STRIDE: every 10th reference design and every
  # 4th contest of the heavy tests (docs/testing.md); the Release tiers run them all. The programs'
  # whole contests (label contest, 5 to 25 s each here) run in the Release tier alone: their code
  # is the contest's, which the heavy and unit tiers run here.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 TREBUCHET_REFERENCE_STRIDE=10 TREBUCHET_HEAVY_STRIDE=4 \
    run_ctest build-sanitize --output-on-failure -j"$jobs" -L "^(unit|heavy|cli|robustness)$" -LE "^contest$" --timeout 900
}

stage "installing what is missing" installing
source scripts/ccache.sh  # after the install, which brings ccache to a new machine
stage "formatters: clang-format and ESLint" formatters
stage "Release build, the browser page (WebAssembly) beside it" release_build_and_page
stage "the suite, every tier; the sanitizer build begun beside it" every_tier
stage "sanitizer and fuzzer build (clang), the rest of it" sanitizer_build
stage "fuzzing: the five targets at once, ${TREBUCHET_FUZZ_SECONDS:-60} s each" fuzzing
stage "unit, cli and robustness tiers under the sanitizers" sanitized_tiers
stages_table
