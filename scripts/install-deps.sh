#!/usr/bin/env bash
# Installs the Debian 12 packages trebuchet builds and tests with, skipping what is present.
# Run as root (or with sudo available). Safe to run again.
set -euo pipefail

packages=(
  cmake g++ make
  libeigen3-dev     # Eigen 3.4
  libgsl-dev        # GSL 2.7: odeiv2, roots, minimisation
  nlohmann-json3-dev
  libfmt-dev        # {fmt} 9: numbers in CSV (header-only)
  catch2            # Catch2 2.13 with CTest discovery
  libcli11-dev
  pkg-config libxlsxwriter-dev  # trebuchet-calc --spreadsheet writes .xlsx with it
  libreoffice-calc-nogui        # the spreadsheet test recalculates the workbook in a real program
  gnuplot-nox       # charts and trebuchet-verify shot --plot, without X11
  libxml2-utils     # xmllint: the pictures' SVG is checked well-formed
  librsvg2-bin      # rsvg-convert: SVG pictures rendered to PNG to look at (scripts/figures.sh)
  units             # GNU units: tests/test_units.cpp checks every conversion factor against it
  clang-14 libclang-rt-14-dev  # libFuzzer for the fuzz targets of tests/fuzz
  parallel slurm-wlm munge     # tab:CPNC derived in shards under GNU parallel and Slurm (tests/scale)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
