#!/usr/bin/env bash
# The formatters' check, in CI before the build: every C++ file as .clang-format lays it out
# (clang-format 14; fix with `clang-format-14 -i FILE`), and the page's JavaScript and its tests
# through ESLint with eslint.config.mjs (ESLint from tests/web's npm packages). Fails naming
# each file that differs or each problem found. The house's sizes (docs/architecture.md): no
# program file (calc/, verify/, cli/) over 250 lines, no function in lib/, calc/, verify/ or cli/
# over 100 (Universal Ctags' extents of functions and members); no file-local name twice in one
# target (every build is a unity build, CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t cpp < <(git ls-files 'lib/*.cpp' 'lib/*.hpp' 'calc/*.cpp' 'verify/*.cpp' 'verify/*.hpp' 'cli/*.cpp' 'cli/*.hpp' 'python/src/*.cpp' \
  'web/src/*.cpp' 'tests/*.cpp' 'tests/*.hpp' 'tests/**/*.cpp' 'tests/**/*.hpp')
clang-format-14 --dry-run --Werror "${cpp[@]}"
echo "lint.sh: ${#cpp[@]} C++ files as .clang-format lays them out"
long_files=$(git ls-files 'calc/*.[ch]pp' 'verify/*.[ch]pp' 'cli/*.[ch]pp' | xargs wc -l | awk '$2 != "total" && $1 > 250 {print "  " $2 ": " $1 " lines"}')
long_functions=$(ctags -R --fields=+ne --kinds-c++=fm -x --_xformat="%{line} %{end} %N %F" lib calc verify cli |
  awk '$2 - $1 + 1 > 100 {print "  " $4 ":" $1 ": " $3 ", " $2 - $1 + 1 " lines"}')
if [ -n "$long_files" ] || [ -n "$long_functions" ]; then
  [ -z "$long_files" ] || printf 'lint.sh: program files over 250 lines; split them along their parts:\n%s\n' "$long_files"
  [ -z "$long_functions" ] || printf 'lint.sh: functions over 100 lines; split them where their parts have names:\n%s\n' "$long_functions"
  exit 1
fi
echo "lint.sh: no program file over 250 lines, no function over 100"
# Every build is a unity build by default (CMakeLists.txt): a name in the anonymous
# namespaces of two source files of one target would then be defined twice. Checked a target's
# sources at a time, by their folder where a folder holds one target's (a folder may hold two
# libraries' files, and overloads count as one name: the check errs safe).
twice=$(for sources in lib/core/src lib/app/src "tests/*.cpp tests/reference/*.cpp" "tests/spreadsheet/*.cpp tests/paper_rounding.cpp" "verify/*.cpp" \
  "calc/*.cpp"; do
  # shellcheck disable=SC2086  # each group's globs, expanded here
  ctags -R --kinds-c++=+p -x --_xformat="%N	%{scope}	%F" $sources | awk -F'\t' '$2 ~ /__anon[0-9a-f]+$/ {sub(/__anon[0-9a-f]+$/, "", $2); print $2 $1 "\t" $3}' | sort -u |
    awk -F'\t' '{files[$1] = files[$1] " " $2; count[$1]++} END {for (name in count) if (count[name] > 1) print "  " name ":" files[name]}'
done)
if [ -n "$twice" ]; then
  printf 'lint.sh: names in the anonymous namespaces of two source files of one target (a unity build would define them twice); rename one, or share one:\n%s\n' "$twice"
  exit 1
fi
echo "lint.sh: no name in the anonymous namespaces of two source files of one target"
tests/web/node_modules/.bin/eslint web/app.js web/viewer.js web/bundle.mjs tests/web/*.mjs
echo "lint.sh: web/ and tests/web/ pass ESLint"
