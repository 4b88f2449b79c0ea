#!/usr/bin/env bash
# web/test.sh SRC BUILD RELCOL_SIM — meson test 'web' (suite web): build the page in
# WebAssembly under BUILD/web-wasm (web/build.sh: installs emscripten and chromium if
# missing), node and npm if missing (scripts/setup.sh RELCOL_NODE_PACKAGES), install
# playwright-core from web/package-lock.json into BUILD/web-node (npm ci;
# no browser download: it drives Debian's /usr/bin/chromium), and run web/test_web.mjs
# against the page headless. The screenshots go next to the test log (BUILD/meson-logs).
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

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    . "$src/scripts/setup.sh"
    set +e  # setup.sh sets -e; this script reports its own failures through cannot
    relcol_install_list "${RELCOL_NODE_PACKAGES[@]}" >&2 ||
        cannot "node and npm are needed (playwright-core drives chromium from node) and could not be installed"
fi
command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 ||
    cannot "node and npm are needed (playwright-core drives chromium from node)"
node -e 'process.exit(Number(process.versions.node.split(".")[0]) >= 18 ? 0 : 1)' ||
    cannot "node >= 18 is needed by playwright-core 1.61 (found $(node --version))"
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || cannot "no chromium at ${CHROMIUM:-/usr/bin/chromium}"

nodedir="$build/web-node"
mkdir -p "$nodedir"
if ! cmp -s "$src/web/package-lock.json" "$nodedir/package-lock.json" ||
   [ ! -f "$nodedir/node_modules/playwright-core/package.json" ]; then
    cp "$src/web/package.json" "$src/web/package-lock.json" "$nodedir/"
    (cd "$nodedir" && npm ci --no-audit --no-fund --loglevel=error >&2) ||
        cannot "npm ci (playwright-core from the npm registry) failed"
fi
# the test imports playwright-core from beside itself
cp "$src/web/test_web.mjs" "$nodedir/"
exec node "$nodedir/test_web.mjs" "$site" "$sim" "$build/meson-logs" $mode
