#include "patch_shell.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strata::icosahedral {
namespace {

// The largest dot(direction, u) over the unit vectors u of the shorter great-circle arc from a to b.
double largestDotOnArc(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& direction) {
  const glm::dvec3 pole = glm::cross(a, b);
  const double poleLength = glm::length(pole);
  double best = std::max(glm::dot(a, direction), glm::dot(b, direction));
  if (poleLength == 0.0) return best;
  // The direction's nearest point on the whole great circle, kept where it falls between a and b.
  const glm::dvec3 inPlane = direction - pole * (glm::dot(direction, pole) / (poleLength * poleLength));
  const double inPlaneLength = glm::length(inPlane);
  if (inPlaneLength == 0.0) return best;
  const glm::dvec3 nearest = inPlane / inPlaneLength;
  if (glm::dot(glm::cross(a, nearest), pole) >= 0.0 && glm::dot(glm::cross(nearest, b), pole) >= 0.0)
    best = std::max(best, inPlaneLength);
  return best;
}

}  // namespace

SphericalCap sampledCap(const SphericalTriangle& corners, int depth) {
  const double edge = std::max({angleBetween(corners[0], corners[1]), angleBetween(corners[1], corners[2]),
                                angleBetween(corners[2], corners[0])});
  return capAround(corners).widened(2.0 * std::ldexp(edge, -depth));
}

bool holds(const SphericalTriangle& t, const glm::dvec3& unit) {
  return glm::dot(glm::cross(t[0], t[1]), unit) >= 0.0 && glm::dot(glm::cross(t[1], t[2]), unit) >= 0.0 &&
         glm::dot(glm::cross(t[2], t[0]), unit) >= 0.0;
}

double largestDot(const SphericalTriangle& t, const glm::dvec3& direction) {
  const double length = glm::length(direction);
  if (length > 0.0 && holds(t, direction / length)) return length;
  return std::max({largestDotOnArc(t[0], t[1], direction), largestDotOnArc(t[1], t[2], direction),
                   largestDotOnArc(t[2], t[0], direction)});
}

bool outsidePlane(const PatchShell& shell, const glm::dvec3& normal, double offset) {
  const double support = largestDot(shell.corners, normal);
  const double radius = support > 0.0 ? shell.outerRadius : shell.innerRadius;
  return support * radius + offset < 0.0;
}

bool belowHorizon(const PatchShell& shell, const glm::dvec3& eye, double occluderRadius) {
  const double distance = glm::length(eye);
  // An eye below the terrain's floor, or a shell reaching no higher than it: nothing is ruled out.
  if (distance <= occluderRadius || shell.outerRadius < occluderRadius) return false;
  const double hidden = std::acos(occluderRadius / distance) + std::acos(occluderRadius / shell.outerRadius);
  if (hidden >= std::numbers::pi) return false;
  // Hidden when even the shell's nearest direction to the eye lies beyond the angle.
  return largestDot(shell.corners, eye / distance) < std::cos(hidden);
}

namespace {

// 1 - the largest dot of the triangle with the eye's direction, and the eye's distance.
std::pair<double, double> nearestAngle(const SphericalTriangle& corners, const glm::dvec3& eye) {
  const double distance = glm::length(eye);
  if (distance == 0.0) return {1.0, 0.0};
  return {std::max(1.0 - largestDot(corners, eye / distance), 0.0), distance};
}

// |eye - radius u|^2 written so that an eye a metre above the ground loses no digits to cancellation.
double distanceAtAngle(double oneLessDot, double distance, double radius) {
  return std::sqrt((distance - radius) * (distance - radius) + 2.0 * distance * radius * oneLessDot);
}

}  // namespace

// A point r u's cosine is (dot(u, eye) - r) / |eye - r u|: at most the largest numerator, at the inner
// radius, over the least denominator. Along the nearest direction the distance is least at r = |eye| cos,
// taken into the shell.
double leastDistance(const PatchShell& shell, const glm::dvec3& eye) {
  const auto [oneLessDot, distance] = nearestAngle(shell.corners, eye);
  const double nearestRadius = std::clamp(distance * (1.0 - oneLessDot), shell.innerRadius, shell.outerRadius);
  return distanceAtAngle(oneLessDot, distance, nearestRadius);
}

double leastFaceOnDistance(const PatchShell& shell, const glm::dvec3& eye) {
  const auto [oneLessDot, distance] = nearestAngle(shell.corners, eye);
  const double nearest = leastDistance(shell, eye);
  const double largestCosine = nearest > 0.0 ? ((distance - shell.innerRadius) - distance * oneLessDot) / nearest : 1.0;
  return nearest / std::sqrt(std::clamp(largestCosine, kGrazingCosine, 1.0));
}

}  // namespace strata::icosahedral
