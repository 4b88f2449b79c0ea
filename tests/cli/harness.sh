# harness.sh — the checks the CLI test scripts share (POSIX sh, sourced after setting $C,
# the app under test): a temporary folder $T removed on exit, pass/fail counters, running
# the app on a given stdin, and the checks on one run. End a script with `summary`.
T=$(mktemp -d) || exit 1
trap 'rm -rf "$T"' EXIT
pass=0
fail=0

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# run INPUT ARGS...: runs "$C" ARGS with INPUT (printf format) on stdin; sets $st, files
# $T/out and $T/err
run() {
    input=$1
    shift
    printf "$input" > "$T/in"
    "$C" "$@" < "$T/in" > "$T/out" 2> "$T/err"
    st=$?
}

# expect_bad NAME INPUT REGEX ARGS...: exit 2, empty stdout, exactly one stderr line that
# matches the extended regex (which names the row and column, or the option, and the reason)
expect_bad() {
    name=$1 input=$2 re=$3
    shift 3
    run "$input" "$@"
    lines=$(wc -l < "$T/err")
    if [ "$st" -ne 2 ]; then
        bad "$name: exit $st, want 2 (stderr: $(cat "$T/err"))"
    elif [ -s "$T/out" ]; then
        bad "$name: stdout not empty"
    elif [ "$lines" -ne 1 ]; then
        bad "$name: $lines stderr lines, want 1: $(cat "$T/err")"
    elif ! grep -Eq -- "$re" "$T/err"; then
        bad "$name: stderr '$(cat "$T/err")' does not match /$re/"
    else
        ok
    fi
}

# expect_ok NAME: the last run exited 0 and printed nothing on stderr
expect_ok() {
    if [ "$st" -ne 0 ]; then bad "$1: exit $st, stderr: $(cat "$T/err")"; else ok; fi
    if [ -s "$T/err" ]; then bad "$1: success must print nothing on stderr: $(cat "$T/err")"; else ok; fi
}

# close NAME GOT WANT TOL: |got - want| <= tol * max(|want|, 1e-300) or, when want = 0,
# |got| <= tol (the callers pass an absolute tolerance for zeros).
close() {
    if awk -v g="$2" -v w="$3" -v t="$4" 'BEGIN {
            if (g == "" || g == "nocol") exit 1
            d = g - w; if (d < 0) d = -d; s = w < 0 ? -w : w
            if (s == 0) s = 1
            exit !(d <= t * s) }'; then
        ok
    else
        bad "$1: got '$2', want $3 (rel tol $4)"
    fi
}

# summary [LABEL]: print the counts; the status is success iff nothing failed and
# something passed (so that a script that checked nothing fails too)
summary() {
    echo "${1:+$1: }$pass passed, $fail failed"
    [ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
}
