#!/bin/sh
# test_gravity_scenario.sh RELCOL_SIM — the scenario key "gravity" (apps/sim/SCENARIO.md):
# each bad entry refused with exit 2 and a message naming its key, nothing written; a good
# 2-D atmosphere runs, writes profiles.csv (header, 20 slabs, finite numbers) and reports
# its coupling's energy error at round-off; continued from its final.json the run keeps
# the field.
sim="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }
G='"dim": 2, "c": 1, "t_end": 200, "boundary": ["periodic", "walls"], "generate": {"kind": "gas", "n": 100, "radius": 1, "packing": 0.05, "v_rms": 0.5}, "outputs": {"plots": false, "snapshots": {"every": 50}}'
bad() { # NAME JSON WANT (a grep pattern of the message)
    printf '%s\n' "$2" > "$tmp/$1.json"
    "$sim" "$tmp/$1.json" --out "$tmp/o-$1" > /dev/null 2> "$tmp/err"; st=$?
    if [ $st -eq 2 ] && grep -q -- "$3" "$tmp/err" && [ ! -e "$tmp/o-$1" ]; then ok
    else ko "$1: exit $st: $(cat "$tmp/err")"; fi
}
bad notobj "{$G, \"gravity\": 1}" 'gravity: must be an object'
bad nog "{$G, \"gravity\": {\"coupling\": \"newtonian\"}}" 'gravity.g'
bad zerog "{$G, \"gravity\": {\"g\": 0, \"coupling\": \"newtonian\"}}" 'gravity.g: must be > 0'
bad negg "{$G, \"gravity\": {\"g\": -1, \"coupling\": \"newtonian\"}}" 'gravity.g: must be > 0'
bad nocp "{$G, \"gravity\": {\"g\": 0.01}}" 'gravity.coupling: is required'
bad cp "{$G, \"gravity\": {\"g\": 0.01, \"coupling\": \"einstein\"}}" "gravity.coupling: unknown coupling 'einstein'"
bad key "{$G, \"gravity\": {\"g\": 0.01, \"coupling\": \"newtonian\", \"h\": 1}}" 'gravity'
bad per "{$(echo "$G" | sed 's/"boundary": \["periodic", "walls"\]/"boundary": "periodic"/'), \"gravity\": {\"g\": 0.01, \"coupling\": \"newtonian\"}}" "the field's axis"
bad frame "{$G, \"contact_frame\": \"covariant\", \"gravity\": {\"g\": 0.01, \"coupling\": \"equivalence\"}}" "contact_frame: frame 'covariant' is not defined in a field"
bad table "{$G, \"contact_frame\": \"table\", \"gravity\": {\"g\": 0.01, \"coupling\": \"equivalence\"}}" "contact_frame: frame 'table' is not defined in a field"
bad thermal "{$G, \"walls\": {\"y-\": {\"rule\": \"thermal\", \"kT\": 1}}, \"gravity\": {\"g\": 0.01, \"coupling\": \"newtonian\"}}" "walls.y-: a thermal wall in a field is not built"
for cp in newtonian equivalence; do
    printf '%s\n' "{$G, \"gravity\": {\"g\": 0.005, \"coupling\": \"$cp\"}}" > "$tmp/$cp.json"
    if "$sim" "$tmp/$cp.json" --out "$tmp/o-$cp" > "$tmp/out" 2> "$tmp/err"; then ok; else ko "$cp: $(cat "$tmp/err")"; fi
    csv="$tmp/o-$cp/profiles.csv"
    if [ "$(grep -c '^[0-9]' "$csv")" -eq 20 ] && grep -q '^z,n,n_err,density' "$csv" &&
       ! grep -qi 'nan\|inf' "$csv"; then ok; else ko "$cp: profiles.csv: $(head -3 "$csv")"; fi
    # energy error at round-off (not the kinetic energy's change in the field)
    e=$(sed -n 's/.*energy error \([^ ,]*\).*/\1/p' "$tmp/out")
    if awk -v e="$e" 'BEGIN { exit !(e < 1e-12 && e > -1e-12) }'; then ok; else ko "$cp: energy error $e"; fi
    # continued from final.json (to t = 400) the same balls, to the bit, as a run that went on
    printf '%s\n' "{$(echo "$G" | sed 's/"t_end": 200/"t_end": 400/'), \"gravity\": {\"g\": 0.005, \"coupling\": \"$cp\"}}" > "$tmp/$cp-400.json"
    if grep -q "\"coupling\":\"$cp\"" "$tmp/o-$cp/final.json" &&
       "$sim" "$tmp/o-$cp/final.json" --out "$tmp/m-$cp" > /dev/null 2> "$tmp/err" &&
       "$sim" "$tmp/$cp-400.json" --out "$tmp/u-$cp" > /dev/null 2>> "$tmp/err" &&
       [ -s "$tmp/m-$cp/profiles.csv" ] &&
       [ "$(tail -n +2 "$tmp/m-$cp/final.json")" = "$(tail -n +2 "$tmp/u-$cp/final.json")" ]; then ok
    else ko "$cp: continued: $(cat "$tmp/err")"; fi
done
echo "$n checks, $fails failed"
[ $fails -eq 0 ]
