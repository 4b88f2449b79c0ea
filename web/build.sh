#!/usr/bin/env bash
# web/build.sh DIR — the page in WebAssembly: install what is missing (Debian's emscripten,
# node-acorn, dpkg-dev, chromium: scripts/setup.sh's RELCOL_WEB_PACKAGES), fetch cJSON's
# source with `apt-get source cjson` (adding deb-src entries for the configured Debian
# suites if there are none), configure DIR with the cross file web/wasm-cross.ini and
# build it. The site is then DIR/web/ (index.html, app.js, relcol_web.js, .wasm).
# Exit status 77 when the tools cannot be installed (not root, no sudo).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
dir="${1:?usage: web/build.sh BUILD_DIR}"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
. "$src/scripts/setup.sh"
relcol_install_list "${RELCOL_WEB_PACKAGES[@]}" || exit 77
# Debian's emcc runs its JavaScript optimiser with the system's node; a node that is not
# Debian's (nodesource) does not look in /usr/share/nodejs, where node-acorn is.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"

deps="$dir/deps"
cjson="$(ls -d "$deps"/cjson-*/ 2>/dev/null | head -n 1 || true)"
if [ -z "$cjson" ] || [ ! -f "$cjson/cJSON.c" ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    if ! grep -rqs '^\(Types: deb-src\|deb-src \)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
        echo "relcol: adding deb-src entries (Debian source packages) for apt-get source" >&2
        if [ -f /etc/apt/sources.list.d/debian.sources ]; then
            sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources |
                $sudo tee /etc/apt/sources.list.d/relcol-deb-src.sources >/dev/null
        else
            grep -h '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' |
                $sudo tee /etc/apt/sources.list.d/relcol-deb-src.list >/dev/null
        fi
        $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    fi
    rm -rf "$deps"
    mkdir -p "$deps"
    (cd "$deps" && apt-get source -qq cjson >/dev/null 2>&1) || {
        echo "relcol: apt-get source cjson failed" >&2; exit 1; }
    cjson="$(ls -d "$deps"/cjson-*/ | head -n 1)"
fi
cjson="${cjson%/}"

if [ ! -f "$dir/build.ninja" ]; then
    meson setup "$dir" "$src" --cross-file "$src/web/wasm-cross.ini" --buildtype=release \
        -Dweb_cjson="$cjson" >/dev/null
fi
meson compile -C "$dir" >/dev/null
echo "$dir/web"
