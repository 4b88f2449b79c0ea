#!/bin/sh
# test_sim_nul.sh RELCOL_SIM — a \u0000 (NUL) inside any JSON string of a scenario or a
# continuation's final.json is refused with exit 2 and one line naming its place (cJSON
# decodes it to a NUL and so cuts the string: "zmf\u0000x" was taken as zmf, an output
# folder "abc\u0000def" was abc/). Every string the reader takes: law, contact_frame,
# groups, checkpoint, c ("inf"), boundary (alone and in a list), generate.kind,
# outputs.dir, and a key; an escaped backslash before u0000 is not a NUL and is read as
# it is (its error, if any, is another).
sim="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }
B='"dim": 2, "box": [10, 10], "t_end": 1, "balls": [{"r": 1, "x": [5, 5], "v": [0.1, 0]}], "outputs": {"plots": false}'
G='"dim": 2, "c": 2, "t_end": 1, "generate": {"kind": "gas", "n": 4, "radius": 1, "packing": 0.1, "v_rms": 0.1}, "outputs": {"plots": false}'
check() { # NAME JSON
    printf '%s\n' "$2" > "$tmp/$1.json"
    "$sim" "$tmp/$1.json" --out "$tmp/o-$1" > /dev/null 2> "$tmp/err"; st=$?
    if [ $st -eq 2 ] && [ "$(wc -l < "$tmp/err")" -eq 1 ] && grep -q 'column [0-9]*: a string holds \\u0000' "$tmp/err" &&
       [ ! -e "$tmp/o-$1" ] && ! ls "$tmp" | grep -q '^abc'; then
        ok
    else
        ko "$1: exit $st: $(cat "$tmp/err")"
    fi
}
check law "{$B, \"law\": \"zmf\\u0000x\"}"
check frame "{$B, \"contact_frame\": \"zmf\\u0000junk\"}"
check groups "{$B, \"groups\": \"simultaneous\\u0000\"}"
check ckpt "{$B, \"checkpoint\": \"final.ckpt\\u0000x\"}"
check c "{$B, \"c\": \"inf\\u0000\"}"
check boundary "{$B, \"boundary\": \"walls\\u0000\"}"
check boundary2 "{$B, \"boundary\": [\"walls\", \"periodic\\u0000\"]}"
check kind "$(echo "{$G}" | sed 's/"gas"/"gas\\u0000x"/')"
check dir "{$B, \"outputs\": {\"dir\": \"$tmp/abc\\u0000def\", \"plots\": false}}"
check key "{$B, \"law\\u0000x\": \"zmf\"}"
check upper "{$B, \"law\": \"zmf\\u0000\"}"
# a continuation's final.json edited to hold one
"$sim" --builtin rack --no-plots --out "$tmp/rack" > /dev/null 2>&1
sed 's/"law":"\([^"]*\)"/"law":"\1\\u0000x"/' "$tmp/rack/final.json" > "$tmp/final-nul.json"
cp "$tmp/rack/final.ckpt" "$tmp/final.ckpt" 2>/dev/null
check final "$(cat "$tmp/final-nul.json")"
# not a NUL: an escaped backslash, then u0000 (the law "zmf\u0000" spelled out is unknown)
printf '%s\n' "{$B, \"law\": \"zmf\\\\u0000\"}" > "$tmp/esc.json"
"$sim" "$tmp/esc.json" --out "$tmp/o-esc" > /dev/null 2> "$tmp/err"; st=$?
[ $st -eq 2 ] && grep -q 'law' "$tmp/err" && ! grep -q 'a string holds' "$tmp/err" && ok ||
    ko "escaped backslash: exit $st: $(cat "$tmp/err")"
echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
