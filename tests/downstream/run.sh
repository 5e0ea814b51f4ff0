#!/usr/bin/env bash
# run.sh BUILD_DIR WORK_DIR: installs the build into WORK_DIR/prefix, builds the downstream
# project against it with find_package(trebuchet), runs it and checks what it prints
# (tab:Alcala_la_Vieja row Ca: T = 40.5 kJ from the calculator, R = 150.5 m ab initio).
set -euo pipefail
build=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
output=$("$work/build/downstream")
echo "$output"
[[ "$output" == "T = 40.5 kJ, R = 150.5 m" ]]
