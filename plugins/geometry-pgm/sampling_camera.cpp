#include "sampling_camera.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "cross_section.hpp"
#include "reference_spheres.hpp"

namespace strata::pgm {

namespace {

// The inward normal of the plane through the eye and the corners i and i + 1 of a polygon of rays,
// n_i = c_{i+1} x c_i ([Mahsman 2010, §3.5.3], its first step): positive dot products lie inside.
glm::dvec3 inwardNormal(const std::vector<glm::dvec3>& rays, std::size_t i) {
  return glm::cross(rays[(i + 1) % rays.size()], rays[i]);
}

// Sutherland-Hodgman on the sphere of directions: the rays of a convex polygon within one open
// hemisphere that lie on the inner side of a plane through the eye. Where an edge crosses the plane the
// ray |m.a| b + |m.b| a lies on it, between a and b.
std::vector<glm::dvec3> clip(const std::vector<glm::dvec3>& rays, const glm::dvec3& normal) {
  std::vector<glm::dvec3> inside;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const glm::dvec3 &a = rays[i], &b = rays[(i + 1) % rays.size()];
    const double sideA = glm::dot(normal, a), sideB = glm::dot(normal, b);
    if (sideA >= 0.0) inside.push_back(a);
    if ((sideA >= 0.0) != (sideB >= 0.0)) inside.push_back(glm::normalize(std::abs(sideA) * b + std::abs(sideB) * a));
  }
  return inside;
}

// Eye space rotated about the forward -z so that the nadir lies in the yz-plane below it: rows
// r = |b x n|, u = b x r, b = +z [Mahsman 2010, §3.5.2]. Looking along the nadir, eye space is kept.
glm::dmat3 eyeToRotatedEye(const glm::dvec3& nadir) {
  const double across = std::hypot(nadir.x, nadir.y);
  if (across < kParallelSine) return glm::dmat3(1.0);
  const glm::dvec3 right(-nadir.y / across, nadir.x / across, 0.0), back(0.0, 0.0, 1.0);
  return glm::transpose(glm::dmat3(right, glm::cross(back, right), back));
}

// The view frustum's corner rays (l,b), (r,b), (r,t), (l,t) on the near plane, unit [Mahsman 2010, §3.5.1].
std::vector<glm::dvec3> viewCorners(const ViewCamera& view) {
  return {glm::normalize(glm::dvec3(view.left, view.bottom, -view.near)),
          glm::normalize(glm::dvec3(view.right, view.bottom, -view.near)),
          glm::normalize(glm::dvec3(view.right, view.top, -view.near)),
          glm::normalize(glm::dvec3(view.left, view.top, -view.near))};
}

// The nadir extension, which [Mahsman 2010, §3.5] gives only in words (docs/references.md, Errata), read as
// the view frustum's bottom tilted down to the nadir: the convex hull of the frustum and the nadir. The
// edges the nadir lies beyond give way to two edges through it, so the hull holds every ray between the
// nadir and any point of the bottom edge. Unchanged when the nadir is inside; when the nadir is beyond every
// edge (the zenith in view) no hull fits a camera, and the view frustum stays.
std::vector<glm::dvec3> extendToNadir(const std::vector<glm::dvec3>& rays, const glm::dvec3& nadir) {
  std::vector<bool> beyond(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) beyond[i] = glm::dot(inwardNormal(rays, i), nadir) < 0.0;
  if (std::ranges::count(beyond, true) == static_cast<std::ptrdiff_t>(rays.size())) return rays;
  std::vector<glm::dvec3> hull;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const bool before = beyond[(i + rays.size() - 1) % rays.size()];
    if (!(before && beyond[i])) hull.push_back(rays[i]);
    if (!before && beyond[i]) hull.push_back(nadir);
  }
  return hull;
}

// The sampling forward in the yz-plane: [Mahsman 2010, §3.5.4] averages the rays' y and z components; this
// takes the mean of the two extreme rays' angles about the nadir in that plane instead. All rays lie within
// the visible-sphere frustum, under 90 degrees from the nadir, so those angles span under 180 degrees and
// every ray ends under 90 degrees from the forward: z < 0.
glm::dvec3 samplingForward(const std::vector<glm::dvec3>& rays, const glm::dvec3& nadir) {
  const glm::dvec3 down = glm::normalize(glm::dvec3(0.0, nadir.y, nadir.z)), ahead(0.0, -down.z, down.y);
  double least = std::numeric_limits<double>::max(), most = -least;
  for (const glm::dvec3& ray : rays) {
    const double angle = std::atan2(glm::dot(ray, ahead), glm::dot(ray, down));
    least = std::min(least, angle);
    most = std::max(most, angle);
  }
  const double middle = 0.5 * (least + most);
  return std::cos(middle) * down + std::sin(middle) * ahead;
}

// O: rotated eye space to sampling space, rows r, u = b x r, b = -f_s [Mahsman 2010, §3.5.4]. The forward and the nadir
// both lie in the yz-plane, so |b x n| is +x or -x; +x is the thesis's whenever the nadir lies below the
// forward and needs no fallback when the two are parallel.
glm::dmat3 rotatedEyeToSampling(const glm::dvec3& forward) {
  const glm::dvec3 right(1.0, 0.0, 0.0), back = -forward;
  return glm::transpose(glm::dmat3(right, glm::cross(back, right), back));
}

// The fitted rays in sampling space and their bounding box on the near plane, t = -near / c_z
// [Mahsman 2010, §3.5.4].
void fitFrustum(SamplingCamera& camera, const std::vector<glm::dvec3>& rays, const glm::dmat3& toSampling) {
  camera.left = camera.bottom = std::numeric_limits<double>::max();
  camera.right = camera.top = -camera.left;
  for (const glm::dvec3& ray : rays) {
    const glm::dvec3 sampled = toSampling * ray;
    assert(sampled.z < 0.0);
    const double scale = -camera.near / sampled.z;
    camera.left = std::min(camera.left, scale * sampled.x);
    camera.right = std::max(camera.right, scale * sampled.x);
    camera.bottom = std::min(camera.bottom, scale * sampled.y);
    camera.top = std::max(camera.top, scale * sampled.y);
    camera.rays.push_back(sampled);
  }
}

}  // namespace

// In rotated eye space the VSF's basis b = -n, r = |n x f|, u = |r x n| [Mahsman 2010, §3.5.1] is r = +x, as the
// nadir lies in the yz-plane below f = -z; the VSF about the exact nadir is built there directly, without
// the detour through planet-fixed and eye space. Near the nadir this is the camera's right, a fallback for f
// parallel to n, where that basis is undefined.
std::vector<glm::dvec3> visibleSphereFrustum(const glm::dvec3& nadir, double tangent) {
  const double half = std::tan(tangent);  // h = n tan(tau) at n = 1
  const glm::dvec3 up = glm::normalize(glm::cross(glm::dvec3(1.0, 0.0, 0.0), nadir));
  const glm::dvec3 right = glm::cross(up, -nadir);
  return {glm::normalize(nadir - half * right - half * up), glm::normalize(nadir + half * right - half * up),
          glm::normalize(nadir + half * right + half * up), glm::normalize(nadir - half * right + half * up)};
}

std::vector<glm::dvec3> intersectCones(std::vector<glm::dvec3> rays, const std::vector<glm::dvec3>& bounds) {
  for (std::size_t i = 0; i < bounds.size() && !rays.empty(); ++i) rays = clip(rays, inwardNormal(bounds, i));
  return rays;
}

// Both frusta in rotated eye space, intersected; the VSF alone where they do not meet, else the
// intersection extended to the nadir when it lacks it, which is when the view frustum lacks it, since the
// nadir is the VSF's axis [Mahsman 2010, §3.5.1-3.5.4].
SamplingCamera samplingCamera(const ViewCamera& view, double radius) {
  const double distance = glm::length(view.eye);
  const glm::dvec3 nadirInEye = view.planetToEye * (-view.eye / distance);
  const glm::dmat3 toRotated = eyeToRotatedEye(nadirInEye);
  const glm::dvec3 nadir = toRotated * nadirInEye;
  std::vector<glm::dvec3> frustum = viewCorners(view);
  for (glm::dvec3& corner : frustum) corner = toRotated * corner;
  const std::vector<glm::dvec3> sphere =
      visibleSphereFrustum(nadir, tangentAngle(distance, clampPrimaryRadius(radius, distance)));
  SamplingCamera camera{.near = view.near, .fit = SamplingFit::kIntersection};
  std::vector<glm::dvec3> rays = intersectCones(frustum, sphere);
  if (rays.empty()) {
    rays = sphere;
    camera.fit = SamplingFit::kVisibleSphereAlone;
  } else if (const std::vector<glm::dvec3> extended = extendToNadir(frustum, nadir); extended != frustum) {
    rays = intersectCones(extended, sphere);
    camera.fit = SamplingFit::kExtendedToNadir;
  }
  const glm::dmat3 toSampling = rotatedEyeToSampling(samplingForward(rays, nadir));
  camera.planetToSampling = toSampling * toRotated * view.planetToEye;
  fitFrustum(camera, rays, toSampling);
  return camera;
}

}  // namespace strata::pgm
