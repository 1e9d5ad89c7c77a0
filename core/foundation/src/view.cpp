#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include <strata/camera.hpp>

#include "earth_rotation.hpp"

namespace strata {

glm::dvec3 unitNormal(double lonRad, double latRad) {
  return {std::cos(latRad) * std::cos(lonRad), std::cos(latRad) * std::sin(lonRad), std::sin(latRad)};
}

glm::dvec2 View::halfFrameTangents() const {
  const double up = std::tan(0.5 * verticalFov);
  return {up * double(width) / double(std::max(1, height)), up};
}

glm::vec4 sinesAndCosines(glm::dvec2 lonlat) {
  return glm::vec4(glm::dvec4(std::sin(lonlat.x), std::cos(lonlat.x), std::sin(lonlat.y), std::cos(lonlat.y)));
}

glm::dmat3 planetToLocal(glm::dvec2 lonlat) {
  const double sinLon = std::sin(lonlat.x), cosLon = std::cos(lonlat.x);
  const double sinLat = std::sin(lonlat.y), cosLat = std::cos(lonlat.y);
  const glm::dvec3 east(-sinLon, cosLon, 0.0);
  const glm::dvec3 north(-sinLat * cosLon, -sinLat * sinLon, cosLat);
  const glm::dvec3 up(cosLat * cosLon, cosLat * sinLon, sinLat);
  return glm::transpose(glm::dmat3(east, north, up));
}

namespace {

// Infinite far plane with reversed depth: window depth = near / distance, 1 at the near plane and 0 at
// infinity. Floating-point depth then keeps about the same relative precision at every distance, which a
// view from orbit down to a metre needs (used with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)).
glm::mat4 reversedInfiniteProjection(double verticalFov, double aspect, double near) {
  const double f = 1.0 / std::tan(verticalFov / 2.0);
  glm::dmat4 p(0.0);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][3] = -1.0;
  p[3][2] = near;
  return glm::mat4(p);
}

// A thousandth of the way to the nearest ground the terrain may hold keeps it in front of the near plane;
// 1 cm is the closest anyone needs. Reversed float depth keeps its relative precision at any distance
// whatever the near plane (ReversedDepth), so a near plane this close costs no depth resolution.
double nearPlane(double altitude, const HeightRange& terrain) {
  return std::max(0.01, std::abs(altitude - groundLevelNear(terrain, altitude)) * 1e-3);
}

}  // namespace

Camera cameraAhead(const Body& body, const Camera& before, const Camera& now, double frames) {
  const auto eyeOf = [&body](const Camera& c) {
    return unitNormal(glm::radians(c.lon), glm::radians(c.lat)) * (body.radius + c.altitude);
  };
  const glm::dvec3 eye = eyeOf(now) + frames * (eyeOf(now) - eyeOf(before));
  const double distance = glm::length(eye);
  if (!(distance > 0.0) || !std::isfinite(distance)) return now;
  Camera ahead = now;
  const glm::dvec2 below = lonLatOf(eye);
  ahead.lon = glm::degrees(below.x);
  ahead.lat = glm::degrees(below.y);
  ahead.altitude = std::max(distance - body.radius, 0.1 * now.altitude);
  return ahead;
}

View makeView(const Body& body, const Camera& camera, int width, int height, const HeightRange& terrain) {
  const double lon = glm::radians(camera.lon), lat = glm::radians(camera.lat);
  const double heading = glm::radians(camera.heading), tilt = glm::radians(camera.tilt);
  const glm::dvec3 up = unitNormal(lon, lat);
  const glm::dvec3 east(-std::sin(lon), std::cos(lon), 0.0);
  const glm::dvec3 north = glm::cross(up, east);
  const glm::dvec3 ahead = north * std::cos(heading) + east * std::sin(heading);
  const glm::dvec3 forward = -up * std::cos(tilt) + ahead * std::sin(tilt);
  const glm::dvec3 cameraUp = up * std::sin(tilt) + ahead * std::cos(tilt);
  const glm::dvec3 right = glm::cross(forward, cameraUp);

  View view;
  view.width = width;
  view.height = height;
  view.eye = up * (body.radius + camera.altitude);
  view.reference = {lon, lat};
  view.planetToEye = glm::transpose(glm::dmat3(right, cameraUp, -forward));
  view.near = nearPlane(camera.altitude, terrain);
  view.verticalFov = glm::radians(camera.fov);
  view.projection = reversedInfiniteProjection(view.verticalFov, double(width) / double(height), view.near);
  return view;
}

View viewOfBody(const View& seen, const BodyPlacement& from, const BodyPlacement& to, const Body& body,
                const HeightRange& terrain) {
  View view = seen;
  view.eye = glm::transpose(to.axes) * (from.centre + from.axes * seen.eye - to.centre);
  view.planetToEye = seen.planetToEye * glm::transpose(from.axes) * to.axes;
  const double distance = glm::length(view.eye);
  view.reference = lonLatOf(view.eye);
  view.near = nearPlane(distance - body.radius, terrain);
  view.projection = reversedInfiniteProjection(view.verticalFov, double(view.width) / double(view.height), view.near);
  return view;
}

}  // namespace strata
