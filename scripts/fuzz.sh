#!/usr/bin/env bash
# fuzz.sh — fuzz the apps' input readers with libFuzzer under ASan and UBSan: any input
# must be read or refused with a message, never crash, hang or hand back a bad number.
#
#   scripts/fuzz.sh [scenario|table|engine] [seconds] [runs]   (default: scenario, 300)
#
# runs: stop after that many inputs (libFuzzer's -runs) if the time is not up first; the
# count it ran is libFuzzer's last line ("Done N runs in S second(s)").
# scenario: relcol-sim's scenario reader (tests/fuzz/fuzz_scenario.c; what it reads must
# write back as a scenario that reads again), from data/scenarios/*.json with a dictionary
# of the schema's keys. table: the CSV reader and ball rows every other app reads
# (tests/fuzz/fuzz_table.c), from data/examples/*.csv. engine: the engine itself on small
# configurations of up to 8 balls on a coarse grid (tests/fuzz/fuzz_engine.c: ties,
# touching balls, simultaneous contacts; every frame; conservation checked), from
# tests/fuzz/engine-seeds/.
# Needs clang with libFuzzer (Debian: clang libclang-rt-14-dev). Builds into
# build-fuzz/TARGET/ and keeps its corpus there; a failing input is left as
# build-fuzz/TARGET/crash-* (replay: build-fuzz/TARGET/fuzz_TARGET that-file). Add it to
# tests/fuzz/regress/ and to tests/fuzz/meson.build so the suite replays it. Exit status:
# libFuzzer's (0: nothing found).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
target=${1:-scenario}
secs=${2:-300}
runs=${3:--1}
case "$target" in
scenario) seeds=("$here"/data/scenarios/*.json); extra=("$here/apps/sim/scenario.c" "$here/apps/sim/scenario_write.c"); libs=(-lcjson) ;;
table) seeds=("$here"/data/examples/*.csv "$here"/tests/fuzz/table-seeds/*.csv); extra=(); libs=() ;;
engine) seeds=("$here"/tests/fuzz/engine-seeds/*); extra=(); libs=() ;;
*) echo "fuzz: target '$target': not scenario, table or engine" >&2; exit 2 ;;
esac
[[ "$secs" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: seconds '$secs': not a positive whole number" >&2; exit 2; }
[[ "$runs" =~ ^(-1|[1-9][0-9]*)$ ]] || { echo "fuzz: runs '$runs': not a positive whole number" >&2; exit 2; }
command -v clang >/dev/null || { echo "fuzz: needs clang and libFuzzer (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
out="$here/build-fuzz/$target"
mkdir -p "$out/corpus"
cp -n "${seeds[@]}" "$out/corpus/" 2>/dev/null || true

# relcol/version.h, as lib/include/relcol/meson.build makes it from project()'s version
ver=$(sed -n "s/^ *version *: *'\([0-9.]*\)'.*/\1/p" "$here/meson.build" | head -1)
[[ "$ver" =~ ^[0-9]+\.[0-9]+\.[0-9]+$ ]] || { echo "fuzz: cannot read the version from meson.build" >&2; exit 2; }
mkdir -p "$out/include/relcol"
IFS=. read -r vmaj vmin vpat <<< "$ver"
sed -e "s/@VERSION@/$ver/" -e "s/@MAJOR@/$vmaj/" -e "s/@MINOR@/$vmin/" -e "s/@PATCH@/$vpat/" \
    "$here/lib/include/relcol/version.h.in" > "$out/include/relcol/version.h"

# the library, the apps' common code and the reader, compiled together with the harness;
# the engine's AVX2 and AVX-512 lanes each for their instruction set (as lib/meson.build)
flags=(-g -O1 -fno-sanitize-recover=undefined -std=c11 -D_GNU_SOURCE -ffp-contract=off
       -I"$out/include" -I"$here/lib/include" -I"$here/lib" -I"$here/apps/common" -I"$here/apps/sim")
clang "${flags[@]}" -fsanitize=fuzzer-no-link,address,undefined -mavx2 \
    -c "$here/lib/engine/lanes_avx2.c" -o "$out/lanes_avx2.o"
clang "${flags[@]}" -fsanitize=fuzzer-no-link,address,undefined -mavx512f -mavx512vl \
    -c "$here/lib/engine/lanes_avx512.c" -o "$out/lanes_avx512.o"
engine=()
for f in "$here"/lib/engine/*.c "$here"/lib/engine/perball/*.c "$here"/lib/contacts/*.c; do
    case "$f" in *lanes_avx*) ;; *) engine+=("$f") ;; esac
done
clang "${flags[@]}" -fsanitize=fuzzer,address,undefined \
    "$here/tests/fuzz/fuzz_$target.c" "${extra[@]}" "$here"/apps/common/*.c "$here"/lib/*.c \
    "${engine[@]}" "$out/lanes_avx2.o" "$out/lanes_avx512.o" \
    "${libs[@]}" -lgsl -lgslcblas -lsundials_cvode -lsundials_nvecserial \
    -lsundials_sunmatrixdense -lsundials_sunlinsoldense -lm -o "$out/fuzz_$target"

# the schema's keys and values, so that mutations make scenarios rather than noise
dict="$out/scenario.dict"
{
    for k in relcol dim box c law restitution ball wall contact_frame tc seed time t_end \
        restart balls generate kind gas rack n radius packing v_rms density speed aim gap \
        outputs dir snapshots every xyz_every plots gif summary r m x v p tau tau_last inf \
        table zmf sphere transport boundary periodic walls image groups simultaneous \
        sequential drop h5md_every xyz_from checkpoint; do
        printf '"\\"%s\\""\n' "$k"
    done
    printf '"%s"\n' true false null 1e308 -0 1e-320 0.45 0.7
} > "$dict"

cd "$out"
dictarg=()
[ "$target" = scenario ] && dictarg=(-dict="$dict")
# allocator_may_return_null: a huge ball count must be refused as out of memory, not abort
ASAN_OPTIONS=allocator_may_return_null=1 "./fuzz_$target" corpus "${dictarg[@]}" \
    -max_len=4096 -timeout=60 -rss_limit_mb=2048 -max_total_time="$secs" -runs="$runs"
