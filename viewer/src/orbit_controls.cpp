#include <strata/viewer/orbit_controls.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

namespace strata::viewer {
namespace {

constexpr double kFlyingShare = 0.1;  // a key press flies a tenth of the altitude: speed follows altitude

// Longitude and latitude (rad) where the ray through pixel (x, y) meets the sphere of `radius`, or none.
std::optional<glm::dvec2> groundAt(const View& view, double radius, double x, double y) {
  const double tanHalf = std::tan(view.verticalFov / 2.0), aspect = double(view.width) / view.height;
  const double ndcX = (x + 0.5) / view.width * 2.0 - 1.0, ndcY = 1.0 - (y + 0.5) / view.height * 2.0;
  const glm::dvec3 d =
      glm::transpose(view.planetToEye) * glm::normalize(glm::dvec3(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0));
  const double b = glm::dot(view.eye, d), c = glm::dot(view.eye, view.eye) - radius * radius;
  if (b * b - c < 0.0 || -b - std::sqrt(b * b - c) < 0.0) return std::nullopt;
  const glm::dvec3 n = glm::normalize(view.eye + (-b - std::sqrt(b * b - c)) * d);
  return glm::dvec2(std::atan2(n.y, n.x), std::asin(n.z));
}

}  // namespace

void OrbitControls::drag(double dx, double dy, int button, int viewportHeight) {
  if (button == 0) {
    // Ground metres per pixel at the nadir, turned into degrees of arc; headings turn the drag with the view.
    const double metresPerPixel = 2.0 * camera_.altitude * std::tan(glm::radians(camera_.fov) / 2.0) / viewportHeight;
    const double degreesPerPixel = glm::degrees(metresPerPixel / body_.radius);
    const double heading = glm::radians(camera_.heading);
    const double north = dy * std::cos(heading) + dx * std::sin(heading);
    const double east = -dx * std::cos(heading) + dy * std::sin(heading);
    camera_.lat = std::clamp(camera_.lat + north * degreesPerPixel, -90.0, 90.0);
    const double cosLat = std::max(std::cos(glm::radians(camera_.lat)), 1e-3);
    camera_.lon = std::remainder(camera_.lon + east * degreesPerPixel / cosLat, 360.0);
  } else {
    camera_.heading = std::remainder(camera_.heading + dx * 0.25, 360.0);
    camera_.tilt = std::clamp(camera_.tilt + dy * 0.25, 0.0, 90.0);
  }
}

void OrbitControls::scroll(double steps) {
  // 15% closer per wheel step: about seven steps per factor of three.
  camera_.altitude = std::clamp(camera_.altitude * std::pow(0.85, steps), 1.0, 1.0e9);
}

// The ground under the pointer, from the ray through it and the body's sphere, computed in double; the point
// below the eye then moves toward it by the share the altitude falls, so that a view looking down keeps it
// under the pointer (exactly for a flat ground, nearly for a sphere seen from its own scale).
void OrbitControls::scrollToward(double steps, double x, double y, int width, int height) {
  const double before = camera_.altitude;
  const std::optional<glm::dvec2> target = groundAt(makeView(body_, camera_, width, height), body_.radius, x, y);
  scroll(steps);
  if (!target) return;
  const double share = 1.0 - camera_.altitude / before;  // negative: zooming out moves away
  const glm::dvec3 from = unitNormal(glm::radians(camera_.lon), glm::radians(camera_.lat));
  const glm::dvec3 to = unitNormal(target->x, target->y);
  const double angle = std::acos(std::clamp(glm::dot(from, to), -1.0, 1.0));
  if (angle < 1e-12) return;
  const glm::dvec3 moved =
      (std::sin((1.0 - share) * angle) * from + std::sin(share * angle) * to) / std::sin(angle);  // slerp
  camera_.lat = glm::degrees(std::asin(std::clamp(moved.z, -1.0, 1.0)));
  camera_.lon = glm::degrees(std::atan2(moved.y, moved.x));
}

// Along the line of sight, tilt from straight down: the altitude falls by cos(tilt) of the distance, and
// the point below the eye moves forward along the heading by sin(tilt) of it, over the ground.
void OrbitControls::fly(double share) {
  const double distance = share * camera_.altitude, tilt = glm::radians(camera_.tilt);
  camera_.altitude = std::clamp(camera_.altitude - distance * std::cos(tilt), 1.0, 1.0e9);
  const double ahead = distance * std::sin(tilt) / body_.radius, heading = glm::radians(camera_.heading);
  camera_.lat = std::clamp(camera_.lat + glm::degrees(ahead * std::cos(heading)), -90.0, 90.0);
  const double cosLat = std::max(std::cos(glm::radians(camera_.lat)), 1e-3);
  camera_.lon = std::remainder(camera_.lon + glm::degrees(ahead * std::sin(heading)) / cosLat, 360.0);
}

// An arrow drags the ground by a tenth of the view's height; + and - are a wheel step each.
void OrbitControls::key(NavigationKey key, int viewportHeight) {
  const double step = viewportHeight / 10.0;
  switch (key) {
    case NavigationKey::Left: drag(step, 0.0, 0, viewportHeight); break;
    case NavigationKey::Right: drag(-step, 0.0, 0, viewportHeight); break;
    case NavigationKey::Up: drag(0.0, step, 0, viewportHeight); break;
    case NavigationKey::Down: drag(0.0, -step, 0, viewportHeight); break;
    case NavigationKey::Closer: scroll(1.0); break;
    case NavigationKey::Farther: scroll(-1.0); break;
    case NavigationKey::Forward: fly(kFlyingShare); break;
    case NavigationKey::Back: fly(-kFlyingShare); break;
    case NavigationKey::Home: break;
  }
}

}  // namespace strata::viewer
