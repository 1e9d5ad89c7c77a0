// The HEALPix projection (H = 4, K = 3) of [Calabretta & Roukema 2007]: the closed forms that the HEALPix
// terrain generator evaluates ([Westerteiger et al. 2011, §3.1, §3.2.4], which uses them without printing
// them). As in PROJ's healpix, an ellipsoid is mapped through its authalic latitude onto the sphere of equal
// area (Snyder 1987, ch. 3), and the map is scaled by that sphere's radius.
#include "healpix.hpp"

#include <algorithm>
#include <cmath>

#include "projection/projection_terms.hpp"

namespace strata {
namespace {

// atanh(u) / u, which the authalic formulas below are written in to keep their precision near zero.
double atanhRatio(double u) { return u == 0.0 ? 1.0 : std::atanh(u) / u; }

// The authalic latitude beta of a geodetic latitude phi: sin(beta) = q(phi) / q_p (Snyder 1987, ch. 3),
// with q(s) = (1 - e^2) s (1 / (1 - e^2 s^2) + atanh(e s) / (e s)) for s = sin(phi).
class AuthalicLatitude {
 public:
  explicit AuthalicLatitude(double e2) : e2_(e2), e_(std::sqrt(e2)), qp_(1.0 + (1.0 - e2) * atanhRatio(e_)) {}

  double qp() const { return qp_; }

  // |sin(beta)| of `lat` in .x and 1 - |sin(beta)| in .y. The second is formed from 1 - |sin(lat)| =
  // cos^2 / (1 + |sin|) and atanh(e) - atanh(e s) = atanh(e (1 - s) / (1 - e^2 s)), so that it keeps its
  // relative precision at the pole, where the polar-cap formulas take its square root.
  glm::dvec2 sine(double lat) const {
    const double s = std::abs(std::sin(lat));
    const double cosLat = std::cos(lat);
    const double oneMinusS = cosLat * cosLat / (1.0 + s);
    const double q = (1.0 - e2_) * s * (1.0 / (1.0 - e2_ * s * s) + atanhRatio(e_ * s));
    return {q / qp_, oneMinusS * qpMinusQPerOneMinusS(s, oneMinusS) / qp_};
  }

  // |geodetic latitude| of the authalic colatitude `colat` (pi/2 - |beta|): Snyder's series (ch. 3), then
  // Newton steps on q, which leave no truncation error.
  double geodetic(double colat) const {
    const double beta = kHalfPi - colat;
    if (e2_ == 0.0 || colat == 0.0) return beta;
    const double e4 = e2_ * e2_, e6 = e4 * e2_;
    double lat = beta + (e2_ / 3.0 + 31.0 * e4 / 180.0 + 517.0 * e6 / 5040.0) * std::sin(2.0 * beta) +
                 (23.0 * e4 / 360.0 + 251.0 * e6 / 3780.0) * std::sin(4.0 * beta) +
                 761.0 * e6 / 45360.0 * std::sin(6.0 * beta);
    const double target = 2.0 * std::pow(std::sin(0.5 * colat), 2) * qp_;  // q_p (1 - sin(beta))
    for (int step = 0; step < 3; ++step) {
      const double s = std::sin(lat), cosLat = std::cos(lat);
      const double oneMinusS = cosLat * cosLat / (1.0 + s);
      const double dq = 2.0 * (1.0 - e2_) * cosLat / std::pow(1.0 - e2_ * s * s, 2);  // dq / dlat
      lat += (oneMinusS * qpMinusQPerOneMinusS(s, oneMinusS) - target) / dq;
    }
    return lat;
  }

 private:
  // (q_p - q(s)) / (1 - s), for s >= 0.
  double qpMinusQPerOneMinusS(double s, double oneMinusS) const {
    const double w = e_ * oneMinusS / (1.0 - e2_ * s);
    return (1.0 + e2_ * s) / (1.0 - e2_ * s * s) + (1.0 - e2_) / (1.0 - e2_ * s) * atanhRatio(w);
  }

  double e2_;
  double e_;
  double qp_;
};

// The polar cap's central meridian on the plane for a (relative) longitude, extended periodically.
double capCentre(double lon) { return -0.75 * kPi + kHalfPi * std::floor(2.0 * lon / kPi + 2.0); }

class Healpix final : public Projection {
 public:
  Healpix(double lon0, glm::dvec2 origin, const Ellipsoid& ellipsoid)
      : lon0Degrees_(lon0),
        origin_(origin),
        ellipsoid_(ellipsoid),
        authalic_(ellipsoid.eccentricitySquared()),
        radius_(ellipsoid.semiMajorAxis * std::sqrt(0.5 * authalic_.qp())),
        lon0_(lon0 * kDegree),
        centre_(lon0_) {}

  std::string type() const override { return "healpix"; }

  std::string projString() const override {
    return "+proj=healpix" + term("lon_0", lon0Degrees_) + term("x_0", origin_.x) + term("y_0", origin_.y) +
           ellipsoidTerms(ellipsoid_);
  }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (!validLonLat(lonlat)) return std::nullopt;
    const double lon = wrapLongitude(lonlat.x - lon0_, centre_ - lon0_);
    const glm::dvec2 sine = authalic_.sine(lonlat.y);
    const double north = lonlat.y < 0.0 ? -1.0 : 1.0;
    if (sine.x <= 2.0 / 3.0) return radius_ * glm::dvec2(lon, north * 0.375 * kPi * sine.x) + origin_;
    // Polar caps: sigma = sqrt(3 (1 - |z|)) shrinks each cap's quarter of the parallels towards its
    // central meridian, forming the triangles.
    const double sigma = std::sqrt(3.0 * sine.y);
    const double cap = capCentre(lon);
    return radius_ * glm::dvec2(cap + (lon - cap) * sigma, north * 0.25 * kPi * (2.0 - sigma)) + origin_;
  }

  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    const glm::dvec2 plane = (xy - origin_) / radius_;
    const double height = std::abs(plane.y);
    if (!(height <= kHalfPi * (1.0 + 1e-15)) || !std::isfinite(plane.x)) return std::nullopt;
    const double north = plane.y < 0.0 ? -1.0 : 1.0;
    if (height <= 0.25 * kPi) {
      const double colat = kHalfPi - std::asin(plane.y / (0.375 * kPi) * north);
      return glm::dvec2(plane.x + lon0_, north * authalic_.geodetic(colat));
    }
    const double sigma = std::max(2.0 - height / (0.25 * kPi), 0.0);
    const double cap = capCentre(plane.x);
    // Between the triangles of the polar caps the plane maps nowhere.
    if (std::abs(plane.x - cap) > 0.25 * kPi * sigma + 1e-12) return std::nullopt;
    const double lon = sigma > 0.0 ? cap + (plane.x - cap) / sigma : cap;
    // 1 - sin(beta) = sigma^2 / 3 = 2 sin^2(colat / 2), solved for the colatitude without cancellation.
    const double colat = 2.0 * std::asin(sigma / std::sqrt(6.0));
    return glm::dvec2(lon + lon0_, north * authalic_.geodetic(colat));
  }

  std::optional<double> periodX() const override { return kTwoPi * radius_; }
  void setLongitudeCentre(double centre) override { centre_ = centre; }

  std::string glslInclude() const override { return "strata/projection/healpix.glsl"; }
  std::string glslFunction() const override { return "healpix"; }
  std::array<glm::dvec4, 2> glslParameters() const override {
    const double e = std::sqrt(ellipsoid_.eccentricitySquared());
    return {glm::dvec4(lon0_, centre_ - lon0_, e, authalic_.qp()), glm::dvec4(origin_ / radius_, 0.0, 0.0)};
  }
  double glslMapScale() const override { return radius_; }

 private:
  double lon0Degrees_;
  glm::dvec2 origin_;  // false easting and northing, m
  Ellipsoid ellipsoid_;
  AuthalicLatitude authalic_;
  double radius_;  // the authalic radius: a on a sphere
  double lon0_;
  double centre_;  // longitude around which forward() wraps
};

std::unique_ptr<Projection> createHealpix(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  checkEllipsoid(ellipsoid);
  if (!plainFrame(terms) || terms.real("rot_xy", 0.0) != 0.0) return nullptr;  // rotated planes
  return std::make_unique<Healpix>(terms.real("lon_0", 0.0), falseOrigin(terms), ellipsoid);
}

}  // namespace

ProjectionDeclaration healpixDeclaration() {
  return {.type = "healpix",
          .summary = "equal-area HEALPix plane of 12 base patches (Calabretta & Roukema 2007)",
          .projNames = {"healpix"},
          .create = createHealpix};
}

}  // namespace strata
