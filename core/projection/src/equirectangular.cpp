// Equirectangular projection: x proportional to longitude, y to latitude. Snyder (1987), ch. 12
// "Equidistant cylindrical", eqs. 12-1 and 12-2, on the sphere of radius a, which PROJ's eqc uses for
// ellipsoids as well. A geographic CRS is the same mapping with one degree per radian / (180 / pi).
#include "equirectangular.hpp"

#include <algorithm>
#include <cmath>

#include "projection/projection_terms.hpp"

namespace strata {
namespace {

// The mapping as the CRS defines it (angles in degrees, as PROJ writes them).
struct EquirectangularForm {
  bool geographic = false;  // +proj=longlat: degrees, with no false origin, lat_0 or lat_ts (as PROJ)
  double lon0 = 0.0;
  double lat0 = 0.0;
  double latTs = 0.0;
  glm::dvec2 origin{0.0};  // false easting and northing, m
  Ellipsoid ellipsoid;
};

class Equirectangular final : public Projection {
 public:
  explicit Equirectangular(const EquirectangularForm& form)
      : form_(form),
        radius_(form.geographic ? 1.0 / kDegree : form.ellipsoid.semiMajorAxis),
        lon0_(form.lon0 * kDegree),
        lat0_(form.lat0 * kDegree),
        cosTs_(std::cos(form.latTs * kDegree)),
        centre_(lon0_) {}

  std::string type() const override { return "equirectangular"; }

  std::string projString() const override {
    if (form_.geographic) return "+proj=longlat" + term("lon_0", form_.lon0) + ellipsoidTerms(form_.ellipsoid);
    return "+proj=eqc" + term("lat_ts", form_.latTs) + term("lat_0", form_.lat0) + term("lon_0", form_.lon0) +
           term("x_0", form_.origin.x) + term("y_0", form_.origin.y) + ellipsoidTerms(form_.ellipsoid);
  }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (!validLonLat(lonlat)) return std::nullopt;
    // Longitude from the central meridian, wrapped so that the longitude itself lies within half a turn
    // of the centre (PROJ wraps it within half a turn of lon_0, the default centre).
    const double lon = wrapLongitude(lonlat.x - lon0_, centre_ - lon0_);
    return radius_ * glm::dvec2(cosTs_ * lon, lonlat.y - lat0_) + form_.origin;
  }

  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    const glm::dvec2 plane = (xy - form_.origin) / radius_;
    const double lat = plane.y + lat0_;
    // A raster edge at exactly 90 degrees may land an ulp beyond the pole.
    if (!(std::abs(lat) <= kHalfPi * (1.0 + 1e-15)) || !std::isfinite(plane.x)) return std::nullopt;
    return glm::dvec2(plane.x / cosTs_ + lon0_, std::clamp(lat, -kHalfPi, kHalfPi));
  }

  std::optional<double> periodX() const override { return kTwoPi * radius_ * cosTs_; }
  void setLongitudeCentre(double centre) override { centre_ = centre; }
  double longitudeCentre() const override { return centre_; }
  bool affineInLonLat() const override { return true; }  // x = a cos(lat_ts) lon, y = a lat, plus offsets

  std::string glslInclude() const override { return "strata/projection/equirectangular.glsl"; }
  std::string glslFunction() const override { return "equirectangular"; }
  std::array<glm::dvec4, 2> glslParameters() const override {
    return {glm::dvec4(lon0_, centre_ - lon0_, cosTs_, lat0_), glm::dvec4(form_.origin / radius_, 0.0, 0.0)};
  }
  double glslMapScale() const override { return radius_; }
  // +lat_0 only moves the origin along the meridian: the map stays in its normal aspect.
  ProjectionAspect aspect() const override { return ProjectionAspect::Equatorial; }

 private:
  EquirectangularForm form_;
  double radius_;  // map units per radian along a meridian: a in metres, or degrees per radian
  double lon0_;
  double lat0_;
  double cosTs_;   // the scale of parallels relative to meridians
  double centre_;  // longitude around which forward() wraps
};

std::unique_ptr<Projection> createEquirectangular(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  checkEllipsoid(ellipsoid);
  if (!plainFrame(terms)) return nullptr;
  EquirectangularForm form{
      .geographic = terms.name() != "eqc", .lon0 = terms.real("lon_0", 0.0), .ellipsoid = ellipsoid};
  if (form.geographic) return std::make_unique<Equirectangular>(form);
  form.lat0 = latitudeTerm(terms, "lat_0");
  form.latTs = latitudeTerm(terms, "lat_ts");
  if (std::abs(form.latTs) == 90.0)
    throw projectionError(
        "+proj=eqc with" + term("lat_ts", form.latTs) + " has no extent in x: it is true to scale at the pole",
        "give the latitude where the map is true to scale, |lat_ts| < 90, e.g. +lat_ts=0");
  form.origin = falseOrigin(terms);
  return std::make_unique<Equirectangular>(form);
}

}  // namespace

ProjectionDeclaration equirectangularDeclaration() {
  return {.type = "equirectangular",
          .summary = "longitude and latitude on a regular grid: geographic (degrees) and PROJ's eqc (metres)",
          .projNames = {"longlat", "latlong", "lonlat", "latlon", "eqc"},
          .create = createEquirectangular};
}

}  // namespace strata
