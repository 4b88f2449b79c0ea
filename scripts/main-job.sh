#!/usr/bin/env bash
# main-job.sh — README command 1: install what is missing, build, and run the main job:
# the classical-limit sweep over c, writing CSV, gnuplot scripts and PNGs into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/setup.sh
relcol_install_packages
relcol_build build --buildtype=release
out="${RELCOL_OUT:-out}"
mkdir -p "$out"
echo "== relcol main job: classical-limit sweep over c (writes $out/sweep-c/) =="
./build/apps/sweep-c/relcol-sweep-c --example --out "$out/sweep-c"
echo "== done: see $out/ =="
