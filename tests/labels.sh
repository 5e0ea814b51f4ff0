#!/usr/bin/env bash
# labels.sh ROOT: docs/paper_labels.md names one implementation for each paper label the
# library cites. Fails when a cited eq:/tab: label has no row or more than one, when a row's
# file lacks one of its functions, or when a row's file does not cite its label.
set -u
root=$1
table=$root/docs/paper_labels.md
failures=0
rows=$(grep -E '^\| (eq|tab):' "$table")
# Labels as the paper writes them: letters, digits, _ and - (tab:SketchBook-I).
cited=$(grep -rhoE "(eq|tab):[A-Za-z][A-Za-z0-9_-]*[A-Za-z0-9]" "$root/lib" --include=*.cpp --include=*.hpp --include=*.in | sort -u)
[ -n "$cited" ] || { echo "labels.sh: $root/lib cites no label; is ROOT the project?" >&2; exit 1; }
for label in $cited; do
  count=$(printf '%s\n' "$rows" | grep -c "^| $label |")
  if [ "$count" -ne 1 ]; then echo "labels.sh: $label has $count rows in docs/paper_labels.md, not 1" >&2; failures=$((failures + 1)); fi
done
while IFS='|' read -r _ label _ file functions _; do
  label=$(echo "$label" | xargs) file=$(echo "$file" | xargs)
  [ -f "$root/$file" ] || { echo "labels.sh: $label: no file $file" >&2; failures=$((failures + 1)); continue; }
  grep -q "$label\b" "$root/$file" || { echo "labels.sh: $file does not cite $label" >&2; failures=$((failures + 1)); }
  IFS=',' read -ra names <<< "$functions"
  for name in "${names[@]}"; do
    name=$(echo "$name" | xargs)
    grep -qE "(^|[^A-Za-z0-9_])${name}([^A-Za-z0-9_]|$)" "$root/$file" || { echo "labels.sh: $label: $file has no $name" >&2; failures=$((failures + 1)); }
  done
done <<< "$rows"
echo "labels.sh: $(printf '%s\n' "$rows" | wc -l) rows, $failures problems"
[ "$failures" -eq 0 ]
