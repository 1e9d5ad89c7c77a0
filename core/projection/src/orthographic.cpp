// Orthographic projection on the sphere and the ellipsoid. Forward: EPSG Guidance Note 7-2 (2020),
// section 3.3.5 "Orthographic" (EPSG method 9840), as PROJ 9 computes it; on a sphere it is Snyder (1987),
// ch. 20. The map is the tangent plane at the centre, each point reached along the normal there, so the
// inverse intersects that line with the ellipsoid in closed form (GN 7-2 iterates instead).
#include "orthographic.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "projection/projection_terms.hpp"

namespace strata {
namespace {

// The mapping as the CRS defines it (angles in degrees, as PROJ writes them).
struct OrthographicForm {
  double lat0 = 0.0;
  double lon0 = 0.0;
  glm::dvec2 origin{0.0};  // false easting and northing, m
  Ellipsoid ellipsoid;
};

class Orthographic final : public Projection {
 public:
  explicit Orthographic(const OrthographicForm& form)
      : form_(form),
        a_(form.ellipsoid.semiMajorAxis),
        e2_(form.ellipsoid.eccentricitySquared()),
        lat0_(form.lat0 * kDegree),
        lon0_(form.lon0 * kDegree),
        sinLat0_(std::sin(lat0_)),
        cosLat0_(std::cos(lat0_)),
        nu0_(1.0 / std::sqrt(1.0 - e2_ * sinLat0_ * sinLat0_)) {}

  std::string type() const override { return "orthographic"; }

  std::string projString() const override {
    return "+proj=ortho" + term("lat_0", form_.lat0) + term("lon_0", form_.lon0) + term("x_0", form_.origin.x) +
           term("y_0", form_.origin.y) + ellipsoidTerms(form_.ellipsoid);
  }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (!validLonLat(lonlat)) return std::nullopt;
    const double lon = lonlat.x - lon0_;
    const double sinLat = std::sin(lonlat.y), cosLat = std::cos(lonlat.y);
    // The far side, where the normal points away from the one at the centre (GN 7-2, as PROJ tests it).
    if (sinLat0_ * sinLat + cosLat0_ * cosLat * std::cos(lon) < 0.0) return std::nullopt;
    const double nu = 1.0 / std::sqrt(1.0 - e2_ * sinLat * sinLat);
    // cos(lat0) sin(lat) - sin(lat0) cos(lat) cos(lon), written without the cancellation near the centre.
    const double halfLonSine = std::sin(0.5 * lon);
    const double north = std::sin(lonlat.y - lat0_) + 2.0 * sinLat0_ * cosLat * halfLonSine * halfLonSine;
    const double x = nu * cosLat * std::sin(lon);
    const double y = nu * north + e2_ * (nu0_ * sinLat0_ - nu * sinLat) * cosLat0_;
    return a_ * glm::dvec2(x, y) + form_.origin;
  }

  // In units of a, in the frame of the centre's meridian (x towards (0, lon0), y east, z north): the
  // point p0 + x east + y north of the tangent plane, moved along the normal n by the t that puts it on
  // the ellipsoid x^2 + y^2 + z^2 / (1 - e^2) = 1. The larger root is the near side.
  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    const glm::dvec2 map = (xy - form_.origin) / a_;
    const glm::dvec3 normal(cosLat0_, 0.0, sinLat0_);
    const glm::dvec3 p = glm::dvec3(nu0_ * cosLat0_, 0.0, nu0_ * (1.0 - e2_) * sinLat0_) +
                         glm::dvec3(-map.y * sinLat0_, map.x, map.y * cosLat0_);
    const glm::dvec3 metric(1.0, 1.0, 1.0 / (1.0 - e2_));  // the ellipsoid's quadratic form
    const double qa = glm::dot(normal * metric, normal);
    const double qb = glm::dot(p * metric, normal);
    const double qc = glm::dot(p * metric, p) - 1.0;
    const double discriminant = qb * qb - qa * qc;
    if (!(discriminant >= 0.0)) return std::nullopt;  // beyond the rim
    const double root = std::sqrt(discriminant);
    const double t = qb > 0.0 ? -qc / (qb + root) : (root - qb) / qa;  // the form without cancellation
    const glm::dvec3 s = p + t * normal;
    const double lat = std::atan2(s.z, (1.0 - e2_) * std::hypot(s.x, s.y));
    return glm::dvec2(wrapLongitude(lon0_ + std::atan2(s.y, s.x), 0.0), lat);
  }

  std::string glslInclude() const override { return "strata/projection/orthographic.glsl"; }
  std::string glslFunction() const override { return "orthographic"; }
  std::array<glm::dvec4, 2> glslParameters() const override {
    return {glm::dvec4(lon0_, sinLat0_, cosLat0_, e2_), glm::dvec4(form_.origin / a_, nu0_, lat0_)};
  }
  double glslMapScale() const override { return a_; }
  ProjectionAspect aspect() const override { return azimuthalAspect(form_.lat0); }

 private:
  OrthographicForm form_;
  double a_;
  double e2_;
  double lat0_;
  double lon0_;
  double sinLat0_;
  double cosLat0_;
  double nu0_;  // the prime vertical radius of curvature at the centre, in units of a
};

std::unique_ptr<Projection> createOrthographic(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  checkEllipsoid(ellipsoid);
  // A scale factor is a variant PROJ 9.1 ignores and later versions may not: declined rather than guessed.
  if (!plainFrame(terms) || scaleFactorTerm(terms) != 1.0) return nullptr;
  return std::make_unique<Orthographic>(OrthographicForm{.lat0 = latitudeTerm(terms, "lat_0"),
                                                         .lon0 = terms.real("lon_0", 0.0),
                                                         .origin = falseOrigin(terms),
                                                         .ellipsoid = ellipsoid});
}

}  // namespace

ProjectionDeclaration orthographicDeclaration() {
  return {.type = "orthographic",
          .summary = "the visible hemisphere as seen from infinitely far away (photographs from afar)",
          .projNames = {"ortho"},
          .create = createOrthographic};
}

}  // namespace strata
