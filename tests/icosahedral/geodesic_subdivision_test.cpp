// The double reference of the GPU subdivision (plugins/geometry-icosahedral/geodesic_subdivision.hpp)
// against the exact points of its normals, and its float twin, which mirrors the compute shader, against
// the exact points: on an Earth-sized body, for patches of levels 2 to 18 of the icosahedral tree, across
// the date line and at a pole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geodesic_subdivision.hpp"

namespace strata::icosahedral {
namespace {

using Corners = std::array<glm::dvec3, 3>;

constexpr double kEarth = 6371000.0;  // m
constexpr double kPi = std::numbers::pi;
constexpr int kDepth = 5;

glm::dvec3 at(double lonDeg, double latDeg) {
  const double lon = glm::radians(lonDeg), lat = glm::radians(latDeg);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// The edge, rad, of a patch `level` splits below the icosahedron's faces, whose edges span atan(2).
double edgeOfLevel(int level) { return std::atan(2.0) / std::ldexp(1.0, level); }

// An equilateral spherical triangle of the given edge around a centre off the poles, counter-clockwise
// seen from outside (bearings 90, 210 and 330 degrees, counted from east toward north).
Corners patchAround(double lonDeg, double latDeg, double edge) {
  const glm::dvec3 centre = at(lonDeg, latDeg), east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), centre));
  const glm::dvec3 north = glm::cross(centre, east);
  const double toCorner = edge / std::sqrt(3.0);
  Corners corners;
  for (std::size_t c = 0; c < 3; ++c) {
    const double bearing = kPi / 2.0 + 2.0 * kPi / 3.0 * double(c);
    const glm::dvec3 toward = std::cos(bearing) * east + std::sin(bearing) * north;
    corners[c] = std::cos(toCorner) * centre + std::sin(toCorner) * toward;
  }
  return corners;
}

// A patch with a corner at the north pole and two at colatitude `edge`, 72 degrees of longitude apart as
// around the icosahedron's pole, counter-clockwise seen from outside.
Corners patchAtPole(double lonDeg, double edge) {
  const double lat = 90.0 - glm::degrees(edge);
  return {glm::dvec3(0, 0, 1), at(lonDeg, lat), at(lonDeg + 72.0, lat)};
}

glm::dvec3 centreOf(const Corners& corners) { return glm::normalize(corners[0] + corners[1] + corners[2]); }

// The per-frame reference the GPU would take for a patch near the eye: the patch's centre.
LonLatReference referenceAt(const glm::dvec3& normal) {
  return {std::atan2(normal.y, normal.x), std::atan2(normal.z, std::hypot(normal.x, normal.y))};
}

// The largest differences of subdivided vertices from the exact points of the double subdivision's
// normals: on the ground, m, longitude (at the cosine of the latitude) and latitude together; and in
// eye-relative position, m.
struct Discrepancy {
  double ground = 0.0;
  double position = 0.0;
};

template <typename Real>
Discrepancy discrepancy(const std::vector<GeodesicVertex<Real>>& vertices,
                        const std::vector<GeodesicVertex<double>>& reference, const glm::dvec3& eye,
                        LonLatReference origin) {
  Discrepancy worst;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const ExactPoint exact = exactSurfacePoint(reference[i].normal, kEarth, eye, origin);
    const glm::dvec2 error = glm::dvec2(vertices[i].lonlat) - exact.lonlat;
    const double lat = origin.lat + exact.lonlat.y;
    worst.ground = std::max(worst.ground, kEarth * std::hypot(error.x * std::cos(lat), error.y));
    worst.position = std::max(worst.position, glm::length(glm::dvec3(vertices[i].position) - exact.position));
  }
  return worst;
}

template <typename Real>
Discrepancy subdivisionError(const Corners& corners, const glm::dvec3& eye, LonLatReference origin) {
  const SubdivisionTable table(kDepth);
  const PatchSeed seed = patchSeed(corners, kEarth, eye, origin.lon);
  return discrepancy(subdivideGeodesic<Real>(seed, origin, table), subdivideGeodesic<double>(seed, origin, table), eye,
                     origin);
}

struct Case {
  const char* name;
  Corners corners;
};

std::vector<Case> patchesOfLevel(int level) {
  const double edge = edgeOfLevel(level);
  return {{"mid-latitude", patchAround(10.0, 45.0, edge)},
          {"southern", patchAround(-60.0, -70.0, edge)},
          {"date line", patchAround(180.0, 30.0, edge)},
          {"pole", patchAtPole(170.0, edge)}};
}

double angleBetween(const glm::dvec3& u, const glm::dvec3& v) {
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

TEST(GeodesicSubdivision, DoubleSubdivisionGivesTheExactPointsOfItsNormals) {
  for (int level : {2, 16}) {
    for (const Case& patch : patchesOfLevel(level)) {
      SCOPED_TRACE(testing::Message() << "level " << level << ", " << patch.name);
      const glm::dvec3 centre = centreOf(patch.corners);
      for (LonLatReference origin : {referenceAt(centre), LonLatReference{referenceAt(centre).lon, 0.0}}) {
        const Discrepancy error = subdivisionError<double>(patch.corners, (kEarth + 1000.0) * centre, origin);
        EXPECT_LT(error.ground, 1e-6);
        EXPECT_LT(error.position, 1e-6);
      }
    }
  }
}

// Recursive great-circle midpoints along an edge divide its arc into equal parts; each vertex's angle is
// the one between its parents.
TEST(GeodesicSubdivision, NormalsAreGreatCircleMidpoints) {
  const Corners corners = patchAround(10.0, 45.0, edgeOfLevel(2));
  const SubdivisionTable table(kDepth);
  const PatchSeed seed = patchSeed(corners, kEarth, glm::dvec3(0.0), 0.0);
  const std::vector<GeodesicVertex<double>> vertices = subdivideGeodesic<double>(seed, {}, table);
  const int n = table.segments();
  for (int a = 0; a <= n; ++a) {
    const glm::dvec3& normal = vertices[table.indexOf({a, 0})].normal;
    EXPECT_NEAR(angleBetween(corners[0], normal), angleBetween(corners[0], corners[1]) * a / n, 1e-15);
  }
  for (std::uint32_t i = 3; i < std::uint32_t(table.vertexCount()); ++i) {
    const auto [j, k] = table.parents(i);
    EXPECT_NEAR(glm::length(vertices[i].normal), 1.0, 1e-15);
    EXPECT_NEAR(vertices[i].angle, angleBetween(vertices[j].normal, vertices[k].normal), 1e-15);
  }
}

TEST(GeodesicSubdivision, LongitudesStayContinuousAcrossTheDateLine) {
  const Corners corners = patchAround(180.0, 30.0, edgeOfLevel(2));
  const LonLatReference origin = referenceAt(centreOf(corners));
  const PatchSeed seed = patchSeed(corners, kEarth, glm::dvec3(0.0), origin.lon);
  EXPECT_LT(seed.lonlat[1].x, kPi);  // west of the date line,
  EXPECT_GT(seed.lonlat[2].x, kPi);  // east of it, but unwrapped past pi
  for (const GeodesicVertex<float>& vertex : subdivideGeodesic<float>(seed, origin, SubdivisionTable(kDepth)))
    EXPECT_LT(std::abs(vertex.lonlat.x), edgeOfLevel(2));  // measured from the centre, within a patch's width
}

// Small patches, the ones the eye sees from nearby, with the reference at their centre.
TEST(GeodesicSubdivision, FloatLonLatOfSmallPatchesIsWithinAMillimetre) {
  for (int level : {16, 18}) {
    for (const Case& patch : patchesOfLevel(level)) {
      SCOPED_TRACE(testing::Message() << "level " << level << ", " << patch.name);
      const glm::dvec3 centre = centreOf(patch.corners);
      const glm::dvec3 eye = (kEarth + 1000.0) * centre;
      EXPECT_LT(subdivisionError<float>(patch.corners, eye, referenceAt(centre)).ground, 1e-3);
    }
  }
}

// A level-2 patch spans 0.28 rad, and a float coordinate of 0.16 rad, half that, resolves 0.095 m on Earth
// (one ulp); five levels of rounding made 0.13 to 0.19 m when measured, so a millimetre is out of float's
// reach here whatever the formula. Such a patch is drawn only far from the eye, where that is sub-pixel.
TEST(GeodesicSubdivision, FloatLonLatOfALevelTwoPatchIsAsFineAsFloatResolvesIt) {
  for (const Case& patch : patchesOfLevel(2)) {
    SCOPED_TRACE(patch.name);
    const glm::dvec3 centre = centreOf(patch.corners);
    const glm::dvec3 eye = (kEarth + 1000.0) * centre;
    EXPECT_LT(subdivisionError<float>(patch.corners, eye, referenceAt(centre)).ground, 0.3);
  }
}

// The eye 1 m above a vertex of a level-18 patch (about 27 m across) around it.
TEST(GeodesicSubdivision, FloatPositionsNearTheEyeAreWithinAMillimetre) {
  for (const Case& patch : patchesOfLevel(18)) {
    SCOPED_TRACE(patch.name);
    const SubdivisionTable table(kDepth);
    const LonLatReference origin = referenceAt(centreOf(patch.corners));
    const std::uint32_t below = table.indexOf({table.segments() / 4, table.segments() / 4});
    const PatchSeed fromCentre = patchSeed(patch.corners, kEarth, glm::dvec3(0.0), origin.lon);
    const glm::dvec3 nadir = subdivideGeodesic<double>(fromCentre, origin, table)[below].normal;
    const glm::dvec3 eye = (kEarth + 1.0) * nadir;
    const PatchSeed seed = patchSeed(patch.corners, kEarth, eye, origin.lon);
    const GeodesicVertex<float> vertex = subdivideGeodesic<float>(seed, origin, table)[below];
    EXPECT_LT(glm::length(glm::dvec3(vertex.position) + nadir), 1e-3);  // it lies at -nadir, 1 m below
    EXPECT_LT(subdivisionError<float>(patch.corners, eye, origin).position, 1e-3);
  }
}

}  // namespace
}  // namespace strata::icosahedral
