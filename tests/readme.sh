#!/usr/bin/env bash
# readme.sh ROOT BUILD: every example command of README.md runs and exits 0. The lines of its
# ```sh blocks that start with build/ are run in order by bash, in a scratch folder where build
# is BUILD and tests and data are the repository's, with the files they read made first:
# sites.csv (a site column, R and m with units in the header) and designs.json (two of the
# calculator's designs). The lines that run scripts
# (quickstart, test, derive-tables) are the set-up and the whole suite themselves, not run here.
set -u
root=$(realpath "$1") build=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
ln -s "$build" build
ln -s "$root/tests" tests  # the README's commands run from the repository's root
ln -s "$root/data" data
printf 'site,R_m,m_kg\nAlcala la Vieja Ca,150,50\nSaone,250,80\n' > sites.csv
{
  echo "["
  build/calc/trebuchet-calc --R 150m --m 50kg --format json
  echo ","
  build/calc/trebuchet-calc --R 425m --T 224kJ --F 1 --format json
  echo "]"
} > designs.json
failures=0 commands=0
while IFS= read -r line; do
  commands=$((commands + 1))
  bash -c "$line" > out.txt 2>&1
  code=$?
  if [ "$code" -ne 0 ]; then
    failures=$((failures + 1))
    echo "FAIL (exit $code): $line"
    head -5 out.txt
  fi
done < <(awk '/^```/{block=!block; next} block && /^build\//' "$root/README.md")
echo "readme.sh: $commands commands, $failures failed"
[ "$failures" -eq 0 ] && [ "$commands" -gt 0 ]
