#!/usr/bin/env bash
# Checks the compositor example the way its author would: installs the build tree into a scratch prefix,
# builds sdk/examples/slope_mask against it out of tree, and renders ground of known slopes with the
# INSTALLED strata: the mask must paint exactly the ground steeper than its threshold.
#   slope_mask_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/sdk_test_functions.sh"
set_up_example "$1" "$2" slope_mask

step "the installed strata describes the plugin's compositor"
"$strata" plugins --describe composite.slope_mask | tee "$work/describe.txt"
grep -q 'threshold' "$work/describe.txt" || fail "composite.slope_mask's parameters are not described"

# Two planes tilted north, side by side: over 30W to 30E and 15S to 15N, at 0.1 degree cells, heights rise
# northwards by tan(10 deg) metres per metre west of the prime meridian and by tan(30 deg) east of it. A
# plane's central differences are exact, whatever the footprint, so the slope the mask measures is the
# plane's but for float rounding (heights reach 960 km, a few metres of rounding over differences of a
# footprint's rise, some 2 to 6 km).
step "write two planes of 10 and 30 degrees' slope as a height raster"
awk 'BEGIN {
  print "ncols 600"; print "nrows 300"; print "xllcorner -30"; print "yllcorner -15"; print "cellsize 0.1"
  pi = atan2(0, -1); radius = 6371000
  for (row = 0; row < 300; ++row) {
    latitude = (15 - (row + 0.5) * 0.1) * pi / 180; line = ""
    for (column = 0; column < 600; ++column) {
      slope = column < 300 ? 10 : 30
      line = line sprintf("%.3f ", sin(slope * pi / 180) / cos(slope * pi / 180) * radius * latitude)
    }
    print line
  } }' >"$work/planes.asc"
gdal_translate -q -a_srs "+proj=longlat +R=6371000 +no_defs" "$work/planes.asc" "$work/planes.tif"

# From 2200 km above 0N 0E the planes fill the 320x180 frame (about 19 degrees either side, 9 up and down);
# the prime meridian, where the planes meet, is the middle column. Paint: opaque magenta, which the
# imagery below never has.
cat >"$work/planes.yaml" <<YAML
strata: 1
body: {name: Earth, radius: 6371000}
camera: {lon: 0, lat: 0, altitude: 2.2e6}
nodes:
  imagery: {type: source.gdal, path: /usr/share/xplanet/images/earth.jpg, kind: color}
  planes: {type: source.gdal, path: $work/planes.tif, kind: height}
  steep: {type: composite.slope_mask, height: planes, surface: imagery, threshold: 20, colour: [1, 0, 1], opacity: 1}
  globe: {type: geometry.icosahedral}
  frame: {type: output.image, geometry: globe, surface: [steep], shading: none}
YAML

# How many pixels of the west plane (columns 8 to 149) and of the east one (170 to 311) are painted
# magenta, within 2 levels (the sRGB encoding's rounding). The columns beside the meridian are left out:
# the mask's differences there straddle both planes. Each side counts 142 x 180 = 25,560 pixels.
painted() {
  pixels "$1" | awk '
    { column = (NR - 1) % 320 }
    $1 >= 253 && $2 <= 2 && $3 >= 253 { if (column >= 8 && column < 150) west++; if (column >= 170 && column < 312) east++ }
    END { print west + 0, east + 0 }'
}

# Thresholds a degree either side of each plane's slope: the mask must tell 10 from 9 and 11 degrees and
# 30 from 29 and 31, every pixel of a side painted or none.
for case in "9 25560 25560" "11 0 25560" "29 0 25560" "31 0 0"; do
  read -r threshold west east <<<"$case"
  step "threshold $threshold degrees paints $west pixels of the 10-degree plane and $east of the 30-degree one"
  "$strata" render "$work/planes.yaml" -o "$work/threshold-$threshold.png" --size 320x180 \
    --set nodes.steep.threshold="$threshold"
  read -r paintedWest paintedEast < <(painted "$work/threshold-$threshold.png")
  echo "painted: $paintedWest west, $paintedEast east"
  ((paintedWest == west && paintedEast == east)) ||
    fail "threshold $threshold painted $paintedWest and $paintedEast pixels, not $west and $east"
done

# Where nothing is steep enough the surface must come through untouched: beside the meridian, the frame of
# threshold 31 is the imagery's own frame to the level (both sample it with the same filtering). On the
# meridian the planes' heights jump, some hundreds of kilometres, and the mask rightly paints that cliff.
step "where the ground is not steep the surface shows unchanged"
"$strata" render "$work/planes.yaml" -o "$work/imagery.png" --size 320x180 --set 'nodes.frame.surface=[imagery]'
differing=$(paste -d ' ' <(pixels "$work/threshold-31.png") <(pixels "$work/imagery.png") |
  awk '{ column = (NR - 1) % 320 }
       (column < 150 || column >= 170) && ($1 != $4 || $2 != $5 || $3 != $6) { n++ } END { print n + 0 }')
echo "$differing pixels differ beside the meridian"
((differing == 0)) || fail "$differing pixels differ from the imagery's own frame where nothing is painted"

step "the example's own pipeline renders"
cp "$example/slope_mask.yaml" "$work/"
"$strata" render "$work/slope_mask.yaml" -o "$work/slope_mask.png" --size 320x180
gdalinfo "$work/slope_mask.png" | grep -q '^Size is 320, 180$' || fail "slope_mask.png is not 320x180"
