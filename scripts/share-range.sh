#!/usr/bin/env bash
# share-range.sh — the overlap-policy share of the covariant frame over issue 16's test
# range: periodic gases, 2-D to packing 0.7 and 3-D to 0.45, rms 0.5c and 0.9c, eps 1 and
# 0.5 with TC (papers/model-regime.md section 4). One line per dimension, rms and eps,
# one column per packing: the share of the collisions the policy decided.
#
#   scripts/share-range.sh [build dir (build-release)] [N (2000)] [collisions a ball (20)]
#
# Each entry is one run of tests/engine/kink_clusters (seed 3; two collisions a ball melt
# the start, then the given number a ball are read); ~10 minutes with the defaults.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build-release}
n=${2:-2000}
per=${3:-20}
tool=$build/tests/engine/kink_clusters
if [ ! -x "$tool" ]; then
    echo "share-range.sh: $tool not built (meson compile -C $build kink_clusters)" >&2
    exit 2
fi
for d in 2 3; do
    if [ "$d" = 2 ]; then packs="0.005 0.01 0.02 0.05 0.1 0.2 0.3 0.5 0.7"
    else packs="0.005 0.01 0.02 0.05 0.1 0.2 0.3 0.45"; fi
    for v in 0.5 0.9; do
        for e in 1 0.5; do
            line="d $d rms ${v}c eps $e:"
            for p in $packs; do
                share=$("$tool" "$d" "$p" "$v" "$n" "$per" 3 "$e" | tail -1 | awk '{print $NF}')
                line="$line $p=$share"
            done
            echo "$line"
        done
    done
done
