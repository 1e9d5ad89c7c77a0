#pragma once
// A raster's texture coordinates about the frame's reference point (View::reference, the point below the
// eye), for sampling relative to it: a float longitude resolves 1.7 m at 137 degrees on Earth, an offset
// from the reference micrometres (docs/architecture.md, "Precision"). Computed in double on the CPU each frame
// from the projection's own forward mapping, so every projection, built in or a plugin's, gets it unchanged.
#include <functional>
#include <optional>

#include <glm/glm.hpp>

namespace strata {

// The offsets from the reference the polynomial is in. Longitude/latitude offsets suit maps linear in them
// (equirectangular: exactly); the tangent plane's east and north (on the unit sphere) suit maps smooth on
// the ground, such as polar stereographic near its pole, where a longitude offset curves at the scale of the
// distance to the pole.
enum class LocalCoordinates { LonLat, Tangent };

// uv(reference + d) ~ uv + jacobian d + (d.hessianU d, d.hessianV d) / 2 for offsets d in `coordinates`
// shorter than `reach` (rad), where it agrees with the exact mapping to the tolerance it was made for.
struct LocalTextureFrame {
  LocalCoordinates coordinates = LocalCoordinates::LonLat;
  glm::dvec2 uv{0.0};
  glm::dmat2 jacobian{0.0};  // columns: d uv / d first offset, d uv / d second
  glm::dmat2 hessianU{0.0};  // second derivatives of u
  glm::dmat2 hessianV{0.0};
  double reach = 0.0;  // rad; 0: the mapping is undefined at the reference, or not smooth about it

  // The polynomial at `offset`, in double.
  glm::dvec2 at(glm::dvec2 offset) const;
};

// Texture coordinates (u, v) of longitude/latitude (rad), empty where the projection is undefined.
using TextureMapping = std::function<std::optional<glm::dvec2>(glm::dvec2 lonlat)>;

// Longitude and latitude of the point east and north of `reference` (all rad) in its tangent plane, on the
// unit sphere: the inverse of what shaders/strata/local_offsets.glsl computes from a point's offsets.
glm::dvec2 lonlatOfTangentOffset(glm::dvec2 reference, glm::dvec2 eastNorth);

// The frame of `mapping` about `reference` in whichever coordinates reach farther. `tolerance` (in u and in
// v: a hundredth of a texel is a different share of each where the raster is not square) bounds the
// polynomial's error within the reach, checked against `mapping` at 32 points on two circles
// about the reference for each reach tried, from kLargestReach down by halves. `periodicU`: u is periodic
// with period 1 (a raster around the body), so that the check compares u modulo 1.
LocalTextureFrame localTextureFrame(const TextureMapping& mapping, glm::dvec2 reference, glm::dvec2 tolerance,
                                    bool periodicU);

// 0.05 rad: 320 km on Earth, beyond what a view near the ground sees of the surface at a pixel's precision.
inline constexpr double kLargestReach = 0.05;

}  // namespace strata
