#include "projection/projection_terms.hpp"

#include <charconv>
#include <cmath>

namespace strata {
namespace {

std::string decimal(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

bool termIs(const ProjParameters& terms, const std::string& key, const std::string& plain) {
  return !terms.has(key) || terms.terms().at(key) == plain;
}

}  // namespace

Error projectionError(const std::string& problem, const std::string& fix) {
  return Error(SourceLocation{.node = "projection"}, problem, fix);
}

void checkEllipsoid(const Ellipsoid& ellipsoid) {
  if (!(ellipsoid.semiMajorAxis > 0.0) || !std::isfinite(ellipsoid.semiMajorAxis))
    throw projectionError("the semi-major axis " + decimal(ellipsoid.semiMajorAxis) + " m is not a size",
                          "give the body's radius in metres, e.g. +R=3396190 for Mars");
  const double f = ellipsoid.flattening();
  if (!(f >= 0.0 && f < 1.0))
    throw projectionError(
        "the inverse flattening " + decimal(ellipsoid.inverseFlattening) + " gives no oblate ellipsoid",
        "give 1/f above 1 (298.257223563 for WGS84), or 0 for a sphere");
}

bool plainFrame(const ProjParameters& terms) {
  const bool metres = termIs(terms, "units", "m") && terms.real("to_meter", 1.0) == 1.0;
  const bool greenwich = termIs(terms, "pm", "greenwich") || termIs(terms, "pm", "0");
  return metres && greenwich && termIs(terms, "axis", "enu");
}

double latitudeTerm(const ProjParameters& terms, const std::string& key, double fallbackDegrees) {
  const double degrees = terms.real(key, fallbackDegrees);
  if (std::abs(degrees) > 90.0)
    throw projectionError("+" + key + "=" + decimal(degrees) + " is not a latitude",
                          "give +" + key + " in degrees between -90 and 90");
  return degrees;
}

ProjectionAspect azimuthalAspect(double lat0) {
  if ((90.0 - std::abs(lat0)) * kDegree >= 1e-10) return ProjectionAspect::Other;
  return lat0 > 0.0 ? ProjectionAspect::NorthPolar : ProjectionAspect::SouthPolar;
}

double scaleFactorTerm(const ProjParameters& terms) {
  const double k0 = terms.has("k_0") ? terms.real("k_0", 1.0) : terms.real("k", 1.0);
  if (!(k0 > 0.0))
    throw projectionError("the scale factor +k_0=" + decimal(k0) + " is not positive",
                          "give +k_0 as the scale at the projection's centre, e.g. +k_0=0.994");
  return k0;
}

glm::dvec2 falseOrigin(const ProjParameters& terms) { return {terms.real("x_0", 0.0), terms.real("y_0", 0.0)}; }

bool validLonLat(glm::dvec2 lonlat) { return std::isfinite(lonlat.x) && std::abs(lonlat.y) <= kHalfPi; }

double wrapLongitude(double lon, double centre) {
  const double offset = lon - (centre - kPi);
  if (offset >= 0.0 && offset < kTwoPi) return lon;  // the common case keeps `lon` bit for bit
  return lon - kTwoPi * std::floor(offset / kTwoPi);
}

std::string term(const std::string& key, double value) { return " +" + key + "=" + decimal(value); }

std::string ellipsoidTerms(const Ellipsoid& ellipsoid) {
  if (ellipsoid.inverseFlattening == 0.0) return term("R", ellipsoid.semiMajorAxis);
  return term("a", ellipsoid.semiMajorAxis) + term("rf", ellipsoid.inverseFlattening);
}

}  // namespace strata
