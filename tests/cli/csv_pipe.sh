#!/usr/bin/env bash
# csv_pipe.sh CALC VERIFY SITES: the calculator's batch CSV piped into the verifier, one row a
# site (issue 15). sites.csv is written as a spreadsheet in a decimal-comma locale writes it: a
# byte-order mark, CRLF, ';' between cells, decimal commas, "150 m" with a blank, the unit of m
# in its header (m_kg), a 'site' and a 'note' column, a row with a negative mass and a row with
# an ambiguous "1,500". Checks that every site comes out in its place, in both programs, the
# bad rows with their error, the good ones verified, and the exit codes non-zero.
set -u
calc=$1 verify=$2 sites=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
fail() { echo "FAIL: $*"; status=1; }

"$calc" --batch "$sites" > "$dir/calc.csv" 2> "$dir/calc.err"
calc_code=$?
"$verify" - --format csv < "$dir/calc.csv" > "$dir/verify.csv" 2> "$dir/verify.err"
verify_code=$?
cat "$dir/calc.csv" "$dir/calc.err" "$dir/verify.csv" "$dir/verify.err"
[ "$calc_code" -eq 8 ] || fail "calc exit $calc_code, expected 8 (some rows failed)"
[ "$verify_code" -eq 2 ] || fail "verify exit $verify_code, expected 2 (rows that failed upstream)"

# The site column is the second of the calculator's output (after line) and the first of the
# verifier's (the pass-through columns lead); no cell before it is quoted.
expected_sites=$'Alcala la Vieja Ca\na bad row\nSaone\nthousands?\nVillard'
[ "$(tail -n +2 "$dir/calc.csv" | cut -d, -f2)" = "$expected_sites" ] || fail "calc: the sites are not in their places"
[ "$(tail -n +2 "$dir/verify.csv" | cut -d, -f2)" = "$expected_sites" ] || fail "verify: the sites are not in their places"
[ "$(head -1 "$dir/verify.csv" | cut -d, -f1-3)" = "line,site,note" ] || fail "verify: the pass-through columns do not lead"
head -1 "$dir/calc.csv" | grep -q '^line,site,note,R_m,T_J,' || fail "calc: header without units"
head -1 "$dir/verify.csv" | grep -q ',R_m,T_J,R_vacuum_m,T_vacuum_J,eps,Q,' || fail "verify: header without units"
head -1 "$dir/verify.csv" | grep -q ',error$' || fail "verify: no error column"

# The bad rows keep their place with the reason; the good rows have no error.
grep -q "^3,a bad row,.*m: '-5kg' must be positive" "$dir/verify.csv" || fail "the negative mass is not in its row"
grep -q '^5,thousands?,.*could be a decimal comma or a thousands separator' "$dir/verify.csv" || fail "the ambiguous comma is not in its row"
grep -q "line 3 (site a bad row, note the stone's mass is negative)" "$dir/verify.err" || fail "stderr does not name the bad row by its site"

# The good rows: "250,5 m" read as 250.5 m, "80,5" as 80.5 kg, and each verified within the
# default 2 % (the calculator's constants hold to about 1 %): pass = yes.
grep -q '^4,Saone,"decimal comma, quoted",250.5,' "$dir/calc.csv" || fail "'250,5 m' is not 250.5 m"
grep -q '^6,Villard,decimal comma in the mass,300,' "$dir/calc.csv" || fail "Villard's row is not R = 300 m"
[ "$(grep -c ',yes,vacuum,Q,' "$dir/verify.csv")" -eq 3 ] || fail "not three verified rows that pass"

# Six significant digits by default, every digit with --digits 17.
tail -n +2 "$dir/calc.csv" | head -1 | grep -q ',40454.7,' || fail "calc: T not at 6 digits"
"$calc" --batch "$sites" --digits 17 2> /dev/null | grep -q ',40454.745502907805,' || fail "calc --digits 17: T not exact"

# --format json with --batch is JSON, with the pass-through columns.
"$calc" --batch "$sites" --format json 2> /dev/null > "$dir/calc.json"
grep -q '"site": "Saone"' "$dir/calc.json" || fail "calc --format json --batch: no site"
grep -q '"exit_code": 4' "$dir/calc.json" || fail "calc --format json --batch: the bad row has no exit code"
exit $status
