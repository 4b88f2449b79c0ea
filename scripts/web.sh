#!/usr/bin/env bash
# web.sh — README command 3: build the browser page (librelcol in WebAssembly: web/build.sh
# installs emscripten if missing and builds into $RELCOL_WEB_BUILD, default build-web) and
# serve it on localhost with python3's http.server, printing the address. Nothing is
# fetched by the page: it runs offline. PORT (default 8020) picks the port.
set -euo pipefail
cd "$(dirname "$0")/.."
port="${PORT:-8020}"
site="$(bash web/build.sh "${RELCOL_WEB_BUILD:-build-web}")"
echo "relcol: serving $site"
echo "relcol: open http://127.0.0.1:$port/ (Ctrl-C stops the server)"
cd "$site"
exec python3 -m http.server "$port" --bind 127.0.0.1
