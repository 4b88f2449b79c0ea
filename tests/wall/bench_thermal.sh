#!/bin/sh
# bench_thermal.sh RELCOL_SIM — what a thermal wall costs (issue 39 item 5): one classical
# 3-D gas (2 000 balls, packing 0.02, t_end 600, about 30 % of its contacts with walls) run
# by relcol-sim with hard walls and with all six walls thermal at the gas's own temperature
# (kT = 1/3 for v_rms = 1, m = 1), CPU seconds of each (user + system, best of three: the
# machine may be shared) and the ratio thermal / hard per contact.
sim="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
walls='{"x-": {"rule": "thermal", "kT": 0.3333333333333333}, "x+": {"rule": "thermal", "kT": 0.3333333333333333}, "y-": {"rule": "thermal", "kT": 0.3333333333333333}, "y+": {"rule": "thermal", "kT": 0.3333333333333333}, "z-": {"rule": "thermal", "kT": 0.3333333333333333}, "z+": {"rule": "thermal", "kT": 0.3333333333333333}}'
for k in hard thermal; do
    w=''
    [ "$k" = thermal ] && w="\"walls\": $walls,"
    printf '{"relcol": 1, "dim": 3, "c": "inf", "seed": 3, "t_end": 600, %s
 "generate": {"kind": "gas", "n": 2000, "radius": 0.5, "packing": 0.02, "v_rms": 1, "density": 8},
 "outputs": {"dir": "%s/out-%s", "plots": false}}\n' "$w" "$tmp" "$k" > "$tmp/$k.json"
done
best() { # best CPU seconds of three runs of scenario $1, and its contacts
    b=''
    for i in 1 2 3; do
        rm -rf "$tmp/out-$1"
        /usr/bin/time -f '%U %S' -o "$tmp/t" "$sim" "$tmp/$1.json" > /dev/null 2>&1 || return 1
        t=$(awk '{ print $1 + $2 }' "$tmp/t")
        b=$(awk -v a="$t" -v b="$b" 'BEGIN { print (b == "" || a < b) ? a : b }')
    done
    n=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['collisions']['contacts'])" "$tmp/out-$1/summary.json")
    echo "$b $n"
}
h=$(best hard) || { echo "hard-wall run failed"; exit 1; }
t=$(best thermal) || { echo "thermal run failed"; exit 1; }
echo "$h $t" | awk '{ printf "hard walls %.2f s for %d contacts, thermal %.2f s for %d: %.3f x per contact\n", $1, $2, $3, $4, ($3 / $4) / ($1 / $2) }'
