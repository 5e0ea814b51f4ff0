#!/usr/bin/env bash
# The formatters' check, in CI before the build: every C++ file as .clang-format lays it out
# (clang-format 14; fix with `clang-format-14 -i FILE`), and the page's JavaScript and its tests
# through ESLint with eslint.config.mjs (ESLint from tests/web's npm packages). Fails naming
# each file that differs or each problem found.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t cpp < <(git ls-files 'lib/*.cpp' 'lib/*.hpp' 'calc/*.cpp' 'verify/*.cpp' 'verify/*.hpp' 'cli/*.cpp' 'cli/*.hpp' 'python/src/*.cpp' \
  'web/src/*.cpp' 'tests/*.cpp' 'tests/*.hpp' 'tests/**/*.cpp' 'tests/**/*.hpp')
clang-format-14 --dry-run --Werror "${cpp[@]}"
echo "lint.sh: ${#cpp[@]} C++ files as .clang-format lays them out"
tests/web/node_modules/.bin/eslint web/app.js web/viewer.js web/bundle.mjs tests/web/*.mjs
echo "lint.sh: web/ and tests/web/ pass ESLint"
