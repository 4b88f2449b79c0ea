#!/bin/sh
# relcol-shock --sweep-c on a small tube (a few seconds): the files, one row per c, one
# profile row per c and bin, Sod's values equal to the relativistic ones at c = inf, and at
# every c where the relativistic solution and Sod's differ by more than 3 errors of the
# measurement, the balls' plateau p, v and shock speed closer to the relativistic one (a
# control with the two references swapped must fail). Bad lists are refused.
set -u
app="$1"
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
expect() { # expect CODE PATTERN ARGS...
    code="$1"; pat="$2"; shift 2
    "$app" "$@" >"$dir/out" 2>"$dir/err"; rc=$?
    if [ "$rc" != "$code" ] || ! grep -q -- "$pat" "$dir/err"; then
        fail "$* -> $rc: $(cat "$dir/err")"
    fi
}
expect 2 "\-\-sweep-c: c = 0 must be > 0" --sweep-c 1,0
expect 2 "\-\-sweep-c: not a number" --sweep-c 1,x
expect 2 "\-\-sweep-c: more than 16" --sweep-c 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17
expect 2 "\-\-sweep-c: not with \-\-c" --sweep-c inf,2 --c 3
expect 2 "\-\-v-left: |v| = 1 must be < c" --sweep-c inf,1 --v-left 1
# 3-D, 1728 balls a seed, 4 seeds, read at t = 200 (Kn 0.05 at c = inf, 0.09 at c = 1.5)
"$app" --out "$dir/s" --sweep-c inf,3,1.5 --seeds 4 --length 1000 --width 12 \
    --n-left 0.016 --n-right 0.008 --times 100,200 --bins 40 --quiet 2>"$dir/s.err" ||
    fail "the sweep: $(cat "$dir/s.err")"
for f in sweep.csv summary.json sweep_profiles.csv sweep.gp; do
    [ -s "$dir/s/$f" ] || fail "no $f"
done
[ "$(wc -l < "$dir/s/sweep.csv")" -eq 4 ] || fail "sweep.csv rows"
[ "$(wc -l < "$dir/s/sweep_profiles.csv")" -eq 121 ] || fail "sweep_profiles.csv rows"
grep -q "multiplot layout 3,3" "$dir/s/sweep.gp" || fail "no 3 x 3 multiplot"
# columns of sweep.csv: c 1, p 6 err 7 rel 8 sod 9, v 10-13, shock 14-17
judge() { # judge REL SOD: the number of checks made, or exit 1 at a measurement nearer SOD
    awk -F, -v R="$1" -v S="$2" 'NR > 1 {
        for (b = 6; b <= 14; b += 4) {
            m = $b; e = $(b + 1); r = $(b + R); s = $(b + S)
            if ($1 == "inf" && r != s) { print "c = inf: relativistic != Sod"; bad = 1 }
            d = r - s; if (d < 0) d = -d
            if (e == "nan" || !(d > 3 * e)) continue
            n++; dr = m - r; ds = m - s; if (dr < 0) dr = -dr; if (ds < 0) ds = -ds
            if (!(dr < ds)) { print "c = " $1 " column " b ": " m " +- " e " nearer " s " than " r; bad = 1 }
        } } END { print n + 0; exit bad }' "$dir/s/sweep.csv"
}
if out=$(judge 2 3); then
    [ "$(echo "$out" | tail -1)" -ge 3 ] || fail "only $out comparisons beyond the errors"
else
    fail "$out"
fi
# the fitted order of v* (summary.json) against the same weighted least squares done here
# from sweep.csv: ln|v(c)/v(inf) - 1| on ln c over the c beyond three errors
fit=$(awk -F, 'NR > 1 && $1 == "inf" { v0 = $10; e0 = $11 }
    NR > 1 && $1 != "inf" { c[++k] = $1; v[k] = $10; e[k] = $11 }
    END { for (i = 1; i <= k; i++) { r = v[i] / v0; d = r - 1; er = r * sqrt((e[i] / v[i])^2 + (e0 / v0)^2)
            if (d < 0) d = -d; if (!(d > 3 * er)) continue
            x = log(c[i]); y = log(d); w = (d / er)^2; n++
            sw += w; sx += w * x; sy += w * y; sxx += w * x * x; sxy += w * x * y }
          if (n < 2) print "none"; else printf "%.5g\n", (sw * sxy - sx * sy) / (sw * sxx - sx * sx) }' "$dir/s/sweep.csv")
got=$(sed -n 's/.*"v_star": {"slope": \([^,]*\),.*/\1/p' "$dir/s/summary.json")
if [ "$fit" = none ]; then
    [ "$got" = null ] || fail "v* order $got where no two c are beyond the errors"
else
    awk -v a="$got" -v b="$fit" 'BEGIN { d = a - b; exit !(d < 1e-3 && d > -1e-3) }' ||
        fail "v* order: summary.json $got, sweep.csv's fit $fit"
fi
judge 3 2 > /dev/null && fail "the control (references swapped) passed"
echo "$fails failed"
[ "$fails" -eq 0 ]
