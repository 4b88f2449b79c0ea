#!/bin/sh
# test_stdout_full.sh APP... — every app whose standard output cannot be written (here
# /dev/full: every write fails with ENOSPC) says so on stderr and exits non-zero, instead
# of exit 0 with its output lost (relcol-toi and relcol-frames exited 1 without a word);
# --help for each, and a whole run of relcol-sim, relcol-collide, relcol-toi, relcol-frames.
. "$(dirname "$0")/harness.sh"
for app in "$@"; do
    name=$(basename "$app")
    "$app" --help > /dev/full 2> "$T/err"
    st=$?
    if [ "$st" -ne 0 ] && grep -q "^$name: cannot write to standard output: " "$T/err"; then
        ok
    else
        bad "$name --help > /dev/full: exit $st, stderr: $(cat "$T/err")"
    fi
    # a real run, where the app has one that is quick and prints to stdout
    case "$name" in
    relcol-sim) "$app" --builtin rack --no-plots --out "$T/rack" > /dev/full 2> "$T/err" ;;
    relcol-collide) printf 'm,vx\n1,0.6\n1,-0.6\n' | "$app" --c 1 > /dev/full 2> "$T/err" ;;
    relcol-toi) printf 'r,x,vx\n1,0,0.5\n1,10,-0.5\n' | "$app" > /dev/full 2> "$T/err" ;;
    relcol-frames) "$app" --points 5 --out "$T/frames" > /dev/full 2> "$T/err" ;;
    relcol-covariance) "$app" --n 50 --density 0.004 --c inf --out "$T/cov" > /dev/full 2> "$T/err" ;;
    relcol-heat) "$app" --n 200 --aspect 2 --warmup 50 --time 160 --out "$T/heat" > /dev/full 2> "$T/err" ;;
    *) continue ;;
    esac
    st=$?
    if [ "$st" -ne 0 ] && grep -q "cannot write to standard output" "$T/err"; then
        ok
    else
        bad "$name run > /dev/full: exit $st, stderr: $(cat "$T/err")"
    fi
done
# one failure, one message (relcol-collide said it twice: its own and the exit handler's)
printf 'm,vx\n1,0.6\n1,-0.6\n' | "$1" --c 1 > /dev/full 2> "$T/err"
[ "$(wc -l < "$T/err")" -eq 1 ] && ok || bad "relcol-collide > /dev/full: $(wc -l < "$T/err") lines: $(cat "$T/err")"
summary "stdout full"
