#include "face_window.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include <glm/trigonometric.hpp>

#include "tile_target.hpp"

namespace strata::tiling {
namespace {

// Points along each side of the input: between two of them an edge of any smooth projection bulges by far
// less than the margin below.
constexpr int kSamples = 65;
// The margin round the samples' box: two texels (what bilinear filtering of the window's edge reads) and a
// hundredth of the box (the edges' bulge between samples).
constexpr double kMarginTexels = 2.0, kMarginShare = 0.01;

struct FaceBox {
  std::set<int> faces;
  double west = HUGE_VAL, east = -HUGE_VAL, north = HUGE_VAL, south = -HUGE_VAL;  // face texels; north: least row
};

FaceBox boxOf(GDALDataset& input, const Projection& strip, std::int64_t nside, const SourceLocation& where) {
  std::array<double, 6> t{};
  input.GetGeoTransform(t.data());
  const Transformation toGeographic = geographicTransformation(*input.GetSpatialRef());
  FaceBox box;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const double column = double(input.GetRasterXSize()) * i / (kSamples - 1);
      const double row = double(input.GetRasterYSize()) * j / (kSamples - 1);
      double x = t[0] + column * t[1] + row * t[2], y = t[3] + column * t[4] + row * t[5];
      std::optional<glm::dvec2> point;
      if (toGeographic && toGeographic->Transform(1, &x, &y)) point = strip.forward(glm::radians(glm::dvec2(x, y)));
      if (!point)
        throw Error(where, "PROJ cannot place every part of '" + std::string(input.GetDescription()) + "' on the body",
                    "check its CRS and geotransform: gdalinfo " + std::string(input.GetDescription()));
      const int face = std::min(int(point->x), 11);
      box.faces.insert(face);
      box.west = std::min(box.west, (point->x - face) * double(nside));
      box.east = std::max(box.east, (point->x - face) * double(nside));
      box.north = std::min(box.north, (1.0 - point->y) * double(nside));
      box.south = std::max(box.south, (1.0 - point->y) * double(nside));
    }
  return box;
}

std::string facesNamed(const std::set<int>& faces) {
  std::string names;
  for (const int face : faces) names += (names.empty() ? "" : ", ") + std::to_string(face);
  return names;
}

}  // namespace

healpix::FaceWindow faceWindowCovering(GDALDataset& input, const Projection& strip, std::int64_t nside,
                                       const SourceLocation& where) {
  const FaceBox box = boxOf(input, strip, nside, where);
  const std::string most = std::to_string(healpix::kMostNside);
  const std::string finer =
      "at nside " + std::to_string(nside) + ", finer than " + most + ", a HEALPix pyramid holds a part of one face";
  if (box.faces.size() > 1)
    throw Error(
        where, finer + ", but '" + std::string(input.GetDescription()) + "' reaches faces " + facesNamed(box.faces),
        "give --nside " + most + " or less for a pyramid of all twelve faces, or cut the input where the faces meet");
  const double margin = kMarginTexels + kMarginShare * std::max(box.east - box.west, box.south - box.north);
  const auto bound = [nside](double texel) { return std::clamp(texel, 0.0, double(nside)); };
  const std::int64_t west = std::int64_t(std::floor(bound(box.west - margin)));
  const std::int64_t east = std::int64_t(std::ceil(bound(box.east + margin)));
  const std::int64_t north = std::int64_t(std::floor(bound(box.north - margin)));
  const std::int64_t south = std::int64_t(std::ceil(bound(box.south + margin)));
  if (east - west > INT_MAX || south - north > INT_MAX)
    throw Error(where,
                finer + ", but '" + std::string(input.GetDescription()) + "' covers " + std::to_string(east - west) +
                    "x" + std::to_string(south - north) + " of its texels, more than a GeoTIFF holds",
                "choose a coarser --nside, or cut the input into pieces");
  return {*box.faces.begin(), west, north, int(east - west), int(south - north)};
}

}  // namespace strata::tiling
