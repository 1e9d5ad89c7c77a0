#!/usr/bin/env bash
# Checks the projection example the way its author would: installs the build tree into a scratch prefix,
# builds sdk/examples/sinusoidal against it out of tree, reprojects an equirectangular image to the
# sinusoidal projection with GDAL, and renders both with the INSTALLED strata: the plugin's projection must
# put the planet where the built-in equirectangular one does.
#   sinusoidal_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/sdk_test_functions.sh"
set_up_example "$1" "$2" sinusoidal

step "the installed strata lists the plugin's projection"
"$strata" plugins | tee "$work/plugins.txt"
grep -Eq '^sinusoidal +.*\(\+proj=sinu\)$' "$work/plugins.txt" || fail "the sinusoidal projection is not listed"

# The plugin's C++ forward and inverse against PROJ's sinu, through `strata project` and gdaltransform, on a
# sphere with a central meridian and a false origin: a point every 10 degrees of longitude (off the
# antimeridian, where either side is right) and of latitude, poles included. Both evaluate Snyder's
# equations in double, so they agree to gdaltransform's 15 digits (measured: 5e-8 m); the bound, a micrometre, is a
# millionth of a texel of a 40,000-texel map of Mars. A longitude off by 1e-6 degree is 0.1 m on the equator.
step "the plugin's forward and inverse agree with PROJ's"
crs="+proj=sinu +lon_0=30 +x_0=500000 +y_0=-200000 +R=6371000"
awk 'BEGIN { for (lat = -90; lat <= 90; lat += 10) for (lon = -175; lon < 180; lon += 10) print lon, lat }' \
  >"$work/lonlat.txt"
"$strata" project "$crs" "$work/lonlat.txt" >"$work/strata-xy.txt"
gdaltransform -s_srs "+proj=longlat +R=6371000" -t_srs "$crs" -output_xy <"$work/lonlat.txt" >"$work/proj-xy.txt"
paste -d ' ' "$work/strata-xy.txt" "$work/proj-xy.txt" | awk '
  NF != 4 { print "unmapped: " $0; bad = 1; exit 1 }
  { for (c = 1; c <= 2; ++c) { d = $c - $(c + 2); d = d < 0 ? -d : d; if (d > worst) worst = d } }
  END { if (bad) exit 1
        printf "forward: %d points, largest difference from PROJ %.3g m\n", NR, worst; exit !(worst <= 1e-6) }' ||
  fail "the forward mapping is not PROJ's to a micrometre"
# Back from PROJ's map coordinates: the same longitudes (modulo a turn; any at the poles, where a parallel
# is a point) and latitudes, to 1e-9 degrees (measured: 6e-13).
"$strata" project --inverse "$crs" "$work/proj-xy.txt" >"$work/strata-lonlat.txt"
paste -d ' ' "$work/strata-lonlat.txt" "$work/lonlat.txt" | awk '
  NF != 4 { print "unmapped: " $0; bad = 1; exit 1 }
  { d = ($1 - $3) % 360; d = d < 0 ? -d : d; d = d > 180 ? 360 - d : d; if ($4 == 90 || $4 == -90) d = 0
    e = $2 - $4; e = e < 0 ? -e : e; if (e > d) d = e; if (d > worst) worst = d }
  END { if (bad) exit 1
        printf "inverse: largest difference from the points %.3g degrees\n", worst; exit !(worst <= 1e-9) }' ||
  fail "the inverse mapping does not give the points back to 1e-9 degrees"

# Blue Marble (Debian's xplanet-images, 2048x1024, whole globe) on the sphere the pipeline's body has; the
# same image warped to the sinusoidal lens of that sphere at the same texels per metre along the equator
# (x within pi R, y within pi R / 2); and a window of the Mediterranean in a sinusoidal CRS with a central
# meridian and a false origin, at 4 km texels.
step "write the equirectangular image and two sinusoidal reprojections"
sphere="+R=6371000 +no_defs"
gdal_translate -q -a_srs "+proj=longlat $sphere" -a_ullr -180 90 180 -90 /usr/share/xplanet/images/earth.jpg \
  "$work/earth-lonlat.tif"
gdalwarp -q -t_srs "+proj=sinu $sphere" -r bilinear -ts 2048 1024 \
  -te -20015086.796 -10007543.398 20015086.796 10007543.398 "$work/earth-lonlat.tif" "$work/earth-sinusoidal.tif"
gdalwarp -q -t_srs "+proj=sinu +lon_0=30 +x_0=500000 +y_0=-200000 $sphere" -r bilinear -ts 2000 1000 \
  -te -4500000 1800000 3500000 5800000 "$work/earth-lonlat.tif" "$work/window-sinusoidal.tif"
gdalinfo "$work/earth-sinusoidal.tif" | grep -q 'Sinusoidal' || fail "gdalwarp did not write a sinusoidal CRS"

step "render the example pipeline"
cp "$example/sinusoidal.yaml" "$work/"
"$strata" render "$work/sinusoidal.yaml" -o "$work/sinusoidal.png" --size 320x180
gdalinfo "$work/sinusoidal.png" | grep -q '^Size is 320, 180$' || fail "sinusoidal.png is not 320x180"

# Over the whole frame: the mean difference per channel, and how many pixels are over 16 levels off in some
# channel.
differences() {
  paste -d ' ' <(pixels "$1") <(pixels "$2") | awk '
    { worst = 0
      for (c = 1; c <= 3; ++c) { d = $c - $(c + 3); d = d < 0 ? -d : d; sum += d; if (d > worst) worst = d }
      if (worst > 16) over++ }
    END { printf "%.2f %d\n", sum / (3 * NR), over + 0 }'
}

# Checks that IMAGE (a frame) and the equirectangular frame FROM agree: a mean of 2 levels, and at most 2%
# of the 57,600 pixels (1,152) over 16 levels off.
expect_agreement() {
  local image=$1 from=$2 mean over
  read -r mean over < <(differences "$image" "$from")
  echo "mean difference $mean levels; $over pixels over 16 levels off"
  awk -v m="$mean" 'BEGIN { exit !(m <= 2) }' || fail "the frames differ by $mean levels on average, more than 2"
  ((over <= 1152)) || fail "$over pixels differ by over 16 levels, more than 1,152 (2%)"
}

# Close views, where the image is magnified (some 25 pixels per degree, texels of 0.18 degree), over regions
# the sinusoidal map shears. The frames differ by gdalwarp's bilinear resampling onto the sinusoidal grid,
# which the equirectangular frame never went through. Measured on llvmpipe: means of 1.07, 0.97 and 0.87
# levels, and 179, 25 and 483 pixels over 16 levels off (coast lines). The bounds leave room for other GPUs'
# filtering; each raster misplaced by 1 degree (+lon_0 one more) gives means of 16.9, 4.5 and 17.0 levels,
# and 23,534, 2,696 and 20,149 pixels over.
for view in "10 40 earth" "60 60 earth" "20 35 window"; do
  read -r lon lat raster <<<"$view"
  step "$raster-sinusoidal.tif and the equirectangular image agree, seen from 1500 km above ${lat}N ${lon}E"
  for image in $raster-sinusoidal earth-lonlat; do
    "$strata" render "$work/sinusoidal.yaml" -o "$work/$image-$lon.png" --size 320x180 \
      --set nodes.imagery.path="$work/$image.tif" --set camera.lon="$lon" --set camera.lat="$lat" \
      --set camera.altitude=1.5e6
  done
  expect_agreement "$work/$raster-sinusoidal-$lon.png" "$work/earth-lonlat-$lon.png"
done

# composite.projection_quality weighs each layer by its texels' footprints, which come from the plugin's
# forward mapping: the sinusoidal layer must compose with the equirectangular one without complaint, and
# the two agreeing, into the same frame (measured: a mean of 0.61 levels, 10 pixels over 16).
step "composite.projection_quality composes the sinusoidal image with the equirectangular one"
cat >"$work/composed.yaml" <<YAML
strata: 1
body: {name: Earth, radius: 6371000}
camera: {lon: 60, lat: 60, altitude: 1.5e6}
nodes:
  sinusoidal: {type: source.gdal, path: earth-sinusoidal.tif, kind: color}
  lonlat: {type: source.gdal, path: earth-lonlat.tif, kind: color}
  composed: {type: composite.projection_quality, layers: [sinusoidal, lonlat]}
  globe: {type: geometry.icosahedral}
  frame: {type: output.image, geometry: globe, surface: [composed]}
YAML
"$strata" render "$work/composed.yaml" -o "$work/composed.png" --size 320x180
expect_agreement "$work/composed.png" "$work/earth-lonlat-60.png"

step "a sinusoidal CRS on an ellipsoid is refused, naming the file and how to state it on a sphere"
gdal_translate -q -a_srs "+proj=sinu +ellps=WGS84 +no_defs" "$work/window-sinusoidal.tif" "$work/ellipsoid.tif"
if "$strata" render "$work/sinusoidal.yaml" -o "$work/ellipsoid.png" --size 64x36 \
     --set nodes.imagery.path="$work/ellipsoid.tif" 2>"$work/ellipsoid.txt"; then
  fail "a sinusoidal raster on an ellipsoid rendered"
fi
cat "$work/ellipsoid.txt"
grep -q "ellipsoid.tif" "$work/ellipsoid.txt" || fail "the error does not name the file"
grep -q "fix: give the CRS a sphere" "$work/ellipsoid.txt" || fail "the error does not say how to fix it"

step "passed"
