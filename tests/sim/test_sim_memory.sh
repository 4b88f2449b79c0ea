#!/bin/bash
# test_sim_memory.sh RELCOL_SIM — relcol-sim refused memory names the bytes it needs (issue 37
# item 9), under an address-space limit (ulimit -v):
# 1. N = 10^7 under 256 MiB (the balls' description) and under 1 GiB (their placement):
#    each refusal names its bytes;
# 2. N = 10^6 from the limit 100 balls need, then each time raised by the bytes the
#    refusal named (and a slack of 10 % + 48 MiB for the allocator and the libraries):
#    every refusal on the way names bytes, the raise gets past it (the number was enough),
#    and the chain ends in a finished run.
# Skipped (77) where an address-space limit cannot be used (a sanitized build reserves
# terabytes of it).
sim="$1"
tmp=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }
gas() {
    cat > "$tmp/$1.json" <<JSON
{"relcol": 1, "dim": 2, "c": 2, "seed": 5, "t_end": 1e-6,
 "generate": {"kind": "gas", "n": $2, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"snapshots": [0], "xyz_every": 0, "plots": false, "gif": false}}
JSON
}
# run NAME LIMIT_KB: relcol-sim under the limit; its exit status in $st, its message in $msg
run() {
    rm -rf "$tmp/o"
    msg=$( (ulimit -v "$2"; "$sim" "$tmp/$1.json" --out "$tmp/o" --no-plots 2>&1 > /dev/null); )
    st=$?
}
gas small 100
run small 4194304
[ $st -eq 0 ] || { echo "skip: a run of 100 balls fails under a 4 GiB address-space limit (a sanitized build?): $msg"; exit 77; }
# base: the smallest limit, doubling from 16 MiB, under which 100 balls run (the program and
# its libraries)
base=16384
while run small $base; [ $st -ne 0 ]; do base=$((base * 2)); done

# 1. N = 10^7
gas big 10000000
for lim in 262144 1048576; do
    run big $lim
    if [ $st -eq 2 ] && echo "$msg" | grep -q 'out of memory for 10000000 balls: .* [0-9][0-9]* bytes'; then
        ok "N = 10^7 under $((lim / 1024)) MiB: exit 2, '$msg'"
    else
        ko "N = 10^7 under $((lim / 1024)) MiB: exit $st, '$msg'"
    fi
done

# 2. N = 10^6: the chain of refusals, from the base
gas mid 1000000
lim=$base; steps=0; seen=""
while [ $steps -lt 10 ]; do
    run mid $lim
    [ $st -eq 0 ] && break
    steps=$((steps + 1))
    # (the largest number of bytes the message names: what it needs)
    need=$(echo "$msg" | grep -o '[0-9][0-9]* bytes' | sed 's/ bytes//' | sort -n | tail -1)
    if ! echo "$msg" | grep -q 'out of memory' || [ -z "$need" ]; then
        ko "N = 10^6 under $((lim / 1024)) MiB: exit $st, a refusal that names no bytes: '$msg'"
        break
    fi
    # (the same refusal again after the raise: the named bytes were not enough)
    what=$(echo "$msg" | sed 's/[0-9][0-9.]*//g')
    if [ "$what" = "$seen" ]; then
        ko "N = 10^6 under $((lim / 1024)) MiB: the same refusal after a raise by the bytes it named: '$msg'"
        break
    fi
    seen=$what
    echo "  under $((lim / 1024)) MiB: $msg"
    lim=$(( lim + need / 1024 * 11 / 10 + 49152 ))
done
[ $st -eq 0 ] && [ $steps -ge 2 ] &&
    ok "N = 10^6: $steps refusals, each naming its bytes and passed by a limit raised by them, then the run finished under $((lim / 1024)) MiB" ||
    { [ $st -eq 0 ] && ko "N = 10^6: only $steps refusals before the run finished (the chain tested nothing)"; } ||
    { [ $st -ne 0 ] && [ $fails -eq 0 ] && ko "N = 10^6: still refused after $steps raises: '$msg'"; }

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
