#!/usr/bin/env bash
# Builds one libFuzzer target with clang, AddressSanitizer and UndefinedBehaviorSanitizer in build-fuzz/, and
# runs it for SECONDS (default 600) on its seed corpus (docs/fuzzing.md). New inputs go to a scratch corpus in
# build-fuzz/fuzz-runs/NAME, never into the repository; crashes, leaks and timeouts land in its crashes/.
# Arguments after SECONDS go to libFuzzer (-jobs=2, -only_ascii=1, ...).
#   scripts/fuzz.sh pipeline|raster_page|bdam_patch [SECONDS] [LIBFUZZER-OPTION...]
set -euo pipefail
name=${1:?usage: scripts/fuzz.sh pipeline|raster_page|bdam_patch [SECONDS] [LIBFUZZER-OPTION...]}
seconds=${2:-600}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STRATA_FUZZ_BUILD:-$root/build-fuzz}
[[ -d $root/tests/fuzz/corpus/$name ]] || { echo "fuzz.sh: no target '$name' (pipeline, raster_page, bdam_patch)" >&2; exit 2; }

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DSTRATA_FUZZ=ON -DSTRATA_SANITIZERS=address,undefined -DSTRATA_BUILD_TESTS=OFF \
  -DSTRATA_BUILD_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "$(nproc)" --target "strata_fuzz_$name"

runs=$build/fuzz-runs/$name
mkdir -p "$runs/corpus" "$runs/crashes"
options=(-max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1
         -artifact_prefix="$runs/crashes/")
[[ -f $root/tests/fuzz/$name.dict ]] && options+=(-dict="$root/tests/fuzz/$name.dict")
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
echo "fuzz.sh: crashes land in $runs/crashes/"
status=0
"$build/bin/strata_fuzz_$name" "${options[@]}" "${@:3}" "$runs/corpus" "$root/tests/fuzz/corpus/$name" || status=$?
echo "fuzz.sh: crashes land in $runs/crashes/ ($(find "$runs/crashes" -type f | wc -l) there now)"
exit "$status"
