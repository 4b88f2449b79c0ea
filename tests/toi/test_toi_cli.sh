#!/bin/sh
# test_toi_cli.sh — relcol-toi through its command line: the issue's head-on case (t = 7,
# uncontracted 20/3), the wall at 0.8 r, "miss" with exit 0, c = inf equal to the sphere
# frame byte for byte, and bad input: exit 2, empty stdout, one stderr line naming the
# row/column (or option) and the reason; overlapping shapes are an error.
# Usage: test_toi_cli.sh PATH/relcol-toi
C=${1:?usage: test_toi_cli.sh relcol-toi}
. "$(dirname "$0")/../cli/harness.sh"

# field COLUMN: the value in the one data row of the CSV on stdout
field() {
    awk -F, -v col="$1" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i }
        NR == 2 { if (!(col in h)) { print "nocol"; exit } print $h[col] }' "$T/out"
}

# Head-on, c = 1, r = 1: contracted to 0.8 along x, they touch at 10 - 1.2 t = 1.6, t = 7.
# Tolerance 1e-14: the velocity -> momentum -> velocity round trip costs a few ulp.
HEAD='r,x,vx\n1,0,0.6\n1,10,-0.6\n'
run "$HEAD" --c 1
expect_ok head-on
close head-on-t "$(field t)" 7 1e-14
close head-on-cx "$(field cx)" 5 1e-14
close head-on-nx "$(field nx)" 1 1e-15
[ "$(head -1 "$T/out")" = "t,cx,nx" ] && ok || bad "1-D header: $(head -1 "$T/out")"
run "$HEAD" --c 1 --frame zmf
close head-on-zmf "$(field t)" 7 1e-14
run "$HEAD" --c 1 --frame sphere
close head-on-sphere "$(field t)" 6.666666666666667 1e-14
# the same pair in 3-D along z, given by momentum (p = gamma m v = 0.75)
run 'r,m,x,y,z,px,py,pz\n1,1,0,0,0,0,0,0.75\n1,1,0,0,10,0,0,-0.75\n' --c 1
expect_ok head-on-3d
close head-on-3d-t "$(field t)" 7 1e-14
[ "$(head -1 "$T/out")" = "t,cx,cy,cz,nx,ny,nz" ] && ok || bad "3-D header: $(head -1 "$T/out")"

# Wall: a ball at 0.6 c touches the wall when its centre is 0.8 r away: 9.2 - 0.8 = 8.4.
run 'r,x,y,vx,vy\n1,0,0,0.6,0\n' --c 1 --wall -5,9.2,-3,3
expect_ok wall
close wall-t "$(field t)" 14 1e-14
[ "$(field side)" = x1 ] && ok || bad "wall side: $(field side)"
[ "$(head -1 "$T/out")" = "t,cx,cy,nx,ny,side" ] && ok || bad "wall header: $(head -1 "$T/out")"
run 'r,x,y,vx,vy\n1,0,0,0,-0.6\n' --c 1 --wall -5,9.2,-3,3
close wall-y0 "$(field t)" 3.6666666666666667 1e-14
[ "$(field side)" = y0 ] && ok || bad "wall side y0: $(field side)"
run 'r,x,y,vx,vy\n1,0,0,0,-0.6\n' --c 1 --wall -5,9.2,-3,3 --frame sphere
close wall-sphere "$(field t)" 3.3333333333333333 1e-14

# Misses: stdout is exactly "miss", exit 0.
run 'r,x,y,vx,vy\n1,0,0,0.6,0\n1,10,3,-0.6,0\n' --c 1
expect_ok miss
[ "$(cat "$T/out")" = miss ] && ok || bad "miss output: $(cat "$T/out")"
# touching but separating (contracted gap 1.6): a miss
run 'r,x,vx\n1,0,-0.6\n1,1.6,0.6\n' --c 1
[ "$st" -eq 0 ] && [ "$(cat "$T/out")" = miss ] && ok || bad "touching-separating: $st $(cat "$T/out")"
# touching and approaching: contact now
run 'r,x,vx\n1,0,0.6\n1,1.6,-0.6\n' --c 1
[ "$st" -eq 0 ] && [ "$(field t)" = 0 ] && ok || bad "touching-approaching: $st $(cat "$T/out")"
# bounding spheres hit but the contracted shapes miss (A along +y, B along +x at 0.99 c:
# offset 1.6 across w, between the contracted half-width 1.43 and the spheres' 2)
run 'r,x,y,vx,vy\n1,0,0,0,0.99\n1,-5.9396969619669,8.2024386526137,0.99,0\n' --c 1
[ "$(cat "$T/out")" = miss ] && ok || bad "contracted miss: $(cat "$T/out")"
run 'r,x,y,vx,vy\n1,0,0,0,0.99\n1,-5.9396969619669,8.2024386526137,0.99,0\n' --c 1 --frame sphere
[ "$(cat "$T/out")" != miss ] && ok || bad "sphere frame should hit"

# c = inf: every frame prints the sphere result byte for byte
IN='r,x,y,vx,vy\n0.7,0.3,-0.2,1.1,0.3\n1.2,9,1,-2,0.1\n'
run "$IN" --frame sphere
cp "$T/out" "$T/sphere"
for fr in table zmf; do
    run "$IN" --frame $fr
    cmp -s "$T/out" "$T/sphere" && ok || bad "c = inf, frame $fr differs from sphere"
done

# Bad input and options.
expect_bad nan-field 'r,x,vx\n1,0,0.6\n1,abc,-0.6\n' 'line 3 \(ball 1\), column x: not a number' --c 1
expect_bad missing-r 'x,vx\n0,0.6\n10,-0.6\n' 'column r: missing column'
expect_bad missing-x 'r,vx\n1,0.6\n1,-0.6\n' 'column x: missing column'
expect_bad huge-radius 'r,x,vx\n1e300,0,0.5\n1,10,-0.5\n' 'line 2 \(ball 0\), column r: 1e\+300 is too large' --c 1
expect_bad tiny-radius 'r,x,vx\n1e-300,0,0.5\n1,10,-0.5\n' 'line 2 \(ball 0\), column r: 1e-300 is too small'
expect_bad r-negative 'r,x,vx\n1,0,0.6\n-1,10,-0.6\n' 'line 3 \(ball 1\), column r: r = -1 must be > 0'
expect_bad r-zero 'r,x,vx\n0,0,0.6\n1,10,-0.6\n' 'line 2 \(ball 0\), column r: r = 0 must be > 0'
expect_bad v-ge-c 'r,x,vx\n1,0,1.5\n1,10,-0.6\n' 'line 2 \(ball 0\), column vx: .*>= c' --c 1
expect_bad three-rows 'r,x,vx\n1,0,0.6\n1,10,-0.6\n1,20,0\n' 'line 4: wrong number of rows'
expect_bad one-row 'r,x,vx\n1,0,0.6\n' 'wrong number of rows'
expect_bad two-rows-wall 'r,x,vx\n1,0,0.6\n1,5,0\n' 'wrong number of rows' --wall -10,10
expect_bad unknown-col 'r,x,vx,q\n1,0,0.6,1\n1,10,-0.6,1\n' 'column q: unknown column'
expect_bad px-without-m 'r,x,px\n1,0,0.6\n1,10,-0.6\n' 'column m: missing column'
expect_bad m-zero 'r,m,x,px\n1,0,0,0.6\n1,1,10,-0.6\n' 'line 2 \(ball 0\), column m: m = 0 must be > 0'
expect_bad pos-dim 'r,x,y,vx\n1,0,0,0.6\n1,10,0,-0.6\n' 'position component'
expect_bad inf-field 'r,x,vx\n1,inf,0.6\n1,10,-0.6\n' 'line 2 \(ball 0\), column x:'
expect_bad overlap 'r,x,vx\n1,0,0.6\n1,1.5,-0.6\n' 'balls 0 and 1.*overlap' --c 1
expect_bad overlap-classical 'r,x,vx\n1,0,0.6\n1,1.9,-0.6\n' 'overlap'
expect_bad outside-box 'r,x,vx\n1,9.5,0.6\n' 'ball 0.*box' --wall -10,10
expect_bad frame 'r,x,vx\n1,0,0.6\n1,10,-0.6\n' "--frame: unknown frame 'foo'" --frame foo
expect_bad c-neg 'r,x,vx\n1,0,0.6\n1,10,-0.6\n' '--c: c = -1 must be > 0' --c -1
expect_bad c-text 'r,x,vx\n1,0,0.6\n1,10,-0.6\n' '--c: not a number' --c fast
expect_bad wall-odd 'r,x,vx\n1,0,0.6\n' '--wall: 3 numbers' --wall 0,1,2
expect_bad wall-order 'r,x,vx\n1,0,0.6\n' '--wall: x0 = 5 must be < x1 = -5' --wall 5,-5
expect_bad wall-dim 'r,x,vx\n1,0,0.6\n' '--wall: 2 axes, but the input is 1-D' --wall -5,5,-5,5
expect_bad option 'r,x,vx\n1,0,0.6\n1,10,-0.6\n' 'unknown option --law' --law zmf
expect_bad empty '' 'stdin'

run '' --help
[ "$st" -eq 0 ] && grep -q 'usage: relcol-toi' "$T/out" && ok || bad "--help"

summary cli-toi
