#!/bin/sh
# test_covariance_cli.sh RELCOL_COVARIANCE HARNESS — relcol-covariance through its command
# line: every bad option is one stderr line naming it (exit 2); a tiny run writes the CSV
# with its columns, one row per (frame, density, c), and the script (and with gnuplot the
# figure); its classical rows agree between the frames to round-off.
C=$1
. "$2"

expect_bad n '' '^relcol-covariance: --n: ' --n 10
expect_bad dim '' '^relcol-covariance: --dim: ' --dim 4
expect_bad density '' '^relcol-covariance: --density: 0.5 outside \(0, 0.08\] in 2-D' --density 0.5
expect_bad density3 '' '^relcol-covariance: --density: 0.05 outside \(0, 0.025\] in 3-D' --dim 3 --density 0.05
expect_bad density0 '' '^relcol-covariance: --density: 0 outside' --density 0,0.01
expect_bad densitynan '' "^relcol-covariance: --density: " --density 0.01,x
expect_bad c '' '^relcol-covariance: --c: ' --c -1
expect_bad cslow '' '^relcol-covariance: --v-rms: 0.5 is not below c = 0.4' --c 0.4 --boost 0.1
expect_bad cempty '' '^relcol-covariance: --c: ' --c ','
expect_bad ctwice '' '^relcol-covariance: --c: inf given twice' --c inf,2,inf
expect_bad dtwice '' '^relcol-covariance: --density: 0.01 given twice' --density 0.01,0.004,0.01
expect_bad boost0 '' '^relcol-covariance: --boost: 0 must be nonzero' --boost 0
expect_bad boostc '' '^relcol-covariance: --boost: \|U\| = 2 is not below c = 1' --boost 2
expect_bad vrms '' '^relcol-covariance: --v-rms: -1 outside \[1e-06, 1e\+06\]' --v-rms -1
expect_bad boostfar '' '^relcol-covariance: --boost: \|U\| = 0.6 is more than 1000 times --v-rms 1e-05' --v-rms 1e-5
expect_bad frame '' "^relcol-covariance: --frames: unknown frame 'bogus' \(known: " --frames table,bogus
expect_bad frame2 '' "^relcol-covariance: --frames: 'table' given twice" --frames table,table
expect_bad seed '' '^relcol-covariance: --seed: ' --seed 5000000000
expect_bad out '' '^relcol-covariance: --out: empty' --out ''
expect_bad unknown '' '^relcol-covariance: unknown option --bogus' --bogus
expect_bad stray '' "^relcol-covariance: unexpected argument 'x'" x
# a ball faster than c (the draw's fastest balls move at about 1.5 v_rms)
expect_bad fast '' '^relcol-covariance: --c: at c = 0.6 a ball' --c 0.6 --v-rms 0.5 --boost 0.3

run '' --help
[ "$st" -eq 0 ] && grep -q 'covariance.csv' "$T/out" && ok || bad "--help: exit $st"

# the tiny run: every default frame, two densities, c = 2 and classical
run '' --n 50 --density 0.004,0.01 --c 2,inf --out "$T/c"
expect_ok tiny
csv=$T/c/covariance.csv
head='frame,covariant,c,c_index,density,radius,n,dim,boost,v_rms,draws,collisions_table,collisions_moving,collisions_roundoff,overlaps_table,overlaps_moving,dp_frames,dp_roundoff,dx_frames,dx_roundoff,conflicts_table,conflicts_moving,note'
[ "$(head -1 "$csv")" = "$head" ] && ok || bad "header: $(head -1 "$csv")"
nf=$(awk -F, 'NR > 1 {print $1}' "$csv" | sort -u | wc -l)
rows=$(awk 'END {print NR - 1}' "$csv")
[ "$nf" -ge 2 ] && [ "$rows" -eq $((nf * 4)) ] && ok || bad "$rows rows for $nf frames, want 4 each"
# every row has 23 fields, covariant is 0 or 1, n = 50, and a row either has all its
# differences or a note saying why not
awk -F, 'NR > 1 && (NF != 23 || ($2 != 0 && $2 != 1) || $7 != 50 ||
                    (($17 == "") != ($23 != ""))) {print "row " NR - 1 ": " $0; b = 1}
         END {exit b}' "$csv" > "$T/bad" && ok || bad "rows: $(cat "$T/bad")"
# the classical rows (c = inf): the change of frame is Galilean and the engine Galilean
# invariant, so the frames may differ only by round-off as the dynamics amplifies it: the
# 1e-15 run's difference (times 1e3: the frame change's own round-off is a few ulps of
# positions and velocities, not one ulp of x) or 1e-9; every frame has such a row
awk -F, 'NR > 1 && $3 == "inf" {
            if ($17 == "") {print "no differences: " $0; b = 1; next}
            if (!($17 <= 1e3 * $18 || $17 <= 1e-9)) {print "dp_frames " $17 " vs round-off " $18 ": " $0; b = 1}
            n++ }
         END {if (n == 0) {print "no classical row"; b = 1}; exit b}' "$csv" > "$T/bad" && ok \
    || bad "classical rows: $(cat "$T/bad")"
# the default cluster (64 balls, every default density and frame) classically, 2-D and
# 3-D: the same check at full size, and the same contacts in both runs (each run ends
# after its last contact, so none counts in one run only)
for dim in 2 3; do
    run '' --dim $dim --c inf --out "$T/g$dim"
    expect_ok "galilean$dim"
    awk -F, 'NR > 1 {
                if ($17 == "") {print "no differences: " $0; b = 1; next}
                if ($12 != $13) {print "contacts " $12 " / " $13 ": " $0; b = 1}
                if (!($17 <= 1e3 * $18 || $17 <= 1e-9)) {print "dp_frames " $17 " vs round-off " $18 ": " $0; b = 1}
                n++ }
             END {if (n < 8) {print n " rows"; b = 1}; exit b}' "$T/g$dim/covariance.csv" > "$T/bad" \
        && ok || bad "default classical rows, $dim-D: $(cat "$T/bad")"
done
# and the relativistic rows are numbers (the frame dependence itself is reported, not tested)
awk -F, 'NR > 1 && $3 == 2 && $17 != "" {n++} END {exit n == 0}' "$csv" && ok \
    || bad "no c = 2 row with differences"
[ -s "$T/c/covariance.gp" ] && ok || bad "no covariance.gp"
if command -v gnuplot > /dev/null 2>&1; then
    [ -s "$T/c/covariance.png" ] && ok || bad "no covariance.png"
fi
# the figure explains itself (issue 38): frames named without "(covariant)" and each kind
# of frame said in the heading; the frames' points offset sideways (one factor per frame,
# so equal values stay visible); a difference within 10x of its round-off control ringed
gp=$T/c/covariance.gp
grep -q "(covariant)" "$gp" && bad "covariance.gp still says (covariant)" || ok
grep -q "table: contact at one table-frame instant" "$gp" && \
    grep -q "covariant: frame-independent contact event, each ball changed at its own event" "$gp" \
    && ok || bad "covariance.gp does not say what each frame is"
k=$(grep -o 'using (\$5\*[0-9.]*):17' "$gp" | sort -u | wc -l)
[ "$k" -eq "$nf" ] && ok || bad "covariance.gp: $k sideways offsets for $nf frames"
if awk -F, 'NR > 1 && $17 != "" && $17 <= 10 * $18 {f = 1} END {exit !f}' "$csv"; then
    grep -q "title 'not resolved'" "$gp" && grep -qF '$17 <= 10*$18' "$gp" && \
        grep -q "ringed: within 10× of its round-off control" "$gp" && ok \
        || bad "covariance.gp: differences within 10x of round-off are not ringed"
else
    grep -q "title 'not resolved'" "$gp" && bad "covariance.gp rings with no row to ring" || ok
fi
# stdout: one line per row between the heading and the files
lines=$(wc -l < "$T/out")
[ "$lines" -eq $((rows + 3)) ] && ok || bad "stdout: $lines lines for $rows rows"

[ ! -e "$T/c/covariance-c.gp" ] && ok || bad "covariance-c.gp with one finite c"

# missing points are marked and explained: at c = 1 and density 0.04 no draw of the default
# cluster starts collision-free in both frames, so that panel has only an x with its note
run '' --frames table,zmf --c 1,inf --density 0.04 --out "$T/m"
expect_ok missing
gp=$T/m/covariance.gp
grep -q "no draw starts collision-free" "$T/m/covariance.csv" && \
    grep -q "×1 no value: no draw starts collision-free in both frames" "$gp" && \
    grep -q "^set label [0-9]* '1' at first 0.04, graph .* point pt 2" "$gp" && ok \
    || bad "covariance.gp: the missing rows are not marked with their note"

# the lists come sorted, and with two finite c the figure against c is written too
run '' --frames zmf --n 50 --density 0.004 --c 3,2 --out "$T/s"
expect_ok sorted
[ "$(awk -F, 'NR > 1 {printf "%s;", $3}' "$T/s/covariance.csv")" = "2;3;" ] && ok \
    || bad "c column not sorted: $(cat "$T/s/covariance.csv")"
[ -s "$T/s/covariance-c.gp" ] && ok || bad "no covariance-c.gp"
if command -v gnuplot > /dev/null 2>&1; then
    [ -s "$T/s/covariance-c.png" ] && ok || bad "no covariance-c.png"
fi

# one frame chosen by name, 3-D
run '' --frames table --dim 3 --n 50 --density 0.004 --c inf --out "$T/d"
expect_ok one3d
awk -F, 'NR == 2 && $1 == "table" && $8 == 3 && $17 != "" && ($17 <= 1e3 * $18 || $17 <= 1e-9) {f = 1}
         END {exit !(f && NR == 2)}' "$T/d/covariance.csv" && ok \
    || bad "3-D table row: $(cat "$T/d/covariance.csv")"

summary
