#pragma once
#include <strata/body.hpp>

namespace strata::clipmap {

// The levels of the hemisphere's rings a view draws [Clasen & Hege 2006, §4.5]: from the
// coarsest, which holds the horizon, to the finest, which holds the footprint of a pixel below the eye; inside the
// finest, its fill cap.
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

// The levels between those two, of a mesh of `levels` levels (ringColatitude: level i spans pi 2^-i to
// pi 2^-(i+1)).
DrawnLevels drawnLevels(double horizon, double pixel, int levels);

}  // namespace strata::clipmap
