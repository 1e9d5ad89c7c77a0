#!/usr/bin/env bash
# Installs what is missing, builds with warnings as errors, and runs every test; ends with ctest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DSTRATA_WERROR=ON -DSTRATA_BUILD_TESTS=ON
cd build
ctest --output-on-failure --parallel "$(nproc)"
