#!/usr/bin/env bash
# Writes GeoTIFFs of the procedural planet observed through several projections (global, north, south,
# healpix, strip; see tests/data/) into OUTDIR, default build/test-data, and geometry.bdam's patches of the EGM96
# geoid (OUTDIR/egm96-bdam, for pipelines/bdam.yaml). Builds strata-make-test-data and strata into build/ first if
# needed (configuring it as scripts/build.sh does).
#   scripts/make-test-data.sh [OUTDIR] [--large WIDTHxHEIGHT]
# --large writes only a global longitude/latitude colour raster of that size, e.g. 40000x20000 for benchmarks.
set -euo pipefail

outdir=""
tool_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --large) [ $# -ge 2 ] || { echo "make-test-data: --large needs WIDTHxHEIGHT" >&2; exit 1; }
             tool_args+=(--large "$2"); shift 2 ;;
    -h|--help) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "make-test-data: unknown option '$1'" >&2; exit 1 ;;
    *) outdir=$(realpath -m "$1"); shift ;;  # relative to where the script was run from
  esac
done
cd "$(dirname "$0")/.."
outdir=${outdir:-build/test-data}

if [ ! -f build/CMakeCache.txt ]; then
  scripts/install-deps.sh
  cmake -S . -B build >/dev/null
fi
cmake --build build --target strata-make-test-data --parallel "$(nproc)" >/dev/null
build/bin/strata-make-test-data "$outdir" "${tool_args[@]}"
if [ ${#tool_args[@]} -eq 0 ]; then
  cmake --build build --target strata --parallel "$(nproc)" >/dev/null
  build/bin/strata build-bdam /usr/share/proj/egm96_15.gtx "$outdir/egm96-bdam" --radius 6371000 --scale 2000 --level 8 \
    --overwrite 2>/dev/null
fi
