#!/usr/bin/env bash
# sweep_same_as_shot.sh VERIFY: every point of `trebuchet-verify sweep --format json` is the
# record `trebuchet-verify shot --format json` prints for that engine alone, bit for bit (issue
# 37), in air with the range-optimal release. The value is passed as the JSON's shortest
# round-trip text, so the shot's engine is the point's to the last bit.
set -euo pipefail
verify=$1
engine=(--L1 6.13m --L2 1.08m --F 1 --M 14.3t --m 100kg --mb 660kg --air --quality range)
sweep=$("$verify" sweep "${engine[@]}" --L4 5.8m --vary L4=2m..8m --points 5 --format json)
for i in 0 1 2 3 4; do
  L4=$(printf '%s' "$sweep" | /usr/bin/python3 -c "import json, sys; print(repr(json.load(sys.stdin)['points'][$i]['engine']['L4']))")
  single=$("$verify" shot "${engine[@]}" --L4 "${L4}m" --format json)
  printf '%s' "$sweep" | /usr/bin/python3 -c "
import json, sys
point = json.load(sys.stdin)['points'][$i]
single = json.loads(sys.argv[1])
assert point == single, 'point $i (L4 = $L4 m) differs from its shot alone'
print('point $i: L4 = $L4 m, R =', point['R'], 'm, the same record as its shot alone')
" "$single"
done
