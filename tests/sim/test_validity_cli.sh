#!/bin/sh
# test_validity_cli.sh RELCOL_SIM RELCOL_GAS PYTHON — the validity report and --sensitivity
# from the command line (issue 36): summary.json's model block gives `defined` for a dilute
# covariant gas and `outside` for the 3-D packing 0.45 gas (0.5c), whose run prints exactly
# one warning line and the dilute one none; the table frame is `non_covariant`. The
# sensitivity mode flags the three-ball group at c = 3 (simultaneous and sequential move
# its final momenta by ~0.15, ~1e14 of its round-off) and not its collision count, and
# flags nothing in a dilute sphere-frame gas (relcol-gas).
sim="$1"; gas="$2"; py="$3"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }
field() { "$py" -c "import json,sys; print(json.load(open(sys.argv[1]))$2)" "$1"; }

gasrun() { # NAME FRAME PACKING N T_END
    cat > "$tmp/$1.json" <<JSON
{"relcol": 1, "dim": 3, "c": 1, "contact_frame": "$2", "seed": 3, "t_end": $5,
 "boundary": "periodic",
 "generate": {"kind": "gas", "n": $4, "radius": 0.5, "packing": $3, "v_rms": 0.5},
 "outputs": {"plots": false, "gif": false}}
JSON
    "$sim" "$tmp/$1.json" --out "$tmp/$1" > /dev/null 2> "$tmp/$1.err"
}

gasrun dilute covariant 0.01 216 60; st=$?
v=$(field "$tmp/dilute/summary.json" "['model']['verdict']")
pm=$(field "$tmp/dilute/summary.json" "['model']['p_model']")
k=$(field "$tmp/dilute/summary.json" "['model']['kink_pairs_model']")
if [ $st -eq 0 ] && [ "$v" = defined ] && [ ! -s "$tmp/dilute.err" ] && [ "$k" -gt 100 ]; then
    ok "dilute covariant gas: $v (p_model $pm over $k kink pairs), nothing on stderr"
else
    ko "dilute covariant gas: exit $st, verdict '$v', p_model $pm, pairs $k: $(cat "$tmp/dilute.err")"
fi

gasrun dense covariant 0.45 216 3; st=$?
v=$(field "$tmp/dense/summary.json" "['model']['verdict']")
pm=$(field "$tmp/dense/summary.json" "['model']['p_model']")
th=$(field "$tmp/dense/summary.json" "['model']['threshold_p_model']")
if [ $st -eq 0 ] && [ "$v" = outside ] && [ "$th" = 0.001 ] &&
    [ "$(grep -c 'warning' "$tmp/dense.err")" -eq 1 ] &&
    grep -q "outside the rigid-ball model's regime: p_model" "$tmp/dense.err"; then
    ok "3-D packing 0.45: $v (p_model $pm > $th), one warning line"
else
    ko "3-D packing 0.45: exit $st, verdict '$v', p_model $pm: $(cat "$tmp/dense.err")"
fi

gasrun table table 0.1 125 5; st=$?
v=$(field "$tmp/table/summary.json" "['model']['verdict']")
c=$(field "$tmp/table/summary.json" "['model']['covariant']")
[ $st -eq 0 ] && [ "$v" = non_covariant ] && [ "$c" = False ] &&
    ok "table frame: $v" || ko "table frame: exit $st, verdict '$v', covariant $c"

# the three-ball group: ball 0 (m = 1, 0.9 along x, c = 3) meets m = 1 and m = 2 at rest,
# at +6 and -66 degrees, both at one instant (uncontracted spheres: the contact is exact)
"$py" - "$tmp" <<'PY'
import json, math, sys
x0 = (5.9, 10.0); a1, a2 = math.radians(6), math.radians(66)
balls = [{"r": 0.5, "m": 1, "x": [5.0, 10.0], "v": [0.9, 0]},
         {"r": 0.5, "m": 1, "x": [x0[0] + math.cos(a1), x0[1] + math.sin(a1)]},
         {"r": 0.5, "m": 2, "x": [x0[0] + math.cos(a2), x0[1] - math.sin(a2)]}]
json.dump({"relcol": 1, "dim": 2, "box": [20, 20], "c": 3, "contact_frame": "sphere",
           "t_end": 3, "balls": balls, "outputs": {"plots": False, "gif": False}},
          open(sys.argv[1] + "/three.json", "w"))
PY
"$sim" "$tmp/three.json" --out "$tmp/three" --sensitivity > "$tmp/three.out" 2> "$tmp/three.err"; st=$?
r=$("$py" - "$tmp/three/sensitivity.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
o = {x["name"]: x for x in j["observables"]}
p = [o[k] for k in o if k.startswith("p") and "." in k]
big = max(abs(x["shifts"]["groups sequential"]["shift"]) for x in p)
good = (all(x["flag"] for x in p) and not o["collisions"]["flag"] and
        all(x["shifts"]["moved 1e-15"]["in_errors"] <= 1.0 for x in p) and 0.1 < big < 0.3 and
        j["variants"] == ["moved 1e-15", "groups sequential"])
print("%d %.3f %d" % (good, big, j["flagged"]))
PY
)
if [ $st -eq 0 ] && [ "${r%% *}" = 1 ] && [ -s "$tmp/three/sensitivity.csv" ] &&
    grep -q "depends on the model's rules" "$tmp/three.out"; then
    ok "three-ball group at c = 3: every momentum flagged, largest shift (sequential) $r"
else
    ko "three-ball group: exit $st, '$r': $(cat "$tmp/three.err")"
fi

(cd "$tmp" && "$gas" --dim 2 --n 200 --packing 0.02 --out "$tmp/g" --sensitivity) \
    > "$tmp/g.out" 2> "$tmp/g.err"; st=$?
f=$(field "$tmp/g/sensitivity.json" "['flagged']")
nobs=$(field "$tmp/g/sensitivity.json" "['observables'].__len__()")
if [ $st -eq 0 ] && [ "$f" = 0 ] && [ "$nobs" = 4 ]; then
    ok "dilute sphere-frame gas: $f of $nobs observables flagged"
else
    ko "dilute sphere-frame gas: exit $st, flagged '$f' of '$nobs': $(cat "$tmp/g.out" "$tmp/g.err")"
fi

echo "$n checks, $fails failed"
[ $fails -eq 0 ]
