#!/usr/bin/env bash
# ab-revs.sh — the engine's speed at two revisions, timed in one process (ab_engine: both
# libraries loaded side by side, alternating chunks on the same gas), so that the drift of
# a shared machine between minutes does not enter the ratio.
#
#   scripts/ab-revs.sh REV_A REV_B [N] [dim] [rounds] [c] [frame] [packing]
#
# REV_A, REV_B: git revisions, each built (release) in a temporary worktree that is removed
# afterwards; "." is this checkout as it is, uncommitted changes included (its build-rel/).
# The rest goes to ab_engine (tests/engine/ab_engine.c): N (10000), dim (3), rounds (10),
# c (inf), frame (default), packing (0.45 in 3-D, 0.7 in 2-D). ab_engine runs RUNS times (default 3), A and B swapping places
# each time; printed are each run and the median of B/A over the runs. Why repeat: a run's
# two gases each sit in memory their own way, which biases one run by up to ~5 % (one
# library against itself: 0.956, 0.991, 1.030 at N = 1e5; 1.012, 0.954, 0.990 at 1e4).
# Both revisions must agree on the public structures ab_engine passes (relcol/sim.h).
# RELCOL_SIMD=avx2|scalar and RELCOL_DEFER=0 in the environment force those paths in both.
# Example: RUNS=5 scripts/ab-revs.sh HEAD~1 HEAD 100000 3 10
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: scripts/ab-revs.sh REV_A REV_B [N] [dim] [rounds] [c] [frame] [packing]"
rev_a=${1:?$usage}
rev_b=${2:?$usage}
shift 2

# ab_engine and "." come from this checkout's release build
if [ ! -f "$here/build-rel/build.ninja" ]; then
    meson setup "$here/build-rel" "$here" --buildtype=release >/dev/null
fi
ninja -C "$here/build-rel" build.ninja >/dev/null # (meson compile names targets from it)
meson compile -C "$here/build-rel" ab_engine relcol >/dev/null

tmp=$(mktemp -d)
# (the worktrees are made in subshells: removed with the folder, then forgotten by git)
cleanup() {
    rm -rf "$tmp"
    git -C "$here" worktree prune >/dev/null 2>&1 || true
}
trap cleanup EXIT

# the library of revision $1, built under $tmp/$2; its path on stdout
library_of() {
    local rev=$1 name=$2 dir
    if [ "$rev" = "." ]; then
        dir="$here/build-rel"
    else
        local commit
        commit=$(git -C "$here" rev-parse --verify --quiet "$rev^{commit}") || {
            echo "ab-revs: '$rev' is not a revision of $here" >&2
            exit 2
        }
        git -C "$here" worktree add --detach -f "$tmp/$name" "$commit" >/dev/null 2>&1
        meson setup "$tmp/$name/build" "$tmp/$name" --buildtype=release >/dev/null
        meson compile -C "$tmp/$name/build" relcol >/dev/null
        dir="$tmp/$name/build"
    fi
    local so
    so=$(ls "$dir"/lib/librelcol.so.*.*.* 2>/dev/null | head -1)
    [ -n "$so" ] || { echo "ab-revs: no library built for '$rev' in $dir" >&2; exit 2; }
    echo "$so"
}

runs=${RUNS:-3}
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "ab-revs: RUNS '$runs': not a positive whole number" >&2; exit 2; }
lib_a=$(library_of "$rev_a" a)
lib_b=$(library_of "$rev_b" b)
echo "A = $rev_a, B = $rev_b"
ratios=()
for r in $(seq "$runs"); do
    if (( r % 2 )); then
        line=$("$here/build-rel/tests/engine/ab_engine" "$lib_a" "$lib_b" "$@")
        echo "run $r: $line"
        ratios+=("$(awk '{print $NF}' <<<"$line")")
    else # (B first: the printed B/A is A's rate over B's)
        line=$("$here/build-rel/tests/engine/ab_engine" "$lib_b" "$lib_a" "$@")
        echo "run $r (B loaded first): $line"
        ratios+=("$(awk '{printf "%.3f", 1 / $NF}' <<<"$line")")
    fi
done
printf '%s\n' "${ratios[@]}" | sort -g |
    awk -v all="${ratios[*]}" '{a[NR] = $1} END {m = NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
        printf "B/A median %.3f over %d runs (%s)\n", m, NR, all}' 
