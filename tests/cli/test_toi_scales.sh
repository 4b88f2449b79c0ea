#!/bin/sh
# test_toi_scales.sh RELCOL_TOI — relcol-toi at every scale its reader accepts (issue 37
# item 5): a pair of unit balls, ball 0 at the origin moving at 0.5 along x, ball 1 at rest
# a distance D away along x (D = 1e1 .. 1e150, the reader's range), in 1-, 2- and 3-D, in
# every frame, classical (c = inf: every frame meets at t = (D - 2) / 0.5, the point
# D - 1 on the axis, normal +x): either that row (t and the point to 1e-12 relative, the
# normal |n| = 1 to 1e-12; the transport frame meets elsewhere: a finite row) up to
# D = 1e12, and from 1e13 on exit 2 with one line saying the contact cannot be resolved
# (rc_toi: the doubles at the centres coarser than 1e-3 of the radius, D > 4.5e12) --
# never a NaN with exit 0 (relcol-toi printed -nan from D ~ 1e17), a wrong sign (-1 at
# 1e30) or a miss (c = 1, from 1e16). With c = 1, a finite row with |n| = 1.
. "$(dirname "$0")/harness.sh"
C="$1"
rows=0; refused=0
for e in 1 3 6 9 12 15 16 17 18 20 30 60 100 150; do
    D="1e$e"
    for dim in 1 2 3; do
        case $dim in
        1) hdr='r,x,vx'; b0='1,0,0.5'; b1="1,$D,0" ;;
        2) hdr='r,x,y,vx,vy'; b0='1,0,0,0.5,0'; b1="1,$D,0,0,0" ;;
        3) hdr='r,x,y,z,vx,vy,vz'; b0='1,0,0,0,0.5,0,0'; b1="1,$D,0,0,0,0,0" ;;
        esac
        for frame in table zmf sphere transport covariant; do
            for c in inf 1; do
                run "$hdr\n$b0\n$b1\n" --c "$c" --frame "$frame"
                name="D=$D ${dim}-D $frame c=$c"
                if grep -qi 'nan\|inf' "$T/out"; then
                    bad "$name: $(cat "$T/out" | tail -1), exit $st"
                elif [ "$st" -eq 2 ]; then
                    if [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q 'contact cannot be resolved' "$T/err" &&
                       [ "$e" -ge 13 ]; then
                        ok; refused=$((refused + 1))
                    else
                        bad "$name: exit 2: $(cat "$T/err")"
                    fi
                elif [ "$st" -eq 0 ] && [ "$e" -le 12 ]; then
                    rows=$((rows + 1))
                    line=$(tail -1 "$T/out")
                    # |n| = 1 (the last dim columns), and classically t, x
                    awk -F, -v d="$dim" -v D="$D" -v c="$c" -v f="$frame" '{
                        nn = 0; for (k = 0; k < d; k++) nn += $(NF - k) ^ 2
                        if (nn < 1 - 1e-12 || nn > 1 + 1e-12) exit 1
                        if (c == "inf" && f != "transport") {
                            t = (D - 2) / 0.5; x = D - 1
                            if ((($1 - t) ^ 2) ^ 0.5 > 1e-12 * t) exit 1
                            if ((($2 - x) ^ 2) ^ 0.5 > 1e-12 * x) exit 1
                            if ($(NF - d + 1) < 1 - 1e-12) exit 1
                        } }' <<AWK && ok || bad "$name: row $line"
$line
AWK
                else
                    bad "$name: exit $st: $(cat "$T/err")"
                fi
            done
        done
    done
done
echo "$rows rows, $refused refused with the reason"
summary "toi scales"
