#!/bin/sh
# test_frames_cli.sh — relcol-frames: writes frames.csv and frames.gp (and frames.png when
# gnuplot is installed) into --out, and the fitted orders are those the physics gives:
# contraction ignored vs included differs at (v/c)^2, table vs zmf frame at (v/c)^4
# (ranges +-0.05: the fits over c >= 10 v carry the next order, ~1% at c = 10 v).
# Usage: test_frames_cli.sh PATH/relcol-frames
F=${1:?usage: test_frames_cli.sh relcol-frames}
T=$(mktemp -d) || exit 1
trap 'rm -rf "$T"' EXIT
fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

"$F" --out "$T/f" --points 17 > "$T/out" 2> "$T/err" || bad "exit $? ($(cat "$T/err"))"
[ -s "$T/f/frames.csv" ] || bad "no frames.csv"
[ -s "$T/f/frames.gp" ] || bad "no frames.gp"
if command -v gnuplot > /dev/null 2>&1; then
    [ -s "$T/f/frames.png" ] || bad "gnuplot installed but no frames.png"
fi
# the figure explains itself (issue 38): the reference lines are named in the key, each
# pair of frames has its own title (and colour family), and the shading is explained
gp="$T/f/frames.gp"
for want in "title '(v/c)^2'" "title '(v/c)^4'" "title 'table vs zmf'" \
            "title 'table vs sphere (no contraction)'" "light to dark: b/R = 0.25"; do
    grep -qF "$want" "$gp" || bad "frames.gp lacks: $want"
done
# no two pairs of frames share a colour
awk '/^plot/ { delete owner } /lc rgb/ && /\$1 ==/ { match($0, /\$[0-9]+ > 0/); col = substr($0, RSTART + 1, RLENGTH - 5)
     match($0, /#[0-9a-f]+/); rgb = substr($0, RSTART, RLENGTH)
     if ((rgb in owner) && owner[rgb] != col) bad = 1; owner[rgb] = col }
     END { exit bad }' "$gp" || bad "frames.gp: two pairs of frames share a colour"
ls "$T/f" | grep -q '\.tmp' && bad "temporary files left in --out"
# header + 6 impact parameters x 17 values of c
[ "$(wc -l < "$T/f/frames.csv")" -eq 103 ] || bad "frames.csv has $(wc -l < "$T/f/frames.csv") lines"
range() { # PAIR LO HI: both ends of the printed p range inside [LO, HI]
    line=$(grep "^$1: frame differences vanish" "$T/out")
    [ -n "$line" ] || { bad "no summary for $1"; return; }
    echo "$line" | awk -v lo="$2" -v hi="$3" '{ gsub(/[\[\],]/, " "); for (i = 1; i <= NF; i++)
        if ($i == "in") { a = $(i + 1); b = $(i + 2) } }
        END { exit !(a >= lo && b <= hi) }' || bad "$1: $line (want p in [$2, $3])"
}
range "table vs sphere" 1.95 2.05
range "zmf vs sphere" 1.95 2.05
range "table vs zmf" 3.95 4.05
grep -q "0     angle *exact 0 *exact 0 *exact 0" "$T/out" || bad "head-on differences not exactly 0"

"$F" --from 0.5 > "$T/out" 2> "$T/err"
[ $? -eq 2 ] && grep -q -- '--from' "$T/err" || bad "--from 0.5 accepted"
"$F" --bogus 1 > "$T/out" 2> "$T/err"
[ $? -eq 2 ] && grep -q 'unknown option --bogus' "$T/err" || bad "unknown option accepted"

echo "cli-frames: $fail failed"
[ "$fail" -eq 0 ]
