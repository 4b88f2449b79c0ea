#!/bin/bash
# test_sim_final.sh RELCOL_SIM — final.json's balls, byte for byte: the streaming writer
# (scenario_write.c's ball()) prints what cJSON_PrintUnformatted printed of each ball's tree
# of raw %.17g numbers. The expected lines are those relcol-sim wrote before the streaming
# writer (main at 135af1b, its cJSON printer): a 3-D run with periodic and walled axes
# (image, a wrap to -1, -0 momenta, 1e-100, 0.30000000000000004) and a classical 2-D one,
# each with a collision (tau_last).
sim="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
cat > "$tmp/a.json" <<'JSON'
{"relcol": 1, "dim": 3, "box": [10, 10, 10], "c": 3, "t_end": 3, "boundary": ["periodic", "walls", "periodic"],
 "balls": [{"r": 1, "m": 1, "x": [2, 2, 2], "p": [-1.5, -0.0, -0.0]},
           {"r": 0.5, "m": 2.5, "x": [9.9, 6, 6], "p": [1e-100, -0.0, 0.30000000000000004]},
           {"r": 1, "m": 1, "x": [3, 8, 8], "p": [0.7, 0, 0]},
           {"r": 1, "m": 2, "x": [6.5, 8, 8], "p": [-0.4, 0, 0]}],
 "outputs": {"xyz_every": 0}}
JSON
cat > "$tmp/a.want" <<'WANT'
 "balls": [
  {"r":1,"m":1,"tau":2.6832815729997472,"x":[7.9750776405003787,2,2],"p":[-1.5,-0,-0],"image":[-1,0,0]},
  {"r":0.5,"m":2.5,"tau":2.9976028761653684,"x":[9.9000000000000004,6,6.3597123451398438],"p":[1e-100,-0,0.30000000000000004],"image":[0,0,0]},
  {"r":1,"m":1,"tau":2.9375423977747621,"tau_last":1.6889647527585487,"x":[3.5604185001247579,8,8],"p":[-0.49805218705333387,0,0],"image":[0,0,0]},
  {"r":1,"m":2,"tau":2.9851094616515477,"tau_last":1.7304915273530697,"x":[6.6545269877210043,8,8],"p":[0.79805218705333381,0,0],"image":[0,0,0]}
 ]}
WANT
cat > "$tmp/b.json" <<'JSON'
{"relcol": 1, "dim": 2, "box": [10, 10], "c": "inf", "t_end": 2,
 "balls": [{"r": 1, "m": 1, "x": [2, 5], "p": [1, -0.0]}, {"r": 1, "m": 3, "x": [6, 5.5], "p": [-0.1, 0]}],
 "outputs": {"xyz_every": 0}}
JSON
cat > "$tmp/b.want" <<'WANT'
 "balls": [
  {"r":1,"m":1,"tau":2,"tau_last":1.9969435421577013,"x":[3.9955585846979096,4.9988532315000942],"p":[-0.45312500000000022,-0.37519526166384354]},
  {"r":1,"m":3,"tau":2,"tau_last":1.9969435421577013,"x":[5.9348138051006964,5.5003822561666356],"p":[1.3531250000000001,0.37519526166384354]}
 ]}
WANT
for k in a b; do
    (cd "$tmp" && "$sim" $k.json --out o$k --no-plots > /dev/null 2> $k.err) ||
        { echo "FAILED: $k.json: $(cat "$tmp/$k.err")"; fails=$((fails + 1)); continue; }
    if sed -n '/"balls": \[/,$p' "$tmp/o$k/final.json" | cmp -s - "$tmp/$k.want"; then
        echo "ok: $k.json: final.json's balls are the expected bytes ($(grep -c '^  {' "$tmp/$k.want") balls)"
    else
        echo "FAILED: $k.json: final.json's balls differ from the expected bytes:"
        sed -n '/"balls": \[/,$p' "$tmp/o$k/final.json" | diff "$tmp/$k.want" - | head -20
        fails=$((fails + 1))
    fi
    # ... and the continuation from it is accepted (its numbers read back)
    (cd "$tmp" && "$sim" o$k/final.json --out c$k --no-plots > /dev/null 2> $k.err) ||
        { echo "FAILED: $k: the continuation from final.json: $(cat "$tmp/$k.err")"; fails=$((fails + 1)); }
done
[ $fails -eq 0 ]
