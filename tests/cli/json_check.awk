# json_check.awk — a strict JSON syntax checker in POSIX awk (CI has no python): reads the
# whole input, prints "ok" and exits 0 if it is one valid JSON value, else prints where it
# failed and exits 1. Grammar of RFC 8259; strings may not hold raw control characters.
function fail(msg) { printf "json: %s at offset %d near '%s'\n", msg, pos, substr(s, pos, 20); bad = 1; exit 1 }
function ws() { while (pos <= n && index(" \t\r\n", substr(s, pos, 1)) > 0) pos++ }
function peek() { return substr(s, pos, 1) }
function value(   c) {
    ws(); c = peek()
    if (c == "{") return object()
    if (c == "[") return array()
    if (c == "\"") return string()
    if (c ~ /[-0-9]/) return number()
    if (substr(s, pos, 4) == "true" || substr(s, pos, 4) == "null") { pos += 4; return }
    if (substr(s, pos, 5) == "false") { pos += 5; return }
    fail("expected a value")
}
function object() {
    pos++; ws()
    if (peek() == "}") { pos++; return }
    for (;;) {
        ws(); if (peek() != "\"") fail("expected a key string")
        string(); ws()
        if (peek() != ":") fail("expected ':'")
        pos++; value(); ws()
        if (peek() == ",") { pos++; continue }
        if (peek() == "}") { pos++; return }
        fail("expected ',' or '}'")
    }
}
function array() {
    pos++; ws()
    if (peek() == "]") { pos++; return }
    for (;;) {
        value(); ws()
        if (peek() == ",") { pos++; continue }
        if (peek() == "]") { pos++; return }
        fail("expected ',' or ']'")
    }
}
function string(   c) {
    pos++
    while (pos <= n) {
        c = substr(s, pos, 1)
        if (c == "\"") { pos++; return }
        if (c == "\\") {
            c = substr(s, pos + 1, 1)
            if (c == "u") { if (substr(s, pos + 2, 4) !~ /^[0-9a-fA-F][0-9a-fA-F][0-9a-fA-F][0-9a-fA-F]$/) fail("bad \\u escape"); pos += 6; continue }
            if (index("\"\\/bfnrt", c) == 0) fail("bad escape")
            pos += 2; continue
        }
        if (c < " ") fail("raw control character in a string")
        pos++
    }
    fail("unterminated string")
}
function number(   rest) {
    rest = substr(s, pos)
    if (!match(rest, /^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) fail("bad number")
    pos += RLENGTH
}
{ s = s $0 "\n" }
END {
    if (bad) exit 1
    n = length(s); pos = 1
    value(); ws()
    if (pos <= n) fail("trailing characters")
    print "ok"
}
