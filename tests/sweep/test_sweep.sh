#!/bin/sh
# test_sweep.sh RELCOL_SWEEP HAVE_MPI — relcol-sweep: every fitted order is -2 within 0.05;
# the OpenMP sweep (2 threads) and, in an MPI build, the sweep split over 2 MPI ranks give
# output identical, bit for bit, to the serial sweep; bad options exit 2.
sweep="$1"; have_mpi="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; n=0
ok() { n=$((n + 1)); echo "ok: $1"; }
ko() { n=$((n + 1)); fails=$((fails + 1)); echo "FAILED: $1"; }
args="--points 13 --no-plots"
# In an MPI build the mpirun run calls MPI_Init, and Open MPI keeps allocations in plugins it
# dlopens and unloads (LeakSanitizer then sees "unknown module" frames that no
# suppression can name): leak checking of this program is meaningless there. Address and
# undefined-behaviour checks stay on.
if [ "$have_mpi" = "yes" ]; then
    export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi

OMP_NUM_THREADS=1 "$sweep" $args --out "$tmp/serial" > "$tmp/serial.txt" 2> "$tmp/err" \
    && ok "serial sweep ran" || ko "serial sweep failed: $(cat "$tmp/err")"
cat "$tmp/serial.txt"
# started without a launcher, not an MPI program: nothing on stderr (no runtime messages)
[ ! -s "$tmp/err" ] && ok "serial run: stderr empty" || ko "serial run printed: $(head -3 "$tmp/err")"
orders=$(grep -c '^order' "$tmp/serial.txt")
[ "$orders" -eq 8 ] && ok "8 fitted orders printed" || ko "$orders fitted orders printed, want 8"
bad=$(awk '/^order/ { d = $4 + 2; if (d < 0) d = -d; if (!(d < 0.05)) print }' "$tmp/serial.txt")
[ -z "$bad" ] && ok "every order within 0.05 of -2" || ko "orders off: $bad"
rows=$(wc -l < "$tmp/serial/sweep.csv")
[ "$rows" -eq 15 ] && ok "sweep.csv: header + 13 points + reference" || ko "sweep.csv has $rows lines"

# the figure explains itself (issue 38): one panel per scenario (the soft reference's
# curves are not hidden under the collision law's), each with the (v/c)^2 reference and its
# noise floor in the key, every curve in a colour of its own from a list without yellow
gp=$tmp/serial/sweep.gp
[ "$(grep -c '^set title "' "$gp")" -eq 4 ] && grep -q '^set multiplot layout 2,2' "$gp" \
    && ok "sweep.gp: one panel per scenario" || ko "sweep.gp: not one panel per scenario"
[ "$(grep -c "t '(|v|_{max}/c)^2'" "$gp")" -eq 4 ] && [ "$(grep -c "t 'noise floor " "$gp")" -eq 4 ] \
    && ok "sweep.gp: reference and noise floor in every key" || ko "sweep.gp: reference or floor unnamed"
nolc=$(grep "w lp" "$gp" | grep -v "lc rgb '#" | wc -l)
yellow=$(grep -ci "lc rgb '#\(ff\|e[0-9a-f]\|f[0-9a-f]\)[c-f][0-9a-f]\{3\}'" "$gp")
[ "$nolc" -eq 0 ] && [ "$yellow" -eq 0 ] && ok "sweep.gp: every curve coloured, none yellow" \
    || ko "sweep.gp: $nolc curves in gnuplot's default colours, $yellow yellow"
OMP_NUM_THREADS=2 "$sweep" $args --out "$tmp/omp" > /dev/null 2>&1
cmp -s "$tmp/serial/sweep.csv" "$tmp/omp/sweep.csv" && ok "OpenMP (2 threads) = serial, bit for bit" \
    || ko "OpenMP sweep differs from the serial one"

if [ "$have_mpi" = "yes" ]; then
    OMP_NUM_THREADS=1 timeout 300 mpirun --allow-run-as-root --oversubscribe \
        -np 2 "$sweep" $args --out "$tmp/mpi" > "$tmp/mpi.txt" 2> "$tmp/mpierr"
    cmp -s "$tmp/serial/sweep.csv" "$tmp/mpi/sweep.csv" && ok "MPI (2 ranks) = serial, bit for bit" \
        || ko "MPI sweep differs from the serial one: $(head -5 "$tmp/mpierr")"
    grep -q '^order' "$tmp/mpi.txt" && [ "$(grep -c '^order' "$tmp/mpi.txt")" -eq 8 ] \
        && ok "only rank 0 prints" || ko "MPI output: $(cat "$tmp/mpi.txt")"
    # the option table's parse on every rank, its words from rank 0 only (app_cli.speaks):
    # --help and --version once (a bad option's line is no check of it: mpirun aborts the
    # job at the first non-zero exit and may drop the other ranks' output)
    for w in --help --version; do
        timeout 60 mpirun --allow-run-as-root --oversubscribe -np 2 "$sweep" $w \
            > "$tmp/mpi.txt" 2> "$tmp/mpierr"; st=$?
        k=$(grep -c '^usage: relcol-sweep\|^relcol-sweep (relcol)' "$tmp/mpi.txt")
        [ $st -eq 0 ] && [ "$k" -eq 1 ] && ok "MPI $w: exit 0, printed once" \
            || ko "MPI $w: exit $st, printed $k times"
    done
    timeout 60 mpirun --allow-run-as-root --oversubscribe -np 2 "$sweep" --points 1 \
        > "$tmp/mpi.txt" 2> "$tmp/mpierr"; st=$?
    [ $st -eq 2 ] && grep -q '^relcol-sweep: option --points: ' "$tmp/mpierr" \
        && ok "MPI bad option: exit 2 and its line" \
        || ko "MPI --points 1: exit $st: $(grep '^relcol-sweep' "$tmp/mpierr")"
else
    echo "note: not an MPI build: the MPI identity check does not apply"
fi

for bad in "--grid cubic" "--from 0.5" "--points 1" "--eps 0" "--scenario nope" "--frobnicate"; do
    "$sweep" $bad --out "$tmp/x" > /dev/null 2> "$tmp/err"; st=$?
    [ $st -eq 2 ] && [ "$(wc -l < "$tmp/err")" -eq 1 ] && ok "'$bad' -> exit 2: $(cat "$tmp/err")" \
        || ko "'$bad' -> exit $st: $(cat "$tmp/err")"
done
echo "$((n - fails)) passed, $fails failed"
[ $fails -eq 0 ]
