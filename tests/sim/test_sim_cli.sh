#!/bin/sh
# test_sim_cli.sh RELCOL_SIM DATA_DIR — relcol-sim's contract: every malformed or impossible
# scenario is rejected (exit 2) with the JSON path of the offending value and the reason;
# a run writes its files; continuing from final.json is bit-identical to not stopping.
sim="$1"; data="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }

# reject NAME JSON EXPECTED-SUBSTRING
reject() {
    printf '%s\n' "$2" > "$tmp/$1.json"
    "$sim" "$tmp/$1.json" --out "$tmp/o-$1" > "$tmp/out" 2> "$tmp/err"; st=$?
    if [ $st -eq 2 ] && grep -qF -- "$3" "$tmp/err" && [ "$(wc -l < "$tmp/err")" -eq 1 ]; then
        ok "$1 -> exit 2: $(cat "$tmp/err")"
    else
        ko "$1: exit $st, stderr: $(cat "$tmp/err") (wanted: $3)"
    fi
}

B='"dim": 2, "box": [10, 10], "t_end": 1'
ball='{"r": 1, "x": [5, 5], "v": [0.1, 0]}'
reject malformed '{"dim": 2, "box": [10, 10],' 'malformed JSON'
reject notobject '[1, 2]' 'must be a JSON object'
reject unknownkey "{$B, \"balls\": [$ball], \"colour\": 3}" 'colour: unknown key'
reject wrongtype "{\"dim\": \"two\", \"box\": [10, 10], \"t_end\": 1, \"balls\": [$ball]}" 'dim: must be a number'
reject baddim "{\"dim\": 4, \"box\": [10, 10], \"t_end\": 1, \"balls\": [$ball]}" 'dim: must be 2 or 3'
reject boxcomp "{\"dim\": 2, \"box\": [10, 10, 10], \"t_end\": 1, \"balls\": [$ball]}" 'box: has 3 components'
reject negc "{$B, \"c\": -1, \"balls\": [$ball]}" 'c: must be > 0'
reject epsw "{$B, \"restitution\": {\"wall\": 1.5}, \"balls\": [$ball]}" 'restitution.wall: must be in [0, 1]'
reject frame "{$B, \"contact_frame\": \"lab\", \"balls\": [$ball]}" "contact_frame: unknown frame 'lab'"
reject law "{$B, \"law\": \"sticky\", \"balls\": [$ball]}" "law: unknown collision law 'sticky'"
reject groups "{$B, \"groups\": \"together\", \"balls\": [$ball]}" "groups: unknown rule for simultaneous contacts 'together' (expected simultaneous, sequential, drop)"
reject groupstype "{$B, \"groups\": 1, \"balls\": [$ball]}" 'groups: must be a string'
reject noballs "{$B}" 'balls: missing'
reject both "{$B, \"balls\": [$ball], \"generate\": {\"kind\": \"rack\"}}" 'give either balls or generate'
reject outside "{$B, \"balls\": [{\"r\": 1, \"x\": [9.5, 5]}]}" "balls[0]: the ball's shape is not inside the box"
reject centre "{$B, \"balls\": [{\"r\": 1, \"x\": [12, 5]}]}" 'balls[0].x: the centre is not inside the box along axis 0'
reject speed "{$B, \"c\": 1, \"balls\": [{\"r\": 1, \"x\": [5, 5], \"v\": [1.2, 0]}]}" 'balls[0].v: |v| = 1.2'
reject radius "{$B, \"balls\": [{\"r\": 0, \"x\": [5, 5]}]}" 'balls[0].r: radius must be > 0'
reject mass "{$B, \"balls\": [{\"r\": 1, \"m\": -2, \"x\": [5, 5]}]}" 'balls[0].m: rest mass must be > 0'
reject ballkey "{$B, \"balls\": [{\"r\": 1, \"x\": [5, 5], \"spin\": 1}]}" 'balls[0].spin: unknown key'
reject vandp "{$B, \"balls\": [{\"r\": 1, \"x\": [5, 5], \"v\": [0, 0], \"p\": [0, 0]}]}" 'balls[0]: give either v or p'
reject overlap "{$B, \"balls\": [$ball, {\"r\": 1, \"x\": [6, 5]}]}" 'balls[1]: overlaps another ball'
reject tend "{\"dim\": 2, \"box\": [10, 10], \"t_end\": 0, \"balls\": [$ball]}" 't_end: must be later'
reject packing '{"dim": 3, "t_end": 1, "generate": {"kind": "gas", "n": 10, "packing": 0.6, "v_rms": 0.1}}' 'generate.packing: must be in (0, 0.45]'
reject snaps "{$B, \"balls\": [$ball], \"outputs\": {\"snapshots\": [0.5, 7]}}" 'outputs.snapshots[1]: time 7 is outside'
reject outkey "{$B, \"balls\": [$ball], \"outputs\": {\"snapshot\": 1}}" 'outputs.snapshot: unknown key'
reject nan "{$B, \"balls\": [{\"r\": 1, \"x\": [5, NaN]}]}" 'malformed JSON'
reject twice "{$B, \"balls\": [$ball], \"dim\": 2}" 'dim: given twice'
reject twiceinner '{"dim": 2, "t_end": 1, "generate": {"kind": "gas", "n": 4, "packing": 0.2, "v_rms": 0.1, "packing": 0.3}}' 'generate.packing: given twice'
# found by fuzzing (tests/fuzz/fuzz_scenario.c): a one-ball gas had NaN momenta, a huge
# classical v_rms was called faster than light
reject oneball '{"dim": 2, "t_end": 1, "generate": {"kind": "gas", "n": 1, "packing": 0.2, "v_rms": 0.1}}' 'generate.v_rms: must be 0 for a gas of one ball'
reject hugev '{"dim": 2, "t_end": 1, "generate": {"kind": "gas", "n": 4, "packing": 0.2, "v_rms": 1e200}}' 'generate.v_rms: too large'
# one scenario a file; a restart keeps the overlap check for spheres (c = inf)
reject trailing "{$B, \"balls\": [$ball]} xyz" "(document): text after the scenario's closing brace at line 1, column 90"
reject second "{$B, \"balls\": [$ball]}
{}" "(document): text after the scenario's closing brace at line 2, column 1"
reject restartoverlap "{$B, \"restart\": true, \"balls\": [$ball, {\"r\": 1, \"x\": [5.5, 5]}]}" 'balls[1]: overlaps another ball'
reject frames "{$B, \"balls\": [$ball], \"outputs\": {\"xyz_every\": 1e-12}}" 'outputs.xyz_every: gives 1e+12 frames from 0 to 1, more than 100000'
reject checkpointnorestart "{$B, \"checkpoint\": \"final.ckpt\", \"balls\": [$ball]}" 'checkpoint: belongs to a restart file'
reject checkpointdir "{$B, \"restart\": true, \"checkpoint\": \"../x.ckpt\", \"balls\": [$ball]}" 'checkpoint: must be a file name beside the scenario'

# a byte order mark and CRLF line ends (editors, spreadsheets) are read; a table at rest
# reports no NaN
printf '\357\273\277{"dim": 2, "box": [10, 10], "t_end": 1,\r\n "balls": [{"r": 1, "x": [5, 5]}], "outputs": {"plots": false}}\r\n' > "$tmp/bom.json"
if "$sim" "$tmp/bom.json" --out "$tmp/bom" > "$tmp/out" 2> "$tmp/err" && ! grep -qi nan "$tmp/out" "$tmp/bom/summary.txt" "$tmp/bom/summary.json"; then
    ok "BOM + CRLF read; at rest: $(cat "$tmp/out")"
else
    ko "BOM/CRLF or NaN at rest: $(cat "$tmp/err") $(cat "$tmp/out")"
fi

# periodic boundaries: the key, each axis, a centre on the face, room for four cells
reject bndval "{$B, \"boundary\": \"open\", \"balls\": [$ball]}" "boundary: unknown boundary 'open'"
reject bndlen "{$B, \"boundary\": [\"periodic\"], \"balls\": [$ball]}" 'boundary: has 1 entries, the scenario is 2-D'
reject bndaxis "{$B, \"boundary\": [\"walls\", 3], \"balls\": [$ball]}" 'boundary[1]: must be "walls" or "periodic"'
reject bndtype "{$B, \"boundary\": {}, \"balls\": [$ball]}" 'boundary: must be "walls", "periodic" or a list of 2 of them'
reject bndcentre "{$B, \"boundary\": \"periodic\", \"balls\": [{\"r\": 1, \"x\": [10, 5]}]}" 'balls[0].x: the centre is not inside the box along periodic axis 0'
reject bndroom "{\"dim\": 2, \"box\": [7.9, 10], \"t_end\": 1, \"boundary\": [\"periodic\", \"walls\"], \"balls\": [{\"r\": 1, \"x\": [4, 5]}]}" 'boundary: axis 0 is periodic, so its box edge 7.9 must be at least 4 largest ball diameters'
reject bndimage "{$B, \"boundary\": [\"periodic\", \"walls\"], \"balls\": [{\"r\": 1, \"x\": [5, 5], \"image\": [2, 1]}]}" 'balls[0].image: component 1 must be 0: axis 1 has walls'
reject bndacross "{$B, \"boundary\": \"periodic\", \"balls\": [{\"r\": 1, \"x\": [0.5, 5]}, {\"r\": 1, \"x\": [9, 5]}]}" 'balls[1]: overlaps another ball'

# the shipped scenario files are the built-ins
for b in rack gas; do
    "$sim" --builtin $b --dump > "$tmp/$b-builtin.json" 2>/dev/null
    "$sim" "$data/scenarios/$b.json" --dump > "$tmp/$b-file.json" 2>/dev/null
    if cmp -s "$tmp/$b-builtin.json" "$tmp/$b-file.json" && [ -s "$tmp/$b-file.json" ]; then
        ok "data/scenarios/$b.json reads as --builtin $b"
    else
        ko "data/scenarios/$b.json differs from --builtin $b"
    fi
done

# a small run writes its files
cat > "$tmp/run.json" <<JSON
{"relcol": 1, "dim": 2, "c": 2, "restitution": {"ball": 0.9, "wall": 1},
 "contact_frame": "table", "seed": 3, "t_end": 40,
 "generate": {"kind": "gas", "n": 60, "radius": 1, "packing": 0.15, "v_rms": 0.5},
 "outputs": {"snapshots": [10, 20], "xyz_every": 5, "plots": false, "gif": false}}
JSON
if "$sim" "$tmp/run.json" --out "$tmp/full" > "$tmp/out" 2> "$tmp/err"; then
    ok "run: $(cat "$tmp/out")"
else
    ko "run failed: $(cat "$tmp/err")"
fi
for f in summary.txt final.json trajectory.xyz snapshots/snap-0000.csv snapshots/snap-0001.csv; do
    [ -s "$tmp/full/$f" ] && ok "wrote $f" || ko "missing $f"
done
ls "$tmp/full" | grep -q '\.tmp' && ko "temporary files left behind" || ok "no temporary files left"
frames=$(grep -c '^Lattice=' "$tmp/full/trajectory.xyz")
[ "$frames" -eq 9 ] && ok "trajectory.xyz has 9 frames (t = 0, 5, ..., 40)" || ko "trajectory.xyz has $frames frames, want 9"
head -2 "$tmp/full/trajectory.xyz" | tail -1 | grep -q 'Properties=species:S:1:pos:R:3' \
    && ok "extended-XYZ header" || ko "extended-XYZ header"
grep -q 'overlaps         0 found' "$tmp/full/summary.txt" && ok "no overlaps" || ko "overlaps: $(grep overlaps "$tmp/full/summary.txt")"

# continuing from final.json writes into a folder of its own (full.1, then full.2), and
# the run it continues keeps its files
cp "$tmp/full/trajectory.xyz" "$tmp/traj-first.xyz"
grep -qF "\"dir\":\"$tmp/full.1\"" "$tmp/full/final.json" && ok "final.json continues into full.1" \
    || ko "final.json's outputs.dir: $(grep -o '"dir":"[^"]*"' "$tmp/full/final.json")"
if "$sim" "$tmp/full/final.json" > /dev/null 2> "$tmp/err" && [ -s "$tmp/full.1/final.json" ] &&
    cmp -s "$tmp/traj-first.xyz" "$tmp/full/trajectory.xyz" &&
    grep -qF "\"dir\":\"$tmp/full.2\"" "$tmp/full.1/final.json"; then
    ok "continuing: wrote full.1/, left full/ as it was, next into full.2"
else
    ko "continuing from final.json: $(cat "$tmp/err")"
fi

# restart identity: 0 -> 20 -> (final.json) -> 40 equals 0 -> 40 with a stop at 20
# (the edited copy stays beside final.ckpt, the checkpoint final.json names)
sed 's/"t_end": 40/"t_end": 20/' "$tmp/run.json" > "$tmp/half.json"
"$sim" "$tmp/half.json" --out "$tmp/half" > /dev/null 2>&1
sed 's/"t_end":[0-9.e+-]*/"t_end": 40/' "$tmp/half/final.json" > "$tmp/half/cont.json"
"$sim" "$tmp/half/cont.json" --out "$tmp/cont" > /dev/null 2> "$tmp/err"
sed -n '/"balls"/,$p' "$tmp/full/final.json" > "$tmp/a"
sed -n '/"balls"/,$p' "$tmp/cont/final.json" > "$tmp/b"
if [ -s "$tmp/a" ] && cmp -s "$tmp/a" "$tmp/b"; then
    ok "restart from final.json at t = 20 is bit-identical at t = 40"
else
    ko "restart differs: $(cat "$tmp/err") $(cmp "$tmp/a" "$tmp/b" 2>&1 | head -1)"
fi
# a periodic (mixed) gas: 0 -> 10 -> (final.json, image counters) -> 20 equals 0 -> 20
cat > "$tmp/per.json" <<'EOF'
{"relcol": 1, "dim": 3, "boundary": ["periodic", "walls", "periodic"], "c": 1,
 "contact_frame": "zmf", "t_end": 20,
 "generate": {"kind": "gas", "n": 200, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"snapshots": [5], "xyz_every": 0, "plots": false, "gif": false}}
EOF
sed 's/"t_end": 20/"t_end": 10/' "$tmp/per.json" > "$tmp/perhalf.json"
"$sim" "$tmp/per.json" --out "$tmp/perfull" > /dev/null 2>&1
"$sim" "$tmp/perhalf.json" --out "$tmp/perhalf" > /dev/null 2>&1
sed 's/"t_end":[0-9.e+-]*/"t_end": 20/' "$tmp/perhalf/final.json" > "$tmp/perhalf/cont.json"
"$sim" "$tmp/perhalf/cont.json" --out "$tmp/percont" > /dev/null 2> "$tmp/err"
sed -n '/"balls"/,$p' "$tmp/perfull/final.json" > "$tmp/pa"
sed -n '/"balls"/,$p' "$tmp/percont/final.json" > "$tmp/pb"
if [ -s "$tmp/pa" ] && cmp -s "$tmp/pa" "$tmp/pb" && grep -q '"image":\[-\{0,1\}[1-9]' "$tmp/pa" &&
    grep -qF '"boundary":["periodic","walls","periodic"]' "$tmp/percont/final.json" &&
    head -2 "$tmp/perfull/snapshots/snap-0000.csv" | grep -q ',image_x,image_y,image_z$'; then
    ok "periodic: restart from final.json is bit-identical, images and boundary kept"
else
    ko "periodic restart: $(cat "$tmp/err") $(cmp "$tmp/pa" "$tmp/pb" 2>&1 | head -1)"
fi

# determinism: the same scenario twice
"$sim" "$tmp/run.json" --out "$tmp/again" > /dev/null 2>&1
sed -n '/"balls"/,$p' "$tmp/again/final.json" > "$tmp/c"
cmp -s "$tmp/a" "$tmp/c" && ok "same scenario twice -> identical final state" \
    || ko "two runs of one scenario differ"

# the outputs do not change the run: no outputs at all, and outputs at irregular times
sed 's/"outputs": {[^}]*}/"outputs": {"plots": false, "gif": false, "summary": false}/' "$tmp/run.json" > "$tmp/quiet.json"
sed 's/"snapshots": \[10, 20\], "xyz_every": 5/"snapshots": [0.3, 1.7, 2.71828, 19.99, 33.3], "xyz_every": 0.37, "h5md_every": 0.29/' "$tmp/run.json" > "$tmp/busy.json"
"$sim" "$tmp/quiet.json" --out "$tmp/quiet" > /dev/null 2>&1
"$sim" "$tmp/busy.json" --out "$tmp/busy" > /dev/null 2>&1
sed -n '/"balls"/,$p' "$tmp/quiet/final.json" > "$tmp/q"
sed -n '/"balls"/,$p' "$tmp/busy/final.json" > "$tmp/b2"
[ -s "$tmp/q" ] && cmp -s "$tmp/a" "$tmp/q" && cmp -s "$tmp/a" "$tmp/b2" \
    && [ -s "$tmp/busy/trajectory.h5" ] \
    && ok "outputs change no bit: no outputs, every 5, 109 XYZ and 138 H5MD frames and 5 snapshots at odd times" \
    || ko "the outputs changed the run"

# a checkpoint that is not this state, or not there: refused, naming why
sed '0,/"tau":[0-9.e+-]*/s//"tau":12345/' "$tmp/half/final.json" > "$tmp/half/edited.json"
"$sim" "$tmp/half/edited.json" --out "$tmp/edited" > /dev/null 2> "$tmp/err"; st=$?
[ $st -eq 2 ] && grep -q 'balls\[0\]: differs from the state in the checkpoint' "$tmp/err" \
    && ok "an edited ball against its checkpoint -> exit 2: $(cat "$tmp/err")" \
    || ko "edited ball: exit $st: $(cat "$tmp/err")"
cp "$tmp/half/final.json" "$tmp/moved.json"
"$sim" "$tmp/moved.json" --out "$tmp/moved" > /dev/null 2> "$tmp/err"; st=$?
[ $st -eq 2 ] && grep -q 'checkpoint: cannot read' "$tmp/err" \
    && ok "final.json away from its checkpoint -> exit 2: $(cat "$tmp/err")" \
    || ko "missing checkpoint: exit $st: $(cat "$tmp/err")"
head -c 100 "$tmp/half/final.ckpt" > "$tmp/cut.ckpt"
sed 's/"checkpoint":"final.ckpt"/"checkpoint":"cut.ckpt"/' "$tmp/half/final.json" > "$tmp/cut.json"
"$sim" "$tmp/cut.json" --out "$tmp/cut" > /dev/null 2> "$tmp/err"; st=$?
[ $st -eq 2 ] && grep -q 'not a whole, undamaged relcol checkpoint' "$tmp/err" \
    && ok "a cut checkpoint -> exit 2" || ko "cut checkpoint: exit $st: $(cat "$tmp/err")"

# summary.json: the machine-readable results, with the counts summary.txt gives
j="$tmp/full/summary.json"
for k in '"t":' '"collisions":' '"ball":' '"wall":' '"group":' '"overlaps_resolved":' \
         '"energy_error":' '"momentum_error":' '"rest_mass_total":' '"x-":' '"y+":' \
         '"cell_crossings":' '"events":'; do
    grep -q "$k" "$j" || { ko "summary.json lacks $k"; break; }
done
coll=$(sed -n 's/^collisions *\([0-9]*\).*/\1/p' "$tmp/full/summary.txt")
grep -q "\"contacts\":[[:space:]]*$coll," "$j" && ok "summary.json: $coll contacts, as summary.txt" \
    || ko "summary.json's contacts differ from summary.txt's $coll"

# --frame: the covariant frame runs, counts its conflicts, continues bit-identically;
# an unknown name is refused
"$sim" --builtin gas --frame covariant --t-end 3 --no-plots --out "$tmp/cov" > /dev/null 2> "$tmp/err" \
    && grep -q '"contact_frame":"covariant"' "$tmp/cov/final.json" \
    && grep -q '"tube_conflicts":' "$tmp/cov/summary.json" \
    && grep -q '"order_conflicts":' "$tmp/cov/summary.json" \
    && ok "--frame covariant runs, summary.json has its conflicts" \
    || ko "--frame covariant: $(cat "$tmp/err")"
"$sim" "$tmp/cov/final.json" --t-end 5 --no-plots > /dev/null 2> "$tmp/err" \
    && "$sim" --builtin gas --frame covariant --t-end 5 --no-plots --out "$tmp/cov5" > /dev/null 2>&1 \
    && sed -n '/"balls"/,$p' "$tmp/cov.1/final.json" | sed 1d > "$tmp/a" \
    && sed -n '/"balls"/,$p' "$tmp/cov5/final.json" | sed 1d > "$tmp/b" && cmp -s "$tmp/a" "$tmp/b" \
    && ok "covariant: continued to t = 5 bit-identical to one run" \
    || ko "covariant continued run differs: $(cat "$tmp/err")"
"$sim" --builtin gas --frame nope > /dev/null 2> "$tmp/err"; st=$?
[ $st -eq 2 ] && grep -q "unknown contact frame 'nope'" "$tmp/err" \
    && ok "--frame nope -> exit 2" || ko "--frame nope: exit $st: $(cat "$tmp/err")"

# Ctrl-C: a long run interrupted writes a restart state that reads back, and exits 130
sed 's/"t_end": 40/"t_end": 1e9/; s/"snapshots": \[10, 20\], /"snapshots": {"every": 1e8}, /; s/"xyz_every": 5/"xyz_every": 1e7/; s/"ball": 0.9/"ball": 1/' "$tmp/run.json" > "$tmp/long.json"
"$sim" "$tmp/long.json" --out "$tmp/long" > /dev/null 2> "$tmp/err" &
pid=$!
# its handler is set just after its staging folder DIR/.run.relcol-PID.* is made: wait for that (up to 60 s)
for _ in $(seq 600); do ls -d "$tmp"/long/.run.relcol-* > /dev/null 2>&1 && break; sleep 0.1; done
sleep 0.3
kill -INT $pid
wait $pid; st=$?
[ $st -eq 130 ] && grep -q 'interrupted' "$tmp/err" && ok "Ctrl-C: exit 130, says so" || ko "Ctrl-C: exit $st: $(cat "$tmp/err")"
"$sim" "$tmp/long/final.json" --dump > /dev/null 2> "$tmp/err" && ok "Ctrl-C: final.json reads back as a scenario" \
    || ko "Ctrl-C: final.json does not read back: $(cat "$tmp/err")"
grep -q 'interrupted' "$tmp/long/summary.txt" && ok "Ctrl-C: summary written" || ko "Ctrl-C: no summary"
# ... continuing from it equals the run that was never stopped (same end, same bits), and
# its frames stay on the uninterrupted run's grid
sed 's/"t_end": 40/"t_end": 300/; s/"snapshots": \[10, 20\], "xyz_every": 5/"xyz_every": 0.7/' "$tmp/run.json" > "$tmp/mid.json"
"$sim" "$tmp/mid.json" --out "$tmp/mid-full" > /dev/null 2>&1
# relcol-sim sets its handler before it makes its staging folder DIR/.run.relcol-PID.*
# (a SIGINT before that is lost: a background job starts with SIGINT ignored): wait for the
# folder, then interrupt d s later; a run that ended first (exit 0) is retried sooner.
i=0; st=0; d=0.02
while [ $i -lt 12 ]; do
    rm -rf "$tmp/mid" "$tmp/mid.1"
    "$sim" "$tmp/mid.json" --out "$tmp/mid" > /dev/null 2> "$tmp/err" &
    pid=$!
    k=0
    until ls -d "$tmp"/mid/.run.relcol-* > /dev/null 2>&1 || [ $k -ge 2000 ] || ! kill -0 $pid 2>/dev/null; do
        sleep 0.005; k=$((k + 1))
    done
    sleep "$d"
    kill -INT $pid 2>/dev/null
    wait $pid; st=$?
    [ $st -eq 130 ] && [ -f "$tmp/mid/final.json" ] && break
    d=$(awk -v d="$d" 'BEGIN { print d / 2 }')
    i=$((i + 1))
done
if [ $st -eq 130 ] && [ -f "$tmp/mid/final.json" ]; then
    "$sim" "$tmp/mid/final.json" > /dev/null 2> "$tmp/err"
    sed -n '/"balls"/,$p' "$tmp/mid-full/final.json" > "$tmp/m1"
    sed -n '/"balls"/,$p' "$tmp/mid.1/final.json" > "$tmp/m2"
    [ -s "$tmp/m1" ] && cmp -s "$tmp/m1" "$tmp/m2" \
        && ok "stopped by SIGINT at t = $(sed -n 's/.*"time":\([^,]*\),.*/\1/p' "$tmp/mid/final.json") and continued: bit-identical at t = 300" \
        || ko "SIGINT restart differs: $(cat "$tmp/err")"
    grep '^Lattice=' "$tmp/mid-full/trajectory.xyz" | grep -o 'Time=[^ ]*' > "$tmp/t-full"
    cat "$tmp/mid/trajectory.xyz" "$tmp/mid.1/trajectory.xyz" | grep '^Lattice=' | grep -o 'Time=[^ ]*' | sort -u -t= -k2 -g > "$tmp/t-parts"
    cmp -s "$tmp/t-full" "$tmp/t-parts" && ok "the frames of the two parts are the uninterrupted run's ($(wc -l < "$tmp/t-full") times)" \
        || ko "frame times differ: $(diff "$tmp/t-full" "$tmp/t-parts" | head -3 | tr '\n' ' ')"
else
    ko "could not interrupt the 300 s run mid-way in 12 tries (last exit $st, waited ${d} s)"
fi

# ... and takes the snapshot times still ahead along (here all ten: every 1e8 up to 1e9)
nsnap=$(grep -o '"snapshots":\[[^]]*\]' "$tmp/long/final.json" | tr ',' '\n' | grep -c '[0-9]')
[ "$nsnap" -eq 10 ] && ok "Ctrl-C: final.json carries the 10 snapshot times ahead" \
    || ko "Ctrl-C: final.json carries $nsnap snapshot times, want 10"

# time that stands still stops the run in well under the test's time limit, exit 3, the
# balls and the time named, the state written: a chain of two balls exactly as wide as the
# box pushed against its walls; a clock of 1e20, where a step rounds to nothing
stall() { # NAME JSON EXPECTED
    printf '%s\n' "$2" > "$tmp/$1.json"
    "$sim" "$tmp/$1.json" --out "$tmp/$1" > /dev/null 2> "$tmp/err"; st=$?
    if [ $st -eq 3 ] && grep -q "simulated time stands still: $3" "$tmp/err" && [ -s "$tmp/$1/final.json" ]; then
        ok "$1 -> exit 3: $(cat "$tmp/err")"
    else
        ko "$1: exit $st: $(cat "$tmp/err")"
    fi
}
# a ball exactly as wide as the box pushed against a wall is jammed: the wall contact is
# plastic along x (papers/relcol.md, "Limits"), the run ends at t_end and says so
printf '%s\n' '{"dim": 2, "box": [2, 10], "t_end": 5, "balls": [{"r": 1, "x": [1, 5], "v": [-0.5, 0.3]}], "outputs": {"plots": false}}' > "$tmp/pinned.json"
if "$sim" "$tmp/pinned.json" --out "$tmp/pinned" > /dev/null 2> "$tmp/err" &&
   grep -q '"pinned":[[:space:]]*1,' "$tmp/pinned/summary.json" && grep -q '"t":[[:space:]]*5,' "$tmp/pinned/summary.json"; then
    ok "pinned ball runs to t_end, summary.json counts 1 pinned contact"
else
    ko "pinned ball: $(cat "$tmp/err") $(grep -o '"pinned": *[0-9]*' "$tmp/pinned/summary.json" 2>/dev/null)"
fi
stall chain '{"dim": 2, "box": [4, 10], "t_end": 5, "balls": [{"r": 1, "x": [1, 5], "v": [-0.5, 0]}, {"r": 1, "x": [3, 5], "v": [0.3, 0]}], "outputs": {"plots": false}}' 'ball [01] and '
# a clock whose doubles cannot resolve the balls' motion is refused before it runs (issue 37
# item 9, apps/sim/clock.c: at 1e17 every collision was the overlap policy's); at 1e12 a
# unit ball at unit speed moves 1.2e-4 within a step of the clock, and runs
reject clock '{"dim": 2, "box": [10, 10], "time": 1e20, "t_end": 1.0000000000001e20, "balls": [{"r": 1, "x": [5, 5], "v": [1, 0]}], "outputs": {"plots": false}}' 'e+20: doubles near it are 16384 apart'
reject clock17 '{"dim": 2, "box": [10, 10], "t_end": 1e17, "balls": [{"r": 1, "x": [5, 5], "v": [0.5, 0]}], "outputs": {"plots": false}}' 'collisions cannot be resolved there'
reject clockrel '{"dim": 2, "box": [10, 10], "c": 1, "time": -1e14, "t_end": 1, "balls": [{"r": 1, "x": [5, 5], "v": [0.5, 0]}], "outputs": {"plots": false}}' 'time 100000000000000: doubles near it are 0.015625 apart'
printf '%s\n' '{"dim": 2, "box": [10, 10], "time": 1e12, "t_end": 1000000000010, "balls": [{"r": 1, "x": [5, 5], "v": [1, 0]}], "outputs": {"plots": false}}' > "$tmp/clock12.json"
"$sim" "$tmp/clock12.json" --out "$tmp/clock12" > /dev/null 2> "$tmp/err" && ok "time 1e12, unit speed and radius: runs" ||
    ko "time 1e12: $(cat "$tmp/err")"

# a killed run's temporaries are removed by the next run into the same folder; a live
# writer's, and files that only look alike, are not
sh -c 'exit 0' & dead=$!
wait $dead
mkdir -p "$tmp/stale"
for f in ".summary.txt.relcol-$dead.AbCdEf" ".frames.dat.relcol-$dead.x1y2z3" \
         ".summary.txt.relcol-$$.LiVeOn" ".summary.txt.keep"; do
    printf 'half a file' > "$tmp/stale/$f"
done
sed 's/"t_end": 40/"t_end": 2/; s/"snapshots": \[10, 20\], //' "$tmp/run.json" > "$tmp/stale.json"
"$sim" "$tmp/stale.json" --out "$tmp/stale" > /dev/null 2> "$tmp/err"
# (.relcol-run and .relcol-run.XXXXXX: the published run, simout_publish.c)
left=$(ls -A "$tmp/stale" | grep '^\.' | grep -v '^\.relcol-run' | sort | tr '\n' ' ')
[ "$left" = ".summary.txt.keep .summary.txt.relcol-$$.LiVeOn " ] \
    && ok "stale temporaries of a dead writer removed, a live one's kept" \
    || ko "temporaries left: $left $(cat "$tmp/err")"

# an output folder whose name needs escaping in JSON: final.json still reads back
q="$tmp/o\"q\\z"
sed 's/"t_end": 40/"t_end": 2/; s/"snapshots": \[10, 20\], //' "$tmp/run.json" > "$tmp/quote.json"
if "$sim" "$tmp/quote.json" --out "$q" > /dev/null 2> "$tmp/err" &&
    "$sim" "$q/final.json" --dump > "$tmp/quote-dump.json" 2> "$tmp/err" &&
    grep -qF 'o\"q\\z' "$tmp/quote-dump.json"; then
    ok "final.json of a folder named with a quote and a backslash reads back"
else
    ko "folder with a quote: $(cat "$tmp/err")"
fi

# a momentum component of -0 written as -0 (cJSON's own number printer writes 0): the
# continuation's balls must equal the checkpoint's to the bit
printf '{"relcol": 1, "dim": 2, "box": [10, 10], "t_end": 1, "balls": [{"r": 1, "x": [5, 5],
 "p": [-0.0, 0]}, {"r": 1, "x": [2, 2], "p": [0.5, -0.0]}], "outputs": {"plots": false}}' > "$tmp/negz.json"
if "$sim" "$tmp/negz.json" --out "$tmp/negz" > /dev/null 2> "$tmp/err" &&
    grep -qF '"p":[-0,0]' "$tmp/negz/final.json" &&
    "$sim" "$tmp/negz/final.json" > /dev/null 2> "$tmp/err"; then
    ok "momentum -0 written as -0, and the continuation accepts its checkpoint"
else
    ko "momentum -0: $(cat "$tmp/err")"
fi

# a covariant run outside the rigid-ball model's regime (p_model > 1e-3) says so in one line
# on stderr, with summary.json's model block's numbers (to the 3 digits printed); one that
# the rules did not touch (the momentum -0 run above, classical) printed nothing
[ ! -s "$tmp/err" ] && ok "a classical run: nothing on stderr" || ko "classical run's stderr: $(cat "$tmp/err")"
cat > "$tmp/cov.json" <<JSON
{"relcol": 1, "dim": 2, "c": 1, "contact_frame": "covariant", "seed": 3, "t_end": 20,
 "boundary": "periodic",
 "generate": {"kind": "gas", "n": 100, "radius": 1, "packing": 0.3, "v_rms": 0.9},
 "outputs": {"plots": false, "gif": false}}
JSON
"$sim" "$tmp/cov.json" --out "$tmp/covw" > /dev/null 2> "$tmp/err"; st=$?
num() { awk -v k="\"$1\":" '$1 == k { sub(/,$/, "", $2); print $2; exit }' "$2"; }
pm=$(num p_model "$tmp/covw/summary.json"); sp=$(num policy_share "$tmp/covw/summary.json")
verdict=$(sed -n 's/^[[:space:]]*"verdict":[[:space:]]*"\([a-z_]*\)".*/\1/p' "$tmp/covw/summary.json")
w=$(sed -n "s/^relcol-sim: warning: outside the rigid-ball model's regime: p_model \([0-9.e+-]*\) > 0.001 .*the overlap policy decided \([0-9.e+-]*\) % of.*(papers\/validity.md)$/\1 \2/p" "$tmp/err")
if [ $st -eq 0 ] && [ "$verdict" = outside ] && [ "$(wc -l < "$tmp/err")" -eq 1 ] &&
    awk -v w="$w" -v pm="$pm" -v sp="$sp" 'BEGIN { split(w, a, " ");
        exit !(pm > 0.001 && (a[1] - pm) ^ 2 < (0.006 * pm) ^ 2 &&
               (a[2] - 100 * sp) ^ 2 < (0.006 * 100 * sp) ^ 2) }'; then
    ok "outside the regime: one warning line, $w (summary.json: p_model $pm, policy $sp)"
else
    ko "outside the regime: exit $st, verdict '$verdict', '$w' against p_model $pm, policy $sp: $(cat "$tmp/err")"
fi

# the figures explain themselves (issue 38): the GIF has axes with units, the time and a
# colour key; trajectories.png has the GIF's colours (one palette, by ball number) and its
# final balls are their shapes in those colours (contracted at finite c), not grey circles
cat > "$tmp/fig.json" <<JSON
{"relcol": 1, "dim": 2, "c": 1, "seed": 5, "t_end": 4,
 "generate": {"kind": "gas", "n": 12, "radius": 1, "packing": 0.1, "v_rms": 0.6},
 "outputs": {"xyz_every": 0.5, "plots": true, "gif": true}}
JSON
"$sim" "$tmp/fig.json" --out "$tmp/fig" > "$tmp/out" 2> "$tmp/err"; st=$?
tg=$tmp/fig/table.gp; jg=$tmp/fig/trajectories.gp
if [ $st -eq 0 ] && [ -s "$tg" ] && [ -s "$jg" ]; then
    bad=
    for f in "$tg" "$jg"; do
        for want in "set xlabel 'x (the scenario''s length unit)'" "set ylabel 'y'" \
                    "set cblabel 'ball number' offset 1,0" "Lorentz-contracted along its velocity"; do
            grep -qF "$want" "$f" || bad="$bad; $(basename "$f") lacks: $want"
        done
    done
    grep -qF "t = %.3f (the scenario's time unit)" "$tg" || bad="$bad; table.gp: no time with its unit"
    [ "$(grep '^set palette' "$tg")" = "$(grep '^set palette' "$jg")" ] || bad="$bad; the palettes differ"
    grep -q "w ellipses lc palette" "$jg" && ! grep -q "ellipses lc rgb 'black'" "$jg" \
        || bad="$bad; trajectories.gp: final balls not in their colours"
    if command -v gnuplot > /dev/null 2>&1; then
        [ -s "$tmp/fig/table.gif" ] && [ -s "$tmp/fig/trajectories.png" ] || bad="$bad; no figures"
    fi
    [ -z "$bad" ] && ok "table.gp and trajectories.gp: axes, units, time, colour key, shared colours" \
        || ko "figures:$bad"
else
    ko "figure run: exit $st: $(cat "$tmp/err")"
fi

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
