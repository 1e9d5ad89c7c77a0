#!/usr/bin/env bash
# Installs what is missing, builds, and renders pipelines/demo.yaml to out/demo.png, replacing the one an
# earlier run of this script wrote.
# Arguments go to `strata render`, e.g. --size 1920x1080 or --set camera.lon=-60.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/bin/strata render pipelines/demo.yaml -o out/demo.png --overwrite "$@"
