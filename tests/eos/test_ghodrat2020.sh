#!/bin/sh
# test_ghodrat2020.sh RELCOL_EOS HARNESS CSV — data/reproductions/ghodrat2020.{md,csv}
# against fresh short runs: at theta = 10 (c = 1, packing 0.005, N = 250 instead of 500,
# 2000 mean free times instead of 16000: about 9 % errors on eta and lambda) the transport
# frame's eta and lambda lie within 4 combined standard errors of the CSV's and of the
# invariant gas's converged Chapman–Enskog value, which relcol-eos writes for that frame
# and which is the CSV's to 0.2 % (the r^2 of lambda moves with the run's Z); the zmf
# frame's eta lies above twice the invariant value (the CSV's zmf row, lag 40, is 9.8 times
# and still lag-limited: section 12 of papers/transport.md; this lag-10 run is not compared).
C=$1
. "$2"
CSV=$3

# field NAME FILE [ROW-FILTER]: column NAME of FILE's rows matching the awk filter
field() {
    awk -F, -v want="$1" -v flt="$3" 'NR == 1 {for (i = 1; i <= NF; i++) col[$i] = i; next}
        { split(flt, f, "="); if (flt == "" || $col[f[1]] == f[2]) { print $col[want]; exit } }' "$2"
}
# within NAME GOT GOT_SE WANT WANT_SE K: |got - want| <= K sqrt(se1^2 + se2^2)
within() {
    if awk -v g="$2" -v gs="$3" -v w="$4" -v ws="$5" -v k="$6" 'BEGIN {
            if (g == "" || w == "") exit 1
            d = g - w; if (d < 0) d = -d; exit !(d <= k * sqrt(gs * gs + ws * ws)) }'; then ok
    else bad "$1: got $2 +- $3, want $4 +- $5 (within $6 errors)"; fi
}
row() { # row FRAME: the CSV's seed-1, N = 500 row at theta = 10, as "eta eta_se lambda ..."
    # (lag <= 40: the sweep's row, not the lag-160 study's)
    awk -F, -v fr="$1" 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next}
        $c["frame"] == fr && $c["theta"] == 10 && $c["n"] == 500 && $c["seed"] == 1 && $c["lag"] <= 40 {
            print $c["eta"], $c["eta_se"], $c["lambda"], $c["lambda_se"], $c["eta_inv_16"], $c["lambda_inv_16"] }' "$CSV"
}

for fr in transport zmf; do
    run '' --transport --c 1 --theta 10 --packing 0.005 --n 250 --frame $fr --t-run 2000 \
        --blocks 20 --lag 10 --out "$T/$fr"
    [ "$st" -eq 0 ] && ok || bad "$fr run: exit $st: $(cat "$T/err")"
    f=$T/$fr/eos.csv
    set -- $(row $fr)
    [ $# -eq 6 ] || { bad "$fr: no theta = 10 row in $CSV"; continue; }
    eta=$(field eta "$f") eta_se=$(field eta_se "$f") lam=$(field lambda "$f") lam_se=$(field lambda_se "$f")
    # (zmf's eta at theta = 10 grows with the lag, papers/transport.md section 12: a lag-10
    # run is not comparable with the CSV's lag-40 row; the transport frame's is converged)
    [ $fr = transport ] && within "$fr eta vs csv" "$eta" "$eta_se" "$1" "$2" 4
    # the invariant frames get the invariant gas's reference, and no sphere-kernel D
    close "$fr eta_chapman_enskog = csv eta_inv_16" "$(field eta_chapman_enskog "$f")" "$5" 2e-3
    close "$fr lambda_chapman_enskog = csv lambda_inv_16" "$(field lambda_chapman_enskog "$f")" "$6" 2e-3
    [ -z "$(field D_chapman_enskog "$f")" ] && ok || bad "$fr: a sphere-kernel D_chapman_enskog"
    if [ $fr = transport ]; then
        within "transport lambda vs csv" "$lam" "$lam_se" "$3" "$4" 4
        within "transport eta vs Chapman-Enskog" "$eta" "$eta_se" "$5" 0 4
        within "transport lambda vs Chapman-Enskog" "$lam" "$lam_se" "$6" 0 4
    else
        awk -v e="$eta" -v r="$5" 'BEGIN {exit !(e > 2 * r)}' && ok ||
            bad "zmf eta $eta not above twice the invariant gas's $5"
    fi
done
summary
