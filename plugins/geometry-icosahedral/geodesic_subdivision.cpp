#include "geodesic_subdivision.hpp"

#include <cmath>
#include <numbers>

namespace strata::icosahedral {
namespace {

glm::dvec2 unwrappedLonLat(const glm::dvec3& normal, double nearLongitude) {
  const double lon = std::atan2(normal.y, normal.x);
  return {nearLongitude + std::remainder(lon - nearLongitude, 2.0 * std::numbers::pi),
          std::atan2(normal.z, std::hypot(normal.x, normal.y))};
}

bool atPole(const glm::dvec3& normal) { return std::hypot(normal.x, normal.y) < 1e-12; }

// sin and cos of the reference latitude, computed in double and rounded once: the shader's uniforms.
template <typename Real>
struct ReferenceLatitude {
  Real sin;
  Real cos;
};

// The normal and the angle between the parents ([Kooima 2008, §3.3.3], the angle from the chord rather than
// acos; docs/references.md, Errata). The sum
// is symmetric in the parents, and so is the chord |n_j - n_k|, from which w = 2 asin(chord / 2) keeps its
// resolution as w tends to 0, where acos of the dot product loses it.
template <typename Real>
void subdivideNormal(const GeodesicVertex<Real>& j, const GeodesicVertex<Real>& k, GeodesicVertex<Real>& i) {
  i.normal = glm::normalize(j.normal + k.normal);
  i.angle = Real(2) * std::asin(Real(0.5) * glm::length(j.normal - k.normal));
}

// The geodesic midpoint of [Kooima 2008, §3.3.4] (the method it uses, not the one it rejects), both
// coordinates measured from the reference rather than absolute (docs/references.md, Errata), written as
// the plain midpoint plus two corrections; the compute pass (subdivide_patches.comp) does the same,
// operation for operation. With A, B the cosines of the parents' latitudes, phi_m and delta the mean and
// half the difference of those latitudes, and D the difference of the longitudes, the thesis's
// lambda_i = lambda_j + atan2(B sin D, A + B cos D), rotated by -D/2, is
//   lambda_i = lambda_m + atan(-sin phi_m sin delta tan(D/2), cos phi_m cos delta)
// (B - A = -2 sin phi_m sin delta, A + B = 2 cos phi_m cos delta), and its
// tan phi_i = (sin phi_j + sin phi_k) / h, with h^2 = (A + B)^2 - 4 A B sin^2(D/2), is
//   phi_i = phi_m + atan(sin phi_m cos phi_m u, 1 + u sin^2 phi_m),
//   u = 1/sqrt(1 - s) - 1 = s / (sqrt(1 - s) (1 + sqrt(1 - s))),  s = A B sin^2(D/2) / (cos phi_m cos delta)^2.
// The corrections are second order in the parents' separation, so the error of a GPU's sin, cos and atan
// (about 1e-6 on llvmpipe, tens of metres on Earth in the thesis's form) only scales them. Longitude only
// ever enters as differences, so it is never wrapped.
template <typename Real>
glm::vec<2, Real> geodesicMidpoint(glm::vec<2, Real> j, glm::vec<2, Real> k, ReferenceLatitude<Real> reference) {
  const glm::vec<2, Real> middle = Real(0.5) * (j + k);
  const Real halfDLon = Real(0.5) * (k.x - j.x), halfDLat = Real(0.5) * (k.y - j.y);
  // sin and cos of the absolute mean latitude, from the reference's and the relative one's
  const Real sinMiddle = reference.sin * std::cos(middle.y) + reference.cos * std::sin(middle.y);
  const Real cosMiddle = reference.cos * std::cos(middle.y) - reference.sin * std::sin(middle.y);
  const Real cosDelta = std::cos(halfDLat), sinDelta = std::sin(halfDLat);
  const Real cosJ = cosMiddle * cosDelta + sinMiddle * sinDelta, cosK = cosMiddle * cosDelta - sinMiddle * sinDelta;
  const Real lonCorrection = std::atan2(-sinMiddle * sinDelta * std::tan(halfDLon), cosMiddle * cosDelta);
  const Real sinHalfDLon = std::sin(halfDLon), cosMiddleDelta = cosMiddle * cosDelta;
  const Real s = cosJ * cosK * sinHalfDLon * sinHalfDLon / (cosMiddleDelta * cosMiddleDelta);
  const Real root = std::sqrt(Real(1) - s);
  const Real u = s / (root * (Real(1) + root));
  const Real latCorrection = std::atan2(sinMiddle * cosMiddle * u, Real(1) + u * sinMiddle * sinMiddle);
  return middle + glm::vec<2, Real>(lonCorrection, latCorrection);
}

// The position without the radius ([Kooima 2008, §3.3.5], whose Fig. 3.9 is missing; docs/references.md,
// Errata): the chord's midpoint raised along the new normal by the sagitta x tan(w / 4), x being half the
// chord. That is exact on the sphere (x = r sin(w/2), sagitta r (1 - cos(w/2))) and tends to the plain
// midpoint as w tends to 0, so float keeps its precision at every scale.
template <typename Real>
void subdividePosition(const GeodesicVertex<Real>& j, const GeodesicVertex<Real>& k, GeodesicVertex<Real>& i) {
  const Real halfChord = Real(0.5) * glm::length(j.position - k.position);
  i.position = Real(0.5) * (j.position + k.position) + halfChord * std::tan(Real(0.25) * i.angle) * i.normal;
}

template <typename Real>
GeodesicVertex<Real> seedVertex(const PatchSeed& seed, std::size_t corner, LonLatReference reference) {
  const glm::dvec2 lonlat = seed.lonlat[corner] - glm::dvec2(reference.lon, reference.lat);
  return {glm::vec<3, Real>(seed.normals[corner]), Real(0), glm::vec<2, Real>(lonlat),
          glm::vec<3, Real>(seed.positions[corner])};
}

}  // namespace

PatchSeed patchSeed(const std::array<glm::dvec3, 3>& normals, double radius, const glm::dvec3& eye,
                    double nearLongitude) {
  PatchSeed seed{normals, {}, {}};
  for (std::size_t c = 0; c < 3; ++c) {
    seed.lonlat[c] = unwrappedLonLat(normals[c], nearLongitude);
    seed.positions[c] = radius * normals[c] - eye;
  }
  for (std::size_t c = 0; c < 3; ++c)
    if (atPole(normals[c])) seed.lonlat[c].x = 0.5 * (seed.lonlat[(c + 1) % 3].x + seed.lonlat[(c + 2) % 3].x);
  return seed;
}

template <typename Real>
std::vector<GeodesicVertex<Real>> subdivideGeodesic(const PatchSeed& seed, LonLatReference reference,
                                                    const SubdivisionTable& table) {
  std::vector<GeodesicVertex<Real>> vertices(std::size_t(table.vertexCount()));
  for (std::size_t corner = 0; corner < 3; ++corner) vertices[corner] = seedVertex<Real>(seed, corner, reference);
  const ReferenceLatitude<Real> latitude{Real(std::sin(reference.lat)), Real(std::cos(reference.lat))};
  // Parents precede their children, so index order is one of the orders level-by-level passes allow.
  for (std::uint32_t i = 3; i < std::uint32_t(table.vertexCount()); ++i) {
    const auto [j, k] = table.parents(i);
    GeodesicVertex<Real>& vertex = vertices[i];
    subdivideNormal(vertices[j], vertices[k], vertex);
    // Ordered by value as the compute pass orders them, so that shared edges subdivide alike.
    const glm::vec<2, Real> lj = vertices[j].lonlat, lk = vertices[k].lonlat;
    const bool ordered = lj.x < lk.x || (lj.x == lk.x && lj.y <= lk.y);
    vertex.lonlat = ordered ? geodesicMidpoint(lj, lk, latitude) : geodesicMidpoint(lk, lj, latitude);
    subdividePosition(vertices[j], vertices[k], vertex);
  }
  return vertices;
}

template std::vector<GeodesicVertex<float>> subdivideGeodesic<float>(const PatchSeed&, LonLatReference,
                                                                     const SubdivisionTable&);
template std::vector<GeodesicVertex<double>> subdivideGeodesic<double>(const PatchSeed&, LonLatReference,
                                                                       const SubdivisionTable&);

ExactPoint exactSurfacePoint(const glm::dvec3& normal, double radius, const glm::dvec3& eye,
                             LonLatReference reference) {
  return {unwrappedLonLat(normal, reference.lon) - glm::dvec2(reference.lon, reference.lat), radius * normal - eye};
}

}  // namespace strata::icosahedral
