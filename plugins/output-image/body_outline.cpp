#include "body_outline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace strata::image {
namespace {

constexpr int kRimPoints = BodyOutline::kRimPoints;
constexpr double kLimbPixels = 2.0;
// 80 degrees: from under 1.5 % of the radius above the sphere (94 km on Earth) the body fills nearly every
// view, and the cut plane would lie far from the frame's centre; the whole frame is as cheap there.
constexpr double kWidestCone = 80.0 * std::numbers::pi / 180.0;

// One triangle, as strata/fullscreen.vert draws: no edge crosses the frame.
BodyOutline wholeFrame() { return {{{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}}, true}; }

// Whether the rays through the frame's four corners lie within `cone` (rad) of `axis` (planet-fixed): then so
// does every ray through the frame, the cone being convex.
bool holdsTheFrame(const View& view, const glm::dvec3& axis, double cone) {
  const glm::dvec2 halfFrame = view.halfFrameTangents();
  for (const glm::dvec2 corner : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
    const glm::dvec3 ray = glm::normalize(glm::transpose(view.planetToEye) * glm::dvec3(corner * halfFrame, -1.0));
    if (std::acos(std::clamp(glm::dot(ray, axis), -1.0, 1.0)) >= cone) return false;
  }
  return true;
}

}  // namespace

// The fan lies in front of the eye along the axis, not necessarily along the view: where the body is beside
// or behind the view, GL clips the fan's triangles in clip space (w < 0 behind the eye) as any others.
BodyOutline bodyOutline(const View& view, double radius) {
  const double distance = glm::length(view.eye);
  if (distance <= radius) return wholeFrame();
  const double cone = std::asin(radius / distance) + kLimbPixels * view.verticalFov / view.height;
  const glm::dvec3 axis = -view.eye / distance;  // toward the body's centre
  if (cone >= kWidestCone || holdsTheFrame(view, axis, cone)) return wholeFrame();
  const double along = distance - radius;
  const double rim = along * std::tan(cone) / std::cos(std::numbers::pi / kRimPoints);
  const glm::dvec3 helper = std::abs(axis.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 across = glm::normalize(glm::cross(helper, axis)), up = glm::cross(axis, across);
  const glm::dmat4 projection(view.projection);
  const auto clip = [&](const glm::dvec3& fromEye) {
    return glm::vec4(projection * glm::dvec4(view.planetToEye * fromEye, 1.0));
  };
  BodyOutline outline{{clip(along * axis)}, false};
  for (int i = 0; i <= kRimPoints; ++i) {
    const double turn = 2.0 * std::numbers::pi * (i % kRimPoints) / kRimPoints;
    outline.fan.push_back(clip(along * axis + rim * (std::cos(turn) * across + std::sin(turn) * up)));
  }
  return outline;
}

}  // namespace strata::image
