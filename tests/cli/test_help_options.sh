#!/bin/sh
# test_help_options.sh — each app's --help names exactly the options its option table
# holds (apps/common/opttab.c): the names that open an option line of --help ("  --name",
# capitals allowed: relcol-shock's --T-left) are the names the hidden --list-options
# prints from the table, and every "--name" of the usage synopsis is one of them. A fake
# app whose help and table disagree must fail the same comparison (the check can fail).
# Usage: test_help_options.sh APP...
. "$(dirname "$0")/harness.sh"

# compare NAME HELP_FILE LIST_FILE: 0 if they agree, else 1 with the differences on stdout
compare() {
    awk '/^  --[a-zA-Z]/ { print $1 }' "$2" | sort -u > "$T/h"
    sort -u "$3" > "$T/l"
    # the synopsis: from "usage:" to the first blank line
    awk '/^usage:/ { u = 1 } u && /^$/ { exit } u' "$2" |
        grep -o -- '--[a-zA-Z][a-zA-Z0-9-]*' | sort -u > "$T/s"
    r=0
    d=$(comm -3 "$T/h" "$T/l" | tr -s ' \t\n' ' ')
    [ -z "$d" ] || { echo "$1: help lines and table differ: $d (left: help only)"; r=1; }
    d=$(comm -23 "$T/s" "$T/l" | tr '\n' ' ')
    [ -z "$d" ] || { echo "$1: the synopsis names options the table lacks: $d"; r=1; }
    return $r
}

for app in "$@"; do
    n=$(basename "$app")
    if ! "$app" --help > "$T/help" 2> "$T/err"; then
        bad "$n --help: exit status not 0: $(cat "$T/err")"
        continue
    fi
    if ! "$app" --list-options > "$T/list" 2> "$T/err" || ! [ -s "$T/list" ]; then
        bad "$n --list-options: failed or empty: $(cat "$T/err")"
        continue
    fi
    if out=$(compare "$n" "$T/help" "$T/list"); then ok; else bad "$out"; fi
done

# the control: a help line the table lacks, and a table entry the help lacks
printf 'usage: fake [--a A] [--zz]\n\noptions:\n  --a A   a\n  --b B   b\n' > "$T/help"
printf -- '--a\n--c\n' > "$T/list"
if compare fake "$T/help" "$T/list" > "$T/out"; then
    bad "the control passed: help --a --b against table --a --c"
else
    grep -q -- '--b' "$T/out" && grep -q -- '--c' "$T/out" && grep -q -- '--zz' "$T/out" &&
        ok || bad "the control's differences: $(cat "$T/out")"
fi
summary
