#!/usr/bin/env bash
# Installs what is missing, builds Strata under a sanitizer preset of CMakePresets.json (asan-ubsan or tsan,
# in build-PRESET/) and runs the unit and render tests there (docs/robustness.md, "Sanitizers"). The e2e,
# window and SDK tests start whole programs and compilers; they run in the plain build (scripts/test.sh).
# Extra arguments go to ctest, e.g. -R Paging to run fewer tests, or -LE render to leave out the GL ones.
#   scripts/test-sanitized.sh asan-ubsan|tsan [CTEST-OPTION...]
set -euo pipefail
preset=${1:?usage: scripts/test-sanitized.sh asan-ubsan|tsan [CTEST-OPTION...]}
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" --parallel "$(nproc)"
ctest --preset "$preset" --parallel "$(nproc)" --exclude-regex '^(e2e\.|window_|sdk_)' "${@:2}"
