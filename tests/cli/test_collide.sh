#!/bin/sh
# test_collide.sh — relcol-collide through its command line: every kind of bad input gives
# exit 2 and one stderr line naming the row/column/option and the reason; separating balls
# give exit 3 and no stdout; the published values, momentum input, positions, 1-/2-/3-D,
# conservation and JSON syntax. Usage: test_collide.sh PATH/relcol-collide [json_check.awk]
C=${1:?usage: test_collide.sh relcol-collide [json_check.awk]}
JSON_AWK=${2:-$(dirname "$0")/json_check.awk}
. "$(dirname "$0")/harness.sh"

# field BALL COLUMN: value from the CSV on stdout (header names the columns)
field() {
    awk -F, -v r="$1" -v col="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i }
        NR == r + 2 { if (!(col in h)) { print "nocol"; exit } print $h[col] }' "$T/out"
}

# The law's arithmetic is a few dozen roundings on numbers of order 1, so a correct result
# is within ~1e-15 relative; 1e-13 leaves room for the libm but still fails any wrong formula
# (the smallest physical effect checked here, 2/sqrt(3) vs 1.15, is 1e-1).
TOL=1e-13

# same_csv NAME FILE: stdout equals FILE up to TOL relative to each row's largest number
# (two routes to one result, e.g. a normal given as (2,2) or (3,3), round differently)
same_csv() {
    if awk -F, -v t=$TOL 'NR == FNR { a[FNR] = $0; n = FNR; next }
        { if (!(FNR in a)) exit 1; split(a[FNR], x, ","); if (FNR == 1) { if (a[1] != $0) exit 1; next }
          s = 0; for (i = 1; i <= NF; i++) { v = $i < 0 ? -$i : $i; if (v > s) s = v }
          for (i = 1; i <= NF; i++) { d = $i - x[i]; if (d < 0) d = -d; if (d > t * s) exit 1 } }
        END { if (FNR != n) exit 1 }' "$2" "$T/out"; then
        ok
    else
        bad "$1: $(cat "$T/out") differs from $(cat "$2")"
    fi
}

# ---------------------------------------------------------------- published values (c = 1)
run 'm,vx\n1,0.6\n1,-0.6\n' --c 1 --eps 0
expect_ok "stick +-0.6"
for b in 0 1; do
    close "stick m$b" "$(field $b m)" 1.25 $TOL
    close "stick vx$b" "$(field $b vx)" 0 $TOL
    close "stick px$b" "$(field $b px)" 0 $TOL
    close "stick E$b" "$(field $b E)" 1.25 $TOL   # M c^2 with the ball at rest: m c^2
done
[ "$(head -1 "$T/out")" = "ball,m,px,vx,E" ] && ok || bad "1-D header: $(head -1 "$T/out")"
[ "$(wc -l < "$T/out")" -eq 3 ] && ok || bad "1-D output must be header + 2 rows"

run 'm,vx\n1,0.8\n1,0\n' --c 1 --eps 0
expect_ok "0.8 on rest"
for b in 0 1; do
    close "0.8 on rest m$b" "$(field $b m)" "$(awk 'BEGIN { printf "%.17g", 2 / sqrt(3) }')" $TOL
    close "0.8 on rest vx$b" "$(field $b vx)" 0.5 $TOL
done

run 'm,vx\n1,0.6\n2,0\n' --c 1
expect_ok "elastic 1 on 2"
close "elastic v0" "$(field 0 vx)" "$(awk 'BEGIN { printf "%.17g", -9 / 41 }')" $TOL
close "elastic v1" "$(field 1 vx)" "$(awk 'BEGIN { printf "%.17g", 39 / 89 }')" $TOL
close "elastic m0 kept" "$(field 0 m)" 1 $TOL
close "elastic m1 kept" "$(field 1 m)" 2 $TOL

# ---------------------------------------------------------------- momentum input
# p = m gamma v = 0.75 is v = 0.6 at c = 1: the same sticking collision
run 'm,px\n1,0.75\n1,-0.75\n' --c 1 --eps 0
expect_ok "momentum input"
close "momentum input m0" "$(field 0 m)" 1.25 $TOL
close "momentum input m1" "$(field 1 m)" 1.25 $TOL
# any finite momentum is valid, however close to c it makes the ball
run 'm,px\n1,1e6\n1,0\n' --c 1
expect_ok "momentum 1e6 at c = 1"
close "ultrarelativistic px1" "$(field 1 px)" "$(field 1 px)" 0   # column present
v0=$(field 0 vx) v1=$(field 1 vx)
awk -v a="$v0" -v b="$v1" 'BEGIN { exit !(a < 1 && b < 1 && b > 0.999) }' && ok ||
    bad "ultrarelativistic speeds must stay below c: $v0 $v1"

# ---------------------------------------------------------------- classical, E = p^2/2m
run 'm,vx\n1,1\n1,0\n'
expect_ok "classical default"
close "classical exchange v0" "$(field 0 vx)" 0 $TOL
close "classical exchange v1" "$(field 1 vx)" 1 $TOL
close "classical E is kinetic" "$(field 1 E)" 0.5 $TOL

# ---------------------------------------------------------------- positions give the normal (2-D)
# equal masses, elastic, classical, n = (1,1)/sqrt2: ball 0 keeps its tangential part.
run 'm,vx,vy,x,y\n1,0.6,0,0,0\n1,0,0,1,1\n'
expect_ok "positions normal"
close "pos v0x" "$(field 0 vx)" 0.3 $TOL
close "pos v0y" "$(field 0 vy)" -0.3 $TOL
close "pos v1x" "$(field 1 vx)" 0.3 $TOL
close "pos v1y" "$(field 1 vy)" 0.3 $TOL
[ "$(head -1 "$T/out")" = "ball,m,px,py,vx,vy,E" ] && ok || bad "2-D header: $(head -1 "$T/out")"
cp "$T/out" "$T/pos_out"
run 'm,vx,vy\n1,0.6,0\n1,0,0\n' --normal 1,1
same_csv "--normal 1,1 must equal the positions' normal" "$T/pos_out"
# the same at c = 2, relativistic: still identical between the two ways of giving n
run 'm,vx,vy,x,y\n1,0.6,0,0,0\n1,0,0,2,2\n' --c 2 --eps 0.3
cp "$T/out" "$T/pos_out"
run 'm,vx,vy\n1,0.6,0\n1,0,0\n' --c 2 --eps 0.3 --normal 3,3
same_csv "relativistic: --normal 3,3 must equal positions" "$T/pos_out"
# no positions, no --normal: +x, so this oblique pair collides head-on along x
run 'm,vx,vy\n1,0.6,0.2\n1,0,0\n'
close "default +x v0y kept" "$(field 0 vy)" 0.2 $TOL
close "default +x v0x" "$(field 0 vx)" 0 $TOL

# ---------------------------------------------------------------- 3-D
run 'm,vx,vy,vz\n1,0.1,0.2,0.5\n1,0,0,-0.5\n' --normal 0,0,1
expect_ok "3-D"
[ "$(head -1 "$T/out")" = "ball,m,px,py,pz,vx,vy,vz,E" ] && ok || bad "3-D header"
close "3-D v0x" "$(field 0 vx)" 0.1 $TOL
close "3-D v0y" "$(field 0 vy)" 0.2 $TOL
close "3-D v0z" "$(field 0 vz)" -0.5 $TOL
close "3-D v1z" "$(field 1 vz)" 0.5 $TOL
# fewer --normal components are zero-padded
run 'm,vx,vy,vz\n1,0.5,0.2,0.1\n2,-0.3,0,0\n' --c 3 --eps 0.5 --normal 1
cp "$T/out" "$T/pad"
run 'm,vx,vy,vz\n1,0.5,0.2,0.1\n2,-0.3,0,0\n' --c 3 --eps 0.5 --normal 1,0,0
same_csv "--normal 1 must equal --normal 1,0,0 in 3-D" "$T/pad"
# relativistic 3-D conservation at c = 2, eps = 0.5: total p and total E = sum M c^2
IN='m,px,py,pz,x,y,z\n1.5,0.7,-0.2,0.4,0,0,0\n0.8,-0.9,0.3,0.1,0.6,0.2,-0.4\n'
run "$IN" --c 2 --eps 0.5
expect_ok "3-D conservation"
for col in px py pz; do
    got=$(awk -F, -v col=$col 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i }
        NR > 1 { s += $h[col] } END { printf "%.17g", s }' "$T/out")
    want=$(printf "$IN" | awk -F, -v col=$col 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i }
        NR > 1 { s += $h[col] } END { printf "%.17g", s }')
    # scale: the largest momentum component, ~1, so absolute 1e-13 is relative to it
    awk -v a="$got" -v b="$want" 'BEGIN { d = a - b; exit !(d < 1e-13 && d > -1e-13) }' &&
        ok || bad "3-D total $col: $got vs $want"
done
Ein=$(printf "$IN" | awk -F, 'NR > 1 { s += sqrt($1 * $1 * 16 + ($2 * $2 + $3 * $3 + $4 * $4) * 4) }
    END { printf "%.17g", s }')
Eout=$(awk -F, 'NR > 1 { s += $NF } END { printf "%.17g", s }' "$T/out")
close "3-D total energy" "$Eout" "$Ein" $TOL
m0=$(field 0 m)
awk -v m="$m0" 'BEGIN { exit !(m > 1.5) }' && ok || bad "eps < 1 must raise rest mass: $m0"

# ---------------------------------------------------------------- JSON
run 'm,vx,vy\n1,0.6,0.1\n2,0,0\n' --format json --c 1 --eps 0.5
expect_ok "json"
awk -f "$JSON_AWK" "$T/out" > "$T/jc" && ok || bad "json syntax: $(cat "$T/jc")"
grep -q '"law":"zmf"' "$T/out" && grep -q '"dimension":2' "$T/out" &&
    grep -q '"eps":0.5' "$T/out" && grep -q '"c":1,' "$T/out" &&
    [ "$(grep -c '"ball":' "$T/out")" -eq 2 ] && grep -q '"p":\[[^],]*,[^],]*\]' "$T/out" &&
    ok || bad "json fields: $(cat "$T/out")"
run 'm,vx\n1,0.6\n2,0\n' --format json
grep -q '"c":"inf"' "$T/out" && ok || bad "json c = inf must be the string \"inf\""
awk -f "$JSON_AWK" "$T/out" > "$T/jc" && ok || bad "json syntax (inf): $(cat "$T/jc")"
# the checker itself must be able to fail
printf '{"c": inf}' | awk -f "$JSON_AWK" > /dev/null 2>&1 && bad "json checker accepts bad JSON" || ok

# ---------------------------------------------------------------- cm-isotropic, alpha
run 'm,vx\n1,0.6\n2,0\n' --c 1 --law cm-isotropic
cp "$T/out" "$T/cm"
run 'm,vx\n1,0.6\n2,0\n' --c 1
same_csv "1-D elastic: cm-isotropic must equal zmf" "$T/cm"
run 'm,vx,vy\n1,0.6,0\n2,0,0\n' --c 1 --law cm-isotropic --alpha random --seed 7
expect_ok "alpha random"
cp "$T/out" "$T/r7"
run 'm,vx,vy\n1,0.6,0\n2,0,0\n' --c 1 --law cm-isotropic --alpha random --seed 7
cmp -s "$T/out" "$T/r7" && ok || bad "--alpha random --seed 7 must reproduce"
run 'm,vx,vy\n1,0.6,0\n2,0,0\n' --c 1 --law cm-isotropic --alpha random --seed 8
cmp -s "$T/out" "$T/r7" && bad "--seed 8 gave the same draw as --seed 7" || ok
run 'm,vx,vy,vz\n1,0.6,0,0\n2,0,0,0\n' --law cm-isotropic --alpha 0.3 --azimuth 1
expect_ok "3-D alpha azimuth"

# ---------------------------------------------------------------- near c (issue 16)
# balls moving together at gamma 1e6 and 1e8, the faster behind: they approach, and equal
# masses swap their momenta exactly (the law's old form said 'no collision')
for P in "1e6 999990" "1e8 99999000"; do
    run "m,px\n1,${P% *}\n1,${P#* }\n" --c 1
    expect_ok "gamma ${P% *} co-moving"
    close "gamma ${P% *} px0" "$(field 0 px)" "${P#* }" $TOL
    close "gamma ${P% *} px1" "$(field 1 px)" "${P% *}" $TOL
done

# ---------------------------------------------------------------- separating: exit 3
for args in "m,vx\n1,-0.6\n1,0.6\n|" "m,vx,x\n1,0.6,1\n1,0,0\n|" "m,vx,vy\n1,0.6,0\n1,0,0\n|--normal 0,1"; do
    input=${args%%|*} opts=${args#*|}
    # shellcheck disable=SC2086
    run "$input" $opts
    if [ "$st" -eq 3 ] && [ ! -s "$T/out" ] && grep -q "no collision" "$T/err"; then ok; else
        bad "separating ($input $opts): exit $st, stdout '$(cat "$T/out")', stderr '$(cat "$T/err")'"
    fi
done

# ---------------------------------------------------------------- bad input: exit 2
G='m,vx\n1,0.6\n1,0\n'   # a good input, for option errors
expect_bad "v > c" 'm,vx\n1,1.5\n1,0\n' 'line 2 \(ball 0\), column vx: \|v\| = 1.5 >= c = 1' --c 1
expect_bad "v = c" 'm,vx\n1,0\n1,-1\n' 'line 3 \(ball 1\), column vx: \|v\| = 1 >= c = 1' --c 1
expect_bad "v > c 2-D" 'm,vx,vy\n1,0.6,0.8\n1,0,0\n' 'line 2 \(ball 0\), columns vx,vy: \|v\| = 1 >= c = 1' --c 1
expect_bad "m = 0" 'm,vx\n0,0.6\n1,0\n' 'line 2 \(ball 0\), column m: m = 0 must be > 0'
expect_bad "m < 0" 'm,vx\n1,0.6\n-2,0\n' 'line 3 \(ball 1\), column m: m = -2 must be > 0'
expect_bad "m < 0 momentum" 'm,px\n1,0.6\n-2,0\n' 'line 3 \(ball 1\), column m: m = -2'
expect_bad "eps > 1" "$G" '^relcol-collide: --eps: eps = 1.5 outside \[0, 1\]' --eps 1.5
expect_bad "eps < 0" "$G" '--eps: eps = -0.1 outside' --eps -0.1
expect_bad "eps nan" "$G" '--eps: .*not finite' --eps nan
expect_bad "c = 0" "$G" '--c: c = 0 must be > 0' --c 0
expect_bad "c < 0" "$G" '--c: c = -3 must be > 0' --c=-3
expect_bad "c = -inf" "$G" '--c: .*not finite' --c -inf
expect_bad "c nan" "$G" '--c: .*not finite' --c nan
expect_bad "c junk" "$G" "--c: not a number: '1x'" --c 1x
expect_bad "nan field" 'm,vx\n1,0.6\n1,nan\n' "line 3 \(ball 1\), column vx: 'nan' is not finite"
expect_bad "inf field" 'm,vx\ninf,0.6\n1,0\n' "line 2 \(ball 0\), column m: 'inf' is not finite"
expect_bad "overflow field" 'm,vx\n1,1e999\n1,0\n' "line 2 \(ball 0\), column vx: '1e999' is not finite"
expect_bad "junk field" 'm,vx\n1,0.6\n1,abc\n' "line 3 \(ball 1\), column vx: not a number: 'abc'"
expect_bad "trailing junk" 'm,vx\n1,0.6x\n1,0\n' "line 2 \(ball 0\), column vx: not a number: '0.6x'"
expect_bad "overflowing state" 'm,px\n1e140,1e140\n1,0\n' 'line 2 \(ball 0\), columns m,px: too large' --c 1e-100
# magnitudes whose squares would overflow or underflow are refused, naming row and column
expect_bad "huge mass" 'm,px\n1e200,1\n1,0\n' 'line 2 \(ball 0\), column m: 1e\+200 is too large' --c 1
expect_bad "tiny mass" 'm,vx\n1e-170,0.6\n1e-170,-0.6\n' 'line 2 \(ball 0\), column m: 1e-170 is too small' --c 1
expect_bad "tiny speed" 'm,vx\n1,1e-300\n1,-1e-300\n' 'line 2 \(ball 0\), column vx: 1e-300 is too small'
expect_bad "far position" 'm,x,vx\n1,1e308,1\n1,0,-1\n' 'line 2 \(ball 0\), column x: 1e\+308 is too large'
# a normal of any finite length is a direction
run 'm,vx\n1,0.6\n1,-0.6\n' --normal 1e300
[ "$st" -eq 0 ] && grep -q '^1,1,0.59999999999999998' "$T/out" && ok || bad "--normal 1e300: exit $st: $(cat "$T/err")"
run 'm,vx\n1,0.6\n1,-0.6\n' --normal 1e-300
[ "$st" -eq 0 ] && grep -q '^1,1,0.59999999999999998' "$T/out" && ok || bad "--normal 1e-300: exit $st: $(cat "$T/err")"
expect_bad "empty field" 'm,vx,vy\n1,0.6,\n1,0,0\n' 'line 2 \(ball 0\), column vy: empty value'
expect_bad "one row" 'm,vx\n1,0.6\n' 'line 1 \(header\): wrong number of rows: expected exactly 2 data rows \(balls\), found 1'
expect_bad "three rows" 'm,vx\n1,0.6\n1,0\n1,0\n' 'line 4: wrong number of rows: expected exactly 2 .*found 3'
expect_bad "no rows" 'm,vx\n' 'wrong number of rows.*found 0'
expect_bad "empty input" '' 'stdin: empty input'
expect_bad "unknown column" 'm,vx,r\n1,0.6,1\n1,0,1\n' 'line 1 \(header\), column r: unknown column'
expect_bad "missing m" 'mass,vx\n1,0.6\n1,0\n' 'column mass: unknown column'
expect_bad "missing m only" 'vx\n0.6\n0\n' 'line 1 \(header\), column m: missing column'
expect_bad "missing velocity" 'm,x\n1,0\n1,1\n' 'column vx: missing column'
expect_bad "vz without vy" 'm,vx,vz\n1,0.6,0\n1,0,0\n' 'column vz: present without vy'
expect_bad "mixed v and p" 'm,vx,px\n1,0.6,0.6\n1,0,0\n' 'columns vx and px: mixed velocity and momentum'
expect_bad "position dimension" 'm,vx,x,y\n1,0.6,0,0\n1,0,1,0\n' 'columns x,y: 2 position components, but the velocity columns give dimension 1'
expect_bad "field count" 'm,vx\n1,0.6\n1\n' 'line 3: 1 field, but the header \(line 1\) has 2 columns'
expect_bad "repeated column" 'm,vx,vx\n1,0.6,1\n1,0,1\n' 'column vx: repeated column'
expect_bad "zero --normal" "$G" '--normal: zero normal' --normal 0
expect_bad "zero normal positions" 'm,vx,vy,x,y\n1,0.6,0,1,2\n1,0,0,1,2\n' 'line 3 \(ball 1\), columns x,y: zero normal'
expect_bad "--normal too long" "$G" '--normal: 2 components, but the input is 1-D' --normal 1,0
expect_bad "--normal junk" "$G" "--normal: component 2: not a number: 'a'" --normal 1,a
expect_bad "--normal 4 comps" "$G" '--normal: more than 3 components' --normal 1,0,0,0
expect_bad "unknown option" "$G" 'unknown option --frobnicate' --frobnicate 1
expect_bad "missing value" "$G" '--eps: missing value' --eps
expect_bad "positional" "$G" "unexpected argument 'file.csv'" file.csv
expect_bad "unknown law" "$G" "--law: unknown law 'bogus' \(known: zmf, cm-isotropic" --law bogus
expect_bad "bad format" "$G" "--format: unknown format 'xml'" --format xml
expect_bad "alpha with zmf" "$G" '--alpha: only with --law cm-isotropic' --alpha 0.2
expect_bad "alpha in 1-D" "$G" '--alpha: alpha = 0.2, but a 1-D collision is head-on' --law cm-isotropic --alpha 0.2
expect_bad "alpha too big" "$G" '--alpha: \|alpha\| = 2 must be < pi/2' --law cm-isotropic --alpha 2
expect_bad "alpha junk" "$G" "--alpha: not a number: 'x'" --law cm-isotropic --alpha x
expect_bad "alpha and normal" "$G" '--alpha: conflicts with --normal' --law cm-isotropic --alpha 0 --normal 1
expect_bad "seed without random" "$G" '--seed: only with --alpha random' --law cm-isotropic --seed 3
expect_bad "seed junk" "$G" "--seed: not a non-negative integer: '-1'" --law cm-isotropic --alpha random --seed -1
expect_bad "azimuth in 2-D" 'm,vx,vy\n1,0.6,0\n1,0,0\n' '--azimuth: only in 3-D \(the input is 2-D\)' --law cm-isotropic --alpha 0.1 --azimuth 1
expect_bad "azimuth without alpha" "$G" '--azimuth: only with a numeric --alpha' --azimuth 1

# ---------------------------------------------------------------- tolerated input forms
# CRLF line ends, spaces around fields, comment and trailing blank lines, any column order
run '# two balls\r\n vx , m \r\n 0.6 , 1 \r\n0,2\r\n\r\n\n' --c 1
expect_ok "CRLF, spaces, blank lines"
close "CRLF v0" "$(field 0 vx)" "$(awk 'BEGIN { printf "%.17g", -9 / 41 }')" $TOL
# a spreadsheet's "CSV UTF-8" export: byte order mark, CRLF, every header and field quoted
run '\357\273\277"vx","m"\r\n"0.6","1"\r\n"0","2"\r\n' --c 1
expect_ok "BOM, CRLF, quoted header and fields"
close "quoted v0" "$(field 0 vx)" "$(awk 'BEGIN { printf "%.17g", -9 / 41 }')" $TOL
expect_bad "unclosed quote" 'm,vx\n1,"0.6\n0,2\n' 'line 2: a quoted field is not closed' --c 1

# ---------------------------------------------------------------- --help
"$C" --help > "$T/out" 2> "$T/err"
st=$?
[ "$st" -eq 0 ] && grep -q 'kinetic energy p^2/2m' "$T/out" && grep -q 'cm-isotropic' "$T/out" &&
    ok || bad "--help (exit $st)"

summary
