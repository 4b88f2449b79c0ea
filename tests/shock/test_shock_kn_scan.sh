#!/bin/sh
# relcol-shock --kn-scan on a small tube (3-D, c = inf, 2400 balls, 8 seeds, t = 400, Kn
# 0.025, 0.2, 5; about 20 s of CPU): the files; the distance from the ideal fluid rises and the distance from
# free streaming falls as Kn grows; at the smallest Kn the fluid is the nearer reference,
# at the largest free streaming (the same checks with the two references swapped must
# fail); the crossing lies inside the list. Bad lists are refused with their reasons.
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
expect 2 "\-\-kn-scan: a scan needs at least two" --kn-scan 0.1
expect 2 "\-\-kn-scan: Kn = 0.05 is not above the one before" --kn-scan 0.1,0.05
expect 2 "\-\-kn-scan: Kn = 0 must be in (0, 1000\]" --kn-scan 0,1
expect 2 "\-\-kn-scan: Kn = 2000 must be in" --kn-scan 1,2000
expect 2 "\-\-kn-scan: not a number" --kn-scan 0.1,x
expect 2 "\-\-kn-scan: more than 16" --kn-scan 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17
expect 2 "\-\-kn-scan: not with \-\-radius" --kn-scan 0.1,1 --radius 0.3
expect 2 "\-\-kn-scan: not with \-\-sweep-c" --kn-scan 0.1,1 --sweep-c inf,2
expect 2 "\-\-kn-scan: Kn = 0.001 needs radius .* packed" --kn-scan 0.001,1
expect 2 "\-\-kn-scan: the right wave is not a shock" --kn-scan 0.1,1 --n-left 0.001 --T-left 0.5
expect 2 "\-\-gif: not with \-\-kn-scan" --kn-scan 0.1,1 --gif
# (the three Kn lie a factor 8-25 apart: measured, d_fluid 0.33, 0.72, 0.92 and d_free
# 0.80, 0.43, 0 with errors 0.03-0.19, and each within 0.07 at W = 12 over two seed sets;
# closer neighbours, 0.5 and 5 at
# t = 200, reversed d_free in one set of three, both near free streaming)
"$app" --out "$dir/k" --kn-scan 0.025,0.2,5 --seeds 8 --length 2000 --width 10 \
    --n-left 0.016 --n-right 0.008 --times 400 --bins 80 --quiet 2>"$dir/k.err" ||
    fail "the scan: $(cat "$dir/k.err")"
for f in kn_scan.csv kn_scan_profiles.csv kn_scan.json kn_scan.gp kn_scan_profiles.gp; do
    [ -s "$dir/k/$f" ] || fail "no $f"
done
[ "$(wc -l < "$dir/k/kn_scan.csv")" -eq 4 ] || fail "kn_scan.csv rows"
[ "$(wc -l < "$dir/k/kn_scan_profiles.csv")" -eq 241 ] || fail "kn_scan_profiles.csv rows"
# columns of kn_scan.csv: kn 1, d_fluid 9, d_free 11
judge() { # judge FLUID FREE: exit 1 unless the trends and the extremes hold
    awk -F, -v F="$1" -v S="$2" 'NR > 1 {
        k++; fl[k] = $F; fr[k] = $S; kn[k] = $1 }
        END {
            for (i = 2; i <= k; i++) {
                if (!(fl[i] > fl[i - 1])) { print "d_fluid does not rise from Kn " kn[i - 1] " to " kn[i]; bad = 1 }
                if (!(fr[i] < fr[i - 1])) { print "d_free does not fall from Kn " kn[i - 1] " to " kn[i]; bad = 1 }
            }
            if (!(fl[1] < fr[1])) { print "at Kn " kn[1] " the fluid is not the nearer"; bad = 1 }
            if (!(fr[k] < fl[k])) { print "at Kn " kn[k] " free streaming is not the nearer"; bad = 1 }
            exit bad }' "$dir/k/kn_scan.csv"
}
out=$(judge 9 11) || fail "$out"
judge 11 9 > /dev/null && fail "the control (references swapped) passed"
awk -F'"crossing_kn": ' 'NF > 1 { split($2, a, ","); x = a[1] + 0; ok = x > 0.025 && x < 5 }
    END { exit !ok }' "$dir/k/kn_scan.json" || fail "no crossing inside the list: $(cat "$dir/k/kn_scan.json")"
echo "$fails failed"
[ "$fails" -eq 0 ]
