#pragma once
#include <functional>
#include <string>
#include <vector>

#include "planet_model.hpp"

namespace strata::testdata {

// Mars' mean radius (m): every observation is of a sphere this size.
inline constexpr double kMarsRadius = 3396190.0;

// One raster of the procedural planet as an instrument in some projection would deliver it: a north-up grid
// of pixel centres in a CRS (given to PROJ), what a pixel's sample spans on the ground, and where it has data.
struct Observation {
  std::string name;  // file names are <name>-height.tif and <name>-color.tif
  std::string crs;   // a PROJ string
  int width = 0;
  int height = 0;
  double west = 0.0;         // CRS units (degrees or metres) of the raster's left edge
  double north = 0.0;        // and of its top edge
  double pixelWidth = 0.0;   // CRS units
  double pixelHeight = 0.0;  // CRS units, positive (rows run south)
  double footprint = 0.0;    // m: the ground a pixel's sample averages over, so the planet does not alias
  std::function<bool(double lonRad, double latRad)> covers;  // false: nodata (PROJ's failures are nodata too)
};

// The observations the tests use, each covering what [Kooima 2008, ch. 4] composes: global, both polar caps,
// HEALPix, and a narrow strip along an inclined ground track.
std::vector<Observation> standardObservations();

// A HiRISE-like strip of 25 cm texels, 256 m east-west by 1 km north-south, centred on Gale crater's place
// (137.4 E, 4.6 S), for pipelines/mars_strip.yaml: far from longitude 0, where float longitude resolves
// about a metre. Observe it with finePlanetParameters().
Observation galeStrip();
// The planet at the scale of galeStrip(): the same one (seed, amplitude, first wavelength), summed down to
// octaves of about a metre (24 octaves: 3000 km / 2^23 = 0.36 m, the finest faded out by the footprint), so
// that the strip holds relief finer than the global map's 1.5 km octaves, with contour lines every metre.
procedural::PlanetParameters finePlanetParameters();

// The whole planet in longitude/latitude at width x height, for benchmarks.
Observation largeGlobalObservation(int width, int height);

}  // namespace strata::testdata
