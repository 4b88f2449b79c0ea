#!/bin/sh
# bench_sweep.sh RELCOL_SWEEP — wall time of the same sweep (all scenarios, 400 points, soft
# stiffness 1e12 so that the work dwarfs the fixed start-up, ~0.35 s of MPI_Init in an MPI
# build) on 1 and on 2 OpenMP threads, and their ratio (the speed-up). Not a test.
sweep="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
t() { # seconds of wall time of the sweep with $1 threads
    s=$(date +%s.%N)
    OMP_NUM_THREADS=$1 "$sweep" --points 400 --stiffness 1e12 --no-plots --out "$tmp/o$1" > /dev/null
    e=$(date +%s.%N)
    echo "$s $e" | awk '{printf "%.3f", $2 - $1}'
}
t1=$(t 1); t2=$(t 2); t1b=$(t 1); t2b=$(t 2)
echo "relcol-sweep, 400 points x 4 scenarios (soft stiffness 1e12):"
echo "  1 thread : $t1 s, $t1b s"
echo "  2 threads: $t2 s, $t2b s"
echo "$t1 $t1b $t2 $t2b" | awk '{a = ($1 < $2 ? $1 : $2); b = ($3 < $4 ? $3 : $4); printf "  speed-up (best of 2 each): %.2f\n", a / b}'
cmp -s "$tmp/o1/sweep.csv" "$tmp/o2/sweep.csv" && echo "  outputs identical" || echo "  OUTPUTS DIFFER"
