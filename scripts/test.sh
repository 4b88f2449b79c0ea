#!/usr/bin/env bash
# test.sh — README command 2: install what is missing, build, run the whole test suite.
# Extra arguments go to `meson setup` (e.g. -Db_sanitize=address,undefined) and
# RELCOL_BUILD names the build folder (default: build).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/setup.sh
relcol_install_packages
dir="${RELCOL_BUILD:-build}"
relcol_build "$dir" "$@"
# RELCOL_TIMEOUT_MULTIPLIER stretches every test's time limit (a loaded or emulated machine);
# RELCOL_TEST_ARGS goes to meson test (CI's sanitizer build: --no-suite slow)
# shellcheck disable=SC2086
meson test -C "$dir" --print-errorlogs --num-processes "$(nproc)" \
    --timeout-multiplier "${RELCOL_TIMEOUT_MULTIPLIER:-1}" ${RELCOL_TEST_ARGS:-}
