// The HEALPix grid (strata/plugin/healpix.hpp). Sources: the face-local forward and inverse in the HEALPix library's
// closed forms ([Gorski et al. 2005]; [Westerteiger et al. 2011] uses them but prints none, docs/references.md,
// Errata), whose round trip agrees to 5e-15; the pixel numbering of [Gorski et al. 2005, §4, §5]; the planar
// projection of [Calabretta & Roukema 2007] (H = 4, K = 3). The pixel indices floor the same products, in the
// same order, as the HEALPix library does, so that a place on a pixel edge falls into the pixel the library
// puts it in.
#include <strata/plugin/healpix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace strata::healpix {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kQuarterPi = std::numbers::pi / 4.0;
constexpr double kTwoThirds = 2.0 / 3.0;  // |z| of the boundary between the polar caps and the equatorial zone
// Face widths by which a point of the HEALPix plane may lie outside a polar triangle and still be taken as
// on its edge: the plane's coordinates (PROJ's too) put the edge's points a few 1e-16 to either side.
constexpr double kEdgeSlack = 1e-12;

// Per face, its southern corner's ring in face widths (2 at the equator) and its centre's longitude in
// units of pi/4 (the HEALPix library's "jrll" and "jpll", [Gorski et al. 2005]).
constexpr std::array<int, 12> kSouthCornerRing{2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4};
constexpr std::array<int, 12> kCentreLongitude{1, 3, 5, 7, 0, 2, 4, 6, 1, 3, 5, 7};

enum class Zone { northCap, equatorial, southCap };

// A place as HEALPix's forward formulas see it ([Gorski et al. 2005, §4], forward):
// in the equatorial zone `ascending` and `descending` are the global indices, in face widths, of the edge
// lines rising to the east and to the west, 0.5 + tt -/+ 0.75 z; in a cap they are the distances from the
// pole along the two edges of the quadrant `face` covers, in [0, 1]. `turns` is the longitude in quarter
// turns, in [0, 4].
struct EdgeLines {
  Zone zone;
  int face;
  double ascending, descending, turns;
};

// `lon` in [0, 2 pi): fmod keeps it exact; a negative one that rounds up to 2 pi is 0.
double longitudeFromZero(double lon) {
  double phi = std::fmod(lon, kTwoPi);
  if (phi < 0.0) phi += kTwoPi;
  return phi < kTwoPi ? phi : 0.0;
}

int positiveModulo4(int value) { return ((value % 4) + 4) % 4; }

// The face of a point on the ascending and descending edge lines of indices `ascending`, `descending`
// ([Gorski et al. 2005], forward: the same two lines cross in one face, neighbouring ones bound a polar face
// above or below); -1 where the lines are two apart (between the polar triangles of the HEALPix plane).
int faceOfEdgeLines(int ascending, int descending) {
  if (ascending == descending) return 4 + positiveModulo4(ascending);
  if (descending == ascending + 1) return positiveModulo4(ascending);
  if (ascending == descending + 1) return 8 + positiveModulo4(descending);
  return -1;
}

EdgeLines edgeLines(glm::dvec2 lonlat) {
  const double z = std::sin(lonlat.y), za = std::abs(z);
  const double turns = longitudeFromZero(lonlat.x) * (2.0 * std::numbers::inv_pi);
  if (za <= kTwoThirds) {
    const double ascending = 0.5 + turns - 0.75 * z, descending = 0.5 + turns + 0.75 * z;
    const int face = faceOfEdgeLines(static_cast<int>(std::floor(ascending)), static_cast<int>(std::floor(descending)));
    return {Zone::equatorial, face, ascending, descending, turns};
  }
  // sigma = sqrt(3 (1 - |z|)), the distance from the pole in face widths; near the pole from sin(colatitude),
  // which 1 - |z| has lost to cancellation ([Gorski et al. 2005]; the library switches at |z| = 0.99).
  const double sinColatitude = std::cos(lonlat.y);
  const double sigma = za > 0.99 ? sinColatitude / std::sqrt((1.0 + za) / 3.0) : std::sqrt(3.0 * (1.0 - za));
  const int quadrant = std::min(3, static_cast<int>(turns));
  const double fraction = turns - quadrant;
  const double ascending = std::min(1.0, fraction * sigma), descending = std::min(1.0, (1.0 - fraction) * sigma);
  return z > 0.0 ? EdgeLines{Zone::northCap, quadrant, ascending, descending, turns}
                 : EdgeLines{Zone::southCap, quadrant + 8, ascending, descending, turns};
}

// Face-local x and y of edge-line coordinates ([Gorski et al. 2005], forward).
FacePoint toFacePoint(const EdgeLines& lines) {
  switch (lines.zone) {
    case Zone::northCap: return {lines.face, 1.0 - lines.descending, 1.0 - lines.ascending};
    case Zone::southCap: return {lines.face, lines.ascending, lines.descending};
    case Zone::equatorial: break;
  }
  return {lines.face, lines.descending - std::floor(lines.descending),
          1.0 - (lines.ascending - std::floor(lines.ascending))};
}

struct FacePixel {
  int face;
  std::int64_t ix, iy;
};

// The pixel of edge-line coordinates: the distances along the edge lines floored in pixel units, counted
// from the corner the library counts them from ([Gorski et al. 2005, §4]), so that x = 1 or y = 1 stays in
// the face. Scaling by nside, a power of two, is exact: these are the library's products.
FacePixel toFacePixel(std::int64_t nside, const EdgeLines& lines) {
  const auto index = [nside](double distance) {
    return std::min(static_cast<std::int64_t>(std::floor(static_cast<double>(nside) * distance)), nside - 1);
  };
  const auto fromTop = [nside](std::int64_t i) { return nside - 1 - i; };
  switch (lines.zone) {
    case Zone::northCap: return {lines.face, fromTop(index(lines.descending)), fromTop(index(lines.ascending))};
    case Zone::southCap: return {lines.face, index(lines.ascending), index(lines.descending)};
    case Zone::equatorial: break;
  }
  const auto wrapped = [](double line) { return line - std::floor(line); };
  return {lines.face, index(wrapped(lines.descending)), fromTop(index(wrapped(lines.ascending)))};
}

void checkNside(std::int64_t nside, bool nested) {
  if (nside < 1 || nside > kMaxNside)
    throw std::invalid_argument("HEALPix nside " + std::to_string(nside) + " is outside 1 to 2^29");
  if (nested && (nside & (nside - 1)) != 0)
    throw std::invalid_argument("HEALPix nside " + std::to_string(nside) + " is not a power of two (NESTED)");
}

void checkPixel(std::int64_t nside, std::int64_t pixel) {
  if (pixel < 0 || pixel >= 12 * nside * nside)
    throw std::invalid_argument("HEALPix pixel " + std::to_string(pixel) + " is outside 0 to 12 nside^2 - 1");
}

// The bits of `value` moved to the even positions, and back: the NESTED scheme's interleaving
// ([Gorski et al. 2005, §5]), ix's bits even, iy's odd.
std::uint64_t spreadBits(std::uint64_t value) {
  value &= 0xffffffffu;
  value = (value | (value << 16)) & 0x0000ffff0000ffffu;
  value = (value | (value << 8)) & 0x00ff00ff00ff00ffu;
  value = (value | (value << 4)) & 0x0f0f0f0f0f0f0f0fu;
  value = (value | (value << 2)) & 0x3333333333333333u;
  return (value | (value << 1)) & 0x5555555555555555u;
}

std::uint64_t gatherBits(std::uint64_t value) {
  value &= 0x5555555555555555u;
  value = (value | (value >> 1)) & 0x3333333333333333u;
  value = (value | (value >> 2)) & 0x0f0f0f0f0f0f0f0fu;
  value = (value | (value >> 4)) & 0x00ff00ff00ff00ffu;
  value = (value | (value >> 8)) & 0x0000ffff0000ffffu;
  return (value | (value >> 16)) & 0x00000000ffffffffu;
}

std::int64_t toNested(std::int64_t nside, const FacePixel& pixel) {
  const auto bits =
      spreadBits(static_cast<std::uint64_t>(pixel.ix)) | (spreadBits(static_cast<std::uint64_t>(pixel.iy)) << 1);
  return pixel.face * nside * nside + static_cast<std::int64_t>(bits);
}

FacePixel fromNested(std::int64_t nside, std::int64_t pixel) {
  const std::int64_t perFace = nside * nside;
  const auto bits = static_cast<std::uint64_t>(pixel % perFace);
  return {static_cast<int>(pixel / perFace), static_cast<std::int64_t>(gatherBits(bits)),
          static_cast<std::int64_t>(gatherBits(bits >> 1))};
}

// A ring of pixels, numbered 1 to 4 nside - 1 from the north ([Gorski et al. 2005, §4]): its pixels per
// quarter turn (the ring's number within a cap, nside in the equatorial zone), whether its centres are half a
// pixel east of the quarter meridians (all cap rings, every other equatorial ring), and its first pixel.
struct Ring {
  std::int64_t number, perQuarter;
  bool shifted;
  std::int64_t first;
};

Ring ring(std::int64_t nside, std::int64_t number) {
  if (number < nside) return {number, number, true, 2 * number * (number - 1)};
  if (number > 3 * nside) {
    const std::int64_t fromSouth = 4 * nside - number;
    return {number, fromSouth, true, 12 * nside * nside - 2 * fromSouth * (fromSouth + 1)};
  }
  return {number, nside, (number - nside) % 2 == 0, 2 * nside * (nside - 1) + 4 * nside * (number - nside)};
}

// The largest ring number i with 2 i (i - 1) <= count: the cap ring holding the count-th pixel from its pole.
std::int64_t capRing(std::int64_t count) {
  auto i = static_cast<std::int64_t>(0.5 * (1.0 + std::sqrt(1.0 + 2.0 * static_cast<double>(count))));
  while (2 * i * (i - 1) > count) --i;
  while (2 * (i + 1) * i <= count) ++i;
  return i;
}

// A face pixel's ring and its place there (inverting the ring's centre longitude of [Gorski et al. 2005]:
// phi = pi/4 (jpll + (x - y) / nr)).
std::int64_t toRing(std::int64_t nside, const FacePixel& pixel) {
  const auto face = static_cast<std::size_t>(pixel.face);
  const Ring r = ring(nside, kSouthCornerRing[face] * nside - pixel.ix - pixel.iy - 1);
  const std::int64_t perTurn = 4 * r.perQuarter;
  const std::int64_t halfSteps =
      kCentreLongitude[face] * r.perQuarter + pixel.ix - pixel.iy - (r.shifted ? 1 : 0) + 2 * perTurn;
  return r.first + (halfSteps / 2) % perTurn;
}

// The face pixel of a ring pixel: in a cap the quarter turn gives the face, elsewhere the edge-line indices
// through the pixel's centre (the equatorial forward formulas of [Gorski et al. 2005] in integers); then
// x - y from the centre's longitude and x + y from the ring, both in pixel steps.
FacePixel fromRing(std::int64_t nside, std::int64_t pixel) {
  const std::int64_t total = 12 * nside * nside, capPixels = 2 * nside * (nside - 1);
  const std::int64_t number = pixel < capPixels           ? capRing(pixel)
                              : pixel < total - capPixels ? nside + (pixel - capPixels) / (4 * nside)
                                                          : 4 * nside - capRing(total - 1 - pixel);
  const Ring r = ring(nside, number);
  const std::int64_t place = pixel - r.first;
  const std::int64_t steps = 2 * place + (r.shifted ? 1 : 0);  // the centre's longitude in pi / (4 perQuarter)
  if (r.perQuarter < nside) {
    const int face = static_cast<int>(place / r.perQuarter) + (number > 2 * nside ? 8 : 0);
    const std::int64_t difference = steps - kCentreLongitude[static_cast<std::size_t>(face)] * r.perQuarter;
    const std::int64_t sum = kSouthCornerRing[static_cast<std::size_t>(face)] * nside - number - 1;
    return {face, (sum + difference) / 2, (sum - difference) / 2};
  }
  const std::int64_t ascending = (steps + number - nside - 1) / 2, descending = (steps + 3 * nside - number - 1) / 2;
  const int face = faceOfEdgeLines(static_cast<int>(ascending / nside), static_cast<int>(descending / nside));
  return {face, descending % nside, nside - 1 - ascending % nside};
}

}  // namespace

// The face-local inverse ([Gorski et al. 2005]): the ring coordinate jr (face widths from the north pole)
// gives z, in the caps through t = nr^2 / 3 = 1 - |z| so that sin(colatitude) = sqrt(t (2 - t)) keeps its
// precision.
SphericalPoint spherical(const FacePoint& point) {
  const double jr = kSouthCornerRing[static_cast<std::size_t>(point.face)] - point.x - point.y;
  const double centre = kCentreLongitude[static_cast<std::size_t>(point.face)];
  const double capRing = jr < 1.0 ? jr : 4.0 - jr;
  if (jr >= 1.0 && jr <= 3.0) {
    const double z = (2.0 - jr) * kTwoThirds;
    return {z, std::sqrt((1.0 - z) * (1.0 + z)), kQuarterPi * (centre + point.x - point.y)};
  }
  const double t = capRing * capRing / 3.0;
  const double longitude = capRing > 0.0 ? kQuarterPi * (centre + (point.x - point.y) / capRing) : kQuarterPi * centre;
  return {jr < 1.0 ? 1.0 - t : t - 1.0, std::sqrt(t * (2.0 - t)), longitude};
}

FacePoint facePoint(glm::dvec2 lonlat) { return toFacePoint(edgeLines(lonlat)); }

glm::dvec3 unitVector(const FacePoint& point) {
  const SphericalPoint s = spherical(point);
  return {s.sinColatitude * std::cos(s.longitude), s.sinColatitude * std::sin(s.longitude), s.z};
}

glm::dvec2 lonlat(const FacePoint& point) {
  const SphericalPoint s = spherical(point);
  double lon = s.longitude;
  if (lon > kPi) lon -= kTwoPi;
  if (lon <= -kPi) lon += kTwoPi;
  return {lon, std::atan2(s.z, s.sinColatitude)};
}

std::int64_t nestedPixel(std::int64_t nside, glm::dvec2 lonlat) {
  checkNside(nside, true);
  return toNested(nside, toFacePixel(nside, edgeLines(lonlat)));
}

// [Gorski et al. 2005, §4] in the library's arithmetic: in the equatorial zone the edge-line indices give the
// ring (their difference) and the place in it (their sum); in a cap the ring is the sum of the two distances
// from the pole and the place the longitude times the ring's pixels per quarter turn.
std::int64_t ringPixel(std::int64_t nside, glm::dvec2 lonlat) {
  checkNside(nside, false);
  const EdgeLines lines = edgeLines(lonlat);
  const auto n = static_cast<double>(nside);
  if (lines.zone == Zone::equatorial) {
    const auto ascending = static_cast<std::int64_t>(std::floor(n * lines.ascending));
    const auto descending = static_cast<std::int64_t>(std::floor(n * lines.descending));
    const Ring r = ring(nside, 2 * nside + ascending - descending);
    const std::int64_t place = (ascending + descending + 1 - nside - (r.shifted ? 1 : 0)) / 2;
    return r.first + place % (4 * nside);
  }
  const std::int64_t capNumber = static_cast<std::int64_t>(std::floor(n * lines.ascending)) +
                                 static_cast<std::int64_t>(std::floor(n * lines.descending)) + 1;
  const Ring r = ring(nside, lines.zone == Zone::northCap ? capNumber : 4 * nside - capNumber);
  const auto place = static_cast<std::int64_t>(lines.turns * static_cast<double>(capNumber));
  return r.first + place % (4 * capNumber);
}

glm::dvec2 nestedPixelCentre(std::int64_t nside, std::int64_t pixel) {
  checkNside(nside, true);
  checkPixel(nside, pixel);
  const FacePixel p = fromNested(nside, pixel);
  const auto n = static_cast<double>(nside);
  return lonlat({p.face, (static_cast<double>(p.ix) + 0.5) / n, (static_cast<double>(p.iy) + 0.5) / n});
}

glm::dvec2 ringPixelCentre(std::int64_t nside, std::int64_t pixel) {
  checkNside(nside, false);
  checkPixel(nside, pixel);
  const FacePixel p = fromRing(nside, pixel);
  const auto n = static_cast<double>(nside);
  return lonlat({p.face, (static_cast<double>(p.ix) + 0.5) / n, (static_cast<double>(p.iy) + 0.5) / n});
}

std::int64_t nestedToRing(std::int64_t nside, std::int64_t pixel) {
  checkNside(nside, true);
  checkPixel(nside, pixel);
  return toRing(nside, fromNested(nside, pixel));
}

std::int64_t ringToNested(std::int64_t nside, std::int64_t pixel) {
  checkNside(nside, true);
  checkPixel(nside, pixel);
  return toNested(nside, fromRing(nside, pixel));
}

// [Calabretta & Roukema 2007] with H = 4, K = 3 is affine on each face: its equatorial x = phi, y = 3 pi z / 8
// and its polar x = phi_c + (phi - phi_c) sigma, y = pi (2 - sigma) / 4 both become pi/4 (jpll + x - y,
// 2 - jrll + x + y) once phi, z and sigma are written in face coordinates.
glm::dvec2 planeOf(const FacePoint& point) {
  const auto face = static_cast<std::size_t>(point.face);
  double x = kQuarterPi * (kCentreLongitude[face] + point.x - point.y);
  if (x >= kPi) x -= kTwoPi;
  return {x, kQuarterPi * (2 - kSouthCornerRing[face] + point.x + point.y)};
}

// The inverse of planeOf: on the plane the edge lines are straight, jp, jm = (1 + u -/+ v) / 2 for
// (u, v) = 4 (x, y) / pi, and the face is where they cross (the equatorial forward formulas of
// [Gorski et al. 2005] with phi = x, 0.75 z = 2 y / pi).
std::optional<FacePoint> faceOfPlane(glm::dvec2 xy) {
  const double u = std::fmod(xy.x, kTwoPi) / kQuarterPi, v = xy.y / kQuarterPi;
  if (!(std::abs(v) <= 2.0) || !std::isfinite(u)) return std::nullopt;
  const double wrapped = u < 0.0 ? u + 8.0 : u;
  const double ascending = 0.5 * (1.0 + wrapped - v), descending = 0.5 * (1.0 + wrapped + v);
  double ascendingFloor = std::floor(ascending), descendingFloor = std::floor(descending);
  // A point on a polar triangle's edge, or rounded to just beside it, floors into the gap next to the
  // triangle; within kEdgeSlack it belongs to the face below (north) or above (south) the gap.
  if (descendingFloor - ascendingFloor == 2.0) {
    if (descending - descendingFloor <= kEdgeSlack)
      descendingFloor -= 1.0;
    else if (ascendingFloor + 1.0 - ascending <= kEdgeSlack)
      ascendingFloor += 1.0;
  } else if (ascendingFloor - descendingFloor == 2.0) {
    if (ascending - ascendingFloor <= kEdgeSlack)
      ascendingFloor -= 1.0;
    else if (descendingFloor + 1.0 - descending <= kEdgeSlack)
      descendingFloor += 1.0;
  }
  const int face = faceOfEdgeLines(static_cast<int>(ascendingFloor), static_cast<int>(descendingFloor));
  if (face < 0) return std::nullopt;
  return FacePoint{face, std::clamp(descending - descendingFloor, 0.0, 1.0),
                   std::clamp(1.0 - (ascending - ascendingFloor), 0.0, 1.0)};
}

}  // namespace strata::healpix
