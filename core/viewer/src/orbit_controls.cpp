#include <strata/viewer/orbit_controls.hpp>

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace strata::viewer {

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
    case NavigationKey::Home: break;
  }
}

}  // namespace strata::viewer
