#!/usr/bin/env bash
# plot.sh VERIFY: `shot --plot DIR` for a small engine (tab:Alcala_la_Vieja row Ca) makes every
# picture of issue 13: each SVG well-formed (xmllint), the GIF animated with more than 20
# frames, and index.html naming every picture.
set -u
verify=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$verify" shot --L1 4.13m --L2 0.88m --F 2/3 --L4 3.55m --M 3.11t --m 50kg --mb 174kg --plot "$dir/pictures" > /dev/null || { echo "FAIL: --plot exited $?"; exit 1; }
status=0
for svg in engine paths forces energy release; do
  if ! xmllint --noout "$dir/pictures/$svg.svg"; then echo "FAIL: $svg.svg is not well-formed"; status=1; fi
  grep -q "$svg.svg" "$dir/pictures/index.html" || { echo "FAIL: index.html lacks $svg.svg"; status=1; }
done
# Each frame of an animated GIF starts with a graphic control extension, 21 F9 04.
frames=$(od -An -v -tx1 "$dir/pictures/shot.gif" | tr -d ' \n' | grep -o '21f904' | wc -l)
[ "$frames" -gt 20 ] || { echo "FAIL: shot.gif has $frames frames"; status=1; }
grep -q "shot.gif" "$dir/pictures/index.html" || { echo "FAIL: index.html lacks shot.gif"; status=1; }
[ "$status" = 0 ] && echo "5 SVG well-formed, shot.gif with $frames frames, index.html"
exit $status
