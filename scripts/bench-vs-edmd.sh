#!/usr/bin/env bash
# bench-vs-edmd.sh — relcol's engine against the leading public event-driven code, in one
# command: Smallenburg's EDMD ("Efficient event-driven simulations of hard spheres",
# Eur. Phys. J. E 45, 22 (2022); https://github.com/FSmallenburg/EDMD), which relcol does
# not ship. Issue 4's throughput targets are "1.5x the leading public codes measured on
# this machine kind"; on a shared machine whose speed drifts by tens of per cent between
# minutes, only runs alternated in one command compare.
#
#   scripts/bench-vs-edmd.sh EDMD_DIR [pairs_1e4] [pairs_1e5] [pairs_1e6]
#
# EDMD_DIR: a checkout of that repository (its Single/ variant is used: neighbour lists,
# one event per particle, the paper's fastest). It is copied to a temporary directory and
# its parameters set there, its own sources untouched: 3-D, FCC start at packing 0.45, N =
# 10976, 108000 or 1048576 (4 n^3: relcol runs the same N), no thermostat, no
# snapshots, and a CPU-time clock (CLOCK_PROCESS_CPUTIME_ID, as bench_engine) started
# after 2 time units (~28 collisions a particle, the lattice melted). It is built with its
# own Makefile's flags. relcol's side is `bench_engine per:N PER` from a release build
# (build-rel/, made if missing): a periodic box like EDMD's, so both count only pair
# collisions; CPU time of PER collisions a ball after melting 5, PER
# chosen so that both time about 3 M collisions. Each pair runs both, the first
# alternating; printed are the rates, the ratio relcol/EDMD per pair and its median. Last,
# each code's time per collision at the larger N as a multiple of its own at N ~ 1e4
# (medians of its rates; the sizes run one after the other, so the machine's drift between
# them enters these). pairs_1e6 (default 0: skipped) adds N ~ 1e6: ~0.5 GB and ~3 minutes
# a pair.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
edmd=${1:?usage: scripts/bench-vs-edmd.sh EDMD_DIR [pairs_1e4] [pairs_1e5] [pairs_1e6]}
[ -f "$edmd/Single/mdSingle.c" ] || { echo "no Single/mdSingle.c in $edmd" >&2; exit 2; }
pairs4=${2:-7}
pairs5=${3:-3}
pairs6=${4:-0}
bench="$here/build-rel/tests/engine/bench_engine"
if [ ! -x "$bench" ]; then
    meson setup "$here/build-rel" "$here" --buildtype=release >/dev/null
    ninja -C "$here/build-rel" tests/engine/bench_engine >/dev/null
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# a copy of Single/ with the parameters above; maxtime bounds the timed stretch
make_edmd() { # $1 N, $2 maxtime
    local d="$tmp/edmd_$1"
    mkdir -p "$d"
    cp "$edmd"/Single/* "$d"/
    [ -f "$d/mt19937ar.c" ] || cp "$edmd/Grow/mt19937ar.c" "$d"/
    N="$1" MAXTIME="$2" perl -0pi -e '
        s/^double maxtime = [^;]*;/double maxtime = $ENV{MAXTIME};/m or die "maxtime\n";
        s/^int makesnapshots = [^;]*;/int makesnapshots = 0;/m or die "makesnapshots\n";
        s/^int initialconfig = [^;]*;/int initialconfig = 1;/m or die "initialconfig\n";
        s/^double packfrac = [^;]*;/double packfrac = 0.45;/m or die "packfrac\n";
        s/^int N = [^;]*;/int N = $ENV{N};/m or die "N\n";
        s/^const int usethermostat = [^;]*;/const int usethermostat = 0;/m or die "thermostat\n";
        s/^#include <string.h>\n/#include <string.h>\n#include <time.h>\n/m or die "include\n";
        s{(\n\s*)while \(simtime <= maxtime\)(\s*\{\s*step\(\);\s*\})}{$1while (simtime <= 2.0) step();$1unsigned int bench_c0 = colcounter;$1struct timespec bench_t0, bench_t1;$1clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &bench_t0);$1while (simtime <= maxtime)$2$1clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &bench_t1);$1printf("BENCH %.0f collisions/s\\n", (colcounter - bench_c0) / ((bench_t1.tv_sec - bench_t0.tv_sec) + 1e-9 * (bench_t1.tv_nsec - bench_t0.tv_nsec)));} or die "main loop\n";
    ' "$d/mdSingle.c"
    (cd "$d" && make -s >/dev/null 2>&1) || { echo "EDMD did not build in $d" >&2; exit 1; }
}
edmd_rate() { (cd "$tmp/edmd_$1" && ./md | sed -n 's/^BENCH \([0-9]*\) collisions\/s$/\1/p'); }
relcol_rate() { "$bench" "per:$1" "$2" | sed -n 's/.* \([0-9][0-9]*\) collisions\/s .*/\1/p' | head -1; }

median() { sort -g | awk '{ a[NR] = $1 } END { print NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

declare -A med_r med_e # median rates by N
compare() { # $1 N (both), $2 EDMD maxtime, $3 pairs, $4 relcol collisions a ball
    make_edmd "$1" "$2"
    echo "== relcol against EDMD Single, both periodic, N=$1 (3-D, packing 0.45), $3 pairs =="
    local ratios=() rs=() es=() k e r q
    for ((k = 1; k <= $3; k++)); do
        if ((k % 2)); then e=$(edmd_rate "$1"); r=$(relcol_rate "$1" "$4");
        else r=$(relcol_rate "$1" "$4"); e=$(edmd_rate "$1"); fi
        q=$(awk -v r="$r" -v e="$e" 'BEGIN { printf "%.3f", r / e }')
        ratios+=("$q") rs+=("$r") es+=("$e")
        echo "pair $k: relcol $r collisions/s, EDMD $e collisions/s, relcol/EDMD $q"
    done
    med_r[$1]=$(printf '%s\n' "${rs[@]}" | median)
    med_e[$1]=$(printf '%s\n' "${es[@]}" | median)
    local lo hi m
    lo=$(printf '%s\n' "${ratios[@]}" | sort -g | head -1)
    hi=$(printf '%s\n' "${ratios[@]}" | sort -g | tail -1)
    m=$(printf '%s\n' "${ratios[@]}" | median)
    awk -v n="$1" -v m="$m" -v lo="$lo" -v hi="$hi" \
        'BEGIN { printf "median relcol/EDMD at N = %s: %.2f (range %.2f-%.2f; target >= 1.75)\n", n, m, lo, hi }'
}
# time per collision at N as a multiple of N = 1e4's: the ratio of the median rates
growth() { # $1 N
    awk -v n="$1" -v r4="${med_r[10976]}" -v r="${med_r[$1]}" -v e4="${med_e[10976]}" -v e="${med_e[$1]}" \
        'BEGIN { printf "time per collision, N = %s / N = 10976: relcol %.2f, EDMD %.2f\n", n, r4 / r, e4 / e }'
}
((pairs4 > 0)) && compare 10976 12 "$pairs4" 300
((pairs5 > 0)) && compare 108000 3 "$pairs5" 30
((pairs6 > 0)) && compare 1048576 2.5 "$pairs6" 3
((pairs4 > 0 && pairs5 > 0)) && growth 108000
((pairs4 > 0 && pairs6 > 0)) && growth 1048576
exit 0
