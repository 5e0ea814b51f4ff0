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
# A sweep of a release reads its points off one trajectory for each run of twenty
# (check_released_designs): 45 points are three runs, spread over two threads as they come free,
# with the same records, refusals included (the pins past the window's end never come).
one=$("$verify" sweep "${engine[@]}" --L4 5.8m --vary pin_angle=-60..170 --points 45 --threads 1 --format json)
two=$("$verify" sweep "${engine[@]}" --L4 5.8m --vary pin_angle=-60..170 --points 45 --threads 2 --format json)
[ "$one" = "$two" ] || { echo "FAIL: a sweep of the pin angle differs between 1 and 2 threads"; exit 1; }
refused=$(printf '%s' "$one" | /usr/bin/python3 -c "import json, sys; print(sum('error' in p for p in json.load(sys.stdin)['points']))")
[ "$refused" -gt 0 ] && [ "$refused" -lt 45 ] || { echo "FAIL: expected some of the 45 pins refused, got $refused"; exit 1; }
echo "pin sweep: the same 45 records on 1 and 2 threads, $refused refused"
