#!/bin/sh
# bench_h5md.sh RELCOL_SIM [N] [T_END] [RADIUS] [REPS] — what the H5MD trajectory costs: one
# gas run of N balls (3-D, packing 0.2, rms speed 0.5 c, c = 1; default 1e5 balls of
# radius 1 to t = 5) without frames, and with a frame every 0.1 for each outputs.h5md choice
# below, REPS times in turn (default 3), the fastest of each kept. Prints each run's wall
# and CPU (user + sys) seconds, its ratios to the run without frames (the goal, issue 38:
# <= 1.2), the file's size and the cost of one frame. Every run writes final.json and
# final.ckpt, so a difference is the frames alone.
sim=${1:?usage: bench_h5md.sh relcol-sim [N] [T_END] [RADIUS] [REPS]}
n=${2:-100000}; t_end=${3:-5}; radius=${4:-1}; reps=${5:-3}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/bench-h5md.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
# name|outputs keys beside dir (none: no frames)
configs='none|
all-float64|, "h5md_every": 0.1
pos-vel-float32|, "h5md_every": 0.1, "h5md": {"fields": ["position", "velocity"], "precision": "float32", "scenario": false}
pos-float32|, "h5md_every": 0.1, "h5md": {"fields": ["position"], "precision": "float32", "scenario": false}'
echo "$configs" | while IFS='|' read -r name keys; do
    cat > "$tmp/$name.json" <<JSON
{"relcol": 1, "dim": 3, "c": 1, "t_end": $t_end, "seed": 1,
 "generate": {"kind": "gas", "n": $n, "radius": $radius, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"dir": "$tmp/$name"$keys, "plots": false, "summary": false}}
JSON
done
names=$(echo "$configs" | cut -d'|' -f1)
# one run: "wall cpu" seconds (GNU time's %e and %U + %S)
one() {
    /usr/bin/time -f '%e %U %S' -o "$tmp/time" "$sim" "$1" > /dev/null 2>&1 || exit 1
    awk '{ printf "%s %.2f\n", $1, $2 + $3 }' "$tmp/time"
}
k=0
while [ $k -lt "$reps" ]; do
    for name in $names; do
        set -- $(one "$tmp/$name.json") || exit 1
        # keep the fastest wall, and the fastest cpu, of each
        if [ ! -f "$tmp/$name.best" ]; then echo "$1 $2" > "$tmp/$name.best"; else
            read -r bw bc < "$tmp/$name.best"
            awk -v a="$1" -v b="$bw" -v c="$2" -v d="$bc" \
                'BEGIN { printf "%s %s\n", (a < b ? a : b), (c < d ? c : d) }' > "$tmp/$name.best"
        fi
    done
    k=$((k + 1))
done
frames=$(awk -v t="$t_end" 'BEGIN { printf "%d", t / 0.1 + 1.5 }')
read -r w0 c0 < "$tmp/none.best"
echo "h5md: $n balls, t = 0..$t_end, radius $radius, $frames frames, fastest of $reps"
printf '%-16s wall %6.2f s, cpu %6.2f s\n' none "$w0" "$c0"
for name in $names; do
    [ "$name" = none ] && continue
    read -r w1 c1 < "$tmp/$name.best"
    bytes=$(wc -c < "$tmp/$name/trajectory.h5")
    awk -v nm="$name" -v w0="$w0" -v w1="$w1" -v c0="$c0" -v c1="$c1" -v f="$frames" -v b="$bytes" 'BEGIN {
        printf "%-16s wall %6.2f s, cpu %6.2f s; ratio wall %.3f, cpu %.3f (goal <= 1.2); %.1f MB, one frame cpu %.1f ms\n",
            nm, w1, c1, w1 / w0, c1 / c0, b / 1e6, 1e3 * (c1 - c0) / f }'
done
