#!/bin/bash
# bench_publish.sh RELCOL_SIM TEST_SIM_PUBLISH [BASELINE_SIM] (or $BASELINE_SIM) — meson benchmark 'publish':
# 1. the publish of a 4 000-file run (4 000 snapshots of 20 balls) into a folder holding
#    another 4 000-file run, on the disk (not tmpfs: fsync is what it costs): the time from
#    the run's last file written (summary.json's mtime) to the process's exit, the median
#    of 3, and with BASELINE_SIM (a relcol-sim of another revision, e.g. d26393f's) the
#    same for it and the ratio this / baseline;
# 2. test_sim_publish.sh with 4 000 files and 200 kill -9 at random instants.
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
# publish_ms SIM: median over 3 of the publish of B into a folder holding A
publish_ms() {
    local times=() d="$tmp/d"
    for k in 1 2 3; do
        rm -rf "$d"; "$1" "$tmp/A.json" --out "$d" > /dev/null 2>&1
        "$1" "$tmp/B.json" --out "$d" > /dev/null 2>&1 || { echo "run failed" >&2; return 1; }
        local t1; t1=$(date +%s%N)
        local m; m=$(stat -L -c %.9Y "$d/summary.json" | tr -d .)
        [ "$(ls "$d/snapshots" | wc -l)" -eq 4000 ] || { echo "not 4000 snapshots" >&2; return 1; }
        times+=($(( (t1 - m) / 1000000 )))
    done
    printf '%s\n' "${times[@]}" | sort -n | sed -n 2p
}
new=$(publish_ms "$sim") || exit 1
echo "publish of a 4000-file run into a folder holding one: $new ms (median of 3)"
if [ -n "$base" ]; then
    old=$(publish_ms "$base") || exit 1
    echo "baseline $base: $old ms; ratio this/baseline $(awk "BEGIN{printf \"%.3f\", $new / ($old > 0 ? $old : 1)}")"
fi
bash "$check" "$sim" 4000 200
