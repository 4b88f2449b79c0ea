#!/bin/sh
# run-notebook.sh EXE NBRENDER SOURCE.c PAGE.md — run a notebook (figures next to PAGE.md)
# and render it; exits with the notebook's status, so a failed check fails the target.
exe="$1"; render="$2"; src="$3"; page="$4"
dir=$(dirname "$page")
mkdir -p "$dir"
"$exe" "$dir" > "$page.out.txt"; st=$?
"$render" "$src" "$page.out.txt" "$page" || exit 2
exit $st
