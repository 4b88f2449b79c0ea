#!/bin/sh
# test_apps_faults.sh SWEEP_C SWEEP FRAMES GAS COVARIANCE — the figure apps under faults (suite
# 'faults'): a disk that fills (RLIMIT_FSIZE with SIGXFSZ ignored, so writes fail with
# EFBIG as on a full disk) at 1 KiB a file (the CSV fails) and at 64 KiB (the CSV and the
# script fit, gnuplot's PNG does not) makes the app exit non-zero with a message, and
# leaves every file of the previous run in its folder with its bytes; the next run leaves
# no temporary; relcol-gas killed with SIGKILL at 10 random points leaves every file under
# a final name whole (a PNG ends in its IEND chunk).
sweep_c="$1"; sweep="$2"; frames="$3"; gas="$4"; covariance="$5"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }
sums() { (cd "$1" && find . -type f | sort | xargs cksum); }

full_disk() { # NAME KIB APP ARGS...
    name=$1; kib=$2; shift 2
    dir="$tmp/$name"
    if ! "$@" --out "$dir" > /dev/null 2> "$tmp/err"; then
        ko "$name: the first run failed: $(cat "$tmp/err")"; return
    fi
    before=$(sums "$dir")
    ( ulimit -f "$kib"; trap '' XFSZ; exec "$@" --out "$dir" ) > /dev/null 2> "$tmp/err"; st=$?
    after=$(sums "$dir")
    if [ $st -ne 0 ] && grep -q 'cannot\|not whole\|failed' "$tmp/err" && [ "$before" = "$after" ]; then
        ok "$name, files cut at $kib KiB: exit $st, '$(head -1 "$tmp/err")'; $(echo "$before" | wc -l) files keep their bytes"
    else
        ko "$name, files cut at $kib KiB: exit $st, stderr '$(cat "$tmp/err")', files changed: $([ "$before" = "$after" ] && echo no || echo yes)"
    fi
    "$@" --out "$dir" > /dev/null 2>&1
    left=$(ls -A "$dir" | grep -c 'relcol-') || true
    [ "$left" -eq 0 ] && ok "$name: no temporary left after the next run" \
        || ko "$name: $left temporaries left: $(ls -A "$dir")"
}

for kib in 1 64; do
    full_disk "sweep-c-$kib" $kib "$sweep_c" --example --points 5
    full_disk "sweep-$kib" $kib "$sweep" --points 5
    full_disk "frames-$kib" $kib "$frames" --points 5
    full_disk "gas-$kib" $kib "$gas" --n 100 --t-sample 20 --snapshots 20
    full_disk "covariance-$kib" $kib "$covariance" --n 50 --density 0.004,0.01 --c 2,inf
done

# kill -9 at random points of relcol-gas runs into one folder
png_whole() { [ ! -e "$1" ] || tail -c 8 "$1" | od -An -c | tr -d ' \n' | grep -q 'IEND'; }
bad=0; seedv=11
for k in $(seq 1 10); do
    seedv=$(( (seedv * 1103515245 + 12345) % 2147483648 ))
    delay=$(( seedv % 40 + 1 ))
    "$gas" --n 300 --t-sample 40 --out "$tmp/kill" > /dev/null 2>&1 &
    pid=$!
    sleep "0.$(printf '%02d' "$delay")"
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null
    png_whole "$tmp/kill/gas.png" || { bad=$((bad + 1)); echo "kill $k: gas.png cut"; }
    if [ -e "$tmp/kill/gas.csv" ] && [ "$(tail -c 1 "$tmp/kill/gas.csv" | od -An -c | tr -d ' ')" != '\n' ]; then
        bad=$((bad + 1)); echo "kill $k: gas.csv cut"
    fi
done
[ $bad -eq 0 ] && ok "10 kill -9 of relcol-gas: every file under a final name whole" \
    || ko "$bad cut files after 10 kills"

echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
