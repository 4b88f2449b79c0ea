#!/usr/bin/env bash
# web/test.sh SRC BUILD RELCOL_SIM — meson test 'web' (suite web): build the page in
# WebAssembly under BUILD/web-wasm (web/build.sh: installs emscripten and chromium if
# missing), node and node-ws if missing (scripts/setup.sh RELCOL_NODE_PACKAGES: Debian
# packages only, no npm registry), and run web/test_web.mjs against the page headless in
# Debian's /usr/bin/chromium, driven over the DevTools protocol by web/cdp.mjs. The screenshots go next to the test log (BUILD/meson-logs).
# When the tools cannot be had (no root to install them, no network): SKIP (77) if CI is
# not set, a failure under CI.
# web/test.sh SRC BUILD BENCH_ENGINE --bench — meson benchmark 'web': the gas's frame rate
# and the engine's collisions per second in the page against the native bench_engine.
set -uo pipefail
src="$1" build="$2" sim="$3" mode="${4:-}"

cannot() {
    echo "web: $*" >&2
    if [ -n "${CI:-}" ] && [ "${CI:-}" != "false" ]; then
        echo "web: CI is set: this is a failure, not a skip" >&2
        exit 1
    fi
    echo "web: skipped (set CI=true to make this a failure)" >&2
    exit 77
}

site="$(bash "$src/web/build.sh" "$build/web-wasm")"
rc=$?
[ $rc -eq 0 ] || cannot "the WebAssembly build failed or its tools could not be installed (web/build.sh: $rc)"

has_ws() { node -e 'try { require("ws") } catch { require("/usr/share/nodejs/ws") }' >/dev/null 2>&1; }
if ! command -v node >/dev/null 2>&1 || ! has_ws; then
    . "$src/scripts/setup.sh"
    set +e  # setup.sh sets -e; this script reports its own failures through cannot
    relcol_install_list "${RELCOL_NODE_PACKAGES[@]}" >&2 ||
        cannot "node and Debian's node-ws are needed (web/cdp.mjs drives chromium) and could not be installed"
fi
command -v node >/dev/null 2>&1 || cannot "node is needed (web/cdp.mjs drives chromium from node)"
has_ws || cannot "the WebSocket module ws (Debian's node-ws) is needed by web/cdp.mjs"
node -e 'process.exit(Number(process.versions.node.split(".")[0]) >= 18 ? 0 : 1)' ||
    cannot "node >= 18 is needed (found $(node --version))"
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || cannot "no chromium at ${CHROMIUM:-/usr/bin/chromium}"

exec node "$src/web/test_web.mjs" "$site" "$sim" "$build/meson-logs" $mode
