#pragma once
#include <vector>

#include <glm/vec4.hpp>

#include <strata/camera.hpp>

namespace strata::image {

// Where in the frame a body may show, so that the layers are composed there only: the sky around a planet
// seen from orbit is most of the frame, and llvmpipe runs a branch's both sides for every pixel of a block
// that holds both, so a pixel off the body costs as much as one on it.
struct BodyOutline {
  // 16: the polygon reaches 2 % beyond the circle it circumscribes; a fan's triangles meet along its spokes,
  // where llvmpipe shades each block of pixels once for each triangle: 64 spokes across a frame cost 50 %.
  static constexpr int kRimPoints = 16;
  static constexpr int kMostPoints = kRimPoints + 2;

  std::vector<glm::vec4> fan;  // clip-space points of a triangle fan: its centre, then its rim, closed
  bool wholeFrame = false;     // the fan is one triangle over the frame: the body may show anywhere
};

// The outline of a sphere of `radius` (m) about the planet-fixed origin (a body with its highest surface) seen
// by `view`: the cone from the eye tangent to it, widened by two pixels (a pixel whose centre lies off the limb
// may hold samples on it), cut by the plane through the sphere's point nearest the eye, which a polygon
// circumscribes. The whole frame where the eye is within the sphere, the cone is wider than kWidestCone or it
// holds the frame's corners.
BodyOutline bodyOutline(const View& view, double radius);

}  // namespace strata::image
