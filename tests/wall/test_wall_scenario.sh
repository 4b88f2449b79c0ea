#!/bin/sh
# test_wall_scenario.sh RELCOL_SIM — relcol-sim's "walls" key (issue 39 item 5): bad walls
# refused with the key named and the reason; a run with thermal walls writes each wall's
# heat and temperature in summary.json, carries the walls into final.json, and a run
# stopped at t = 30 and continued from its checkpoint ends with the bits of one run to 60.
set -eu
SIM=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

gas='"generate": {"kind": "gas", "n": 120, "radius": 0.5, "packing": 0.1, "v_rms": 0.3}'
scn() { # scn FILE DIM WALLS [BOUNDARY]: a scenario with walls WALLS
    printf '{"relcol": 1, "dim": %s, "c": 1, "seed": 4, "t_end": %s, %s "walls": %s,\n %s,\n "outputs": {"dir": "%s", "plots": false}}\n' \
        "$2" "${TEND:-60}" "${4:-}" "$3" "$gas" "$T/out.$(basename "$1" .json)" > "$1"
}
refused() { # refused FILE WORDS...: relcol-sim exits 2 (a bad input) naming WORDS
    f=$1; shift
    if "$SIM" "$f" > "$T/o" 2> "$T/e"; then fail "$f accepted"; fi
    for w in "$@"; do
        grep -qF -- "$w" "$T/e" || fail "$f: '$w' not in: $(cat "$T/e")"
    done
}
scn "$T/neg.json" 3 '{"x-": {"rule": "thermal", "kT": -1}}'
refused "$T/neg.json" 'walls.x-' 'kT = -1' '> 0'
scn "$T/zero.json" 3 '{"x+": {"rule": "thermal", "kT": 0}}'
refused "$T/zero.json" 'walls.x+' 'must be > 0'
scn "$T/nokT.json" 3 '{"y-": "thermal"}'
refused "$T/nokT.json" 'walls.y-' 'needs its temperature'
scn "$T/per.json" 3 '{"x-": {"rule": "thermal", "kT": 1}}' '"boundary": ["periodic", "walls", "walls"],'
refused "$T/per.json" 'walls.x-' 'axis 0 is periodic'
scn "$T/rule.json" 3 '{"x-": {"rule": "warm", "kT": 1}}'
refused "$T/rule.json" 'walls.x-' "unknown wall rule 'warm'" 'reflecting, thermal'
scn "$T/refl.json" 3 '{"x-": {"rule": "reflecting", "kT": 1}}'
refused "$T/refl.json" 'walls.x-' 'no temperature'
scn "$T/z2.json" 2 '{"z-": {"rule": "thermal", "kT": 1}}'
refused "$T/z2.json" 'walls.z-' 'unknown key'
scn "$T/key.json" 3 '{"x-": {"rule": "thermal", "kT": 1, "eps": 1}}'
refused "$T/key.json" 'walls.x-.eps' 'unknown key'
scn "$T/nan.json" 3 '{"x-": {"rule": "thermal", "kT": "hot"}}'
refused "$T/nan.json" 'walls.x-.kT' 'must be a number'

scn "$T/cov.json" 3 '{"x-": {"rule": "thermal", "kT": 1}}' '"contact_frame": "covariant",'
refused "$T/cov.json" 'walls.x-' "contact_frame 'covariant'"

# the whole run, and the same stopped at 30 and continued from final.json (its checkpoint)
hot='{"x-": {"rule": "thermal", "kT": 2}, "x+": {"rule": "thermal", "kT": 0.5}}'
scn "$T/full.json" 3 "$hot"
"$SIM" "$T/full.json" > /dev/null 2>&1 || fail "thermal run failed"
TEND=30 scn "$T/half.json" 3 "$hot"
"$SIM" "$T/half.json" > /dev/null 2>&1 || fail "first half failed"
grep -q '"walls":{"x-":{"rule":"thermal","kT":2},"x+":{"rule":"thermal","kT":0.5}}' "$T/out.half/final.json" ||
    fail "final.json does not carry the walls"
sed 's/"t_end":[0-9.e+]*/"t_end":60/' "$T/out.half/final.json" > "$T/out.half/cont.json"
"$SIM" "$T/out.half/cont.json" > /dev/null 2>&1 || fail "continued run failed"
cont=$(ls -d "$T"/out.half.* | head -1)
/usr/bin/python3 - "$T/out.full" "$cont" <<'PY' || fail "summary or continuation"
import json, sys
full, cont = sys.argv[1], sys.argv[2]
a = json.load(open(full + "/summary.json"))
b = json.load(open(cont + "/summary.json"))
q = a["wall_heat"]
assert a["wall_kT"] == {"x-": 2, "x+": 0.5}, a["wall_kT"]
assert q["x-"] < 0 < q["x+"], q             # the hot wall heats the gas, the cold one cools it
assert all(q[w] == 0 for w in ("y-", "y+", "z-", "z+")), q
assert abs(a["energy_error"]) < 1e-10, a["energy_error"]
fa = json.load(open(full + "/final.json"))["balls"]
fb = json.load(open(cont + "/final.json"))["balls"]
assert fa == fb, "continued run's balls differ from the whole run's"
print("heat per wall", q)
PY
echo "ok"
