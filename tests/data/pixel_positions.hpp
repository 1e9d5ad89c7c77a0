#pragma once
#include <vector>

#include <proj.h>

#include <glm/glm.hpp>

#include "observation.hpp"

namespace strata::testdata {

// Where an observation's pixel centres lie on the sphere, by PROJ's inverse of its CRS: never Strata's own
// projections, so that the data stay independent of what they test. PROJ objects must not be shared between
// threads, so each thread makes its own.
class PixelPositions {
 public:
  explicit PixelPositions(const Observation& observation);
  ~PixelPositions();
  PixelPositions(const PixelPositions&) = delete;
  PixelPositions& operator=(const PixelPositions&) = delete;

  // Longitude and latitude (rad) of each pixel centre of `row`; NaN where PROJ's inverse fails.
  const std::vector<glm::dvec2>& row(int row);

 private:
  const Observation& observation_;
  PJ_CONTEXT* context_;
  PJ* projection_;
  bool angularMapUnits_;  // longitude/latitude CRSs: map coordinates are degrees, PROJ takes radians
  std::vector<double> x_, y_;
  std::vector<glm::dvec2> lonlat_;
};

}  // namespace strata::testdata
