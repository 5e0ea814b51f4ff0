# Sourced by the build scripts (test.sh, quick.sh, quickstart.sh, build-web.sh): every CMake build
# compiles through ccache (Debian's), for g++, clang++ and em++ alike (emcc's own system libraries are cached by Emscripten), and for the builds the tests
# make themselves (the downstream package's core). A source compiled once with the same flags is
# taken from the cache: a second clone on the same machine, a later commit, or CI after a session
# rebuilds only what changed. An empty cache (a new machine) compiles everything, as before.
if command -v ccache >/dev/null; then
  # CMake reads these when it configures a build folder for the first time (CMake 3.17 and later).
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
  # Paths below the checkout are hashed relative to it, so that two clones share the cache; the
  # line tables of the sanitizer build may then name the folder that compiled a file first.
  CCACHE_BASEDIR=$(pwd -P)
  export CCACHE_BASEDIR CCACHE_NOHASHDIR=1
fi
