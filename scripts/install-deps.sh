#!/usr/bin/env bash
# Installs the Debian 12 packages trebuchet builds and tests with, skipping what is present.
# Run as root (or with sudo available). Safe to run again.
#   bash scripts/install-deps.sh          everything: the programs, their tests and the browser page
#   bash scripts/install-deps.sh native   the programs and their tests only (scripts/quickstart.sh)
# The page's part also enables Debian's source packages (GSL for WebAssembly is built from
# Debian's source of it) and installs the page's npm packages (web: qrcode-generator, bundled into
# the page; tests/web: playwright-core, ESLint, jsqr).
set -euo pipefail
cd "$(dirname "$0")/.."
scope=${1:-all}

packages=(
  cmake g++ make
  ccache            # every build compiles through it (scripts/ccache.sh)
  libeigen3-dev     # Eigen 3.4
  libgsl-dev        # GSL 2.7: odeiv2, roots, minimisation
  libnlopt-dev      # NLopt 2.7: the contest's constrained search (COBYLA)
  nlohmann-json3-dev
  libfmt-dev        # {fmt} 9: numbers in CSV (header-only)
  libfast-float-dev # fast_float: numbers read as from_chars reads them, also in the browser build
  catch2            # Catch2 2.13 with CTest discovery
  libcli11-dev
  pkg-config libxlsxwriter-dev  # trebuchet-calc --spreadsheet writes .xlsx with it
  libreoffice-calc-nogui        # the spreadsheet test recalculates the workbook in a real program
  gnuplot-nox       # charts and trebuchet-verify shot --plot, without X11
  libxml2-utils     # xmllint: the pictures' SVG is checked well-formed
  librsvg2-bin      # rsvg-convert: SVG pictures rendered to PNG to look at (scripts/figures.sh)
  units             # GNU units: tests/test_units.cpp checks every conversion factor against it
  clang-14 libclang-rt-14-dev  # libFuzzer for the fuzz targets of tests/fuzz
  clang-format-14              # the C++ layout CI checks (scripts/lint.sh, .clang-format)
  universal-ctags              # scripts/lint.sh: each function's extent, none over 100 lines
  parallel slurm-wlm munge     # tab:CPNC derived in shards under GNU parallel and Slurm (tests/scale)
)
if [ "$scope" != native ]; then
  packages+=(
    emscripten node-acorn  # the page: the library compiled to WebAssembly (acorn: emcc's optimiser)
    dpkg-dev               # apt-get source gsl: GSL for WebAssembly from Debian's own source
    nodejs                 # bundles the page and drives its tests
    chromium               # the page's tests, headless, driven by playwright-core
    python3-dev pybind11-dev python3-numpy  # the Python module (docs/python.md)
    python3-setuptools python3-wheel python3-venv python3-pip python3-pytest python3-pandas  # its package, its install test, its tests, to_frame()
    python3-scipy python3-sympy  # the machines' independent integration (tests/machines/independent.py)
    jupyter-nbconvert python3-ipykernel python3-matplotlib  # its example notebook, run in CI
  )
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive

# Debian's source packages, for apt-get source gsl (scripts/build-gsl-wasm.sh).
if [ "$scope" != native ] && ! grep -rqsE "^(Types:.*deb-src|deb-src )" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  echo "install-deps: enabling Debian's source packages (bookworm main) for apt-get source gsl"
  printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
    "${sudo_cmd[@]}" tee /etc/apt/sources.list.d/trebuchet-deb-src.sources >/dev/null
  "${sudo_cmd[@]}" apt-get update -qq
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
else
  echo "install-deps: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if [ "$scope" != native ]; then
  # npm ships with a nodejs from NodeSource; Debian's own nodejs has it as a package of its own.
  command -v npm >/dev/null || "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends npm
  # playwright-core (the browser tests) needs Node 20 or later; Debian 12's own nodejs is 18.
  node_major=$(node -p 'process.versions.node.split(".")[0]')
  if [ "$node_major" -lt 20 ]; then
    echo "install-deps: the browser tests need Node 20 or later (playwright-core); this node is $(node --version). Install a newer nodejs (NodeSource's, as this project's machines have), then run this again" >&2
    exit 1
  fi
  # Debian's source of GSL, for GSL in WebAssembly (built by scripts/build-web.sh, once a machine).
  bash scripts/build-gsl-wasm.sh --fetch
  # The page's npm packages at the versions of tests/web/package-lock.json: playwright-core, which
  # drives Debian's chromium and downloads no browser, and ESLint (scripts/lint.sh).
  # jsqr reads the page's QR code back in its test.
  if [ ! -d tests/web/node_modules/playwright-core ] || [ ! -x tests/web/node_modules/.bin/eslint ] || [ ! -d tests/web/node_modules/jsqr ]; then
    (cd tests/web && npm ci --no-audit --no-fund --loglevel=error)
  fi
  # What the page bundles (web/package-lock.json): qrcode-generator, the share link's QR code.
  if [ ! -d web/node_modules/qrcode-generator ]; then
    (cd web && npm ci --no-audit --no-fund --loglevel=error)
  fi
fi
