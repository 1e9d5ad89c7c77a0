#!/usr/bin/env bash
# Checks the SDK the way a plugin author uses it: installs the build tree into a scratch prefix, builds
# sdk/examples/graticule against that prefix out of tree (find_package(Strata)), and runs the INSTALLED
# strata with the example plugin on STRATA_PLUGIN_PATH; builds it once more with pkg-config's flags alone.
# Catches install rules, the package configs and the installed headers drifting from what an out-of-tree
# plugin needs.
#   graticule_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/sdk_test_functions.sh"
set_up_example "$1" "$2" graticule

step "the installed strata loads its built-in plugins from $prefix and the example from the build"
"$strata" plugins | tee "$work/plugins.txt"
for module in source-gdal geometry-icosahedral output-image; do
  grep -q " $prefix/lib/strata/plugins/strata-$module.so\$" "$work/plugins.txt" ||
    fail "strata-$module.so was not loaded from $prefix/lib/strata/plugins"
done
grep -q "^source.graticule " "$work/plugins.txt" || fail "source.graticule is not listed"

# Without CMake: the same source built by the compiler alone with pkg-config's flags (strata.pc), loaded
# in place of the CMake build.
step "build the example with pkg-config instead, and load that"
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
pkg-config --modversion strata
mkdir "$work/pkg-config"
# shellcheck disable=SC2046  # the flags are words
c++ -std=c++20 -shared -fPIC -fvisibility=hidden -Werror "$example/graticule_source.cpp" \
  $(pkg-config --cflags --libs strata) -o "$work/pkg-config/strata-graticule.so"
STRATA_PLUGIN_PATH=$work/pkg-config "$strata" plugins >"$work/pkg-config/plugins.txt"
grep -q "^  graticule .* $work/pkg-config/strata-graticule.so\$" "$work/pkg-config/plugins.txt" ||
  fail "strata did not load the graticule plugin built with pkg-config's flags"

step "describe source.graticule"
"$strata" plugins --describe source.graticule | tee "$work/describe.txt"
grep -Eq '^  spacing +real +default 30 ' "$work/describe.txt" || fail "no 'spacing' parameter with default 30"

step "render the example pipeline"
"$strata" render "$example/graticule.yaml" -o "$prefix/g.png" --size 320x180
[[ -f $prefix/g.png ]] || fail "no $prefix/g.png"
gdalinfo "$prefix/g.png" | tee "$work/gdalinfo.txt" | grep -q '^Size is 320, 180$' || {
  cat "$work/gdalinfo.txt"
  fail "g.png is not 320x180"
}

# output.image averages overlapping layers by coverage, so over imagery a line is half graticule, half
# imagery, and never exactly the graticule colour. Alone and unlit, the grid shows its colour exactly where
# it has coverage and the empty-surface grey (0.18 linear, 118 in sRGB) where it has none.
step "the grid alone, unlit: its colour on lines, empty grey between them"
"$strata" render "$example/graticule.yaml" -o "$work/grid.png" --size 320x180 \
  --set 'nodes.frame.surface=[grid]' --set nodes.frame.shading=none
# [1, 0.85, 0.2] linear is (255, 237, 124) in sRGB. The texels are half floats (11-bit mantissa, under 0.1%
# error) divided by their coverage after filtering, then encoded to 8 bits: within 2 levels of 255.
lines=$(count_near "$work/grid.png" 255 237 124 2)
gaps=$(count_near "$work/grid.png" 118 118 118 1)
echo "pixels in the graticule colour: $lines; empty grey: $gaps"
# The globe covers about 9,000 of the 57,600 pixels: on llvmpipe some 2,600 of them show a line and 6,600
# the gaps between lines. The bounds leave room for other GPUs' filtering, not for a missing grid.
((lines >= 1000)) || fail "only $lines pixels have the graticule colour (255, 237, 124)"
((gaps >= 3000)) || fail "only $gaps pixels show the empty surface between the lines"

step "over imagery the grid changes only the pixels near its lines"
"$strata" render "$example/graticule.yaml" -o "$work/imagery.png" --size 320x180 \
  --set 'nodes.frame.surface=[imagery]'
changed=$(paste -d ' ' <(pixels "$prefix/g.png") <(pixels "$work/imagery.png") |
  awk '$1 != $4 || $2 != $5 || $3 != $6 { n++ } END { print n + 0 }')
echo "pixels the grid changed: $changed (lines alone: $lines)"
((changed >= lines / 2 && changed <= 2 * lines)) || fail "the grid changed $changed pixels, expected about $lines"

step "passed"
