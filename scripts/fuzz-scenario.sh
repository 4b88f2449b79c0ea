#!/usr/bin/env bash
# fuzz-scenario.sh — fuzz relcol-sim's scenario reader (tests/fuzz/fuzz_scenario.c) with
# libFuzzer under ASan and UBSan: any input must be read or refused with a message, and
# whatever is read must write back as a scenario that reads again.
#
#   scripts/fuzz-scenario.sh [seconds]      (default 300)
#
# Needs clang with libFuzzer (Debian: clang libclang-rt-14-dev). Builds into
# build-fuzz/, starts from data/scenarios/*.json with a dictionary of the schema's keys,
# keeps its corpus in build-fuzz/corpus; a failing input is left as build-fuzz/crash-*
# (replay: build-fuzz/fuzz_scenario build-fuzz/crash-...). Exit status: libFuzzer's (0:
# nothing found).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
secs=${1:-300}
[[ "$secs" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz-scenario: seconds '$secs': not a positive whole number" >&2; exit 2; }
command -v clang >/dev/null || { echo "fuzz-scenario: needs clang and libFuzzer (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
out="$here/build-fuzz"
mkdir -p "$out/corpus"
cp -n "$here"/data/scenarios/*.json "$out/corpus/" 2>/dev/null || true

# the library, the apps' common code and the reader, compiled together with the harness
clang -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -std=c11 -D_GNU_SOURCE -ffp-contract=off \
    -I"$here/lib/include" -I"$here/lib" -I"$here/apps/common" -I"$here/apps/sim" \
    "$here/tests/fuzz/fuzz_scenario.c" "$here/apps/sim/scenario.c" "$here/apps/sim/frames.c" \
    "$here"/apps/common/*.c "$here"/lib/*.c \
    -lcjson -lgsl -lgslcblas -lsundials_cvode -lsundials_nvecserial \
    -lsundials_sunmatrixdense -lsundials_sunlinsoldense -lm -o "$out/fuzz_scenario"

# the schema's keys and values, so that mutations make scenarios rather than noise
dict="$out/scenario.dict"
{
    for k in relcol dim box c law restitution ball wall contact_frame tc seed time t_end \
        restart balls generate kind gas rack n radius packing v_rms density speed aim gap \
        outputs dir snapshots every xyz_every plots gif summary r m x v p tau tau_last inf \
        table zmf sphere; do
        printf '"\\"%s\\""\n' "$k"
    done
    printf '"%s"\n' true false null 1e308 -0 1e-320 0.45 0.7
} > "$dict"

cd "$out"
# allocator_may_return_null: a huge ball count must be refused as out of memory, not abort
ASAN_OPTIONS=allocator_may_return_null=1 ./fuzz_scenario corpus -dict="$dict" \
    -max_len=4096 -timeout=10 -rss_limit_mb=2048 -max_total_time="$secs"
