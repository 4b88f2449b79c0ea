#!/bin/sh
# test_heat_steady.sh RELCOL_HEAT — the heat-conducting steady state (issue 39 item 5,
# papers/transport.md section 10), classically: both walls' heat rates agree (energy is
# conserved in the bulk) and so do their pressures (P_xx is uniform without flow), each
# within 4 combined errors; the temperature falls from the hot wall to the cold one; and
# lambda from Fourier's law lies within 4 errors of the interval between the dilute
# Chapman-Enskog value of hard spheres (apps/eos/ce_rel.c at z -> inf; Chapman & Cowling's
# converged 1.02513 x 75/64 sqrt(pi kT/m)/sigma_T, checked here to 1e-3) and Enskog's at the
# packing (0.02: 5 % apart).
set -eu
HEAT=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
"$HEAT" --n 600 --aspect 6 --warmup 2000 --time 16000 --every 5 --seed 5 --out "$T/o" > "$T/stdout" 2> "$T/e" ||
    { echo "FAIL: run: $(cat "$T/e")"; exit 1; }
cat "$T/stdout"
/usr/bin/python3 - "$T/o" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
v = lambda k: (s[k]["value"], s[k]["err"])
def agree(a, b, what):
    (x, ex), (y, ey) = v(a), v(b)
    z = abs(x - y) / math.hypot(ex, ey)
    print("%s: %.6g +- %.2g vs %.6g +- %.2g (%.1f errors)" % (what, x, ex, y, ey, z))
    assert z < 4, what
agree("heat_flux_hot_wall", "heat_flux_cold_wall", "heat rates")
agree("pressure_hot_wall", "pressure_cold_wall", "pressures")
kT = s["kT_mid"]["value"]
cc = 1.02513 * 75 / 64 * math.sqrt(math.pi * kT) / math.pi    # m = 1, sigma_T = pi d^2, d = 1
lo, hi = s["lambda_chapman_enskog_dilute"], s["lambda_enskog"]
assert abs(lo / cc - 1) < 1e-3, (lo, cc)
lam, e = v("lambda_fourier_theta_pv")
print("lambda %.4g +- %.2g; dilute CE %.4g, Enskog %.4g" % (lam, e, lo, hi))
assert e < 0.1 * lam, "lambda's error too large to tell"
assert lo - 4 * e < lam < hi + 4 * e, "lambda outside [CE, Enskog] by more than 4 errors"
th = [float(r["theta_pv"]) for r in csv.DictReader(open(d + "/profile.csv"))]
assert all(a > b for a, b in zip(th[::4], th[4::4])), th    # falling, bins 4 apart
print("ok")
PY
