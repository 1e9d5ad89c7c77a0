#include "layers/local_texture_frame.hpp"

#include <cmath>
#include <numbers>

namespace strata {
namespace {

// Central differences in double: steps large enough that rounding in the mapping (about 1e-16 of its
// values, and of the longitudes it subtracts) stays far below the derivatives, small enough that the
// neglected terms do too. Whatever error is left is caught by the reach's check against the mapping.
constexpr double kFirstStep = 1e-6;   // rad
constexpr double kSecondStep = 1e-4;  // rad
constexpr double kLeastReach = 1e-9;  // rad: 6 mm on Earth; below it the absolute path is as good

// The mapping at offsets from the reference in one kind of local coordinates.
struct Samples {
  const TextureMapping& mapping;
  glm::dvec2 reference;
  LocalCoordinates coordinates;
  bool defined = true;

  glm::dvec2 lonlatAt(glm::dvec2 offset) const {
    return coordinates == LocalCoordinates::LonLat ? reference + offset : lonlatOfTangentOffset(reference, offset);
  }
  // Whether an offset names a point of the surface: not beyond a pole, nor beyond the tangent plane's horizon.
  bool onSurface(glm::dvec2 offset) const {
    return coordinates == LocalCoordinates::LonLat ? std::abs(reference.y + offset.y) <= 0.5 * std::numbers::pi
                                                   : glm::dot(offset, offset) < 1.0;
  }
  glm::dvec2 operator()(double first, double second) {
    const std::optional<glm::dvec2> uv = mapping(lonlatAt({first, second}));
    if (!uv) defined = false;
    return uv.value_or(glm::dvec2(0.0));
  }
};

// u differences of a raster around the body taken modulo its period.
glm::dvec2 difference(glm::dvec2 a, glm::dvec2 b, bool periodicU) {
  glm::dvec2 d = a - b;
  if (periodicU) d.x -= std::round(d.x);
  return d;
}

// Derivatives by central differences about the reference; false where the mapping is undefined there.
bool differentiate(Samples& f, LocalTextureFrame& frame, bool periodicU) {
  const glm::dvec2 centre = f(0.0, 0.0);
  const double h = kFirstStep, k = kSecondStep;
  const glm::dvec2 lon = difference(f(h, 0.0), f(-h, 0.0), periodicU) / (2.0 * h);
  const glm::dvec2 lat = difference(f(0.0, h), f(0.0, -h), periodicU) / (2.0 * h);
  const glm::dvec2 lonLon =
      (difference(f(k, 0.0), centre, periodicU) + difference(f(-k, 0.0), centre, periodicU)) / (k * k);
  const glm::dvec2 latLat =
      (difference(f(0.0, k), centre, periodicU) + difference(f(0.0, -k), centre, periodicU)) / (k * k);
  const glm::dvec2 lonLat =
      (difference(f(k, k), f(k, -k), periodicU) - difference(f(-k, k), f(-k, -k), periodicU)) / (4.0 * k * k);
  frame.uv = centre;
  frame.jacobian = glm::dmat2(lon, lat);
  frame.hessianU = glm::dmat2(lonLon.x, lonLat.x, lonLat.x, latLat.x);
  frame.hessianV = glm::dmat2(lonLon.y, lonLat.y, lonLat.y, latLat.y);
  return f.defined;
}

// Whether the polynomial is within `tolerance` of the mapping on circles of `reach` and half of it. Offsets
// that name no surface point are passed over: no surface point has them.
bool agrees(const LocalTextureFrame& frame, Samples& f, double reach, glm::dvec2 tolerance, bool periodicU) {
  constexpr int kPoints = 16;
  for (double radius : {reach, 0.5 * reach})
    for (int i = 0; i < kPoints; ++i) {
      const double angle = 2.0 * std::numbers::pi * (i + 0.5 * (radius < reach)) / kPoints;
      const glm::dvec2 offset = radius * glm::dvec2(std::cos(angle), std::sin(angle));
      if (!f.onSurface(offset)) continue;
      const glm::dvec2 exact = f(offset.x, offset.y);
      if (!f.defined) return false;
      const glm::dvec2 error = difference(frame.at(offset), exact, periodicU);
      if (std::abs(error.x) > tolerance.x || std::abs(error.y) > tolerance.y) return false;
    }
  return true;
}

}  // namespace

glm::dvec2 LocalTextureFrame::at(glm::dvec2 offset) const {
  return uv + jacobian * offset +
         0.5 * glm::dvec2(glm::dot(offset, hessianU * offset), glm::dot(offset, hessianV * offset));
}

glm::dvec2 lonlatOfTangentOffset(glm::dvec2 reference, glm::dvec2 eastNorth) {
  const double sinLon = std::sin(reference.x), cosLon = std::cos(reference.x);
  const double sinLat = std::sin(reference.y), cosLat = std::cos(reference.y);
  const glm::dvec3 east(-sinLon, cosLon, 0.0), north(-sinLat * cosLon, -sinLat * sinLon, cosLat);
  const glm::dvec3 up(cosLat * cosLon, cosLat * sinLon, sinLat);
  const double height = std::sqrt(std::max(0.0, 1.0 - glm::dot(eastNorth, eastNorth)));
  const glm::dvec3 p = up * height + east * eastNorth.x + north * eastNorth.y;
  // The longitude as an offset from the reference's, so that it does not wrap between neighbouring points.
  const double dLon = std::atan2(glm::dot(p, east), glm::dot(p, up * cosLat - north * sinLat));
  return {reference.x + dLon, std::atan2(p.z, std::hypot(p.x, p.y))};
}

// The ground distance (rad) a reach in `coordinates` covers in every direction: a longitude offset spans
// cos(latitude) of it on the ground.
double groundReach(LocalCoordinates coordinates, double reach, glm::dvec2 reference) {
  return coordinates == LocalCoordinates::LonLat ? reach * std::cos(reference.y) : reach;
}

LocalTextureFrame localTextureFrame(const TextureMapping& mapping, glm::dvec2 reference, glm::dvec2 tolerance,
                                    bool periodicU) {
  LocalTextureFrame best;
  double bestGround = 0.0;
  for (const LocalCoordinates coordinates : {LocalCoordinates::LonLat, LocalCoordinates::Tangent}) {
    LocalTextureFrame frame;
    frame.coordinates = coordinates;
    Samples f{mapping, reference, coordinates};
    // Longitude offsets lose their meaning within a step of the pole; the tangent plane does not.
    const bool nearPole = std::abs(reference.y) + kSecondStep > 0.5 * std::numbers::pi;
    if ((nearPole && coordinates == LocalCoordinates::LonLat) || !differentiate(f, frame, periodicU)) continue;
    for (double reach = kLargestReach; reach >= kLeastReach; reach *= 0.5) {
      if (groundReach(coordinates, reach, reference) <= bestGround) break;
      f.defined = true;
      if (agrees(frame, f, reach, tolerance, periodicU)) {
        frame.reach = reach;
        best = frame;
        bestGround = groundReach(coordinates, reach, reference);
        break;
      }
    }
  }
  return best;
}

}  // namespace strata
