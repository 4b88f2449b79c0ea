#!/usr/bin/env bash
# ab-revs.sh — the engine's speed at two revisions, timed in one process (ab_engine: both
# libraries loaded side by side, alternating chunks on the same gas), so that the drift of
# a shared machine between minutes does not enter the ratio.
#
#   scripts/ab-revs.sh REV_A REV_B [N] [dim] [rounds] [c] [frame]
#
# REV_A, REV_B: git revisions, each built (release) in a temporary worktree that is removed
# afterwards; "." is this checkout as it is, uncommitted changes included (its build-rel/).
# The rest goes to ab_engine (tests/engine/ab_engine.c): N (10000), dim (3), rounds (10),
# c (inf), frame (default). Prints A's and B's collisions per CPU second and B/A.
# Both revisions must agree on the public structures ab_engine passes (relcol/sim.h).
# Example: scripts/ab-revs.sh HEAD~1 HEAD 100000 3 10
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: scripts/ab-revs.sh REV_A REV_B [N] [dim] [rounds] [c] [frame]"
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

lib_a=$(library_of "$rev_a" a)
lib_b=$(library_of "$rev_b" b)
echo "A = $rev_a, B = $rev_b"
"$here/build-rel/tests/engine/ab_engine" "$lib_a" "$lib_b" "$@"
