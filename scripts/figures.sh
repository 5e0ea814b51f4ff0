#!/usr/bin/env bash
# Remakes the figures of docs/ (issue 13): the pictures of one shot (tab:Alcala_la_Vieja row Ca)
# in docs/figures/, the engine drawing among them, a floating arm and a contest's Pareto front (docs/machines.md), fig:XY, fig:fZ_vs_X for each re-derived block,
# fig:Merit_Ms, and, with --all, the work-precision charts
# (scripts/work-precision.sh, about four minutes on one core). Renders every SVG to PNG in
# build/figures-png, to look at.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTREBUCHET_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build -j"$(nproc)" --target trebuchet-verify figure-xy figure-fz figure-merit
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build/verify/trebuchet-verify shot --L1 4.13m --L2 0.88m --F 2/3 --L4 3.55m --M 3.11t --m 50kg --mb 174kg --plot "$work" >/dev/null
for picture in engine paths forces energy release pin; do cp "$work/$picture.svg" "docs/figures/$picture.svg"; done
# docs/machines.md: the same engine's beam built as a floating arm, and a contest's Pareto front.
build/verify/trebuchet-verify shot --machine floating-arm --L1 4.13m --L2 0.88m --L3 0.4m --L4 3.55m --M 3.11t --m 50kg --mb 174kg \
  --plot "$work/floating" >/dev/null
cp "$work/floating/engine.svg" docs/figures/floating_arm.svg
# pytrebuchet's default whipper, released as it releases it (docs/machines.md, "The whipper").
build/verify/trebuchet-verify shot --machine whipper --L1 4m --L2 2m --L3 4m --L4 4m --M 100kg --m 3kg --mb 10kg --H 5m \
  --projectile-diameter 0.2m --release-angle 45 --plot "$work/whipper" >/dev/null
cp "$work/whipper/engine.svg" docs/figures/whipper.svg
build/verify/trebuchet-verify contest --machine floating-arm --m 0.5kg --mb-per-m 1.5 --max-width 4m --max-height 3m --max-M 60kg \
  --pareto 20 --plot "$work/contest" >/dev/null
cp "$work/contest/pareto.svg" docs/figures/pareto.svg
build/tests/figure-xy > docs/figures/xy.gp   # fig:XY from the built-in tab:CPNC
gnuplot docs/figures/xy.gp
for script in $(build/tests/figure-fz data/cpnc-derived.json docs/figures); do gnuplot "$script"; done   # fig:fZ_vs_X
build/tests/figure-merit docs/figures   # fig:Merit_Ms: 2000 capacity fits, the quadratic form's axes printed
gnuplot docs/figures/merit.gp
if [ "${1:-}" = --all ]; then bash scripts/work-precision.sh; fi
mkdir -p build/figures-png
for svg in docs/figures/*.svg docs/*.svg; do
  rsvg-convert -w 1100 "$svg" -o "build/figures-png/$(basename "$svg" .svg).png"
done
echo "wrote docs/figures/*.svg; PNG renderings in build/figures-png"
