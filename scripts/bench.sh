#!/usr/bin/env bash
# Builds the benchmarks into build/ (configuring it as scripts/make-test-data.sh does) and runs each of
# build/bin/strata-bench-* on one large raster: STRATA_BENCH_RASTER names the global colour GeoTIFF
# scripts/make-test-data.sh --large writes into OUTDIR (default build/bench-data), and STRATA_BENCH_COG
# the Cloud Optimized GeoTIFF strata tile makes of it there; each is made unless it is there.
#   scripts/bench.sh [--large WIDTHxHEIGHT] [--out OUTDIR] [-- BENCHMARK_FLAGS...]
# --large defaults to 40000x20000. Flags after -- go to every benchmark, e.g. -- --benchmark_format=json.
# What each benchmark measures, and results: docs/benchmarks.md.
set -euo pipefail

large=40000x20000
outdir=""
bench_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --large) [ $# -ge 2 ] || { echo "bench: --large needs WIDTHxHEIGHT" >&2; exit 1; }
             large=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || { echo "bench: --out needs a directory" >&2; exit 1; }
           outdir=$(realpath -m "$2"); shift 2 ;;  # relative to where the script was run from
    --) shift; bench_args=("$@"); break ;;
    -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench: unknown argument '$1' (see --help)" >&2; exit 1 ;;
  esac
done
# The raster's file name is made from the size as given, so it must be the form the tool writes.
[[ $large =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "bench: --large wants WIDTHxHEIGHT, e.g. 40000x20000" >&2; exit 1; }
cd "$(dirname "$0")/.."
outdir=${outdir:-build/bench-data}

if [ ! -f build/CMakeCache.txt ]; then
  scripts/install-deps.sh
  cmake -S . -B build >/dev/null
fi
cmake --build build --target strata-benchmarks --parallel "$(nproc)" >/dev/null

raster="$outdir/global-$large-color.tif"
cog="$outdir/global-$large-color-cog.tif"
[ -f "$raster" ] || scripts/make-test-data.sh "$outdir" --large "$large"
[ -f "$cog" ] || build/bin/strata tile "$raster" "$cog"
status=0
for benchmark in build/bin/strata-bench-*; do
  echo "== $benchmark"
  STRATA_BENCH_RASTER="$raster" STRATA_BENCH_COG="$cog" "$benchmark" "${bench_args[@]}" ||
    { echo "bench: $benchmark failed" >&2; status=1; }
done
exit $status
