#!/bin/sh
# test_interrupt.sh RELCOL_EOS RELCOL_GAS RELCOL_SIM — Ctrl-C on a long run started in the
# background from a script (where `&` starts it with SIGINT ignored): kill -INT must stop
# it, and leave no temporary file (.NAME.relcol-PID.*) behind. relcol-eos and relcol-gas
# die by the signal, nothing published; relcol-sim writes its restart state (exit 130).
eos="$1"; gas="$2"; sim="$3"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail=0
say() { echo "$1"; case "$1" in FAIL*) fail=1 ;; esac; }

# run NAME WANT_STATUS TMP CMD...: start CMD in the background, wait until its temporary
# file exists (TMP = 1; relcol-gas writes only at its end: TMP = 0 waits 2 s), kill -INT,
# then check its exit and leftovers
run() {
    name=$1; want=$2; need=$3; shift 3
    out="$tmp/$name"; mkdir -p "$out"
    "$@" > "$tmp/$name.log" 2>&1 &
    pid=$!
    k=0
    if [ "$need" = 1 ]; then
        until ls -a "$out" | grep -q '\.relcol-' || [ $k -ge 300 ]; do sleep 0.1; k=$((k + 1)); done
        [ $k -lt 300 ] || say "FAIL $name: no temporary file in 30 s (did it start?)"
    fi
    sleep 2
    kill -INT "$pid"
    k=0
    while kill -0 "$pid" 2> /dev/null && [ $k -lt 300 ]; do sleep 0.1; k=$((k + 1)); done
    if kill -0 "$pid" 2> /dev/null; then
        say "FAIL $name: still running 30 s after kill -INT (SIGINT ignored)"
        kill -KILL "$pid"
    fi
    wait "$pid"; st=$?
    [ "$st" = "$want" ] && say "ok   $name: stopped by kill -INT, exit $st" \
                        || say "FAIL $name: exit $st, want $want ($(tail -2 "$tmp/$name.log"))"
    # (relcol-sim's published run is DIR/.relcol-run -> .relcol-run.XXXXXX, not a temporary)
    left=$(find "$out" -name '*.relcol-*' | grep -v -E "^$out/\.relcol-run(\.[^/]*)?\$" | head -3)
    [ -z "$left" ] && say "ok   $name: no temporary file left" \
                   || say "FAIL $name: left $left"
}

run eos 130 1 "$eos" --n 2000 --packing 0.3 --t-run 100000 --out "$tmp/eos"
[ ! -e "$tmp/eos/eos.csv" ] && say "ok   eos: no eos.csv published" || say "FAIL eos: eos.csv"
run gas 130 0 "$gas" --dim 3 --n 2000 --t-sample 100000 --out "$tmp/gas"
cat > "$tmp/sim.json" <<JSON
{"relcol": 1, "dim": 3, "c": 1, "t_end": 100000, "seed": 1,
 "generate": {"kind": "gas", "n": 2000, "radius": 1, "packing": 0.2, "v_rms": 0.5},
 "outputs": {"dir": "$tmp/sim", "h5md_every": 1000, "plots": false}}
JSON
run sim 130 1 "$sim" "$tmp/sim.json"
# relcol-sim's bar on a terminal (util-linux's script gives it one): interrupted at a few
# per cent of a long run, its last drawn percentage is below 100
# (a root without /dev/pts, as a bare chroot, has no terminal to give: the check is skipped)
if ! command -v script > /dev/null 2>&1; then
    say "skip sim bar: no script(1) here"
elif ! script -qfc true /dev/null < /dev/null > /dev/null 2>&1; then
    say "skip sim bar: script(1) cannot open a pseudo-terminal here"
else
    sed "s|\"dir\": \"$tmp/sim\", \"h5md_every\": 1000|\"dir\": \"$tmp/bar\"|" "$tmp/sim.json" > "$tmp/bar.json"
    script -qfc "sh -c '\"$sim\" \"$tmp/bar.json\" & echo \$! > \"$tmp/bar.pid\"; wait'" \
        "$tmp/bar.ts" < /dev/null > /dev/null 2>&1 &
    spid=$!
    k=0
    until grep -aq '%' "$tmp/bar.ts" 2> /dev/null || [ $k -ge 300 ]; do sleep 0.1; k=$((k + 1)); done
    kill -INT "$(cat "$tmp/bar.pid")"
    wait "$spid"
    last=$(tr '\r' '\n' < "$tmp/bar.ts" | grep -a 'relcol-sim \[' | tail -1)
    case "$last" in
        *"100%"*|"") say "FAIL sim bar: last drawn '$last' (want < 100 %)" ;;
        *) say "ok   sim bar: interrupted, stays at '${last##*]}'" ;;
    esac
fi
exit $fail
