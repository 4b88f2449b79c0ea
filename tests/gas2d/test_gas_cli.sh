#!/bin/sh
# test_gas_cli.sh RELCOL_GAS HARNESS — relcol-gas through its command line: every bad
# option is one stderr line naming it (exit 2); a short 2-D run of uncontracted discs reads
# the same theta both ways and writes the CSV, the script and (with gnuplot) the figure;
# a short 1-D mixture run writes both species.
C=$1
. "$2"

expect_bad dim '' '^relcol-gas: --dim: ' --dim 4
expect_bad n '' '^relcol-gas: --n: ' --n 1
expect_bad c-inf '' '^relcol-gas: --c: must be finite' --c inf
expect_bad c-neg '' '^relcol-gas: --c: ' --c -1
expect_bad theta '' '^relcol-gas: --theta-start: ' --theta-start 0
expect_bad vrms '' '^relcol-gas: --v-rms: 1 must be below c' --v-rms 1
expect_bad both '' '^relcol-gas: --v-rms: conflicts with --theta-start' --v-rms 0.5 --theta-start 1
# temperatures the readings cannot resolve are refused, not printed as inf or nan (a
# theta of 1e-8 gave chi2 inf and '-inf sigma'; v_rms a ulp below c, theta = 3e7)
expect_bad theta-tiny '' '^relcol-gas: --theta-start: 1e-08 outside \[0.001, 1000\]' --theta-start 1e-8
expect_bad vrms-near-c '' '^relcol-gas: --v-rms: 0.9999999999999999 gives every ball gamma = 67108864, a gas that settles above theta = 1000' --v-rms 0.9999999999999999
expect_bad vrms-slow '' 'settles below theta = 0.001' --v-rms 0.01
expect_bad packing '' '^relcol-gas: --packing: 0.9 must be below 0.78' --packing 0.9
expect_bad packing1d '' '^relcol-gas: --packing: not used with --dim 1' --dim 1 --packing 0.2
expect_bad frame1d '' '^relcol-gas: --frame: not used with --dim 1' --dim 1 --frame table
expect_bad frame '' "^relcol-gas: --frame: unknown frame 'x'" --frame x
expect_bad snapshots '' '^relcol-gas: --snapshots: ' --snapshots 5
expect_bad tsample '' '^relcol-gas: --t-sample: ' --t-sample 0
expect_bad tequil '' '^relcol-gas: --t-equil: not a number' --t-equil abc
expect_bad seed '' '^relcol-gas: --seed: ' --seed -1
expect_bad unknown '' '^relcol-gas: unknown option --bogus' --bogus
expect_bad memory '' '^relcol-gas: --snapshots: n x snapshots' --n 100000 --snapshots 1000

# 2-D, uncontracted discs: <gamma> is fixed by the energy at theta = 0.6; <p.v>/2 must
# agree within 5 of its standard errors plus the O(theta/N) microcanonical shift
run '' --frame sphere --n 300 --theta-start 0.6 --t-equil 30 --t-sample 150 --snapshots 40 \
    --seed 5 --out "$T/g2"
expect_ok run2d
tg=$(awk -F'= ' '/^theta from <gamma>/ {split($2, a, " "); print a[1]}' "$T/out")
tp=$(awk -F'= ' '/^theta from <p.v>\/2/ {split($2, a, " "); print a[1]}' "$T/out")
se=$(awk -F'= ' '/^theta from <p.v>\/2/ {split($2, a, " "); print a[3]}' "$T/out")
close theta-gamma "$tg" 0.6 1e-5
if awk -v a="$tp" -v b="$tg" -v s="$se" 'BEGIN { d = a - b; if (d < 0) d = -d;
        exit !(s > 0 && s < 0.01 && d <= 5 * s + 2 * 0.6 / 300) }'; then ok; else
    bad "thermometers disagree: <p.v> $tp +- $se, <gamma> $tg"; fi
rows=$(awk 'NR > 1' "$T/g2/gas.csv" | wc -l)
[ "$rows" -eq 60 ] && ok || bad "gas.csv: $rows rows, want 60"
head -1 "$T/g2/gas.csv" | grep -q '^species,mass,gamma_lo,gamma_hi,gamma_mid,density,density_err,juttner,maxwell_boltzmann$' \
    && ok || bad "gas.csv header"
[ -s "$T/g2/gas.gp" ] && ok || bad "no gas.gp"
if command -v gnuplot > /dev/null 2>&1; then
    [ -s "$T/g2/gas.png" ] && ok || bad "no gas.png"
fi
# the histogram integrates to ~1 over the plotted range (it ends at Jüttner's 2e-4 tail)
tot=$(awk -F, 'NR > 1 { s += $6 * ($4 - $3) } END { printf "%.6f", s }' "$T/g2/gas.csv")
close hist-norm "$tot" 1 0.002
grep -q '^chi2/phi' "$T/out" && ok || bad "no chi-square line"

# 1-D mixture: two species in the CSV, one stdout block each
run '' --dim 1 --n 200 --t-equil 200 --t-sample 400 --snapshots 40 --out "$T/g1"
expect_ok run1d
rows=$(awk -F, 'NR > 1 { n[$1]++ } END { print n[0] "," n[1] }' "$T/g1/gas.csv")
[ "$rows" = "60,60" ] && ok || bad "1-D gas.csv species rows: $rows"
n=$(grep -c '^species m = ' "$T/out")
[ "$n" -eq 2 ] && ok || bad "1-D: $n species blocks"

summary
