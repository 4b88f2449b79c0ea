#!/bin/bash
# test_sim_publish.sh RELCOL_SIM [FILES] [KILLS] [PUBKILLS] — relcol-sim publishes a run's files by one
# switch (apps/sim/simout_publish.c, apps/sim/SCENARIO.md "Files written"):
# 1. a link planted at every output name (snapshots/, final.json, .relcol-run, ...) and an
#    earlier scheme's manifest naming paths outside: no file outside the output folder
#    changes its bytes, appears or disappears, over a run and a second run that writes
#    fewer files;
# 2. KILLS (100; the benchmark publish: 200) kill -9 at random instants across two runs' ends into one folder, run A
#    (FILES snapshots, default 40) and run B (FILES/2 snapshots and a trajectory): after each,
#    the folder's names show exactly one run's whole set (every file's bytes those of the
#    uninterrupted A or B), and relcol-sim accepts its final.json as a continuation;
#    where each kill landed (staged, in the publish, after the exit) is counted; then kills
#    aimed at the publish: until PUBKILLS (the benchmark: 200) landed in it, or without
#    PUBKILLS 40 aimed (a publish of a few files lasts about a millisecond: on a loaded
#    machine few land in it, and their count is reported, not required);
# 3. with strace's fault injection (skipped where ptrace is not allowed): each invocation
#    of every rename, write, unlink, link and fsync system call of run B into A's folder
#    made to fail (EIO), then to be a SIGKILL: the same two checks, and the exit is 0 when
#    B is shown, 1 with a message when A is;
# 4. the folder an earlier relcol-sim wrote (its files in DIR, .relcol_sim_outputs) is
#    converted: one run's set, the user's files kept.
# The 4 000-file loop is the benchmark 'publish' (bench_publish.sh runs this with 4000).
sim="$1"; files="${2:-40}"; kills="${3:-100}"; pubkills="${4:-}"
# (on tmpfs where there is one: the runs are fsync-bound on a disk, ten times slower)
tmp=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }

# scen NAME SEED T_END SNAP_EVERY XYZ : a small gas whose run is all file writing
scen() {
    cat > "$tmp/$1.json" <<JSON
{"relcol": 1, "dim": 2, "c": 2, "seed": $2, "t_end": $3,
 "generate": {"kind": "gas", "n": 12, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"snapshots": {"every": $4}, "xyz_every": $5, "plots": false, "gif": false}}
JSON
}
scen A 1 "$files" 1 0
scen B 2 "$((files / 2))" 1 0.5

# view DIR: what DIR's names show (links followed, hidden names not), one line a file with
# its checksum; the summaries without their wall-clock lines, final.json without the name
# of its continuation's folder
view() {
    (cd "$1" 2>/dev/null || exit 0
     for f in summary.txt summary.json; do
         [ -f "$f" ] && echo "$f $(grep -v 'wall.clock' "$f" | cksum)"
     done
     [ -f final.json ] && echo "final.json $(sed 's/"dir":"[^"]*"//' final.json | cksum)"
     cksum $(ls -d * snapshots/* 2>/dev/null | grep -v '^summary\.\|^final\.json$') 2>/dev/null
    ) | sort
}
# refs A B: the views of the uninterrupted runs A and B (viewA, viewB)
refs() {
    rm -rf "$tmp/refA" "$tmp/refB"
    "$sim" "$tmp/$1.json" --out "$tmp/refA" > /dev/null 2>&1 && "$sim" "$tmp/$2.json" --out "$tmp/refB" > /dev/null 2>&1 ||
        { echo "FAILED: the reference runs"; exit 1; }
    viewA=$(view "$tmp/refA"); viewB=$(view "$tmp/refB")
    [ "$viewA" != "$viewB" ] && [ -f "$tmp/refB/trajectory.xyz" ] && [ ! -e "$tmp/refA/trajectory.xyz" ] ||
        { echo "FAILED: the two reference runs are not told apart"; exit 1; }
}
refs A B

# whole DIR WHAT: DIR shows exactly A's or B's files (prints which) and its final.json
# continues; else prints why and fails
whole() {
    local v; v=$(view "$1")
    if [ "$v" = "$viewA" ]; then echo A; elif [ "$v" = "$viewB" ]; then echo B; else
        echo "a mix: $(echo "$v" | wc -l) names, $(echo "$v" | grep -c snap-) snapshots, $(echo "$v" | grep -Fxf <(echo "$viewA") | wc -l) of A's, $(echo "$v" | grep -Fxf <(echo "$viewB") | wc -l) of B's"
        return 1
    fi
    # (accepted: its checkpoint read and one time unit run)
    local t; t=$(sed -n 's/.*"time":\([^,]*\),.*/\1/p' "$1/final.json")
    rm -rf "$tmp/cont"
    "$sim" "$1/final.json" --out "$tmp/cont" --no-plots --t-end "$(awk "BEGIN{print $t + 1}")" > /dev/null 2> "$tmp/cont.err" ||
        { echo "continuation refused: $(cat "$tmp/cont.err")"; return 1; }
}

# 1. planted links
mkdir -p "$tmp/pl" "$tmp/outside/snapdir" "$tmp/outside/rundir"
for f in snap-0000.csv snap-0001.csv; do echo "precious $f" > "$tmp/outside/snapdir/$f"; done
ln -s "$tmp/outside/snapdir" "$tmp/pl/snapshots"
ln -s "$tmp/outside/rundir" "$tmp/pl/.relcol-run"
for f in final.json final.ckpt summary.txt summary.json trajectory.xyz frames.dat trajectory.h5 \
         trajectories.gp trajectories.png paths.dat table.gp table.gif; do
    echo "precious $f" > "$tmp/outside/$f"
    ln -s "$tmp/outside/$f" "$tmp/pl/$f"
done
printf '../outside/final.json\n%s/outside/summary.txt\nsnapshots/../../outside/final.ckpt\nsnapshots/snap-0000.csv\nfinal.json\n' "$tmp" \
    > "$tmp/pl/.relcol_sim_outputs"
outside() { (cd "$tmp/outside" && find . | sort && find . -type f | sort | xargs cksum); }
before=$(outside)
sed 's/"xyz_every": 0,/"xyz_every": 0.5, "h5md_every": 1,/; s/"plots": false, "gif": false/"plots": true, "gif": true/' \
    "$tmp/A.json" > "$tmp/Aplots.json"
"$sim" "$tmp/Aplots.json" --out "$tmp/pl" > /dev/null 2> "$tmp/err"; st1=$?
mid=$(outside)
"$sim" "$tmp/B.json" --out "$tmp/pl" > /dev/null 2> "$tmp/err2"; st2=$?
after=$(outside)
shown=$(whole "$tmp/pl")
if [ $st1 -eq 0 ] && [ $st2 -eq 0 ] && [ "$before" = "$mid" ] && [ "$before" = "$after" ] && [ "$shown" = B ]; then
    ok "links planted at 14 output names and a manifest pointing outside: the $(echo "$before" | grep -c '^[0-9]') files outside keep their bytes and existence over two runs; the folder shows run B"
else
    ko "planted links: exit $st1, $st2 ($(cat "$tmp/err" "$tmp/err2")), outside changed: $([ "$before" = "$mid" ] && [ "$before" = "$after" ] && echo no || echo yes), folder: $shown"
fi

# 2. kill -9 at random instants across the ends of runs into one folder
d="$tmp/k"
"$sim" "$tmp/A.json" --out "$d" > /dev/null 2>&1
# span: the median of 5 runs' wall times, in microseconds (EPOCHREALTIME: no fork)
for k in 1 2 3 4 5; do
    s=B; [ $k -eq 5 ] && s=A
    t0=$EPOCHREALTIME; "$sim" "$tmp/$s.json" --out "$d" > /dev/null 2>&1; t1=$EPOCHREALTIME
    echo $(( ${t1/./} - ${t0/./} ))
done | sort -n > "$tmp/spans"
span=$(sed -n 3p "$tmp/spans")
exec {never}<> <(:) # (read -t on it: a sleep without a fork, whose time would add to the delay)
# where K -9 landed, for the run PID into DIR that found the run folders BEFORE (landed
# prints one of: late, the run had ended; staged, its staging folder still there; publish,
# after the publish's first rename (a run folder not there before), before its exit;
# early, before either folder)
landed() {
    local st=$1 pid=$2 dir=$3 before=$4
    if [ "$st" -ne 137 ]; then echo late
    elif compgen -G "$dir/.run.relcol-$pid.*" > /dev/null; then echo staged
    elif [ -n "$(comm -13 <(echo "$before") <(cd "$dir" && ls -d .relcol-run.?????? 2>/dev/null | sort))" ]; then echo publish
    else echo early; fi
}
rundirs() { (cd "$1" && ls -d .relcol-run.?????? 2>/dev/null | sort); }
declare -A where=([late]=0 [staged]=0 [publish]=0 [early]=0)
bad=0; seen_a=0; seen_b=0; RANDOM=37
for k in $(seq 1 "$kills"); do
    s=A; [ $((k % 2)) -eq 0 ] && s=B
    # uniform over 30 % .. 130 % of a run: most of the kills land in its last third and after
    delay=$(( span * (30 + RANDOM % 100) / 100 ))
    before=$(rundirs "$d")
    "$sim" "$tmp/$s.json" --out "$d" > /dev/null 2>&1 &
    pid=$!
    read -t "$(printf '%d.%06d' $((delay / 1000000)) $((delay % 1000000)))" -u $never
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null; st=$?
    w=$(landed $st $pid "$d" "$before"); where[$w]=$((where[$w] + 1))
    if r=$(whole "$d"); then
        [ "$r" = A ] && seen_a=$((seen_a + 1)) || seen_b=$((seen_b + 1))
    else
        bad=$((bad + 1)); echo "after kill $k ($s, at $delay us of $span, $w): $r"
    fi
done
[ $bad -eq 0 ] && [ $seen_a -gt 0 ] && [ $seen_b -gt 0 ] &&
    ok "$kills kill -9 at random instants (run of $span us, A: $files snapshots, B: $((files / 2)) and a trajectory; ${where[staged]} landed while the run was staged, ${where[publish]} in its publish, ${where[early]} before its staging folder, ${where[late]} after its end): each time one run whole ($seen_a A, $seen_b B) and its continuation accepted" ||
    ko "$bad of $kills kills left the folder not one run's whole set (A $seen_a, B $seen_b)"

# 2b. kill -9 aimed at the publish itself (after its first rename, before the exit): each run is watched (aim_kill.py) until its last file is written (summary.json in
# its staging folder), then killed after a random delay uniform over 0 .. W x the median
# time from there to the exit of 5 unkilled runs (W from 1.25, narrowed by a tenth after a
# kill that came too late, widened after one too early); tried until PUBKILLS landed there
# (at most 6 x PUBKILLS), or 40 times without PUBKILLS
aim="$(dirname "$0")/aim_kill.py" # (a busy wait in one process: a shell's poll and sleep are coarser than a small publish)
# pspan: the median of 5 unkilled runs' times from their last file to their exit
for k in 1 2 3 4 5; do
    s=A; [ $((k % 2)) -eq 0 ] && s=B
    read -r st pid us < <(/usr/bin/python3 "$aim" "$sim" "$tmp/$s.json" "$d" -1)
    echo "${us:-0}"
done | sort -n > "$tmp/pspans"
pspan=$(sed -n 3p "$tmp/pspans")
# (the window aimed at, in per mille of pspan: narrowed after a kill that came after the
# exit, widened after one before the publish, so that most land in it)
win=1250
declare -A pwhere=([late]=0 [staged]=0 [publish]=0 [early]=0)
pbad=0; tries=0; pa=0; pb=0
want=${pubkills:-0}; maxtries=$((6 * want)); [ -z "$pubkills" ] && maxtries=40
while { [ -z "$pubkills" ] || [ ${pwhere[publish]} -lt "$want" ]; } && [ $tries -lt $maxtries ]; do
    tries=$((tries + 1))
    s=A; [ $((tries % 2)) -eq 0 ] && s=B
    delay=$(( pspan * (RANDOM % win) / 1000 ))
    before=$(rundirs "$d")
    read -r st pid us < <(/usr/bin/python3 "$aim" "$sim" "$tmp/$s.json" "$d" "$delay")
    w=$(landed $st $pid "$d" "$before"); pwhere[$w]=$((pwhere[$w] + 1))
    case $w in late) win=$(( win * 9 / 10 > 50 ? win * 9 / 10 : 50 )) ;; staged) win=$(( win * 11 / 10 )) ;; esac
    if r=$(whole "$d"); then
        [ "$r" = A ] && pa=$((pa + 1)) || pb=$((pb + 1))
    else
        pbad=$((pbad + 1)); echo "after aimed kill $tries ($s, $delay us after its last file, $w): $r"
    fi
done
[ $pbad -eq 0 ] && [ ${pwhere[publish]} -ge "$want" ] &&
    ok "${pwhere[publish]} kill -9 landed in the publish (of $tries aimed at 0 .. 1.25 x (adapted: $win per mille at the end) its median $pspan us after the run's last file; ${pwhere[staged]} before its first rename, ${pwhere[late]} after the exit, ${pwhere[early]} before the staging folder): each time one run whole ($pa A, $pb B) and its continuation accepted" ||
    ko "aimed kills: $pbad of $tries left a mix; ${pwhere[publish]} of the $want wanted landed in the publish (${pwhere[staged]} before it, ${pwhere[late]} after)"

# 3. every system call of the publish failed, then killed (strace)
# (LeakSanitizer cannot run under ptrace: in a sanitized build the traced runs keep ASan's
# checks and leave the leak check to the untraced runs above)
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
if ! command -v strace > /dev/null 2>&1 || ! strace -f -qq -o /dev/null true 2> /dev/null; then
    echo "skip: strace cannot trace here (not installed, or ptrace not allowed): no fault injection"
else
    # inject A B SAMPLE: run B into a copy of A's folder with each call failed (and killed);
    # SAMPLE empty: every invocation of each, else SAMPLE of them (the first and last
    # thirds of SAMPLE, the rest at random between)
    inject() {
        local A=$1 B=$2 sample=$3
        refs "$A" "$B"
        rm -rf "$tmp/base"; mkdir -p "$tmp/base"; "$sim" "$tmp/$A.json" --out "$tmp/base/d" > /dev/null 2>&1
        local calls="rename renameat renameat2 unlink unlinkat symlink symlinkat link linkat write fsync mkdir mkdirat flock"
        total=0; badf=0; summary=""
        for sc in $calls; do
            rm -rf "$tmp/f"; cp -a "$tmp/base/d" "$tmp/f"
            strace -f -qq -e trace="$sc" -o "$tmp/trace" "$sim" "$tmp/$B.json" --out "$tmp/f" > /dev/null 2>&1
            local count; count=$(grep -c "$sc(" "$tmp/trace")
            [ "$count" -gt 0 ] || continue
            local which; which=$(seq 1 "$count")
            if [ -n "$sample" ] && [ "$count" -gt "$sample" ]; then
                local e=$((sample / 3)); [ $e -lt 1 ] && e=1
                which=$( { seq 1 $e; seq $((count - e + 1)) "$count"; shuf -i $((e + 1))-$((count - e)) -n $((sample - 2 * e)) --random-source=<(yes); } | sort -n)
            fi
            summary="$summary $sc $(echo "$which" | wc -w)/$count,"
            for how in error=EIO signal=KILL; do
                # (a kill at a write, an fsync or the lock is a kill while the run is staged,
                # before the publish: the random kills cover those)
                case "$sc:$how" in write:signal* | fsync:signal* | flock:signal*) continue ;; esac
                for i in $which; do
                    total=$((total + 1))
                    rm -rf "$tmp/f"; cp -a "$tmp/base/d" "$tmp/f"
                    # (in a subshell: bash's own "Killed" line goes nowhere)
                    st=$( (strace -f -qq -o /dev/null -e trace="$sc" -e inject="$sc:$how:when=$i" \
                        "$sim" "$tmp/$B.json" --out "$tmp/f" > /dev/null 2> "$tmp/err"; echo $?) 2> /dev/null)
                    r=$(whole "$tmp/f") || { badf=$((badf + 1)); echo "$sc #$i $how: exit $st: $r"; continue; }
                    if [ "$how" = error=EIO ]; then
                        # B shown: its exit is 0 (a failure after the switch is a warning); A: 1,
                        # with a message
                        # (or 1 after a failed write of its result line to standard output)
                        if { [ "$r" = B ] && [ $st -ne 0 ] && ! grep -q 'standard output' "$tmp/err"; } ||
                           { [ "$r" = A ] && { [ $st -ne 1 ] || [ ! -s "$tmp/err" ]; }; }; then
                            badf=$((badf + 1)); echo "$sc #$i failed: the folder shows $r, exit $st: $(cat "$tmp/err")"
                        fi
                    fi
                done
            done
        done
    }
    # (fewer files: each injection is a run under strace; the calls are the same)
    scen A6 1 6 1 0; scen B3 2 3 1 0.5
    inject A6 B3 ""
    [ $badf -eq 0 ] && [ $total -gt 0 ] &&
        ok "strace: $total runs, each invocation of every call (${summary%,}) failed with EIO, and each of the publish's killed: one run whole each time, its continuation accepted, exit 0 with B shown and 1 with A" ||
        ko "strace: $badf of $total injected faults left a mix or a wrong exit"
    # the run of FILES itself, when it is large (the benchmark's 4 000): RELCOL_INJECT_SAMPLE
    # (12) invocations of each call, or "all" of them (hours at 4 000 files)
    if [ "$files" -gt 40 ]; then
        sample=${RELCOL_INJECT_SAMPLE:-12}; [ "$sample" = all ] && sample=""
        inject A B "$sample"
        [ $badf -eq 0 ] && [ $total -gt 0 ] &&
            ok "strace on the $files-file run: $total runs, invocations (tried/all) of each call (${summary%,}) failed with EIO, and the publish's killed: one run whole each time, its continuation accepted, exit 0 with B shown and 1 with A" ||
            ko "strace on the $files-file run: $badf of $total injected faults left a mix or a wrong exit"
    fi
fi

# 4. a folder of the earlier scheme: files in DIR, .relcol_sim_outputs listing them
refs A B
o="$tmp/old"; mkdir -p "$o/snapshots"
cp -L "$tmp/refA"/final.json "$tmp/refA"/final.ckpt "$tmp/refA"/summary.txt "$tmp/refA"/summary.json "$o/"
cp -L "$tmp/refA"/snapshots/* "$o/snapshots/"
(cd "$o" && ls final.json final.ckpt summary.txt summary.json && ls snapshots | sed 's|^|snapshots/|') > "$o/.relcol_sim_outputs"
echo mine > "$o/snapshots/my-notes.txt"
v0=$(view "$o")
"$sim" "$tmp/B.json" --out "$o" > /dev/null 2> "$tmp/err"; st1=$?
v1=$(view "$o")
rm "$o/snapshots/my-notes.txt"
"$sim" "$tmp/B.json" --out "$o" > /dev/null 2> "$tmp/err2"; st2=$?
r=$(whole "$o")
[ $st1 -eq 1 ] && grep -q 'not a run.s.*nothing was changed' "$tmp/err" && [ "$v0" = "$v1" ] &&
    [ $st2 -eq 0 ] && [ "$r" = B ] && [ ! -e "$o/.relcol_sim_outputs" ] &&
    ok "an earlier relcol-sim's folder: refused, unchanged, while its snapshots/ holds a file of the user's; then converted: run B whole" ||
    ko "earlier folder: exit $st1 ($(cat "$tmp/err")), unchanged: $([ "$v0" = "$v1" ] && echo yes || echo no); exit $st2 ($(cat "$tmp/err2")), folder $r"
# ... and killed at every step of its conversion (strace), the names show A or B whole
if command -v strace > /dev/null 2>&1 && strace -f -qq -o /dev/null true 2> /dev/null; then
    scen A6 1 6 1 0; scen B3 2 3 1 0.5; refs A6 B3
    rm -rf "$o"; mkdir -p "$o/snapshots"
    cp -L "$tmp/refA"/final.json "$tmp/refA"/final.ckpt "$tmp/refA"/summary.txt "$tmp/refA"/summary.json "$o/"
    cp -L "$tmp/refA"/snapshots/* "$o/snapshots/"
    (cd "$o" && ls final.json final.ckpt summary.txt summary.json && ls snapshots | sed 's|^|snapshots/|') > "$o/.relcol_sim_outputs"
    rm -rf "$tmp/old0"; cp -a "$o" "$tmp/old0"
    badc=0; totc=0
    for sc in linkat renameat renameat2 symlinkat unlinkat; do
        rm -rf "$o"; cp -a "$tmp/old0" "$o"
        strace -f -qq -e trace="$sc" -o "$tmp/trace" "$sim" "$tmp/B3.json" --out "$o" > /dev/null 2>&1
        count=$(grep -c "$sc(" "$tmp/trace")
        for i in $(seq 1 "$count"); do
            totc=$((totc + 1))
            rm -rf "$o"; cp -a "$tmp/old0" "$o"
            st=$( (strace -f -qq -o /dev/null -e trace="$sc" -e inject="$sc:signal=KILL:when=$i" \
                "$sim" "$tmp/B3.json" --out "$o" > /dev/null 2>&1; echo $?) 2> /dev/null)
            r=$(whole "$o") || { badc=$((badc + 1)); echo "conversion, $sc #$i killed: $r"; }
        done
    done
    [ $badc -eq 0 ] && [ $totc -gt 0 ] && ok "an earlier relcol-sim's folder killed at each of $totc calls of its conversion and publish: one run whole each time" ||
        ko "conversion: $badc of $totc kills left a mix"
fi

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
