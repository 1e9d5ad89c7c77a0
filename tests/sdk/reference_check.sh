#!/usr/bin/env bash
# Builds the SDK's API reference (Doxygen, warnings as errors) and checks that it carries the headers'
# comments: a class's, a function's and a member's written after it on its line.
#   reference_check.sh BUILD_DIR
set -euo pipefail

source "$(dirname "$0")/sdk_test_functions.sh"
build=$1
html=$build/sdk-reference/html

step "build the reference"
rm -rf "$build/sdk-reference"
cmake --build "$build" --target sdk-reference

# The text of PAGE (a file of the reference), tags removed, must hold TEXT.
expect_documented() {
  local page=$1 text=$2
  [[ -f $html/$page ]] || fail "the reference has no $page"
  sed "s/<[^>]*>//g" "$html/$page" | grep -F -- "$text" >/dev/null || fail "$page does not say: $text"
  echo "$page: $text"
}

step "the headers' comments are in it"
expect_documented index.html "Where to start"
expect_documented classstrata_1_1Engine.html "Loads pipelines and renders their frames into framebuffers"
expect_documented classstrata_1_1Engine.html "The caller's framebuffer bindings, viewport and clip control"
expect_documented classstrata_1_1PipelineBuilder.html "A pipeline written in code rather than in a file"
expect_documented structstrata_1_1Camera.html "deg, east positive: the point below the eye"
expect_documented classstrata_1_1Layer.html "A layer is a GLSL sampling function over a projection"
