// The HEALPix grid (strata/plugin/healpix.hpp) against two references: the HEALPix library's own C implementation,
// chealpix (pixel indices, pixel centres, NESTED <-> RING), and PROJ's +proj=healpix +R=1 (the planar
// projection, both ways); then round trips through the face coordinates.
//
// Places are random and special: the poles, |z| = 2/3 (the boundary between the polar caps and the
// equatorial zone) and the doubles beside it, the equator, the face edges, and longitudes 0, 2 pi and the
// multiples of pi / 4. Tolerances: 1e-12 in radians or unit-sphere units (chord lengths) everywhere; the
// formulas lose a few units of 2^-53 (~1e-15), so 1e-12 leaves room for no error of substance. Indices must
// be equal. PROJ's own rounding near the poles is added where it is larger (see projPolarRounding).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <chealpix.h>
#include <glm/geometric.hpp>
#include <strata/plugin/healpix.hpp>

#include "proj_reference.hpp"

namespace strata::healpix {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kTolerance = 1e-12;
constexpr double kRounding = 0x1p-53;  // u, half a unit in the last place of 1
constexpr std::int64_t kNsides[] = {1, 2, 4, 1024, std::int64_t{1} << 20, std::int64_t{1} << 29};

glm::dvec3 vectorOf(glm::dvec2 lonlat) {
  return {std::cos(lonlat.y) * std::cos(lonlat.x), std::cos(lonlat.y) * std::sin(lonlat.x), std::sin(lonlat.y)};
}

glm::dvec3 vectorOfColatitude(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// `angle` moved by whole turns into [-pi, pi].
double wrapped(double angle) { return std::remainder(angle, kTwoPi); }

// A place as chealpix takes it (colatitude theta, longitude phi) and as Strata does. The pixel a place on a
// pixel edge falls into is decided by the last bit of z, and z = sin(lat) and z = cos(theta) round
// differently (pi / 2 - theta is not even exactly the same latitude), so the latitude is chosen among the
// doubles nearest pi / 2 - theta for one whose sine is bit for bit the library's cos(theta): both sides
// then pixelise the same z and phi.
struct Place {
  double theta, phi;
  glm::dvec2 lonlat;
};

std::optional<Place> place(double theta, double phi) {
  const double z = std::cos(theta);
  for (double start : {kPi / 2.0 - theta, std::asin(z)}) {
    double below = start, above = start;
    for (int step = 0; step < 16; ++step) {
      for (double lat : {below, above})
        if (std::abs(lat) <= kPi / 2.0 && std::sin(lat) == z) return Place{theta, phi, {phi, lat}};
      below = std::nextafter(below, -kPi);
      above = std::nextafter(above, kPi);
    }
  }
  return std::nullopt;
}

// Colatitudes of the poles, of |z| = 2/3 and the doubles beside it, of the equator, and of |z| = 0.99
// (where the polar formulas switch to sin(theta)); longitudes 0, 2 pi, just under 2 pi, and k pi / 4.
std::vector<double> specialColatitudes() {
  std::vector<double> thetas{0.0, kPi, kPi / 2.0, std::acos(0.99), std::acos(-0.99)};
  for (double z : {2.0 / 3.0, -2.0 / 3.0}) {
    const double theta = std::acos(z);
    thetas.insert(thetas.end(), {theta, std::nextafter(theta, 0.0), std::nextafter(theta, 4.0),
                                 std::nextafter(std::nextafter(theta, 4.0), 4.0)});
  }
  return thetas;
}

std::vector<double> specialLongitudes() {
  std::vector<double> phis{kTwoPi, std::nextafter(kTwoPi, 0.0), std::nextafter(0.0, 1.0)};
  for (int k = 0; k < 8; ++k) phis.push_back(k * kPi / 4.0);
  return phis;
}

std::vector<Place> places(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto randomTheta = [&] { return std::acos(2.0 * unit(random) - 1.0); };
  const auto randomPhi = [&] { return kTwoPi * unit(random); };
  std::vector<std::pair<double, double>> wanted;
  for (int i = 0; i < 20000; ++i) wanted.emplace_back(randomTheta(), randomPhi());
  for (double theta : specialColatitudes()) {
    for (double phi : specialLongitudes()) wanted.emplace_back(theta, phi);
    for (int i = 0; i < 100; ++i) wanted.emplace_back(theta, randomPhi());
  }
  for (double phi : specialLongitudes())
    for (int i = 0; i < 100; ++i) wanted.emplace_back(randomTheta(), phi);
  // Face edges and corners, through the face coordinates (so to rounding).
  for (int i = 0; i < 4000; ++i) {
    const double edge = (i % 2) == 0 ? 0.0 : 1.0, along = i % 7 == 0 ? 1.0 - edge : unit(random);
    const FacePoint point{i % 12, (i / 2) % 2 == 0 ? edge : along, (i / 2) % 2 == 0 ? along : edge};
    const glm::dvec2 ll = lonlat(point);
    wanted.emplace_back(kPi / 2.0 - ll.y, ll.x < 0.0 ? ll.x + kTwoPi : ll.x);
  }
  std::vector<Place> result;
  for (auto [theta, phi] : wanted)
    if (const auto p = place(theta, phi)) result.push_back(*p);
  // Nearly every wanted place has a latitude whose sine matches; the few without one are left out (z just
  // under 1/2, finer there than the sines of the latitudes beside it: 1.5% of random places).
  EXPECT_GT(result.size(), wanted.size() * 97 / 100);
  return result;
}

// The pixels compared by number: the first and last of each face, the rings beside the caps' boundaries
// and the equator, and random ones.
std::vector<std::int64_t> pixels(std::int64_t nside, std::uint64_t seed) {
  const std::int64_t total = 12 * nside * nside, cap = 2 * nside * (nside - 1);
  std::vector<std::int64_t> result{0, total - 1, total / 2};
  for (std::int64_t face = 0; face < 12; ++face)
    result.insert(result.end(), {face * nside * nside, (face + 1) * nside * nside - 1});
  for (std::int64_t edge : {cap, total - cap, total / 2 - 2 * nside})
    for (std::int64_t offset = -5; offset <= 5; ++offset)
      result.push_back(std::clamp(edge + offset, std::int64_t{0}, total - 1));
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::int64_t> any(0, total - 1);
  for (int i = 0; i < 5000; ++i) result.push_back(any(random));
  return result;
}

// chealpix's ang2pix_nest64 misnumbers two corners: where |z| = 2/3 and phi rounds to a quarter turn below
// 2 pi, the ascending and descending edge-line indices floor to 4 and 5 (north) or 5 and 4 (south), and its
// face_num = ifp or ifm + 8, lacking a modulo 4, gives face 4 where face 0 is meant (a pixel whose centre lies
// 45 degrees away, on the equator) or face 12 where face 8 is (a pixel number past the last). Such a place
// is checked to be held by our pixel instead: its centre lies within two pixel widths.
bool chealpixMisnumbersCorner(std::int64_t nside, const Place& p, std::int64_t nested) {
  const double za = std::abs(std::cos(p.theta));
  if (!(za >= 2.0 / 3.0 - 1e-15 && za <= 2.0 / 3.0 && p.phi > kTwoPi - 1e-14)) return false;
  const std::int64_t face = nested / (nside * nside);
  const glm::dvec2 ours = nestedPixelCentre(nside, nestedPixel(nside, p.lonlat));
  if (glm::length(vectorOf(ours) - vectorOf(p.lonlat)) > 2.0 / static_cast<double>(nside)) return false;
  if (face == 12) return true;
  double theta = 0.0, phi = 0.0;
  pix2ang_nest64(nside, nested, &theta, &phi);
  return face == 4 && glm::length(vectorOfColatitude(theta, phi) - vectorOf(p.lonlat)) > 0.5;
}

TEST(HealpixGrid, PixelIndicesEqualChealpix) {
  const std::vector<Place> all = places(1);
  for (std::int64_t nside : kNsides) {
    int nestedMismatches = 0, ringMismatches = 0, misnumbered = 0;
    for (const Place& p : all) {
      std::int64_t nested = 0, ring = 0;
      ang2pix_nest64(nside, p.theta, p.phi, &nested);
      ang2pix_ring64(nside, p.theta, p.phi, &ring);
      if (nestedPixel(nside, p.lonlat) != nested && chealpixMisnumbersCorner(nside, p, nested)) {
        ++misnumbered;
        continue;
      }
      if (nestedPixel(nside, p.lonlat) != nested && ++nestedMismatches <= 3)
        ADD_FAILURE() << "nside " << nside << " theta " << p.theta << " phi " << p.phi << ": nested "
                      << nestedPixel(nside, p.lonlat) << ", chealpix " << nested;
      if (ringPixel(nside, p.lonlat) != ring && ++ringMismatches <= 3)
        ADD_FAILURE() << "nside " << nside << " theta " << p.theta << " phi " << p.phi << ": ring "
                      << ringPixel(nside, p.lonlat) << ", chealpix " << ring;
    }
    EXPECT_EQ(nestedMismatches, 0) << "nside " << nside;
    EXPECT_LE(misnumbered, 8) << "nside " << nside;
    if (misnumbered > 0)
      std::cout << "nside " << nside << ": " << misnumbered << " places in chealpix's misnumbered corner\n";
    EXPECT_EQ(ringMismatches, 0) << "nside " << nside;
  }
}

// RING takes any nside. Random places only: with nside not a power of two the two sides round their
// products differently, so places exactly on pixel edges may go either way.
TEST(HealpixGrid, RingIndicesEqualChealpixForAnyNside) {
  const std::vector<Place> all = places(2);
  for (std::int64_t nside : {3, 5, 1000, 12345}) {
    for (std::size_t i = 0; i < 20000; ++i) {
      std::int64_t ring = 0;
      ang2pix_ring64(nside, all[i].theta, all[i].phi, &ring);
      ASSERT_EQ(ringPixel(nside, all[i].lonlat), ring) << "nside " << nside << " place " << i;
    }
    for (std::int64_t pixel : pixels(nside, 3)) {
      double theta = 0.0, phi = 0.0;
      pix2ang_ring64(nside, pixel, &theta, &phi);
      ASSERT_LE(glm::length(vectorOf(ringPixelCentre(nside, pixel)) - vectorOfColatitude(theta, phi)), kTolerance)
          << "nside " << nside << " pixel " << pixel;
    }
  }
}

// Centres compared as unit vectors (chord lengths), which stay meaningful at the poles where longitude
// does not, and by latitude.
TEST(HealpixGrid, PixelCentresEqualChealpix) {
  double worstChord = 0.0, worstLatitude = 0.0;
  for (std::int64_t nside : kNsides) {
    for (std::int64_t pixel : pixels(nside, 4)) {
      double nestedTheta = 0.0, nestedPhi = 0.0, ringTheta = 0.0, ringPhi = 0.0;
      pix2ang_nest64(nside, pixel, &nestedTheta, &nestedPhi);
      pix2ang_ring64(nside, pixel, &ringTheta, &ringPhi);
      const glm::dvec2 nested = nestedPixelCentre(nside, pixel), ring = ringPixelCentre(nside, pixel);
      const double chords[] = {glm::length(vectorOf(nested) - vectorOfColatitude(nestedTheta, nestedPhi)),
                               glm::length(vectorOf(ring) - vectorOfColatitude(ringTheta, ringPhi))};
      const double latitudes[] = {std::abs(nested.y - (kPi / 2.0 - nestedTheta)),
                                  std::abs(ring.y - (kPi / 2.0 - ringTheta))};
      for (int scheme = 0; scheme < 2; ++scheme) {
        EXPECT_LE(chords[scheme], kTolerance) << "nside " << nside << " pixel " << pixel << " scheme " << scheme;
        EXPECT_LE(latitudes[scheme], kTolerance) << "nside " << nside << " pixel " << pixel << " scheme " << scheme;
        worstChord = std::max(worstChord, chords[scheme]);
        worstLatitude = std::max(worstLatitude, latitudes[scheme]);
      }
    }
  }
  std::cout << "pixel centres against chealpix: worst chord " << worstChord << ", latitude " << worstLatitude << '\n';
}

TEST(HealpixGrid, NestedRingConversionsEqualChealpix) {
  for (std::int64_t nside : kNsides) {
    for (std::int64_t pixel : pixels(nside, 5)) {
      std::int64_t ring = 0, nested = 0;
      nest2ring64(nside, pixel, &ring);
      ring2nest64(nside, pixel, &nested);
      ASSERT_EQ(nestedToRing(nside, pixel), ring) << "nside " << nside << " nested pixel " << pixel;
      ASSERT_EQ(ringToNested(nside, pixel), nested) << "nside " << nside << " ring pixel " << pixel;
      ASSERT_EQ(ringToNested(nside, nestedToRing(nside, pixel)), pixel);
    }
  }
}

// The NESTED number written out in the test's own terms: face * nside^2, then ix's bits in the even
// positions and iy's in the odd ones.
std::int64_t nestedNumber(std::int64_t nside, int face, std::int64_t ix, std::int64_t iy) {
  std::int64_t bits = 0;
  for (int bit = 0; bit < 30; ++bit) bits |= (((ix >> bit) & 1) << (2 * bit)) | (((iy >> bit) & 1) << (2 * bit + 1));
  return face * nside * nside + bits;
}

// The face-point convention against chealpix's numbering: chealpix's centre of (face, ix, iy) is the face
// point ((ix + 0.5) / nside, (iy + 0.5) / nside), for the four corner pixels of every face; and the corners
// lie where FacePoint says (the north corner north of the south one, the east corner east of the west one).
TEST(HealpixGrid, FaceConventionMatchesChealpixNumbering) {
  const std::int64_t nside = 8;
  for (int face = 0; face < 12; ++face) {
    for (std::int64_t ix : {std::int64_t{0}, nside - 1})
      for (std::int64_t iy : {std::int64_t{0}, nside - 1}) {
        double theta = 0.0, phi = 0.0;
        pix2ang_nest64(nside, nestedNumber(nside, face, ix, iy), &theta, &phi);
        const FacePoint centre{face, (static_cast<double>(ix) + 0.5) / 8.0, (static_cast<double>(iy) + 0.5) / 8.0};
        EXPECT_LE(glm::length(unitVector(centre) - vectorOfColatitude(theta, phi)), kTolerance)
            << "face " << face << " ix " << ix << " iy " << iy;
      }
    const glm::dvec2 south = lonlat({face, 0.0, 0.0}), north = lonlat({face, 1.0, 1.0});
    const glm::dvec2 east = lonlat({face, 1.0, 0.0}), west = lonlat({face, 0.0, 1.0});
    const glm::dvec2 middle = lonlat({face, 0.5, 0.5});
    EXPECT_GT(north.y, south.y) << "face " << face;
    EXPECT_NEAR(wrapped(east.x - middle.x), kPi / 4.0, kTolerance) << "face " << face;
    EXPECT_NEAR(wrapped(west.x - middle.x), -kPi / 4.0, kTolerance) << "face " << face;
    const double centreLongitude = face < 4   ? kPi / 4.0 + face * kPi / 2.0
                                   : face < 8 ? (face - 4) * kPi / 2.0
                                              : kPi / 4.0 + (face - 8) * kPi / 2.0;
    const double centreLatitude = face < 4 ? std::asin(2.0 / 3.0) : face < 8 ? 0.0 : -std::asin(2.0 / 3.0);
    EXPECT_NEAR(wrapped(middle.x - centreLongitude), 0.0, kTolerance) << "face " << face;
    EXPECT_NEAR(middle.y, centreLatitude, kTolerance) << "face " << face;
  }
}

// The place's face point floors to chealpix's (face, ix, iy), away from pixel edges.
TEST(HealpixGrid, FacePointFloorsToChealpixPixel) {
  const std::vector<Place> all = places(6);
  for (std::int64_t nside : kNsides) {
    const auto n = static_cast<double>(nside);
    for (const Place& p : all) {
      std::int64_t nested = 0;
      ang2pix_nest64(nside, p.theta, p.phi, &nested);
      const FacePoint point = facePoint(p.lonlat);
      const double nx = point.x * n, ny = point.y * n;
      const auto nearEdge = [](double v) { return std::abs(v - std::round(v)) < 1e-6; };
      if (nearEdge(nx) || nearEdge(ny)) continue;
      const auto ix = static_cast<std::int64_t>(nx), iy = static_cast<std::int64_t>(ny);
      ASSERT_EQ(nestedNumber(nside, point.face, ix, iy), nested) << "nside " << nside << " theta " << p.theta;
    }
  }
}

// PROJ's healpix forms 1 - |sin(lat)| by subtraction near the poles: an error d of some 4 u that becomes
// sqrt(3 d), or 3 d / (2 sigma) where smaller, in sigma = sqrt(3 (1 - |sin lat|)), times pi / 2 on the plane
// (as in projection_proj_test.cpp); it is below 1e-12 beyond some 0.1 degree from the poles.
double projPolarRounding(double lat) {
  const double d = 4.0 * kRounding;
  const double sigma = std::sqrt(3.0 * std::pow(std::cos(lat), 2) / (1.0 + std::abs(std::sin(lat))));
  return kPi / 2.0 * std::min(std::sqrt(3.0 * d), 1.5 * d / sigma);
}

// The inverse takes the latitude as asin(1 - sigma^2 / 3): an error d of some 4 u in the argument moves the
// colatitude by d / sin(colatitude), or sqrt(2 d) at the pole.
double projInverseRounding(double lat) {
  const double d = 4.0 * kRounding;
  return std::min(std::sqrt(2.0 * d), d / std::max(std::cos(lat), 1e-300));
}

glm::dvec2 lonlatOf(const Place& p) { return {wrapped(p.phi), p.lonlat.y}; }

TEST(HealpixGrid, PlaneEqualsProjForward) {
  const test::ProjReference proj("+proj=healpix +R=1");
  double worst = 0.0, worstBeyondPoles = 0.0;
  int otherImage = 0;
  for (const Place& p : places(7)) {
    const glm::dvec2 ll = lonlatOf(p);
    const auto reference = proj.forward(ll);
    ASSERT_TRUE(reference) << ll.x << ' ' << ll.y;
    const glm::dvec2 ours = planeOf(facePoint(ll));
    const double error = std::max(std::abs(wrapped(ours.x - reference->x)), std::abs(ours.y - reference->y));
    const double allowed = kTolerance + projPolarRounding(ll.y);
    if (error > allowed) {
      // On a polar face's edge (a meridian k pi / 2 in a cap) the plane has two images of the place, the
      // edges of neighbouring triangles; PROJ's must then be an image of the same place.
      const auto back = faceOfPlane(*reference);
      ASSERT_TRUE(back) << ll.x << ' ' << ll.y;
      EXPECT_LE(glm::length(unitVector(*back) - vectorOf(ll)), allowed) << ll.x << ' ' << ll.y;
      EXPECT_LT(std::abs(wrapped(ll.x - kPi / 2.0 * std::round(ll.x / (kPi / 2.0)))), 1e-9) << ll.x << ' ' << ll.y;
      EXPECT_GT(std::abs(std::sin(ll.y)), 2.0 / 3.0 - 1e-9) << ll.x << ' ' << ll.y;
      ++otherImage;
      continue;
    }
    worst = std::max(worst, error);
    if (projPolarRounding(ll.y) < kTolerance) worstBeyondPoles = std::max(worstBeyondPoles, error);
  }
  std::cout << "plane against PROJ forward: worst " << worst << " (" << worstBeyondPoles
            << " where PROJ's polar rounding is below 1e-12); " << otherImage << " places on a cap's face edge\n";
}

TEST(HealpixGrid, FaceOfPlaneEqualsProjInverse) {
  const test::ProjReference proj("+proj=healpix +R=1");
  std::mt19937_64 random(8);
  std::uniform_real_distribution<double> across(-kPi, kPi), up(-kPi / 2.0, kPi / 2.0);
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 20000; ++i) points.emplace_back(across(random), up(random));
  for (int k = 0; k < 4; ++k) {  // the apices (poles), the belt's edges, x = -pi
    const double apex = -0.75 * kPi + k * kPi / 2.0;
    points.insert(points.end(), {{apex, kPi / 2.0}, {apex, -kPi / 2.0}, {apex, kPi / 2.0 - 1e-9}});
  }
  for (int i = 0; i < 1000; ++i)
    points.insert(points.end(), {{across(random), kPi / 4.0}, {across(random), -kPi / 4.0}, {-kPi, up(random)}});
  double worst = 0.0, worstBeyondPoles = 0.0;
  for (const glm::dvec2& xy : points) {
    const auto reference = proj.inverse(xy);
    const auto ours = faceOfPlane(xy);
    if (reference.has_value() != ours.has_value()) {
      // Only on a triangle's edge may the two round to different sides.
      bool nearEdge = false;
      for (glm::dvec2 step :
           {glm::dvec2(1e-9, 0.0), glm::dvec2(-1e-9, 0.0), glm::dvec2(0.0, 1e-9), glm::dvec2(0.0, -1e-9)})
        nearEdge = nearEdge || faceOfPlane(xy + step).has_value() != ours.has_value();
      EXPECT_TRUE(nearEdge) << xy.x << ' ' << xy.y;
      continue;
    }
    if (!ours) continue;
    const double allowed = kTolerance + projInverseRounding(reference->y);
    const double chord = glm::length(unitVector(*ours) - vectorOf(*reference));
    const double latitude = std::abs(lonlat(*ours).y - reference->y);
    EXPECT_LE(chord, allowed) << xy.x << ' ' << xy.y;
    EXPECT_LE(latitude, allowed) << xy.x << ' ' << xy.y;
    // Longitude as the distance it moves the place along its parallel.
    EXPECT_LE(std::abs(wrapped(lonlat(*ours).x - reference->x)) * std::cos(reference->y), allowed)
        << xy.x << ' ' << xy.y;
    worst = std::max({worst, chord, latitude});
    if (projInverseRounding(reference->y) < kTolerance)
      worstBeyondPoles = std::max({worstBeyondPoles, chord, latitude});
  }
  std::cout << "face of plane against PROJ inverse: worst " << worst << " (" << worstBeyondPoles
            << " where PROJ's polar rounding is below 1e-12)\n";
}

// Round trips, with no reference but the place itself: facePoint -> unitVector and lonlat; face point ->
// lonlat -> facePoint; and whole turns of longitude make no difference.
TEST(HealpixGrid, RoundTrips) {
  double worstChord = 0.0, worstFace = 0.0;
  for (const Place& p : places(9)) {
    for (int turns = -2; turns <= 2; ++turns) {
      const glm::dvec2 ll{p.lonlat.x + turns * kTwoPi, p.lonlat.y};
      const FacePoint point = facePoint(ll);
      const double chord = glm::length(unitVector(point) - vectorOf(p.lonlat));
      EXPECT_LE(chord, kTolerance) << ll.x << ' ' << ll.y;
      const glm::dvec2 back = lonlat(point);
      EXPECT_LE(std::abs(back.y - ll.y), kTolerance) << ll.x << ' ' << ll.y;
      EXPECT_LE(std::abs(wrapped(back.x - ll.x)) * std::cos(ll.y), kTolerance) << ll.x << ' ' << ll.y;
      EXPECT_GT(back.x, -kPi);
      EXPECT_LE(back.x, kPi);
      worstChord = std::max(worstChord, chord);
    }
  }
  std::mt19937_64 random(10);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    // Every fourth point on an edge of its face.
    const double edge = (i / 12) % 2 == 0 ? 0.0 : 1.0;
    const FacePoint point{i % 12, i % 4 == 1 ? edge : unit(random), i % 4 == 3 ? edge : unit(random)};
    const FacePoint again = facePoint(lonlat(point));
    EXPECT_LE(glm::length(unitVector(again) - unitVector(point)), kTolerance);
    const auto onPlane = faceOfPlane(planeOf(point));
    ASSERT_TRUE(onPlane) << point.face << ' ' << point.x << ' ' << point.y;
    EXPECT_LE(glm::length(unitVector(*onPlane) - unitVector(point)), kTolerance);
    if (std::min({point.x, point.y, 1.0 - point.x, 1.0 - point.y}) < 1e-9) continue;
    ASSERT_EQ(again.face, point.face) << point.x << ' ' << point.y;
    worstFace = std::max({worstFace, std::abs(again.x - point.x), std::abs(again.y - point.y)});
  }
  EXPECT_LE(worstFace, kTolerance);
  std::cout << "round trips: worst chord " << worstChord << ", face coordinates " << worstFace << '\n';
}

TEST(HealpixGrid, RejectsNsidesAndPixelsOutOfRange) {
  EXPECT_THROW(nestedPixel(0, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(nestedPixel(3, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(ringPixel(kMaxNside * 2, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(nestedPixelCentre(4, 12 * 16), std::invalid_argument);
  EXPECT_THROW(ringToNested(4, -1), std::invalid_argument);
  EXPECT_NO_THROW(ringPixelCentre(3, 12 * 9 - 1));
}

}  // namespace
}  // namespace strata::healpix
