#!/usr/bin/env bash
# Installs what is missing and builds Strata into build/ (both cores). Extra arguments go to CMake's
# configure step, e.g. -DSTRATA_WERROR=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build "$@" >/dev/null
cmake --build build --parallel "$(nproc)"
