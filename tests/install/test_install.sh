#!/bin/sh
# test_install.sh MESON BUILD SOURCE CC [PYTHON] — `meson install` into a temporary
# folder (--destdir) and use the toolkit from there, as a user would after installing:
# every app answers --version from the prefix (its RUNPATH finds the installed librelcol,
# no LD_LIBRARY_PATH), relcol-sim runs an installed scenario, the man pages and the
# papers are there, a C program builds with pkg-config against the installed relcol.pc
# and runs, and (with PYTHON) the installed Python package imports and collides.
set -u
MESON=$1 BUILD=$2 SOURCE=$3 CC=$4 PYTHON=${5:-}
T=$(mktemp -d) || exit 1
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
unset LD_LIBRARY_PATH

if ! "$MESON" install -C "$BUILD" --destdir "$T/root" --no-rebuild --quiet > "$T/log" 2>&1; then
    cat "$T/log"; echo "FAIL: meson install"; exit 1
fi
prefix=$("$MESON" introspect "$BUILD" --buildoptions |
         tr '{' '\n' | sed -n 's/.*"name": "prefix", "value": "\([^"]*\)".*/\1/p' | head -1)
[ -n "$prefix" ] || prefix=$(sed -n 's/^prefix=//p' "$BUILD/meson-private/relcol.pc")
P=$T/root$prefix
ver=$(sed -n 's/^#define RELCOL_VERSION "\(.*\)"/\1/p' "$BUILD/lib/include/relcol/version.h")

for app in relcol-collide relcol-toi relcol-frames relcol-sweep-c relcol-sweep relcol-sim relcol-gas relcol-eos relcol-covariance relcol-heat; do
    out=$("$P/bin/$app" --version 2> "$T/err")
    st=$?
    if [ $st -eq 0 ] && [ "$out" = "$app (relcol) $ver" ]; then ok; else
        bad "$app --version from the prefix: exit $st, '$out' $(cat "$T/err")"; fi
    if [ -f "$P/share/man/man1/$app.1" ] || ! command -v help2man > /dev/null; then ok; else
        bad "no man page share/man/man1/$app.1"; fi
done
if readelf -d "$P/bin/relcol-sim" | grep -q 'RUNPATH.*\$ORIGIN/\.\./'; then ok; else
    bad "relcol-sim has no \$ORIGIN-relative RUNPATH: $(readelf -d "$P/bin/relcol-sim" | grep -i path)"; fi

# an installed scenario runs from the prefix
if (cd "$T" && "$P/bin/relcol-sim" "$P/share/relcol/scenarios/rack.json" --t-end 0.5 \
        --out "$T/rack" --no-plots > "$T/out" 2> "$T/err") && [ -s "$T/rack/final.json" ]; then ok
else bad "relcol-sim on share/relcol/scenarios/rack.json: $(cat "$T/err")"; fi
for f in SCENARIO.md papers/relcol.md papers/zmf-law.md scenarios/gas.json examples/stick-0.6.csv; do
    if [ -s "$P/share/relcol/$f" ]; then ok; else bad "share/relcol/$f not installed"; fi
done

# the man pages name the installed scenario format and papers
if ! command -v help2man > /dev/null || { grep -q 'share/relcol/SCENARIO.md' "$P/share/man/man1/relcol-sim.1" &&
        grep -q 'SCENARIO.md' "$P/share/man/man1/relcol-gas.1" && grep -q 'papers/' "$P/share/man/man1/relcol-gas.1"; }; then ok
else bad "the man pages do not name share/relcol/SCENARIO.md and papers/"; fi

# a C program against the installed relcol.pc (its prefix moved to where it now is)
pc=$(find "$P" -name relcol.pc | head -1)
if [ -z "$pc" ]; then bad "relcol.pc not installed"; else
    export PKG_CONFIG_PATH=$(dirname "$pc")
    flags=$(pkg-config --define-variable=prefix="$P" --cflags --libs relcol)
    libdir=$(pkg-config --define-variable=prefix="$P" --variable=libdir relcol)
    # shellcheck disable=SC2086  # (RELCOL_EXTRA_CFLAGS: words, e.g. -fsanitize=address,undefined)
    if "$CC" -std=c11 -Wall -Werror ${RELCOL_EXTRA_CFLAGS:-} "$SOURCE/tests/install/version_check.c" -o "$T/vc" \
            $flags -Wl,-rpath,"$libdir" 2> "$T/err"; then
        out=$("$T/vc")
        case "$out" in
            "relcol $ver (headers $ver): success, m = 1.25 1.25") ok ;;
            *) bad "pkg-config program printed '$out'" ;;
        esac
        if ldd "$T/vc" | grep -q "$libdir/librelcol"; then ok; else
            bad "the program did not load the installed librelcol: $(ldd "$T/vc" | grep relcol)"; fi
    else
        bad "cc with pkg-config relcol: $(cat "$T/err")"
    fi
fi

# the installed Python package (found by its install folder only, no build tree)
if [ -n "$PYTHON" ]; then
    init=$(find "$P" -path '*/relcol/__init__.py' | head -1)
    if [ -z "$init" ]; then bad "the Python package is not installed"; else
        out=$(cd "$T" && PYTHONPATH=$(dirname "$(dirname "$init")") "$PYTHON" -c '
import relcol
r = relcol.collide(1.0, [0.75], 1.0, [-0.75], [1.0], c=1, eps=0)
print(relcol.__version__, relcol.__file__, r.m0)' 2>&1)
        case "$out" in
            "$ver $P/"*" 1.25") ok ;;
            *) bad "installed Python package: $out" ;;
        esac
    fi
fi

echo "install: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
