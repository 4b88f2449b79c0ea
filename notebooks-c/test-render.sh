#!/bin/sh
# test-render.sh RUNNER EXE NBRENDER SOURCE BUILDDIR — renders one notebook into a temp
# folder and checks that prose, fenced code, captured output and the checks summary are there.
runner="$1"; exe="$2"; render="$3"; src="$4"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$runner" "$exe" "$render" "$src" "$tmp/page.md" || { echo "notebook failed"; exit 1; }
fail=0
grep -q '^# 1. Relativistic restitution' "$tmp/page.md" || { echo "no title cell"; fail=1; }
grep -q '^```c' "$tmp/page.md" || { echo "no code cell"; fail=1; }
grep -q 'ZMF velocity u' "$tmp/page.md" || { echo "output not placed"; fail=1; }
grep -q 'checks, 0 failed' "$tmp/page.md" || { echo "no checks summary"; fail=1; }
grep -q '@output' "$tmp/page.md" && { echo "unexpanded @output"; fail=1; }
[ $fail -eq 0 ] && echo "rendered page has prose, code, output and checks"
exit $fail
