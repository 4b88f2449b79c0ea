#!/bin/sh
# bench_h5md.sh RELCOL_SIM [N] [T_END] [RADIUS] — what the H5MD trajectory costs: one
# gas run of N balls (3-D, packing 0.2, rms speed 0.5 c, c = 1; default 1e5 balls of
# radius 1 to t = 5) without frames and with a frame every 0.1, each 3 times alternating,
# the fastest of each kept. Prints both runs' wall and CPU (user + sys) seconds and the
# ratios (the goal, issue 38: <= 1.2), the file's size and the cost of one frame. Both runs write
# final.json and final.ckpt, so the difference is the frames alone.
sim=${1:?usage: bench_h5md.sh relcol-sim [N] [T_END] [RADIUS]}
n=${2:-100000}; t_end=${3:-5}; radius=${4:-1}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/bench-h5md.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/none.json" <<JSON
{"relcol": 1, "dim": 3, "c": 1, "t_end": $t_end, "seed": 1,
 "generate": {"kind": "gas", "n": $n, "radius": $radius, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"dir": "$tmp/none", "plots": false, "summary": false}}
JSON
sed "s|\"dir\": \"$tmp/none\"|\"dir\": \"$tmp/h5\", \"h5md_every\": 0.1|" "$tmp/none.json" > "$tmp/h5.json"
# one run: "wall cpu" seconds (GNU time's %e and %U + %S)
one() {
    /usr/bin/time -f '%e %U %S' -o "$tmp/time" "$sim" "$1" > /dev/null || exit 1
    awk '{ printf "%s %.2f\n", $1, $2 + $3 }' "$tmp/time"
}
best_w0=; best_w1=
for k in 1 2 3; do
    set -- $(one "$tmp/none.json"); w0=$1; c0=$2
    set -- $(one "$tmp/h5.json"); w1=$1; c1=$2
    if [ -z "$best_w0" ] || awk -v a="$w0" -v b="$best_w0" 'BEGIN { exit !(a < b) }'; then
        best_w0=$w0; best_c0=$c0; fi
    if [ -z "$best_w1" ] || awk -v a="$w1" -v b="$best_w1" 'BEGIN { exit !(a < b) }'; then
        best_w1=$w1; best_c1=$c1; fi
done
frames=$(awk -v t="$t_end" 'BEGIN { printf "%d", t / 0.1 + 1.5 }')
bytes=$(wc -c < "$tmp/h5/trajectory.h5")
awk -v n="$n" -v t="$t_end" -v r="$radius" -v w0="$best_w0" -v w1="$best_w1" -v c0="$best_c0" \
    -v c1="$best_c1" -v f="$frames" -v b="$bytes" 'BEGIN {
    printf "h5md: %d balls, t = 0..%g, radius %g: %d frames, trajectory.h5 %.1f MB\n", n, t, r, f, b / 1e6
    printf "without frames: wall %.2f s, cpu %.2f s\n", w0, c0
    printf "with frames:    wall %.2f s, cpu %.2f s\n", w1, c1
    printf "ratio: wall %.3f, cpu %.3f (goal <= 1.2); one frame: wall %.1f ms, cpu %.1f ms\n",
        w1 / w0, c1 / c0, 1e3 * (w1 - w0) / f, 1e3 * (c1 - c0) / f }'
