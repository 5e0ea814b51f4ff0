#!/usr/bin/env bash
# Builds the browser page: the library compiled to WebAssembly with Emscripten (Debian's), over
# GSL for WebAssembly (scripts/build-gsl-wasm.sh, cached per machine), bundled with web/'s page
# into one self-contained file that opens from file:// and fetches nothing:
#   bash scripts/build-web.sh [BUILD_DIR]    -> BUILD_DIR/trebuchet.html (default build-web)
# Needs the packages of scripts/install-deps.sh; no network.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache.sh
out=${1:-build-web}
# emcc's JavaScript optimiser needs acorn from Debian's node modules (node-acorn), which a node
# of another packaging does not look in.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
gsl=$(bash scripts/build-gsl-wasm.sh)
emcmake cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release -DTREBUCHET_GSL_WASM="$gsl" >/dev/null
cmake --build "$out" -j"$(nproc)"
node web/bundle.mjs "$out/web/trebuchet.js" "$out/trebuchet.html"
