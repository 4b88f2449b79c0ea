#!/bin/bash
# bench_publish.sh RELCOL_SIM TEST_SIM_PUBLISH [BASELINE_SIM] (or $BASELINE_SIM) — meson benchmark 'publish':
# 1. the publish of a 4 000-file run (4 000 snapshots of 20 balls) into a folder holding
#    another 4 000-file run, on the disk (not tmpfs: fsync is what it costs): the time from
#    the run's last file written (summary.json's mtime) to the process's exit, the median
#    of 3 (RELCOL_PUBLISH_REPS), and with BASELINE_SIM (a relcol-sim of another revision, e.g. d26393f's) the
#    same for it and the ratio this / baseline;
# 2. test_sim_publish.sh with 4 000 files: 200 kill -9 at random instants, kills aimed at
#    the publish until 200 landed in it, strace failures at a sample of each call
#    (RELCOL_PUBLISH_CHECK=0: not run).
sim="$1"; check="$2"; base="${3:-${BASELINE_SIM:-}}"
tmp=$(mktemp -d -p "${MESON_BUILD_ROOT:-.}" 2>/dev/null || mktemp -d); trap 'rm -rf "$tmp"' EXIT
scen() {
    cat > "$tmp/$1.json" <<JSON
{"relcol": 1, "dim": 2, "c": 2, "seed": $2, "t_end": 400,
 "generate": {"kind": "gas", "n": 20, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"snapshots": {"every": 0.1}, "xyz_every": 0, "plots": false, "gif": false}}
JSON
}
scen A 1; scen B 2
# publish_ms SIM: the publish of B into a folder holding A, in ms
publish_ms() {
    local d="$tmp/d"
    rm -rf "$d"; "$1" "$tmp/A.json" --out "$d" > /dev/null 2>&1
    "$1" "$tmp/B.json" --out "$d" > /dev/null 2>&1 || { echo "run failed" >&2; return 1; }
    local t1; t1=$(date +%s%N)
    local m; m=$(stat -L -c %.9Y "$d/summary.json" | tr -d .)
    [ "$(ls "$d/snapshots" | wc -l)" -eq 4000 ] || { echo "not 4000 snapshots" >&2; return 1; }
    echo $(( (t1 - m) / 1000000 ))
}
med() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# RELCOL_PUBLISH_REPS (3) times each, this and the baseline in turn, so that a drift of the
# machine's speed meets both; the ratio is the median of the pairs' ratios
reps=${RELCOL_PUBLISH_REPS:-3}; : > "$tmp/times"
for k in $(seq 1 "$reps"); do
    new=$(publish_ms "$sim") || exit 1
    old=0; [ -n "$base" ] && { old=$(publish_ms "$base") || exit 1; }
    echo "$new $old" >> "$tmp/times"; echo "pair $k: $new ms, baseline $old ms"
done
echo "publish of a 4000-file run into a folder holding one: $(cut -d' ' -f1 "$tmp/times" | med) ms (median of $reps)"
if [ -n "$base" ]; then
    echo "baseline $base: $(cut -d' ' -f2 "$tmp/times" | med) ms; ratio this/baseline" \
         "$(awk '{print $1 / ($2 > 0 ? $2 : 1)}' "$tmp/times" | med) (median of the $reps pairs:" \
         "$(awk '{printf "%s%.3f", (NR > 1 ? " " : ""), $1 / ($2 > 0 ? $2 : 1)}' "$tmp/times"))"
fi
# RELCOL_PUBLISH_CHECK=0: the timing only
[ "${RELCOL_PUBLISH_CHECK:-1}" = 0 ] && exit 0
bash "$check" "$sim" 4000 200 200
