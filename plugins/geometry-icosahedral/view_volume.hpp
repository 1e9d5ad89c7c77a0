#pragma once
#include <array>

#include <glm/glm.hpp>
#include <strata/camera.hpp>

#include "patch_shell.hpp"

namespace strata::icosahedral {

// One view's frustum as five planes in planet-fixed coordinates (the far plane is at infinity), with
// the eye: what patch visibility tests against [Kooima 2008, §3.2]. In double, so that the planes
// stay exact at planet scale.
class ViewVolume {
 public:
  explicit ViewVolume(const View& view);

  const glm::dvec3& eye() const { return eye_; }
  // Pixels per radian at the centre of the view: what turns an angle into pixels on screen.
  double pixelsPerRadian() const { return pixelsPerRadian_; }
  // Whether some of the shell may lie inside the frustum: false only when it is all outside one plane.
  bool mayHold(const PatchShell& shell) const;

 private:
  struct Plane {
    glm::dvec3 normal;  // toward the inside
    double offset;      // inside where dot(normal, p) + offset >= 0
  };
  glm::dvec3 eye_;
  double pixelsPerRadian_;
  std::array<Plane, 5> planes_;
};

}  // namespace strata::icosahedral
