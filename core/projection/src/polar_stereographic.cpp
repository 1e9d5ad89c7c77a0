// Polar stereographic projection on the sphere and the ellipsoid. Snyder (1987), ch. 21: rho from the
// scale factor at the pole (eq. 21-33) or from the true-scale latitude (eq. 21-34), with t (eq. 15-9) and
// m (eq. 14-15); the south aspect changes the signs of the latitude and of y. The inverse solves for the
// latitude by Snyder's iteration, eq. 7-9.
#include "polar_stereographic.hpp"

#include <cmath>

#include "projection/projection_terms.hpp"

namespace strata {
namespace {

// The mapping as the CRS defines it (angles in degrees, as PROJ writes them).
struct PolarStereographicForm {
  double pole = 1.0;            // +1: north polar aspect, -1: south
  std::optional<double> latTs;  // true-scale latitude; absent: k0 is the scale at the pole
  double k0 = 1.0;
  double lon0 = 0.0;
  glm::dvec2 origin{0.0};  // false easting and northing, m
  Ellipsoid ellipsoid;
};

class PolarStereographic final : public Projection {
 public:
  explicit PolarStereographic(const PolarStereographicForm& form)
      : form_(form),
        a_(form.ellipsoid.semiMajorAxis),
        e_(std::sqrt(form.ellipsoid.eccentricitySquared())),
        lon0_(form.lon0 * kDegree),
        rhoPerT_(rhoPerT()) {}

  std::string type() const override { return "polar-stereographic"; }

  std::string projString() const override {
    const std::string scale = form_.latTs ? term("lat_ts", *form_.latTs) : term("k_0", form_.k0);
    return "+proj=stere" + term("lat_0", 90.0 * form_.pole) + scale + term("lon_0", form_.lon0) +
           term("x_0", form_.origin.x) + term("y_0", form_.origin.y) + ellipsoidTerms(form_.ellipsoid);
  }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (!validLonLat(lonlat)) return std::nullopt;
    const double t = isometricT(form_.pole * lonlat.y);
    if (!std::isfinite(t)) return std::nullopt;  // the opposite pole lies at infinity
    const double rho = a_ * rhoPerT_ * t;
    const double lon = lonlat.x - lon0_;
    return glm::dvec2(rho * std::sin(lon), -form_.pole * rho * std::cos(lon)) + form_.origin;
  }

  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    const glm::dvec2 plane = xy - form_.origin;
    const double rho = std::hypot(plane.x, plane.y);
    if (!std::isfinite(rho)) return std::nullopt;
    const double lon = rho == 0.0 ? 0.0 : std::atan2(plane.x, -form_.pole * plane.y);
    return glm::dvec2(wrapLongitude(lon0_ + lon, 0.0), form_.pole * latitudeOfT(rho / (a_ * rhoPerT_)));
  }

  std::string glslInclude() const override { return "strata/projection/polar_stereographic.glsl"; }
  std::string glslFunction() const override { return "polarStereographic"; }
  std::array<glm::dvec4, 2> glslParameters() const override {
    return {glm::dvec4(lon0_, form_.pole, e_, rhoPerT_), glm::dvec4(form_.origin / a_, 0.0, 0.0)};
  }
  double glslMapScale() const override { return a_; }
  ProjectionAspect aspect() const override {
    return form_.pole > 0.0 ? ProjectionAspect::NorthPolar : ProjectionAspect::SouthPolar;
  }

 private:
  // Snyder's t (eq. 15-9) at latitude `lat` towards the pole, with tan(pi/4 - lat/2) written as
  // cos(lat) / (1 + sin(lat)), which keeps its relative precision near the pole.
  double isometricT(double lat) const {
    const double sinLat = std::sin(lat);
    return std::cos(lat) / (1.0 + sinLat) * std::pow((1.0 + e_ * sinLat) / (1.0 - e_ * sinLat), 0.5 * e_);
  }

  // Snyder eq. 7-9, iterated from the spherical solution; each step gains a factor of about e^2.
  double latitudeOfT(double t) const {
    double lat = kHalfPi - 2.0 * std::atan(t);
    for (int step = 0; step < 30 && e_ > 0.0; ++step) {
      const double eSinLat = e_ * std::sin(lat);
      const double next = kHalfPi - 2.0 * std::atan(t * std::pow((1.0 - eSinLat) / (1.0 + eSinLat), 0.5 * e_));
      const bool converged = std::abs(next - lat) <= 1e-15;
      lat = next;
      if (converged) break;
    }
    return lat;
  }

  // rho / (a t): m_c / t_c at the true-scale latitude (eq. 21-34), else from k0 at the pole (eq. 21-33).
  // PROJ takes the true-scale latitude by its magnitude, and k0 when it is the pole itself.
  double rhoPerT() const {
    if (form_.latTs && (90.0 - std::abs(*form_.latTs)) * kDegree >= 1e-10) {
      const double latC = std::abs(*form_.latTs) * kDegree;
      const double eSinLatC = e_ * std::sin(latC);
      return std::cos(latC) / std::sqrt(1.0 - eSinLatC * eSinLatC) / isometricT(latC);
    }
    return 2.0 * form_.k0 / std::sqrt(std::pow(1.0 + e_, 1.0 + e_) * std::pow(1.0 - e_, 1.0 - e_));
  }

  PolarStereographicForm form_;
  double a_;
  double e_;
  double lon0_;
  double rhoPerT_;  // rho = a rhoPerT_ t
};

std::unique_ptr<Projection> createStereographic(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  checkEllipsoid(ellipsoid);
  if (!plainFrame(terms)) return nullptr;
  const double lat0 = latitudeTerm(terms, "lat_0");
  if (azimuthalAspect(lat0) == ProjectionAspect::Other) return nullptr;  // oblique and equatorial aspects
  PolarStereographicForm form{.pole = lat0 > 0.0 ? 1.0 : -1.0,
                              .k0 = scaleFactorTerm(terms),
                              .lon0 = terms.real("lon_0", 0.0),
                              .origin = falseOrigin(terms),
                              .ellipsoid = ellipsoid};
  if (terms.has("lat_ts")) {
    form.latTs = latitudeTerm(terms, "lat_ts");
    if (*form.latTs * form.pole < 0.0)
      throw projectionError("the true-scale latitude" + term("lat_ts", *form.latTs) +
                                " lies in the other hemisphere than the pole" + term("lat_0", lat0),
                            "give +lat_ts with the sign of +lat_0 (PROJ would read" + term("lat_ts", *form.latTs) +
                                " as" + term("lat_ts", -*form.latTs) + ")");
  }
  return std::make_unique<PolarStereographic>(form);
}

// UPS: the polar stereographic of an ellipsoid with k0 = 0.994 and a false origin of 2000 km.
std::unique_ptr<Projection> createUps(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  checkEllipsoid(ellipsoid);
  if (!plainFrame(terms)) return nullptr;
  if (ellipsoid.inverseFlattening == 0.0)
    throw projectionError("+proj=ups is defined on an ellipsoid only, and this CRS gives a sphere",
                          "for a sphere write the same map as +proj=stere +lat_0=90 +k_0=0.994 +x_0=2000000 "
                          "+y_0=2000000 (+lat_0=-90 for the south)");
  return std::make_unique<PolarStereographic>(PolarStereographicForm{
      .pole = terms.has("south") ? -1.0 : 1.0, .k0 = 0.994, .origin = {2000000.0, 2000000.0}, .ellipsoid = ellipsoid});
}

std::unique_ptr<Projection> createPolarStereographic(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  return terms.name() == "ups" ? createUps(terms, ellipsoid) : createStereographic(terms, ellipsoid);
}

}  // namespace

ProjectionDeclaration polarStereographicDeclaration() {
  return {.type = "polar-stereographic",
          .summary = "conformal azimuthal map of a polar cap, north or south, any true-scale latitude",
          .projNames = {"stere", "ups"},
          .create = createPolarStereographic};
}

}  // namespace strata
