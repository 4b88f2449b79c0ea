#!/bin/sh
# bench_sensitivity.sh RELCOL_GAS — what --sensitivity costs (issue 36): a covariant 2-D gas
# (N 400, packing 0.1, periodic) run once as relcol-gas runs it, and with --sensitivity
# (the base, the 1e-15 move, the other group rule and the three other contracted frames:
# six runs), CPU seconds of each (user + system, the machine may be shared) and the ratio.
gas="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
args="--dim 2 --n 400 --packing 0.1 --frame covariant --boundary periodic --t-sample 200"
cpu() { # the CPU seconds of a command, from /usr/bin/time's format
    /usr/bin/time -f '%U %S' -o "$tmp/t" "$@" > /dev/null 2>&1 || return 1
    awk '{ print $1 + $2 }' "$tmp/t"
}
one=$(cpu "$gas" $args --out "$tmp/one") || { echo "one run failed"; exit 1; }
sens=$(cpu "$gas" $args --out "$tmp/sens" --sensitivity) || { echo "--sensitivity failed"; exit 1; }
awk -v a="$one" -v b="$sens" 'BEGIN { printf "one run %.2f s, --sensitivity %.2f s: %.2f x one run\n", a, b, b / a }'
