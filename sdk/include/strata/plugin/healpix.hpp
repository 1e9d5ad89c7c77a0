#pragma once
#include <strata/export.hpp>
// The HEALPix grid in double precision: the twelve base faces, the face-local coordinates the HEALPix terrain
// generator (issue 6, [Westerteiger et al. 2011]) tessellates, the NESTED and RING pixel numbering of the
// HEALPix library ([Gorski et al. 2005]), and the planar HEALPix projection ([Calabretta & Roukema 2007];
// PROJ's +proj=healpix) on the unit sphere. Longitudes and latitudes are in radians on Strata's axes: +z
// north, +x at longitude 0, +y at longitude pi/2.
#include <cstdint>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

STRATA_EXPORTS_BEGIN
namespace strata::healpix {

// The largest nside the 64-bit pixel numbers hold (12 nside^2 < 2^63, as in the HEALPix library).
constexpr std::int64_t kMaxNside = std::int64_t{1} << 29;

// A place on a base face. Faces 0-3 are the north polar faces, centred at longitudes 45, 135, 225 and 315
// degrees; 4-7 the equatorial faces, centred on the equator at 0, 90, 180 and 270 degrees; 8-11 the south
// polar faces, at the longitudes of 0-3. x and y lie in [0, 1]: (0, 0) is the face's southern corner, (1, 1)
// its northern (the pole for faces 0-3), (1, 0) its eastern and (0, 1) its western corner. Pixel (ix, iy) of
// a face at resolution nside covers [ix, ix + 1) / nside by [iy, iy + 1) / nside.
struct FacePoint {
  int face = 0;
  double x = 0.0, y = 0.0;
};

// The face point of a longitude (any real) and latitude (in [-pi/2, pi/2]).
FacePoint facePoint(glm::dvec2 lonlat);
// A face point as the HEALPix library's face-local inverse ([Gorski et al. 2005]) gives it: z = sin(latitude),
// sin(colatitude) (formed from the ring number in the caps, so that it keeps its precision up to the poles) and
// the longitude phi = (pi / 4) (jpll + (x - y) / nr), not wrapped (at a pole, the face centre's).
struct SphericalPoint {
  double z, sinColatitude, longitude;
};
SphericalPoint spherical(const FacePoint& point);
// The unit vector of a face point, accurate to rounding up to the poles.
glm::dvec3 unitVector(const FacePoint& point);
// The longitude, in (-pi, pi], and latitude of a face point; at a pole the longitude of the face's centre.
glm::dvec2 lonlat(const FacePoint& point);

// The pixel holding a place at resolution nside (1 to kMaxNside; a power of two for the NESTED scheme),
// numbered as the HEALPix library numbers it: NESTED is face * nside^2 + the bits of ix and iy interleaved,
// ix's in the even positions; RING counts rings of pixels from north to south, each from longitude 0
// eastwards. Throws std::invalid_argument for an nside out of range.
std::int64_t nestedPixel(std::int64_t nside, glm::dvec2 lonlat);
std::int64_t ringPixel(std::int64_t nside, glm::dvec2 lonlat);
// The longitude and latitude of a pixel's centre, as lonlat() gives them. Throws std::invalid_argument for
// an nside or a pixel out of range (pixels are 0 to 12 nside^2 - 1).
glm::dvec2 nestedPixelCentre(std::int64_t nside, std::int64_t pixel);
glm::dvec2 ringPixelCentre(std::int64_t nside, std::int64_t pixel);
// A pixel's number in the other scheme; nside a power of two.
std::int64_t nestedToRing(std::int64_t nside, std::int64_t pixel);
std::int64_t ringToNested(std::int64_t nside, std::int64_t pixel);

// The planar HEALPix projection of a face point on the unit sphere, x in [-pi, pi), y in [-pi/2, pi/2]:
// what PROJ's "+proj=healpix +R=1" gives for the same place. Each face is a square there, turned by 45
// degrees; the polar faces stand on the equatorial belt as triangles.
glm::dvec2 planeOf(const FacePoint& point);
// The face point of a point of that plane (x taken modulo 2 pi); empty between the polar triangles and
// beyond |y| = pi/2.
std::optional<FacePoint> faceOfPlane(glm::dvec2 xy);

}  // namespace strata::healpix
STRATA_EXPORTS_END
