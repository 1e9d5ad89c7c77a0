// Near-side perspective: the view of a camera at height h above the centre, looking straight down (nsper)
// or tilted away from the nadir towards an azimuth (tpers). Snyder (1987), ch. 23 "General vertical
// perspective", vertical and tilted, on the sphere of radius a, which PROJ uses for ellipsoids too
// (taking geodetic latitudes as spherical ones). The vertical map is the tangent plane at the centre;
// tilting views that plane from a camera turned by the tilt.
#include "perspective.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "projection/projection_terms.hpp"

namespace strata {
namespace {

// The mapping as the CRS defines it (angles in degrees, as PROJ writes them).
struct PerspectiveForm {
  std::string projName;  // nsper or tpers
  double height = 0.0;   // of the camera above the surface, m
  double lat0 = 0.0;
  double lon0 = 0.0;
  double tilt = 0.0;       // away from the nadir
  double azimuth = 0.0;    // of the tilt, clockwise from north
  glm::dvec2 origin{0.0};  // false easting and northing, m
  Ellipsoid ellipsoid;
};

class Perspective final : public Projection {
 public:
  explicit Perspective(const PerspectiveForm& form)
      : form_(form),
        a_(form.ellipsoid.semiMajorAxis),
        height_(form.height / a_),
        lat0_(form.lat0 * kDegree),
        lon0_(form.lon0 * kDegree),
        sinLat0_(std::sin(lat0_)),
        cosLat0_(std::cos(lat0_)),
        sinTilt_(std::sin(form.tilt * kDegree)),
        cosTilt_(std::cos(form.tilt * kDegree)),
        sinAzimuth_(std::sin(form.azimuth * kDegree)),
        cosAzimuth_(std::cos(form.azimuth * kDegree)),
        horizon_(std::sqrt(height_ / (height_ + 2.0))) {}

  std::string type() const override { return "perspective"; }

  std::string projString() const override {
    const std::string tilt = form_.projName == "tpers" ? term("tilt", form_.tilt) + term("azi", form_.azimuth) : "";
    return "+proj=" + form_.projName + term("h", form_.height) + term("lat_0", form_.lat0) + term("lon_0", form_.lon0) +
           tilt + term("x_0", form_.origin.x) + term("y_0", form_.origin.y) + ellipsoidTerms(form_.ellipsoid);
  }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (!validLonLat(lonlat)) return std::nullopt;
    const double lon = lonlat.x - lon0_;
    const double cosLat = std::cos(lonlat.y);
    const double sinHalfLat = std::sin(0.5 * (lonlat.y - lat0_)), sinHalfLon = std::sin(0.5 * lon);
    // 1 - cos(c) of the angle c from the centre, by the haversine, which keeps it exact near the centre.
    const double versine = 2.0 * (sinHalfLat * sinHalfLat + cosLat * cosLat0_ * sinHalfLon * sinHalfLon);
    // Beyond the horizon cos(c) < 1 / P, P = 1 + h / a being the camera's distance from the centre in radii.
    if (!(versine <= height_ / (1.0 + height_))) return std::nullopt;
    const double k = height_ / (height_ + versine);  // Snyder's k' = (P - 1) / (P - cos(c))
    // cos(lat0) sin(lat) - sin(lat0) cos(lat) cos(lon), written without the cancellation near the centre.
    const double north = std::sin(lonlat.y - lat0_) + 2.0 * sinLat0_ * cosLat * sinHalfLon * sinHalfLon;
    const auto photo = tilted(k * glm::dvec2(cosLat * std::sin(lon), north));
    if (!photo) return std::nullopt;
    return a_ * *photo + form_.origin;
  }

  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    const auto plane = vertical((xy - form_.origin) / a_);
    if (!plane) return std::nullopt;
    // The ray from the camera, at height h above the centre, through the plane point (x, y, 1) meets the
    // unit sphere first at parameter t: the smaller root, written as the product of the roots over the
    // larger one.
    const double discriminant = height_ * height_ - glm::dot(*plane, *plane) * height_ * (height_ + 2.0);
    if (!(discriminant >= 0.0)) return std::nullopt;  // beyond the horizon
    const double t = height_ * (height_ + 2.0) / ((1.0 + height_) * height_ + std::sqrt(discriminant));
    const glm::dvec3 local(t * *plane, 1.0 + height_ - t * height_);    // east, north, up
    const double meridional = local.z * cosLat0_ - local.y * sinLat0_;  // towards (0, lon0) on the equator
    const double lat = std::atan2(local.z * sinLat0_ + local.y * cosLat0_, std::hypot(local.x, meridional));
    return glm::dvec2(wrapLongitude(lon0_ + std::atan2(local.x, meridional), 0.0), lat);
  }

  std::string glslInclude() const override { return "strata/projection/perspective.glsl"; }
  std::string glslFunction() const override { return "perspective"; }
  std::array<glm::dvec4, 2> glslParameters() const override {
    return {glm::dvec4(lon0_, lat0_, height_, form_.tilt * kDegree),
            glm::dvec4(form_.azimuth * kDegree, 1.0 / horizon_, form_.origin / (a_ * horizon_))};
  }
  // The radius of the horizon on the vertical plane, so that the visible disc spans [-1, 1].
  double glslMapScale() const override { return a_ * horizon_; }
  // A tilted camera sees the pole obliquely, its texels stretched towards the horizon.
  ProjectionAspect aspect() const override {
    return form_.tilt == 0.0 ? azimuthalAspect(form_.lat0) : ProjectionAspect::Other;
  }

 private:
  // The tilted camera's view of a point of the vertical plane, empty behind the camera.
  std::optional<glm::dvec2> tilted(glm::dvec2 plane) const {
    const double along = plane.y * cosAzimuth_ + plane.x * sinAzimuth_;  // towards the azimuth
    const double depth = along * sinTilt_ / height_ + cosTilt_;          // in front of the camera
    if (!(depth > 0.0)) return std::nullopt;
    return glm::dvec2((plane.x * cosAzimuth_ - plane.y * sinAzimuth_) * cosTilt_, along) / depth;
  }

  // tilted() solved for the vertical plane.
  std::optional<glm::dvec2> vertical(glm::dvec2 photo) const {
    const double depth = 1.0 - photo.y * sinTilt_ / height_;  // cos(tilt) over tilted()'s depth
    if (!(depth > 0.0)) return std::nullopt;
    const double across = photo.x / depth, along = photo.y * cosTilt_ / depth;
    return glm::dvec2(across * cosAzimuth_ + along * sinAzimuth_, along * cosAzimuth_ - across * sinAzimuth_);
  }

  PerspectiveForm form_;
  double a_;
  double height_;  // of the camera, in units of a (Snyder's P - 1)
  double lat0_;
  double lon0_;
  double sinLat0_;
  double cosLat0_;
  double sinTilt_;
  double cosTilt_;
  double sinAzimuth_;
  double cosAzimuth_;
  double horizon_;  // the horizon's radius on the vertical plane, in units of a
};

std::unique_ptr<Projection> createPerspective(const ProjParameters& terms, const Ellipsoid& ellipsoid) {
  checkEllipsoid(ellipsoid);
  if (!plainFrame(terms)) return nullptr;
  PerspectiveForm form{.projName = terms.name(),
                       .height = terms.real("h", 0.0),
                       .lat0 = latitudeTerm(terms, "lat_0"),
                       .lon0 = terms.real("lon_0", 0.0),
                       .origin = falseOrigin(terms),
                       .ellipsoid = ellipsoid};
  if (!(form.height > 0.0))
    throw projectionError("the camera height" + term("h", form.height) + " m is not above the surface",
                          "give +h, the camera's height above the surface in metres, e.g. +h=35786000");
  if (form.projName == "tpers") {  // nsper has no tilt, and PROJ ignores one given to it
    form.tilt = terms.real("tilt", 0.0);
    form.azimuth = terms.real("azi", 0.0);
    if (!(std::abs(form.tilt) < 90.0))
      throw projectionError("the tilt" + term("tilt", form.tilt) + " degrees does not look down at the body",
                            "give +tilt, the camera's angle from the nadir, between -90 and 90 degrees");
  }
  return std::make_unique<Perspective>(form);
}

}  // namespace

ProjectionDeclaration perspectiveDeclaration() {
  return {.type = "perspective",
          .summary = "a photograph from a camera at a height above the body, vertical or tilted",
          .projNames = {"nsper", "tpers"},
          .create = createPerspective};
}

}  // namespace strata
