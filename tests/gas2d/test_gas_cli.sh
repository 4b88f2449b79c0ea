#!/bin/sh
# test_gas_cli.sh RELCOL_GAS HARNESS — relcol-gas through its command line: every bad
# option is one stderr line naming it (exit 2); a short 2-D run in the default frame
# (uncontracted discs, no warning) reads the same theta both ways and writes the CSV,
# summary.json, the script and (with gnuplot) the figure; a frame that is not thermal is
# warned about; a short 1-D mixture run writes both species and settles at its target;
# moving observers in 2-D and 1-D fit the boosted law.
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
expect_bad obs-dim '' '^relcol-gas: --observer-velocity: 1-D and 2-D only' --dim 3 --observer-velocity 0.5
expect_bad obs-c '' '^relcol-gas: --observer-velocity: 1 must be below c = 1' --observer-velocity 1
expect_bad obs-periodic '' '^relcol-gas: --observer-velocity: needs walls' --boundary periodic --observer-velocity 0.5
expect_bad sens-1d '' '^relcol-gas: --sensitivity: 2-D and 3-D gases only' --dim 1 --sensitivity
expect_bad sens-out '' '^relcol-gas: --out: cannot create folder' --sensitivity --out /dev/null/x

# jget KEY FILE: the "value" of the first object named KEY in a summary.json (the top
# level's, which cJSON prints before the species array); jnum KEY FILE: a plain number
jget() { awk -v k="\"$1\":" 'f && $1 == "\"value\":" { sub(/,$/, "", $2); print $2; exit }
                              $1 == k { f = 1 }' "$2"; }
jnum() { awk -v k="\"$1\":" '$1 == k { sub(/,$/, "", $2); print $2; exit }' "$2"; }

# 2-D, the default frame (uncontracted discs: thermal, so no warning): <gamma> is fixed by
# the energy at theta = 0.6; <p.v>/2 must agree within 5 of its standard errors plus the
# O(theta/N) microcanonical shift
run '' --n 300 --theta-start 0.6 --t-equil 30 --t-sample 150 --snapshots 40 \
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
grep -q 'frame sphere' "$T/out" && ok || bad "default frame is not sphere"
# the chi2 bound is GSL's chi2 quantile at the 5-sigma tail (dof 18: 65.2, where the
# normal approximation dof + 5 sqrt(2 dof) = 48.0 is a 3.6-sigma bound)
grep -q '5 sigma bound (p = 2.9e-7) 65.2$' "$T/out" && ok || bad "chi2 bound: $(grep '^chi2' "$T/out")"

# summary.json: the measurements as printed, with errors, chi2 with dof and p-values
J="$T/g2/summary.json"
[ -s "$J" ] && ok || bad "no summary.json"
close json-theta-pv "$(jget theta_pv "$J")" "$tp" 2e-5
close json-theta-gamma "$(jget theta_gamma "$J")" 0.6 1e-9
close json-mean-pv "$(jget mean_pv "$J")" "$(awk -v t="$tp" 'BEGIN { print 2 * t }')" 2e-5
close json-mean-gamma "$(jget mean_gamma "$J")" "$(awk 'BEGIN { t = 0.6; print (1 + 2*t + 2*t*t)/(1 + t) }')" 1e-9
close json-dof "$(jnum dof "$J")" 18 0
p=$(jnum juttner_p "$J")
awk -v p="$p" 'BEGIN { exit !(p > 1e-4 && p <= 1) }' && ok || bad "juttner_p $p"
r=$(jget collision_rate "$J")
awk -v r="$r" 'BEGIN { exit !(r > 0) }' && ok || bad "collision_rate $r"
pp=$(awk '/^pressure P =/ {print $4}' "$T/out")
close json-pressure "$(jget pressure "$J")" "$pp" 1e-5
grep -q '"pressure_kind":	"the walls'"'"' momentum flux"' "$J" && ok || bad "pressure_kind"
grep -q '"frame":	"sphere"' "$J" && ok || bad "summary.json frame"
ls -a "$T/g2" | grep -q '^\.summary' && bad "a temporary is left beside summary.json" || ok

# a frame whose stationary state is not Jüttner runs, with a warning on stderr
run '' --frame table --n 50 --t-equil 5 --t-sample 20 --snapshots 20 --out "$T/gt"
[ "$st" -eq 0 ] && ok || bad "table run: exit $st"
grep -q '^relcol-gas: warning: frame table: its stationary state is not Jüttner' "$T/err" \
    && ok || bad "no warning for the table frame: $(cat "$T/err")"
# the zmf frame's dilute limit is Jüttner as tested in 2-D; in 3-D (off Jüttner at packing
# 0.01) neither the warning nor summary.json claims it
run '' --dim 3 --frame zmf --n 50 --packing 0.05 --t-equil 5 --t-sample 20 --snapshots 20 \
    --out "$T/gz"
[ "$st" -eq 0 ] && ok || bad "3-D zmf run: exit $st"
grep -q '^relcol-gas: warning: frame zmf: in 3-D its gas is off Jüttner' "$T/err" \
    && ok || bad "3-D zmf warning: $(cat "$T/err")"
grep -q 'dilute limit' "$T/gz/summary.json" && bad "3-D zmf summary claims the dilute limit" || ok
grep -q '"frame_thermal":	"not shown in 3-D"' "$T/gz/summary.json" && ok \
    || bad "3-D zmf frame_thermal: $(grep frame_thermal "$T/gz/summary.json")"
run '' --frame zmf --n 50 --packing 0.05 --t-equil 5 --t-sample 20 --snapshots 20 --out "$T/gz2"
grep -q '"frame_thermal":	"dilute limit only"' "$T/gz2/summary.json" && ok \
    || bad "2-D zmf frame_thermal: $(grep frame_thermal "$T/gz2/summary.json")"

# a dense 3-D covariant gas runs past t = 615.37, where an overlap-policy kink put at a
# kink still pending left the pair's geometry as it was and the same contact came up at
# one instant until the stall guard stopped the run (core.c glue_kink_at, at_event)
run '' --dim 3 --frame covariant --theta-start 0.75 --n 4000 --packing 0.2 \
    --boundary periodic --t-equil 50 --t-sample 600 --snapshots 20 --seed 7 --out "$T/gc3"
[ "$st" -eq 0 ] && ok || bad "3-D covariant gas: exit $st: $(grep -v warning "$T/err")"
# ... and says, in one line, that it is outside the rigid-ball model's regime and how much
# of it the overlap policy decided: the share it names is the one the run's own counts on
# stdout give (to the 3 digits printed)
w=$(sed -n "s/^relcol-gas: warning: outside the rigid-ball model's regime: .*the overlap policy decided \([0-9.e+-]*\) % of \([0-9]*\) collisions.*/\2 \1/p" "$T/err")
c=$(sed -n 's/.* \([0-9]*\) collisions, \([0-9]*\) overlaps (shape change)$/\1 \2/p' "$T/out")
awk -v w="$w" -v c="$c" 'BEGIN { split(w, a, " "); split(c, b, " ");
    s = 100 * b[2] / b[1]; exit !(a[1] == b[1] && a[2] > 0.1 && (a[2] - s) ^ 2 < (0.006 * s) ^ 2) }' \
    && ! grep -q 'were decided by the overlap policy' "$T/err" \
    && ok || bad "the validity warning ($w) against the counts ($c): $(cat "$T/err")"

# the covariant default read-out (--readout slice) in a dense hot 2-D gas: balls with
# three or more kinks ahead of the engine, whose lines at a snapshot a two-line record
# lost, stopped it at t = 166 ("engine: invalid argument"); it runs through now
run '' --dim 2 --frame covariant --theta-start 0.75 --n 4000 --packing 0.2 \
    --boundary periodic --t-equil 50 --t-sample 200 --snapshots 100 --seed 7 --out "$T/gs2"
[ "$st" -eq 0 ] && grep -q '^theta from <gamma> .*not fixed: a table-time read-out' "$T/out" \
    && ok || bad "2-D covariant gas, slice read-out: exit $st: $(grep -v warning "$T/err")"
# every snapshot read from a final slice, each held a further W after the read, and none
# changed after it (a change would mean an undo reached back beyond W: counted, and
# summary.json says so too)
grep -q '^slices: 100 read final, 0 changed after the read' "$T/out" \
    && [ "$(jnum slices_changed_after_read "$T/gs2/summary.json")" = 0 ] \
    && [ "$(jnum slices_read "$T/gs2/summary.json")" = 100 ] \
    && ok || bad "slices: $(grep '^slices' "$T/out")"

# 1-D mixture: two species in the CSV, one stdout block each
run '' --dim 1 --n 200 --t-equil 200 --t-sample 800 --snapshots 40 --out "$T/g1"
expect_ok run1d
rows=$(awk -F, 'NR > 1 { n[$1]++ } END { print n[0] "," n[1] }' "$T/g1/gas.csv")
[ "$rows" = "60,60" ] && ok || bad "1-D gas.csv species rows: $rows"
n=$(grep -c '^species m = ' "$T/out")
[ "$n" -eq 2 ] && ok || bad "1-D: $n species blocks"

# the moving observer: its hyperplane sample fits the boosted law (bound: the 5-sigma
# chi2 quantile, 135.9 at 63 dof) and rejects the law at rest; the files are written
run '' --n 300 --t-sample 400 --snapshots 40 --observer-velocity 0.5 --out "$T/go"
expect_ok observer
x=$(jnum chi2_boosted_juttner "$T/go/summary.json")
x0=$(jnum chi2_juttner_at_rest "$T/go/summary.json")
awk -v x="$x" -v y="$x0" 'BEGIN { exit !(x > 0 && x < 135.9 && y > 1000) }' && ok \
    || bad "observer chi2 $x (boosted), $x0 (at rest)"
[ -s "$T/go/observer.csv" ] && [ -s "$T/go/observer.gp" ] && ok || bad "no observer.csv/gp"

# an observer moving the other way: the hyperplanes start inside the sample (the first
# reaches the box at t_equil; it used to start before it, and the engine refused)
run '' --n 200 --t-sample 200 --snapshots 20 --observer-velocity -0.5 --out "$T/gn"
expect_ok observer-negative
x=$(jnum chi2_boosted_juttner "$T/gn/summary.json")
awk -v x="$x" 'BEGIN { exit !(x > 0 && x < 135.9) }' && ok || bad "observer at -0.5 c: chi2 $x"

# the 1-D observer (Cubero et al. 2007's moving frame): every worldline crosses every
# hyperplane once and none is lost; both species fit their boosted laws (5-sigma chi2
# quantile 98.5 at 38 dof) and the laws at rest are rejected; both directions
for v in 0.5 -0.5; do
    run '' --dim 1 --n 300 --t-equil 300 --t-sample 6000 --snapshots 40 \
        --observer-velocity $v --out "$T/g1o"
    expect_ok observer-1d-$v
    J="$T/g1o/summary.json"
    x=$(jnum chi2_boosted_juttner "$J")
    x0=$(jnum chi2_juttner_at_rest "$J")
    [ "$(jnum sampled "$J")" = 12000 ] && [ "$(jnum lost "$J")" = 0 ] && ok \
        || bad "1-D observer at $v: sampled $(jnum sampled "$J"), lost $(jnum lost "$J")"
    awk -v x="$x" -v y="$x0" 'BEGIN { exit !(x > 0 && x < 98.5 && y > 1000) }' && ok \
        || bad "1-D observer at $v: chi2 $x (boosted), $x0 (at rest)"
    rows=$(awk -F, 'NR > 1 { n[$1]++ } END { print n[0] "," n[1] }' "$T/g1o/observer.csv")
    [ "$rows" = "80,80" ] && ok || bad "1-D observer.csv species rows: $rows"
done

# the 1-D start hits its target: the start's energy is that of the species counts drawn
# (seed 1 draws 487 light and 513 heavy of 1000, which a 50/50 energy put at kT 1.0087),
# so the kT of the gas's energy is the target to round-off; and the light species' reading
# agrees with it within 4 of its standard errors
run '' --dim 1 --theta-start 1 --n 1000 --t-equil 300 --t-sample 600 --snapshots 40 --out "$T/g1b"
J="$T/g1b/summary.json"
close kT-energy "$(jnum theta_of_energy "$J")" 1 1e-12
kt=$(jget theta_gamma "$J")
se=$(awk -v k='"theta_gamma":' 'f && $1 == "\"err\":" { print $2; exit } $1 == k { f = 1 }' "$J")
awk -v k="$kt" -v s="$se" 'BEGIN { d = k - 1; if (d < 0) d = -d; exit !(s > 0 && s < 0.02 && d <= 4 * s) }' \
    && ok || bad "1-D kT $kt +- $se, want 1"

summary
