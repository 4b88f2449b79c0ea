#!/bin/sh
# relcol-shock --gif: an animated GIF with one frame per time (its image descriptors
# counted by gif_frames.py, each after a graphic control extension), renamed into place
# whole (no temporary left); refused with fewer than two times. Skipped (77) without
# gnuplot or python3, which make and read the GIF.
set -u
app="$1"; frames="$2"
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
"$app" --gif --times 100 >"$dir/out" 2>"$dir/err"; rc=$?
{ [ "$rc" = 2 ] && grep -q "\-\-gif: needs at least two \-\-times" "$dir/err"; } || fail "one time -> $rc: $(cat "$dir/err")"
command -v gnuplot >/dev/null && command -v python3 >/dev/null || { echo "no gnuplot or python3: skipped"; exit 77; }
"$app" --out "$dir/g" --gif --seeds 2 --length 600 --width 8 --times 25,50,75,100,125 --bins 20 \
    --quiet 2>"$dir/g.err" || fail "the run: $(cat "$dir/g.err")"
[ -s "$dir/g/profiles.gif" ] || fail "no profiles.gif"
[ -s "$dir/g/profiles_gif.gp" ] || fail "no profiles_gif.gp"
n=$(python3 "$frames" "$dir/g/profiles.gif") || fail "not a whole GIF: $n"
[ "$n" = "5 5" ] || fail "frames and graphic control extensions: $n, not 5 5"
grep -c "set multiplot layout 1,3 title 'relcol-shock: 3-D, t = " "$dir/g/profiles_gif.gp" | grep -qx 5 ||
    fail "not five titled frames in profiles_gif.gp"
ls -a "$dir/g" | grep -q "relcol" && fail "a temporary file left: $(ls -a "$dir/g")"
echo "$fails failed"
[ "$fails" -eq 0 ]
