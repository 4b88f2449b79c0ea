#!/bin/sh
# build-figures.sh SRCDIR OUTDIR SWEEP SWEEP_C FRAMES SIM — make the paper's figures with the
# built apps (OUTDIR/figures/NAME/, each app's printed fits in OUTDIR/figures/NAME.txt) and
# copy papers/*.md into OUTDIR, so relcol.md's links figures/... resolve there.
# Run by `ninja -C build paper` (papers/meson.build).
set -eu
src="$1"; out="$2"; sweep="$3"; sweep_c="$4"; frames="$5"; sim="$6"
fig="$out/figures"
mkdir -p "$fig"

run() { # run NAME CMD...: the app's output to figures/NAME.txt, shown on failure
    name="$1"; shift
    echo "paper: $name"
    if ! "$@" > "$fig/$name.txt" 2>&1; then
        cat "$fig/$name.txt" >&2
        echo "paper: $name failed: $*" >&2
        exit 1
    fi
}

# classical-limit convergence of law, time of impact, soft reference and engine run. In an
# MPI build it calls MPI_Init, whose plugin allocations LeakSanitizer reports and no
# suppression can name (as tests/sweep/test_sweep.sh): in a sanitizer build, leak checking
# is off for this one app (ASAN_OPTIONS is ignored otherwise).
run sweep env ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$sweep" --out "$fig/sweep"
# one collision's approach to the classical result (velocities and heat)
run sweep-c "$sweep_c" --example --out "$fig/sweep-c"
# contact-frame dependence: table vs sphere vs zmf
run frames "$frames" --out "$fig/frames"
# engine: a billiard break (classical) and a relativistic hard-disc gas at c = 1 (the
# gas's default run is t = 200; its first 10 time units keep the trajectories readable)
run rack "$sim" --builtin rack --out "$fig/rack"
run gas "$sim" --builtin gas --t-end 10 --out "$fig/gas"

# transport by contact frame over theta (transport.md §12): drawn from the measured CSV, no run
if command -v gnuplot > /dev/null 2>&1; then
    mkdir -p "$fig/tsweep"
    gnuplot -e "csv='$src/../data/reproductions/ghodrat2020.csv'; out='$fig/tsweep/tsweep.png'" \
        "$src/scripts/tsweep.gp"
fi

cp "$src"/*.md "$out"/
if command -v gnuplot > /dev/null 2>&1; then
    echo "paper: $out/relcol.md with figures in $fig"
else
    echo "paper: gnuplot not installed: data and scripts in $fig, no PNGs"
fi
