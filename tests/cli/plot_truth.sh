#!/usr/bin/env bash
# plot_truth.sh VERIFY: the pictures show the shot that was computed (issue 22, items 1 and 2).
# - Under --air with a target 15 m below, the flight drawn ends where the reported range does
#   (flight.csv's last x is R of the JSON, to its 6 printed digits), is labelled as flown
#   through air, and the page and every title say air and the target level.
# - A shot whose counterweight starts below the base (F = 2) carries NOT PHYSICAL and the
#   warning on every picture, and in the shot the page draws.
set -u
verify=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
fail() { echo "FAIL: $*"; status=1; }
engine=(--L1 4.13m --L2 0.88m --L4 3.55m --M 3.11t --m 50kg --mb 174kg)

"$verify" shot "${engine[@]}" --F 2/3 --air --target-level -15m --format json --plot "$dir/air" > "$dir/air.json" || fail "--air --plot exited $?"
R=$(grep -m1 '"R":' "$dir/air.json" | tr -dc '0-9.e+-')
last_x=$(tail -1 "$dir/air/flight.csv" | cut -d, -f1)
awk -v a="$R" -v b="$last_x" 'BEGIN { d = a / b - 1; exit !(d < 1e-5 && d > -1e-5) }' || fail "the flight ends at x = $last_x m, the range is $R m"
grep -q "flight (air)" "$dir/air/paths.gp" || fail "paths.gp does not label the flight as through air"
grep -q "flight (vacuum)" "$dir/air/paths.gp" && fail "paths.gp labels the flight as in vacuum"
grep -q "R = $(printf '%.4g' "$R") m" "$dir/air/paths.gp" || fail "paths.gp does not print R = $R m"
# index.html is the page's viewer, drawn by script from the shot inside it (tests/web/page.test.mjs
# renders it); its heading, before any script, says what was computed.
heading=$(sed -n '1,/<script/p' "$dir/air/index.html")
grep -q "air (Cd 0.47" <<<"$heading" || fail "index.html does not describe the air"
grep -q "in vacuum" <<<"$heading" && fail "index.html says 'in vacuum'"
grep -q '"air":{"density":1.2' "$dir/air/index.html" || fail "index.html does not carry the shot's air"
for gp in engine paths forces energy release; do
  grep -q "in air (Cd 0.47), release where Q peaks (eq:Q), target level -15 m" "$dir/air/$gp.gp" || fail "$gp.gp does not name the air and the target level"
done

"$verify" shot "${engine[@]}" --F 2 --plot "$dir/below" > /dev/null || fail "--F 2 --plot exited $?"
for gp in engine paths forces energy release animation; do
  grep -q "NOT PHYSICAL" "$dir/below/$gp.gp" || fail "$gp.gp does not say NOT PHYSICAL"
  grep -q "counterweight passes below the engine's base" "$dir/below/$gp.gp" || fail "$gp.gp does not give the warning"
done
grep -q '"warnings":\["[^]]*counterweight passes below' "$dir/below/index.html" || fail "index.html does not carry the warning"
"$verify" shot "${engine[@]}" --F 2/3 --plot "$dir/fine" > /dev/null
grep -q "NOT PHYSICAL" "$dir/fine/"*.gp && fail "a shot without warnings is marked NOT PHYSICAL"
[ "$status" = 0 ] && echo "the pictures show the air, the target level and the warnings"
exit $status
