#!/usr/bin/env bash
# Installs what is missing, builds, designs the engine of a built-in example -- the Catalanes
# site at Alcala la Vieja (tab:Alcala_la_Vieja), 150 m with 50 kg stones -- and verifies the
# design ab initio.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh native
source scripts/ccache.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target trebuchet-calc trebuchet-verify
echo
echo "\$ trebuchet-calc --R 150m --m 50kg --theta 30 --F 2/3"
build/calc/trebuchet-calc --R 150m --m 50kg --theta 30 --F 2/3
echo
echo "\$ trebuchet-calc --R 150m --m 50kg --format json | trebuchet-verify -"
build/calc/trebuchet-calc --R 150m --m 50kg --format json | build/verify/trebuchet-verify -
