#!/bin/bash
# bench_final.sh RELCOL_SIM PHASE_TIME_SO [BASELINE_SIM] (or $BASELINE_SIM) — meson benchmark
# 'final': what writing final.json costs against writing a snapshot of the same balls, at
# 1e5 and 1e6 balls (RELCOL_BENCH_SIZES="N ..." for others). One run per size writes the
# snapshot at t = 0 and final.json at t = 1e-6 (no collision between: the same balls);
# PHASE_TIME_SO (phase_time.c, LD_PRELOAD) measures each file's process CPU seconds from its
# temporary made to its rename, the writer alone. Prints, the median of 3 runs: the CPU
# seconds of each, the ratio final.json / snapshot, and with BASELINE_SIM (another revision's
# relcol-sim, e.g. main's before the streaming ball writer) the same for it and the ratio of
# the two final.json times. Output on /dev/shm where there is one: the writers' CPU, not
# the disk's.
sim="$1"; shim="$2"; base="${3:-${BASELINE_SIM:-}}"
sizes=${RELCOL_BENCH_SIZES:-"100000 1000000"}
tmp=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d); trap 'rm -rf "$tmp"' EXIT
case "$shim" in /*) ;; *) shim="$PWD/$shim" ;; esac
# med: the median of the numbers on standard input
med() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# measure SIM N: prints "SNAPSHOT_CPU FINAL_CPU RATIO" (medians of 3 runs)
measure() {
    cat > "$tmp/s.json" <<JSON
{"relcol": 1, "dim": 2, "c": 2, "seed": 5, "t_end": 1e-6,
 "generate": {"kind": "gas", "n": $2, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"snapshots": [0], "xyz_every": 0, "plots": false, "gif": false}}
JSON
    : > "$tmp/all"
    for k in 1 2 3; do
        rm -rf "$tmp/o" "$tmp/log"
        RELCOL_PHASE_LOG="$tmp/log" LD_PRELOAD="$shim" "$1" "$tmp/s.json" --out "$tmp/o" > /dev/null 2> "$tmp/err" ||
            { echo "bench_final: $1 failed: $(cat "$tmp/err")" >&2; return 1; }
        local sn fj
        sn=$(awk '$1 == "snapshot" {print $2}' "$tmp/log"); fj=$(awk '$1 == "final.json" {print $2}' "$tmp/log")
        [ -n "$sn" ] && [ -n "$fj" ] || { echo "bench_final: the shim timed nothing (LD_PRELOAD $shim)" >&2; return 1; }
        echo "$sn $fj" >> "$tmp/all"
    done
    rm -rf "$tmp/o"
    echo "$(cut -d' ' -f1 "$tmp/all" | med) $(cut -d' ' -f2 "$tmp/all" | med) $(awk '{print $2 / $1}' "$tmp/all" | med)"
}
st=0
for n in $sizes; do
    read -r s1 f1 r1 < <(measure "$sim" "$n") && [ -n "$r1" ] || { st=1; continue; }
    echo "n = $n: snapshot $s1 s cpu, final.json $f1 s cpu, final.json / snapshot $r1"
    if [ -n "$base" ]; then
        read -r s0 f0 r0 < <(measure "$base" "$n") && [ -n "$r0" ] || { st=1; continue; }
        echo "n = $n, baseline $base: snapshot $s0 s cpu, final.json $f0 s cpu, final.json / snapshot $r0;" \
             "final.json this / baseline $(awk "BEGIN {printf \"%.3f\", $f1 / $f0}")"
    fi
done
exit $st
