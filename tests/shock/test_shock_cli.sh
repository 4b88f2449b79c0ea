#!/bin/sh
# relcol-shock through its command line: every bad input is refused with exit 2 (1 for a
# start it cannot place) and a message naming the input; a small run writes its files.
set -u
app="$1"
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
fails=0
expect() { # expect CODE PATTERN ARGS...
    code="$1"; pat="$2"; shift 2
    "$app" "$@" >"$dir/out" 2>"$dir/err"; rc=$?
    if [ "$rc" != "$code" ] || ! grep -q -- "$pat" "$dir/err"; then
        echo "FAIL: $* -> $rc: $(cat "$dir/err")"; fails=$((fails + 1))
    fi
}
expect 2 "c = -1 must be > 0" --c -1
expect 2 "times must be > 0 and increasing" --times 3,1
expect 2 "|v| = 2 must be < c" --v-left 2 --c 1
expect 2 "below four ball diameters" --width 1
expect 2 "unknown option --bogus" --bogus
expect 2 "unknown frame" --frame nope
expect 2 "\-\-dim" --dim 4
expect 2 "must be > 0" --n-left -1
expect 1 "packing fraction" --n-left 0.5 --out "$dir/x"
"$app" --out "$dir/run" --seeds 2 --length 600 --width 8 --times 50,100 --bins 20 --quiet || fails=$((fails + 1))
for f in profiles.csv summary.json shock.gp; do
    [ -s "$dir/run/$f" ] || { echo "FAIL: no $f"; fails=$((fails + 1)); }
done
[ "$(wc -l < "$dir/run/profiles.csv")" -eq 41 ] || { echo "FAIL: rows"; fails=$((fails + 1)); }
grep -q '"model": {"verdict": "defined"' "$dir/run/summary.json" || { echo "FAIL: no model block"; fails=$((fails + 1)); }
# the validity report: a dense covariant tube at c = 1 is outside the rigid-ball model's
# regime and says so in one warning line (and its model block); the c = inf run above did not
"$app" --out "$dir/cov" --dim 2 --c 1 --frame covariant --n-left 0.2 --n-right 0.1 --length 400 \
    --width 20 --times 20,40 --seeds 2 --bins 20 --quiet 2>"$dir/cov.err" || fails=$((fails + 1))
[ "$(grep -c "relcol-shock: warning: .*outside the rigid-ball model's regime" "$dir/cov.err")" -eq 1 ] &&
    [ "$(wc -l < "$dir/cov.err")" -eq 1 ] || { echo "FAIL: no one-line warning: $(cat "$dir/cov.err")"; fails=$((fails + 1)); }
grep -q '"model": {"verdict": "outside", "seeds": 2, "seeds_outside": 2' "$dir/cov/summary.json" ||
    { echo "FAIL: model block of the covariant run"; fails=$((fails + 1)); }
"$app" --out "$dir/run2" --seeds 2 --length 600 --width 8 --times 50,100 --bins 20 --quiet 2>"$dir/run2.err" || fails=$((fails + 1))
[ ! -s "$dir/run2.err" ] || { echo "FAIL: warned inside the regime: $(cat "$dir/run2.err")"; fails=$((fails + 1)); }
"$app" --help | grep -q "usage: relcol-shock" || fails=$((fails + 1))
echo "$fails failed"
[ "$fails" -eq 0 ]
