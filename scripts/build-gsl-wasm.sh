#!/usr/bin/env bash
# GSL for WebAssembly, from Debian's own source of the GSL the native build links (2.7.1), built
# once per machine into a cached prefix: scripts/build-web.sh links the page against it.
#   bash scripts/build-gsl-wasm.sh           -> prints the prefix (include/, lib/libgsl.a)
#   bash scripts/build-gsl-wasm.sh --fetch   downloads Debian's source (apt-get source), once
# Only the parts the core uses are compiled: odeiv2 (appendix A's phases), roots (the release and
# lift-off), multimin (the simplex of the optimizer and the fit), statistics (Monte Carlo), and
# what they call (vectors, matrices, linear algebra, BLAS, errors, system helpers).
set -euo pipefail
version=2.7.1
emcc_version=$(emcc -dumpversion)
prefix=${TREBUCHET_WASM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/trebuchet}/gsl-$version-emcc-$emcc_version
sources=$(dirname "$prefix")/src
if [ "${1:-}" = --fetch ]; then  # scripts/install-deps.sh: the download, before any build
  [ -f "$prefix/lib/libgsl.a" ] || ls "$sources"/gsl_$version*.dsc >/dev/null 2>&1 ||
    (mkdir -p "$sources" && cd "$sources" && apt-get source --download-only -qq gsl 2> >(grep -v "unsandboxed" >&2) >/dev/null)
  exit 0
fi
if [ -f "$prefix/lib/libgsl.a" ]; then echo "$prefix"; exit 0; fi

dsc=$(ls "$sources"/gsl_$version*.dsc 2>/dev/null | head -1)
[ -n "$dsc" ] || { echo "build-gsl-wasm: no source of GSL $version in $sources; run scripts/install-deps.sh" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dpkg-source --no-check -x "$dsc" "$work/gsl" >/dev/null
src=$work/gsl
cd "$src"
# emcc's optimiser needs acorn from Debian's node modules (node-acorn), which a node from another
# packaging does not look in; configure's test programs run under node, whose own fetch must
# stay out of it.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
NODE_OPTIONS=--no-experimental-fetch emconfigure ./configure --disable-shared --enable-static --prefix="$prefix" CFLAGS="-O2" >configure.log 2>&1 ||
  { tail -20 configure.log >&2; exit 1; }
parts=(gsl sys err utils complex block vector matrix permutation blas cblas linalg poly
       ode-initval2 roots min multimin sort statistics)
for part in "${parts[@]}"; do
  emmake make -s -j"$(nproc)" -C "$part" >/dev/null
done
mkdir -p "$prefix/lib" "$prefix/include/gsl"
objects=()
for part in "${parts[@]}"; do
  for o in "$part"/.libs/*.o "$part"/*.o; do [ -f "$o" ] && objects+=("$o"); done
done
emar rcs "$prefix/lib/libgsl.a" "${objects[@]}"
cp gsl/*.h "$prefix/include/gsl/" 2>/dev/null || cp -L gsl/*.h "$prefix/include/gsl/"
echo "$prefix"
