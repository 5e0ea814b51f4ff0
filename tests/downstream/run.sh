#!/usr/bin/env bash
# run.sh SOURCE_DIR WORK_DIR: the core alone, as a downstream project gets it.
# 1. Builds and installs the core from SOURCE_DIR with -DTREBUCHET_APP=OFF, where nlohmann-json
#    and CLI11 cannot be found and the headers of those and of libxlsxwriter are poisoned: an
#    include of any of them fails. No link line may name them (nor gnuplot, which only the
#    application layer runs).
# 2. Builds tests/downstream against the installed package with find_package(trebuchet), under
#    the same conditions, links trebuchet::core alone, runs it and checks what it prints
#    (tab:Alcala_la_Vieja row Ca: T = 40.5 kJ from the calculator, R = 150.5 m ab initio).
set -euo pipefail
source_dir=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work/poison/nlohmann" "$work/poison/CLI"
for header in nlohmann/json.hpp CLI/CLI.hpp xlsxwriter.h; do
  echo "#error \"the core must not include $header\"" > "$work/poison/$header"
done
without=(-DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
         "-DCMAKE_CXX_FLAGS=-I$work/poison")
# Each source of the core compiled alone (no unity build): one that lacks an include fails here.
cmake -S "$source_dir" -B "$work/core" -DTREBUCHET_APP=OFF -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=OFF "${without[@]}" > "$work/core-configure.log"
cmake --build "$work/core" -j"$(nproc)" > "$work/core-build.log"
cmake --install "$work/core" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release "${without[@]}" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
if grep -rlE 'xlsxwriter|nlohmann|CLI11|gnuplot' --include=link.txt --include='*.make' "$work/core" "$work/build" > "$work/named.log"; then
  echo "run.sh: a link line names a format library:" >&2; cat "$work/named.log" >&2; exit 1
fi
output=$("$work/build/downstream")
echo "$output"
[[ "$output" == "T = 40.5 kJ, R = 150.5 m" ]]
