// The compute pass of geometry.icosahedral (plugins/geometry-icosahedral/subdivide_patches.comp) run on the headless
// context and read back, against the subdivision done in double on an Earth-sized body. A vertex's
// longitude and latitude must be right on the ground to 1 mm plus a millionth of its distance from the
// eye: a millionth of a radian is a thousandth of a pixel of a 1280-pixel, 45-degree view, and float
// cannot do better far away (one ulp of a longitude 0.1 rad from the reference is 5 cm on Earth).
// Positions a metre or so from the eye must be right to 1 mm (issue 4).
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_patches.hpp"

namespace strata::icosahedral {
namespace {

constexpr double kEarth = test::GpuPatches::kRadius;

glm::dvec3 at(double lonDeg, double latDeg) {
  const double lon = glm::radians(lonDeg), lat = glm::radians(latDeg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// A patch around the direction: corners `size` metres apart on the ground, counter-clockwise from outside.
Patch patchAround(const glm::dvec3& centre, double size) {
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), centre));
  const glm::dvec3 north = glm::cross(centre, east);
  const double a = size / kEarth / std::sqrt(3.0);
  const auto corner = [&](double angle) {
    return glm::normalize(centre + a * (std::cos(angle) * east + std::sin(angle) * north));
  };
  return {{corner(glm::radians(-90.0)), corner(glm::radians(30.0)), corner(glm::radians(150.0))}, 0, 0};
}

struct Errors {
  double ground = 0.0;    // the largest ground distance between the GPU's lonlat and the reference's, over
                          // what it may be: 1 mm + 1e-6 x the vertex's distance from the eye; below 1 passes
  double position = 0.0;  // m: the largest distance between the GPU's position and the reference's
};

// Subdivides one patch on the GPU as seen from `eye` and measures it against the double subdivision.
Errors subdivideOnGpu(const Patch& patch, const glm::dvec3& eye) {
  View view;
  view.eye = eye;
  view.reference = {std::atan2(eye.y, eye.x), std::asin(eye.z / glm::length(eye))};  // as makeView sets it
  static test::GpuPatches gpu;                                                       // one program for all the tests
  const auto [batch, vertices] = gpu.subdivide({patch}, view, 1.0);                  // level 0: never morphed
  const SubdivisionTable& table = gpu.table();

  const glm::dvec3 centre = patch.corners[0] + patch.corners[1] + patch.corners[2];
  const PatchSeed seed = patchSeed(patch.corners, kEarth, eye, std::atan2(centre.y, centre.x));
  const auto reference = subdivideGeodesic<double>(seed, batch.reference, table);
  Errors errors;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const glm::dvec2 d = glm::dvec2(vertices[i].lonlat) - reference[i].lonlat;
    const double lat = batch.reference.lat + reference[i].lonlat.y;
    const double allowed = 1e-3 + 1e-6 * glm::length(reference[i].position);
    errors.ground = std::max(errors.ground, kEarth * std::hypot(d.x * std::cos(lat), d.y) / allowed);
    errors.position =
        std::max(errors.position, glm::length(glm::dvec3(glm::vec3(vertices[i].position)) - reference[i].position));
  }
  return errors;
}

TEST(GpuSubdivision, ALargePatchSeenFromAfarIsRight) {
  const glm::dvec3 centre = at(30.0, 40.0);
  EXPECT_LT(subdivideOnGpu(patchAround(centre, 1.5e6), centre * (kEarth + 2e6)).ground, 1.0);
}

TEST(GpuSubdivision, APatchAcrossTheDateLineIsRight) {
  const glm::dvec3 centre = at(180.0, 10.0);
  EXPECT_LT(subdivideOnGpu(patchAround(centre, 2e4), centre * (kEarth + 1e4)).ground, 1.0);
}

// A 40 m patch with a corner on the north pole, the eye 10 m above the pole.
TEST(GpuSubdivision, APatchAtThePoleIsRight) {
  Patch patch = patchAround(at(0.0, 90.0 - glm::degrees(15.0 / kEarth)), 40.0);
  patch.corners[2] = glm::dvec3(0, 0, 1);
  EXPECT_LT(subdivideOnGpu(patch, glm::dvec3(0, 0, kEarth + 10.0)).ground, 1.0);
}

// The eye 1 m above a 4 m patch: every vertex is within a few metres of it.
TEST(GpuSubdivision, PositionsAMetreFromTheEyeAreRightToAMillimetre) {
  const glm::dvec3 centre = at(-120.0, -35.0);
  const Errors errors = subdivideOnGpu(patchAround(centre, 4.0), centre * (kEarth + 1.0));
  EXPECT_LT(errors.position, 1e-3);
  EXPECT_LT(errors.ground, 1.0);
}

}  // namespace
}  // namespace strata::icosahedral
