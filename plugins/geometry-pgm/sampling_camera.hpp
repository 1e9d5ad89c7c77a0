#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace strata::pgm {

// The sampling camera of [Mahsman 2010, §3.5]: it shares the eye with the viewing camera, so it is a
// rotation and a frustum. Its rays must hold every pertinent ray, those that hit the primary sphere and
// lie in the view frustum extended down to the nadir, and as few others as it can. Cameras are
// right-handed and look down -z; directions are in double and lengths in any one unit.

// The viewing camera: the eye in planet-fixed coordinates (the planet's centre at the origin), the
// rotation from planet-fixed to eye space, and the frustum as glFrustum takes it, its edges on the near
// plane z = -near [Mahsman 2010, §3.5.1].
struct ViewCamera {
  glm::dvec3 eye;
  glm::dmat3 planetToEye;
  double left, right, bottom, top, near;
};

// Which rays the sampling camera was fitted to [Mahsman 2010, §3.5.3].
enum class SamplingFit {
  kIntersection,        // the view frustum and the visible-sphere frustum, which holds the nadir
  kExtendedToNadir,     // the same, after the view frustum was extended down to the nadir
  kVisibleSphereAlone,  // the two frusta do not meet, e.g. looking away from the planet
};

// The sampling camera: planet-fixed to sampling space, S = O R V without the translation to the eye
// [Mahsman 2010, §3.5.4], and its glFrustum edges on the viewing camera's near plane.
struct SamplingCamera {
  glm::dmat3 planetToSampling;
  double left, right, bottom, top, near;
  SamplingFit fit;
  std::vector<glm::dvec3> rays;  // the corner rays it was fitted to, unit, in sampling space, all z < 0
};

// Below this sine of the angle between the view's forward and the nadir the two are parallel: the
// rotated eye frame keeps eye space, where the rotation of [Mahsman 2010, §3.5.2] is undefined.
constexpr double kParallelSine = 1e-12;

// The sampling camera of a view around the sphere of `radius` centred on the planet. That sphere is the
// primary one: the grid's rays are cast on it and miss beyond its tangent, and the secondary sphere, being
// smaller, would cut off the band of rays from its own tangent to the primary one. The radius is kept
// below the eye as referenceSpheres keeps it.
SamplingCamera samplingCamera(const ViewCamera& view, double radius);

// The corner rays of the visible-sphere frustum in rotated eye space, where the nadir lies in the
// yz-plane below the forward: a square frustum about the nadir whose sides are tangent to the sphere, with
// all four corners at z = -1 in its own frame ([Mahsman 2010, §3.5.1] prints +n for three of them;
// docs/references.md, Errata) and its top edge towards the view [Mahsman 2010, §3.5.1].
std::vector<glm::dvec3> visibleSphereFrustum(const glm::dvec3& nadir, double tangent);

// The rays of a convex polygon of rays, in order, within the planes through the eye spanned by the
// consecutive corners of a second such polygon: the two cones' intersection [Mahsman 2010, §3.5.3]. Empty if they do
// not meet.
std::vector<glm::dvec3> intersectCones(std::vector<glm::dvec3> rays, const std::vector<glm::dvec3>& bounds);

}  // namespace strata::pgm
