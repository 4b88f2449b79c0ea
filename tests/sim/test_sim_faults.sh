#!/bin/sh
# test_sim_faults.sh RELCOL_SIM — relcol-sim under faults: nothing truncated is ever left
# under a final name, nothing already written is lost, no temporary outlives the next run.
# 1. kill -9 at 50 random points of runs into one folder: after every kill each file
#    there is whole (CSV snapshots complete, summary.json closed, figures ending in their
#    end chunk), and the next complete run leaves no temporary behind.
# 2. a disk that fills (RLIMIT_FSIZE with SIGXFSZ ignored, so writes fail with EFBIG as on
#    a full disk): the run fails with a message and exit 1 (not a crash), and the files of the
#    previous run in that folder keep their bytes, and no file of the failed run is left
#    among them.
# 3. runs never mix: a complete run into a folder replaces the previous run's files and
#    removes those it does not replace (a snapshot past its end), and keeps the user's own
#    files there, even one named like an output the run does not write.
sim="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }

cat > "$tmp/run.json" <<JSON
{"relcol": 1, "dim": 2, "c": 2, "restitution": {"ball": 1, "wall": 1},
 "contact_frame": "table", "seed": 5, "t_end": 400,
 "generate": {"kind": "gas", "n": 200, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"dir": "$tmp/out", "snapshots": {"every": 4}, "xyz_every": 1, "h5md_every": 2,
             "plots": false,
             "gif": false}}
JSON

# whole DIR: every final-named file as its writer closes it
whole() {
    for f in "$1"/snapshots/*.csv; do
        [ -e "$f" ] || continue
        rows=$(grep -c '^[0-9]' "$f")
        [ "$rows" -eq 200 ] && [ "$(tail -c 1 "$f" | od -An -c | tr -d ' ')" = '\n' ] ||
            { echo "cut snapshot $f ($rows rows)"; return 1; }
    done
    for f in summary.json; do
        [ -e "$1/$f" ] || continue
        tail -c 3 "$1/$f" | grep -q '}' || { echo "cut $f"; return 1; }
    done
    if [ -e "$1/trajectory.h5" ]; then  # (HDF5's signature: its superblock was written)
        [ "$(head -c 4 "$1/trajectory.h5" | od -An -c | tr -d ' ')" = '211HDF' ] ||
            { echo "trajectory.h5 is not HDF5"; return 1; }
    fi
    if [ -e "$1/final.json" ]; then
        tail -c 4 "$1/final.json" | grep -q ']}' || { echo "cut final.json"; return 1; }
    fi
    return 0
}

# 1. kill -9 at random points (0.01 .. 0.3 s into a run of ~1 s)
bad=0; seedv=7
for k in $(seq 1 50); do
    seedv=$(( (seedv * 1103515245 + 12345) % 2147483648 ))
    delay=$(( seedv % 30 + 1 ))
    "$sim" "$tmp/run.json" > /dev/null 2>&1 &
    pid=$!
    sleep "0.$(printf '%02d' "$delay")"
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null
    if ! why=$(whole "$tmp/out"); then
        bad=$((bad + 1))
        echo "after kill $k at 0.$(printf '%02d' "$delay") s: $why"
    fi
done
[ $bad -eq 0 ] && ok "50 kill -9 at random points: every file under a final name whole" \
    || ko "$bad of 50 kills left a cut file under a final name"
"$sim" "$tmp/run.json" > /dev/null 2> "$tmp/err"; st=$?
left=$(ls -A "$tmp/out" "$tmp/out/snapshots" | grep -c 'relcol-[0-9]') || true
[ $st -eq 0 ] && [ "$left" -eq 0 ] && whole "$tmp/out" > /dev/null \
    && ok "the next complete run: exit 0, no temporary left, every file whole" \
    || ko "after the kills: exit $st, $left temporaries left: $(cat "$tmp/err")"

# 2. a disk that fills: writes fail with EFBIG past 64 kB a file
files() { (cd "$1" && find . -type f ! -name '.*' | sort | xargs cksum); }
before=$(files "$tmp/out")
( ulimit -f 64; trap '' XFSZ; exec "$sim" "$tmp/run.json" ) > /dev/null 2> "$tmp/err"; st=$?
after=$(files "$tmp/out")
if [ $st -eq 1 ] && [ -s "$tmp/err" ] && [ "$before" = "$after" ]; then
    ok "full disk: exit $st, $(head -1 "$tmp/err"); the previous run's $(echo "$before" | wc -l) files keep their bytes, none added"
else
    ko "full disk: exit $st, stderr '$(cat "$tmp/err")', files changed: $([ "$before" = "$after" ] && echo no || echo yes)"
fi
"$sim" "$tmp/run.json" > /dev/null 2>&1
left=$(ls -A "$tmp/out" "$tmp/out/snapshots" | grep -c 'relcol-[0-9]') || true
[ "$left" -eq 0 ] && ok "no temporary left after the full disk and one more run" \
    || ko "$left temporaries left after the full disk"

# 3. a shorter run (t_end 40: 10 snapshots, every 4, of the previous 100) into the same folder
nold=$(ls "$tmp/out/snapshots" | wc -l)
printf 'my notes\n' > "$tmp/out/notes.txt"
printf 'my own paths\n' > "$tmp/out/paths.dat"
sed 's/"t_end": 400/"t_end": 40/' "$tmp/run.json" > "$tmp/short.json"
"$sim" "$tmp/short.json" > /dev/null 2> "$tmp/err"; st=$?
nnew=$(ls "$tmp/out/snapshots" | wc -l)
if [ $st -eq 0 ] && [ "$nold" -eq 100 ] && [ "$nnew" -eq 10 ] &&
   [ "$(cat "$tmp/out/notes.txt")" = "my notes" ] && [ "$(cat "$tmp/out/paths.dat")" = "my own paths" ] &&
   grep -q '"t":[[:space:]]*40,' "$tmp/out/summary.json"; then
    ok "a shorter run replaces the previous run's files: $nold snapshots -> $nnew, the user's files kept"
else
    ko "shorter run: exit $st, snapshots $nold -> $nnew, notes '$(cat "$tmp/out/notes.txt")', paths.dat '$(head -c 20 "$tmp/out/paths.dat")': $(cat "$tmp/err")"
fi

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
