// Fuzz target: bytes as a raster file (GDAL tells TIFF, PNG or JPEG by its content), opened, checked,
// placed and read into pages as source.gdal and the page cache do, for height, colour and mask layers: the
// coarsest level's page and the first and last pages of two finer levels. No GPU: pages stop on the CPU.
// Bad input must end in a strata::Error at open, or a std::runtime_error from a page read.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include <cpl_conv.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>

#include <strata/plugin/plugin_registry.hpp>

#include "gdal_page_source.hpp"
#include "georeferencing.hpp"
#include "healpix_page_source.hpp"
#include "healpix_pyramid_file.hpp"
#include "paging/page_assembly.hpp"
#include "quiet_gdal_errors.hpp"
#include "raster_reading.hpp"
#include "value_range.hpp"

namespace strata::gdal {
namespace {

constexpr const char* kFile = "/vsimem/strata-fuzz/raster";
const SourceLocation kWhere{"fuzz.yaml", 1, 1, "raster"};

const PluginRegistry& plugins() {
  static const PluginRegistry registry = [] {
    GDALAllRegister();
    CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");  // no .aux.xml beside the file, read or written
    return PluginRegistry();
  }();
  return registry;
}

std::unique_ptr<GDALDataset> openRaster() {
  static const char* const drivers[] = {"GTiff", "PNG", "JPEG", nullptr};
  return std::unique_ptr<GDALDataset>(
      GDALDataset::Open(kFile, GDAL_OF_RASTER | GDAL_OF_READONLY, drivers, nullptr, nullptr));
}

// What source.gdal's open() does before it makes the page source; false where it refuses the raster.
bool opens(GDALDataset& dataset, LayerKind kind, std::optional<std::int64_t>& nside) {
  try {
    checkRaster(dataset, kind, kWhere);
    if (kind != LayerKind::Color) exactRawRange(dataset);
    if (const std::optional<HealpixPyramidFile> healpix = healpixPyramidOf(dataset, plugins(), kWhere)) {
      nside = healpix->nside;
      return true;
    }
    georeferenceOf(dataset, plugins(), {{}, kWhere, {}, kWhere, kWhere});
  } catch (const Error&) {
    return false;
  }
  return true;
}

// A page as the page cache's loader assembles it; a read error is what the cache expects.
void assemble(const PageSource& source, const PageKey& key, bool wrapX) {
  static std::vector<std::byte> slot(kPageBytes);
  try {
    paging::assemblePage(source, key, wrapX, slot);
  } catch (const std::runtime_error&) {
  }
}

void readPages(const PageSource& source, bool wrapX) {
  const PagePyramid& pyramid = source.pyramid();
  const int top = pyramid.levels() - 1;
  assemble(source, {top, 0, 0}, wrapX);
  for (const int level : {top / 2, 0})
    if (level != top) {
      assemble(source, {level, 0, 0}, wrapX);
      assemble(source, {level, pyramid.pagesAcross(level) - 1, pyramid.pagesDown(level) - 1}, wrapX);
    }
}

void readAs(LayerKind kind) {
  std::unique_ptr<GDALDataset> dataset = openRaster();
  std::optional<std::int64_t> nside;
  if (!dataset || !opens(*dataset, kind, nside)) return;
  const bool wrapX = kind == LayerKind::Height;  // as a global height map's would; the other kinds clamp
  if (nside)
    readPages(HealpixPageSource(std::move(dataset), kind, std::nullopt, *nside), wrapX);
  else
    readPages(GdalPageSource(std::move(dataset), kind, std::nullopt), wrapX);
}

}  // namespace
}  // namespace strata::gdal

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strata;
  gdal::plugins();
  const gdal::QuietGdalErrors quiet;
  VSILFILE* file = VSIFileFromMemBuffer(gdal::kFile, const_cast<GByte*>(data), vsi_l_offset(size), FALSE);
  VSIFCloseL(file);
  for (const LayerKind kind : {LayerKind::Height, LayerKind::Color, LayerKind::Mask}) gdal::readAs(kind);
  VSIUnlink(gdal::kFile);
  return 0;
}
