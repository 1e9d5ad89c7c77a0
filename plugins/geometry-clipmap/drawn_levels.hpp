#pragma once
#include <strata/body.hpp>

namespace strata::clipmap {

// The levels of the hemisphere's rings a view draws [Clasen & Hege 2006, §4.5]: from the
// coarsest, which holds the horizon, to the finest, which holds the fill cap below the eye (capColatitude).
struct DrawnLevels {
  int coarsest = 0;
  int finest = 0;
};

// theta~ of the horizon (Eqs. 5 and 6), with the paper's "safety factor" made exact: ground as high as
// `heights.highest` shows over the sphere of the lowest ground up to acos(r / (r + h)) beyond that sphere's
// horizon, so mountains behind it are not cut. `altitude`: the eye's, m above `radius`. At most pi.
double horizonColatitude(double radius, double altitude, const HeightRange& heights);

// theta~ of a pixel's footprint straight below the eye (Eqs. 7 and 8): `pixelAngle` rad a pixel, seen from the
// eye's height above the ground nearest it (groundLevelNear).
double pixelColatitude(double radius, double altitude, const HeightRange& heights, double pixelAngle);

// The fill cap's theta~, for a pixel's `pixel`: kCapPixels pixels, inside which the cap's fan interpolates the
// heights. Eq. 8 ends the levels at one pixel, but a level's rings lie only 1 - 2^(-1/m) of its theta~ apart
// (3.4% at the paper's m = 20): from high above, where every ring near the nadir is about as far from the eye, the
// rings just outside a cap of one pixel lie 1/29 of a pixel apart, and the innermost levels' triangles are too
// small to see. Four pixels leave the rings just outside a seventh of a pixel apart at m = 20, and two levels fewer.
constexpr double kCapPixels = 4.0;
double capColatitude(double pixel);

// The levels between the horizon and the cap, of a mesh of `levels` levels (ringColatitude: level i spans
// pi 2^-i to pi 2^-(i+1)).
DrawnLevels drawnLevels(double horizon, double cap, int levels);

}  // namespace strata::clipmap
