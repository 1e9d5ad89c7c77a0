#include "view_volume.hpp"

#include <algorithm>
#include <cmath>

namespace strata::icosahedral {

ViewVolume::ViewVolume(const View& view) : eye_(view.eye) {
  const glm::dvec2 halfFrame = view.halfFrameTangents();
  const double tx = halfFrame.x, ty = halfFrame.y;
  pixelsPerRadian_ = view.pixelsPerRadian();
  // Eye-space normals (x right, y up, looking down -z) of the planes through the eye, and the near plane.
  const std::array<glm::dvec3, 5> eyeNormals{glm::dvec3(1, 0, -tx), glm::dvec3(-1, 0, -tx), glm::dvec3(0, 1, -ty),
                                             glm::dvec3(0, -1, -ty), glm::dvec3(0, 0, -1)};
  const glm::dmat3 eyeToPlanet = glm::transpose(view.planetToEye);
  for (std::size_t i = 0; i < planes_.size(); ++i) {
    // dot(n_eye, R (p - eye)) + c = dot(R^T n_eye, p) - dot(R^T n_eye, eye) + c
    const glm::dvec3 normal = eyeToPlanet * eyeNormals[i];
    const double eyeOffset = i == 4 ? -view.near : 0.0;
    planes_[i] = {normal, eyeOffset - glm::dot(normal, eye_)};
  }
}

bool ViewVolume::mayHold(const PatchShell& shell) const {
  return std::ranges::none_of(planes_,
                              [&](const Plane& plane) { return outsidePlane(shell, plane.normal, plane.offset); });
}

}  // namespace strata::icosahedral
