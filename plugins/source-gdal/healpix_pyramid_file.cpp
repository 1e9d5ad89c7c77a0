#include "healpix_pyramid_file.hpp"

#include <bit>
#include <charconv>
#include <string>

#include <strata/crs.hpp>
#include <strata/plugin/healpix_pyramid.hpp>

namespace strata::gdal {
namespace {

std::string item(GDALDataset& dataset, const char* name) {
  const char* value = dataset.GetMetadataItem(name);
  return value ? value : "";
}

[[noreturn]] void fail(GDALDataset& dataset, const SourceLocation& where, const std::string& problem) {
  throw Error(where, "'" + std::string(dataset.GetDescription()) + "' is marked as a HEALPix pyramid, but " + problem,
              "write it again with `strata tile INPUT OUTPUT --to healpix`");
}

std::int64_t nsideOf(GDALDataset& dataset, const SourceLocation& where) {
  const std::string text = item(dataset, healpix::kNsideItem);
  std::int64_t nside = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), nside);
  if (error != std::errc() || end != text.data() + text.size() || nside < healpix::kLeastNside ||
      nside > healpix::kMostWindowedNside || !std::has_single_bit(std::uint64_t(nside)))
    fail(dataset, where, std::string(healpix::kNsideItem) + " '" + text + "' is not a power of two from 512 to 2^30");
  return nside;
}

// The window of one face the file holds, if it holds one (nside above kMostNside), checked against its size;
// otherwise the check that it holds the whole strip.
std::optional<healpix::FaceWindow> windowOf(GDALDataset& dataset, std::int64_t nside, const SourceLocation& where) {
  const int width = dataset.GetRasterXSize(), height = dataset.GetRasterYSize();
  const std::string size = std::to_string(width) + "x" + std::to_string(height) + " texels";
  if (!dataset.GetMetadataItem(healpix::kWindowItem)) {
    if (nside > healpix::kMostNside)
      fail(dataset, where,
           "its nside " + std::to_string(nside) + " is above 2^26 and it has no " + healpix::kWindowItem);
    if (width != 12 * nside || height != nside)
      fail(dataset, where, "it is " + size + ", not 12 faces of nside " + std::to_string(nside) + " side by side");
    return std::nullopt;
  }
  const std::string text = item(dataset, healpix::kWindowItem);
  std::optional<healpix::FaceWindow> window = healpix::windowOf(text, nside, width, height);
  if (!window)
    fail(dataset, where,
         std::string(healpix::kWindowItem) + " '" + text + "' and its " + size +
             " are not a window of one face (face 0 to 11, first column and row) at nside " + std::to_string(nside));
  return window;
}

// The planar HEALPix projection of the body, with no central meridian or false origin.
std::shared_ptr<const Projection> planeOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                          const SourceLocation& where) {
  std::shared_ptr<const Projection> plane = projectionOfCrs(plugins, item(dataset, healpix::kFigureItem), where);
  const std::optional<glm::dvec2> origin = plane->forward({0.0, 0.0});
  if (plane->type() != "healpix" || !origin || *origin != glm::dvec2(0.0))
    fail(dataset, where, std::string(healpix::kFigureItem) + " is not a plain +proj=healpix");
  return plane;
}

}  // namespace

std::optional<HealpixPyramidFile> healpixPyramidOf(GDALDataset& dataset, const PluginRegistry& plugins,
                                                   const SourceLocation& where) {
  if (!dataset.GetMetadataItem(healpix::kNsideItem)) return std::nullopt;
  const std::int64_t nside = nsideOf(dataset, where);
  const std::optional<healpix::FaceWindow> window = windowOf(dataset, nside, where);
  if (item(dataset, healpix::kOrderingItem) != "NESTED")
    fail(dataset, where, std::string(healpix::kOrderingItem) + " is not NESTED");
  std::optional<healpix::PageRanges> ranges;
  if (!window)
    ranges = healpix::PageRanges::fromMetadata(
        nside, [&](const std::string& name) { return dataset.GetMetadataItem(name.c_str()); });
  return HealpixPyramidFile{nside,
                            window,
                            {healpix::stripProjection(planeOf(dataset, plugins, where)),
                             window ? healpix::windowGeotransform(nside, *window) : healpix::stripGeotransform(nside)},
                            ranges ? std::make_shared<const healpix::PageRanges>(std::move(*ranges)) : nullptr};
}

}  // namespace strata::gdal
