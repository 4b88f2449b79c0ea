#!/bin/sh
# test_eos_cli.sh RELCOL_EOS HARNESS — relcol-eos through its command line: every bad
# option is one stderr line naming it (exit 2); a short classical run writes the CSV, the
# script and (with gnuplot) the figure, and its Z lies near Kolafa's.
C=$1
. "$2"

expect_bad dim '' '^relcol-eos: --dim: ' --dim 4
expect_bad n '' '^relcol-eos: --n: ' --n 2
expect_bad packing '' '^relcol-eos: --packing: 0.8 outside' --packing 0.8
expect_bad packing3d '' '^relcol-eos: --packing: 0.6 beyond the sphere fluid' --packing 0.6
expect_bad theta '' '^relcol-eos: --theta: 0 outside' --theta 0
expect_bad c '' '^relcol-eos: --c: ' --c -1
expect_bad frame '' "^relcol-eos: --frame: unknown frame 'x'" --frame x
expect_bad blocks '' '^relcol-eos: --blocks: ' --blocks 1
expect_bad lag '' '^relcol-eos: --lag: 200 longer than a block' --transport --lag 200
expect_bad trun '' '^relcol-eos: --t-run: ' --t-run 0
expect_bad unknown '' '^relcol-eos: unknown option --bogus' --bogus

# 3-D hard spheres at packing 0.2, a short run: Z within 1 % of Kolafa (its standard error
# at this size is about 0.2 %)
run '' --n 300 --packing 0.2 --t-run 300 --t-equil 20 --out "$T/e"
expect_ok run3d
z=$(awk -F, 'NR == 2 {print $8}' "$T/e/eos.csv")
close z-kolafa "$z" 2.409375 0.01
[ -s "$T/e/eos.gp" ] && ok || bad "no eos.gp"
if command -v gnuplot > /dev/null 2>&1; then
    [ -s "$T/e/eos.png" ] && ok || bad "no eos.png"
fi
# the figure explains itself (issue 38): the right panel is relative to Kolafa and names
# Carnahan-Starling's curve as against Kolafa (not a relcol point); a one-point run writes
# its numbers; the error bars are not cut at the frame (offsets)
gp=$T/e/eos.gp
for want in "title 'Carnahan–Starling against Kolafa'" "title 'relcol against Kolafa'" \
            "100 * (z2(x) / z1(x) - 1)" "Z_{Kolafa}" "if (npts == 1) { set label 1" \
            "set offsets 0, 0, graph 0.08, graph 0.08"; do
    grep -qF "$want" "$gp" && ok || bad "eos.gp lacks: $want"
done
# with --transport the CSV carries finite D, eta, lambda
run '' --n 300 --packing 0.05 --transport --t-run 400 --lag 10 --out "$T/t"
expect_ok transport
d=$(awk -F, 'NR == 2 {print ($14 > 0 && $16 > 0 && $18 > 0) ? "ok" : "bad"}' "$T/t/eos.csv")
[ "$d" = ok ] && ok || bad "transport columns: $(sed -n 2p "$T/t/eos.csv")"
# and Green-Kubo beside them (eta_gk, lambda_gk with errors, cutoffs within the lag of 10),
# named in the header and drawn in the figure
d=$(awk -F, 'NR == 1 {ok = ($30 == "eta_gk" && $32 == "lambda_gk")} NR == 2 {print (ok && $30 > 0 && $31 > 0 &&
    $32 > 0 && $33 > 0 && $34 > 0 && $34 <= 10 && $35 > 0 && $35 <= 10) ? "ok" : "bad"}' "$T/t/eos.csv")
[ "$d" = ok ] && ok || bad "Green-Kubo columns: $(sed -n 2p "$T/t/eos.csv")"
grep -qF "title 'relcol, Green–Kubo'" "$T/t/eos.gp" && ok || bad "eos.gp: no Green-Kubo points"
# its figure: against packing (one theta), the symbols named in the heading (the keys
# of three panels covered their axes' labels)
grep -qF "using 4:14:15 with yerrorbars" "$T/t/eos.gp" && grep -qF "{/:Bold blue points}: relcol" "$T/t/eos.gp" \
    && ok || bad "transport eos.gp: not against packing, or its symbols unnamed"

# fields without a measurement or a theory are empty, never nan (D_chapman_enskog and its
# two neighbours without --transport)
grep -q nan "$T/e/eos.csv" && bad "nan in eos.csv: $(sed -n 2p "$T/e/eos.csv")" || ok
d=$(awk -F, 'NR == 2 {print ($14 == "" && $27 == "" && $28 == "" && $29 == "" && $30 == "" && $37 == "") ? "ok" : "bad"}' "$T/e/eos.csv")
[ "$d" = ok ] && ok || bad "unmeasured columns not empty: $(sed -n 2p "$T/e/eos.csv")"
# a start for N that rc_sim_gas_init's cubic lattice cannot hold at 0.45 (250 on 7^3 sites)
run '' --n 250 --packing 0.45 --t-run 10 --t-equil 2 --out "$T/p"
expect_ok start-n250
# 2-D: the theory column is Luding's disc equation of state (2001), 8.41536 at 0.65, not
# the 10-term virial series (7.9512 there)
run '' --dim 2 --n 200 --packing 0.65 --t-run 5 --t-equil 2 --out "$T/d2"
expect_ok run2d
close z-luding "$(awk -F, 'NR == 2 {print $10}' "$T/d2/eos.csv")" 8.41536 1e-5

# --sensitivity (a table row like the rest): the sphere frame's 3 runs (base, moved,
# sequential groups), Z, kT and P of the one point, both files; a folder that cannot be
# made is the option's error (exit 2)
run '' --sensitivity --n 64 --packing 0.1 --t-equil 5 --t-run 100 --blocks 5 --out "$T/s"
if [ "$st" -eq 0 ] && grep -q '^sensitivity: 0 of 3 observables flagged; 3 runs$' "$T/out" &&
    [ -s "$T/s/sensitivity.csv" ] && [ -s "$T/s/sensitivity.json" ]; then ok
else bad "--sensitivity: exit $st: $(cat "$T/out" "$T/err")"; fi
expect_bad sens-out '' '^relcol-eos: --out: cannot create folder' --sensitivity --out /dev/null/x

summary
