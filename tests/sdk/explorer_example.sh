#!/usr/bin/env bash
# Checks the domain viewer example the way its author would: installs the build tree into a scratch prefix,
# builds sdk/examples/explorer (an application with its own GLFW window and Dear ImGui panel) against it out
# of tree, runs it under Xvfb and checks its screenshots: the planet it shows is the frame the installed
# strata renders with the same settings, and its panel is drawn over it.
#   explorer_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/sdk_test_functions.sh"
set_up_example "$1" "$2" explorer mars-explorer
explorer=$work/explorer/mars-explorer
pipeline=$example/mars_explorer.yaml
# The explorer must find the install's plugins beside the libstrata_core it links, as a host application
# built against an install does, with nothing on the plugin path.
unset STRATA_PLUGIN_PATH

step "the explorer links the installed libstrata_core"
ldd "$explorer" | tee "$work/ldd.txt"
grep -q "$prefix/lib/libstrata_core" "$work/ldd.txt" || fail "mars-explorer does not link $prefix/lib/libstrata_core"

step "a wrong option is refused with the usage"
if "$explorer" "$pipeline" --frames none 2>"$work/usage.txt"; then fail "--frames none was accepted"; fi
cat "$work/usage.txt"
grep -q "usage: mars-explorer" "$work/usage.txt" || fail "no usage text for a wrong option"

# Explorer NAME ARGUMENTS...: the explorer under Xvfb, 640x360, started with the arguments, its window
# written to NAME.png.
explorer_shot() {
  local name=$1
  shift
  xvfb-run -a -s "-screen 0 1024x768x24" "$explorer" "$@" --size 640x360 --screenshot "$work/$name.png"
}

# Screenshot NAME SETTINGS...: the same with mars_explorer.yaml.
screenshot() {
  local name=$1
  shift
  explorer_shot "$name" "$pipeline" "$@"
}

# Reference OVERRIDES... into NAME.png: the installed strata's headless frame of the same scene.
reference() {
  local name=$1
  shift
  "$strata" render "$pipeline" -o "$work/$name.png" --size 640x360 "$@"
}

# The mean difference per channel of two frames in columns BEGIN to END (exclusive), in levels.
mean_difference() {
  paste -d ' ' <(pixels "$1") <(pixels "$2") | awk -v begin="$3" -v end="$4" '
    { column = (NR - 1) % 640 }
    column >= begin && column < end { for (c = 1; c <= 3; ++c) { d = $c - $(c + 3); sum += d < 0 ? -d : d }; n += 3 }
    END { printf "%.2f\n", sum / n }'
}

at_most() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b) }'; }

# The panel sits at the top left and is under 300 pixels wide; right of column 320 the window shows the
# engine's frame alone. The explorer's and strata's frames come from the same engine and pipeline, one on a
# GLX window's context and one on a headless EGL one; on llvmpipe they agree to the level (measured 0.00).
# The bound, half a level, leaves room for a driver that rounds its two contexts' framebuffers apart.
expect_same_planet() {
  local shot=$1 ref=$2 mean
  mean=$(mean_difference "$work/$shot.png" "$work/$ref.png" 320 640)
  echo "right half: mean difference $mean levels from strata render"
  at_most "$mean" 0.5 || fail "$shot.png shows another frame than strata render ($mean levels apart)"
}

step "the explorer's window shows the scene strata renders, with its panel over the top left"
screenshot start
reference start-reference
gdalinfo "$work/start.png" | grep -q '^Size is 640, 360$' || fail "start.png is not 640x360"
expect_same_planet start start-reference
# Where the panel is, the window differs from the bare frame: measured 21.9 levels on average.
panel=$(mean_difference "$work/start.png" "$work/start-reference.png" 10 200)
echo "left: mean difference $panel levels from strata render"
at_most 10 "$panel" || fail "no panel drawn over the top left (only $panel levels from the bare frame)"

# The sample scene built in code (sample_scene.cpp) is mars_explorer.yaml's pipeline: the same engine on
# the same kind of context draws the same window, panel included, to the level (bound 0).
step "the explorer with no file shows the sample scene it builds in code, the scene of mars_explorer.yaml"
explorer_shot built
built=$(mean_difference "$work/built.png" "$work/start.png" 0 640)
echo "whole window: mean difference $built levels from the file's"
at_most "$built" 0 || fail "the scene built in code differs from mars_explorer.yaml's ($built levels apart)"

# Each control changes the scene as the same change made with --set does, and changes what is seen: by at
# least a level on average, where the same scene measures 0.00 (measured 3.84 with the dust hidden, 2.39 in
# July, 49.7 from closer).
for case in "hidden --hide dust -- --set nodes.frame.surface=[terrain]" \
            "summer --date 2030-07-15 -- --set date=2030-07-15" \
            "closer --altitude 2.0e6 -- --set camera.altitude=2.0e6"; do
  name=${case%% *}
  settings=${case#* }
  read -ra options <<<"${settings%% -- *}"
  read -ra overrides <<<"${settings#* -- }"
  step "$name: the explorer started with ${options[*]} shows what strata renders with ${overrides[*]}"
  screenshot "$name" "${options[@]}"
  reference "$name-reference" "${overrides[@]}"
  expect_same_planet "$name" "$name-reference"
  changed=$(mean_difference "$work/$name.png" "$work/start.png" 320 640)
  echo "right half: $changed levels from the first screenshot"
  at_most 1 "$changed" || fail "${options[*]} changed the scene by only $changed levels"
done

step "a layer the pipeline does not have is refused, naming it"
if screenshot none --hide nothing 2>"$work/nothing.txt"; then fail "--hide nothing was accepted"; fi
cat "$work/nothing.txt"
grep -q "no layer 'nothing'" "$work/nothing.txt" || fail "the message does not name the layer"
