// The sinusoidal projection as a plugin: the equal-area pseudocylinder of many planetary mosaics, which
// source.gdal then reads from a raster's CRS (+proj=sinu) like a built-in projection. An example of a
// projection built out of tree against an installed Strata SDK, with only the public headers.
//
// Spherical form, Snyder (1987) "Map Projections: A Working Manual", ch. 30, eqs. 30-1 to 30-5:
//   x = R (lon - lon_0) cos(lat) + x_0,  y = R lat + y_0,  and back  lat = (y - y_0) / R,
//   lon = lon_0 + (x - x_0) / (R cos(lat)).
// PROJ's sinu takes these equations on a sphere; on an ellipsoid it uses the meridian distance instead,
// which this example leaves out (the CRS is refused with how to state it on a sphere).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <strata/error.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/plugin/projection.hpp>

namespace sinusoidal {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// The longitude from the central meridian, in [-pi, pi): the map is one lens, interrupted along the
// antimeridian.
double fromCentralMeridian(double lon, double lon0) { return std::remainder(lon - lon0, 2.0 * kPi); }

std::string term(const std::string& key, double value) {
  return value == 0.0 ? "" : " +" + key + "=" + std::to_string(value);
}

class Sinusoidal final : public strata::Projection {
 public:
  Sinusoidal(double radius, double lon0Degrees, glm::dvec2 falseOrigin)
      : radius_(radius), lon0Degrees_(lon0Degrees), lon0_(lon0Degrees * kDegree), origin_(falseOrigin) {}

  std::string type() const override { return "sinusoidal"; }

  std::string projString() const override {
    return "+proj=sinu" + term("lon_0", lon0Degrees_) + term("x_0", origin_.x) + term("y_0", origin_.y) +
           " +R=" + std::to_string(radius_);
  }

  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const override {
    if (!(std::abs(lonlat.y) <= kPi / 2) || !std::isfinite(lonlat.x)) return std::nullopt;
    const double lon = fromCentralMeridian(lonlat.x, lon0_);
    return radius_ * glm::dvec2(lon * std::cos(lonlat.y), lonlat.y) + origin_;
  }

  // Empty outside the lens |x - x_0| <= pi R cos(lat), |y - y_0| <= pi R / 2 (the corners of a raster
  // around it), give or take 1e-12 R (micrometres): the lens closes at the poles, and a pole's point a
  // rounding off it is still the pole. At the poles, where a whole parallel is one point, any longitude
  // is right: the central meridian, or one clamped to the lens.
  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const override {
    constexpr double kRounding = 1e-12;
    glm::dvec2 plane = (xy - origin_) / radius_;
    if (!(std::abs(plane.y) <= kPi / 2 + kRounding) || !std::isfinite(plane.x)) return std::nullopt;
    plane.y = std::clamp(plane.y, -kPi / 2, kPi / 2);
    const double parallel = std::cos(plane.y);  // the parallel's length over the equator's
    if (std::abs(plane.x) > kPi * parallel + kRounding) return std::nullopt;
    const double lon = parallel > 0.0 ? std::clamp(plane.x / parallel, -kPi, kPi) : 0.0;
    return glm::dvec2(lon0_ + lon, plane.y);
  }

  std::string glslInclude() const override { return "sinusoidal/sinusoidal.glsl"; }
  std::string glslFunction() const override { return "sinusoidal"; }
  // a.x = lon_0; b.xy = the false origin over the radius, so that GLSL values stay near 1.
  std::array<glm::dvec4, 2> glslParameters() const override {
    return {glm::dvec4(lon0_, 0.0, 0.0, 0.0), glm::dvec4(origin_ / radius_, 0.0, 0.0)};
  }
  double glslMapScale() const override { return radius_; }
  // Pseudocylindrical, true only along the equator and the central meridian: neither of Strata's aspects
  // (composite.projection_quality weighs it by its footprints, the isotropy method, instead).
  strata::ProjectionAspect aspect() const override { return strata::ProjectionAspect::Other; }

 private:
  double radius_;       // m
  double lon0Degrees_;  // as the CRS says it, for projString()
  double lon0_;         // rad
  glm::dvec2 origin_;   // false easting and northing, m
};

// The single-precision form, the same equations per vertex and per pixel. Longitudes reach it in
// [-pi, pi] and lon_0 within a turn of them, so one remainder keeps the difference in [-pi, pi).
constexpr const char* kSinusoidalGlsl = R"(#include "strata/constants.glsl"
vec3 sinusoidal(vec2 lonlat, vec4 a, vec4 b) {
  float lon = lonlat.x - a.x;
  lon -= TWO_PI * floor((lon + PI) / TWO_PI);
  return vec3(lon * cos(lonlat.y) + b.x, lonlat.y + b.y, 1.0);
}
)";

std::unique_ptr<strata::Projection> createSinusoidal(const strata::ProjParameters& terms,
                                                     const strata::Ellipsoid& figure) {
  if (figure.inverseFlattening != 0.0)
    throw strata::Error({},
                        "the sinusoidal example projection takes a sphere, not an ellipsoid of inverse flattening " +
                            std::to_string(figure.inverseFlattening),
                        "give the CRS a sphere, e.g. +proj=sinu +R=3396190 for Mars");
  return std::make_unique<Sinusoidal>(figure.semiMajorAxis, terms.real("lon_0", 0.0),
                                      glm::dvec2(terms.real("x_0", 0.0), terms.real("y_0", 0.0)));
}

void registerTypes(strata::PluginRegistrar& registrar) {
  registrar.addProjection({.type = "sinusoidal",
                           .summary = "equal-area pseudocylinder, spherical form (Snyder 1987, ch. 30), from a plugin",
                           .projNames = {"sinu"},
                           .create = createSinusoidal,
                           .shaderSources = {{"sinusoidal/sinusoidal.glsl", kSinusoidalGlsl}}});
}

}  // namespace
}  // namespace sinusoidal

STRATA_PLUGIN("sinusoidal", "0.1.0", sinusoidal::registerTypes)
