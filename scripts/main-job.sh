#!/usr/bin/env bash
# main-job.sh — README command 1: install what is missing, build, and run the main job:
# the classical-limit sweeps over c — the headline sweep (collision law, time of impact,
# soft reference, a small engine run: relcol-sweep) and the collision law's own sweep
# (relcol-sweep-c) — writing CSV, gnuplot scripts and PNGs into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/setup.sh
relcol_install_packages
relcol_build build --buildtype=release
out="${RELCOL_OUT:-out}"
mkdir -p "$out"
echo "== relcol main job: classical-limit convergence over c (writes $out/sweep/) =="
./build/apps/sweep/relcol-sweep --out "$out/sweep"
echo "== the collision law alone, finer grid (writes $out/sweep-c/) =="
./build/apps/sweep-c/relcol-sweep-c --example --out "$out/sweep-c"
echo "== done: see $out/ =="
