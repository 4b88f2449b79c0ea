#!/bin/sh
# test_sweep_c.sh — relcol-sweep-c on its built-in example into a temporary folder: it must
# write the CSV (header + 41 rows) and the gnuplot script atomically (no temporaries left),
# and print fitted log-log slopes within 0.05 of -2 (the (v/c)^2 classical limit). The PNG
# is not required (gnuplot may be absent); without gnuplot on PATH it must still exit 0.
# Usage: test_sweep_c.sh PATH/relcol-sweep-c
S=${1:?usage: test_sweep_c.sh relcol-sweep-c}
. "$(dirname "$0")/harness.sh"

# slope_ok NAME: the "slope NAME: X" line of $T/stdout has |X + 2| <= 0.05
slope_ok() {
    x=$(awk -v k="slope $1:" 'index($0, k) == 1 { print $3 }' "$T/stdout")
    if awk -v x="$x" 'BEGIN { exit !(x != "" && x + 2 <= 0.05 && x + 2 >= -0.05) }'; then
        ok
    else
        bad "slope $1 = '$x', want -2 +- 0.05 (stdout: $(cat "$T/stdout"))"
    fi
}

"$S" --example --out "$T/a/b" > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 0 ] && ok || bad "--example: exit $st: $(cat "$T/stderr")"
[ -f "$T/a/b/sweep-c.csv" ] && ok || bad "no sweep-c.csv in a created nested --out folder"
[ -f "$T/a/b/sweep-c.gp" ] && ok || bad "no sweep-c.gp"
head -1 "$T/a/b/sweep-c.csv" | grep -q '^c,c_over_vmax,' && ok || bad "CSV header"
rows=$(awk 'NR > 1 && NF' "$T/a/b/sweep-c.csv" | wc -l)
[ "$rows" -eq 41 ] && ok || bad "CSV has $rows rows, want 41 (the default --points)"
# every data row: 8 finite numbers, c increasing
awk -F, 'NR > 1 { if (NF != 8) exit 1; for (i = 1; i <= NF; i++) if ($i !~ /^-?[0-9.]+(e[-+][0-9]+)?$/) exit 1
         if (NR > 2 && $1 <= prev) exit 1; prev = $1 }' "$T/a/b/sweep-c.csv" && ok || bad "CSV rows"
slope_ok velocities
slope_ok heat
grep -q "sweep-c.csv" "$T/a/b/sweep-c.gp" && grep -q "pngcairo" "$T/a/b/sweep-c.gp" && ok ||
    bad "gnuplot script must read sweep-c.csv and use pngcairo"
left=$(ls -A "$T/a/b" | grep -c '^\.') || true
[ "$left" -eq 0 ] && ok || bad "temporary files left in the output folder: $(ls -A "$T/a/b")"

# no gnuplot on PATH: a note on stderr, exit 0, data still written, no figure
env PATH=/nonexistent "$S" --example --out "$T/nogp" > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 0 ] && grep -q "gnuplot is not on PATH" "$T/stderr" && [ -f "$T/nogp/sweep-c.csv" ] &&
    ok || bad "without gnuplot: exit $st, stderr: $(cat "$T/stderr")"
slope_ok velocities

# a gnuplot that exits 0 with its figure cut short (what a full disk does): refused, exit
# non-zero, the previous figure kept byte for byte, no temporary left
if [ -f "$T/a/b/sweep-c.png" ]; then
    mkdir -p "$T/fakebin"
    cat > "$T/fakebin/gnuplot" <<'SH'
#!/bin/sh
# writes the PNG signature and 100 more bytes, no IEND chunk, to the outfile it is given
out=$(printf '%s' "$2" | sed "s/^outfile='\(.*\)'$/\1/")
printf '\211PNG\r\n\032\n' > "$out"
head -c 100 /dev/zero >> "$out"
exit 0
SH
    chmod +x "$T/fakebin/gnuplot"
    cksum < "$T/a/b/sweep-c.png" > "$T/png-before"
    PATH="$T/fakebin:$PATH" "$S" --example --out "$T/a/b" > "$T/stdout" 2> "$T/stderr"
    st=$?
    cksum < "$T/a/b/sweep-c.png" > "$T/png-after"
    [ "$st" -ne 0 ] && grep -q "sweep-c.png is not whole: the PNG does not end with its IEND" "$T/stderr" &&
        cmp -s "$T/png-before" "$T/png-after" && ok ||
        bad "cut PNG: exit $st, stderr: $(cat "$T/stderr"), figure changed: $(cmp "$T/png-before" "$T/png-after")"
    left=$(ls -A "$T/a/b" | grep -c '^\.') || true
    [ "$left" -eq 0 ] && ok || bad "temporaries left after a cut figure: $(ls -A "$T/a/b")"
fi

# eps = 1: nothing becomes rest mass; the heat column is empty and no slope is claimed
printf 'm,vx\n1,0.9\n3,-0.2\n' > "$T/in.csv"
"$S" --input "$T/in.csv" --out "$T/el" --points 7 > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 0 ] && ok || bad "--input eps=1: exit $st: $(cat "$T/stderr")"
grep -q "slope heat: none" "$T/stdout" && ok || bad "eps = 1 must print 'slope heat: none'"
slope_ok velocities
awk -F, 'NR > 1 && $5 != "" { exit 1 }' "$T/el/sweep-c.csv" && ok || bad "eps = 1: dev_heat must be empty"

# equal masses head-on, elastic: they swap velocities exactly at every c, so no slope is
# claimed (it printed "slope velocities: 0.0000 +- 0 (expect -2)")
printf 'm,vx\n1,0.6\n1,-0.6\n' | "$S" --out "$T/eq" > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 0 ] && grep -q "slope velocities: none (0 of 41 points above the round-off floor" "$T/stdout" &&
    ! grep -q "nan +-\|-nan\|: nan" "$T/stdout" && ok || bad "equal masses: exit $st: $(cat "$T/stdout" "$T/stderr")"

# stdin input, momentum columns, 3-D
printf 'm,px,py,pz\n1,0.5,0.1,0\n2,-0.4,0,0.2\n' | "$S" --eps 0.3 --out "$T/p" > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 0 ] && ok || bad "stdin momentum 3-D: exit $st: $(cat "$T/stderr")"
slope_ok velocities
slope_ok heat

# bad input: exit 2 with one line
printf 'm,vx\n1,0.9\n' | "$S" --out "$T/x" > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 2 ] && grep -q "wrong number of rows" "$T/stderr" && [ ! -e "$T/x" ] && ok ||
    bad "one row: exit $st, $(cat "$T/stderr")"
"$S" --example --from 1 --out "$T/x" > "$T/stdout" 2> "$T/stderr"
st=$?
[ "$st" -eq 2 ] && grep -q -- "--from: 1 must be > 1" "$T/stderr" && ok || bad "--from 1: exit $st"

summary
