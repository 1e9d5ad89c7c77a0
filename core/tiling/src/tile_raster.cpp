// strata tile: any GDAL raster to the Cloud Optimized GeoTIFF pyramid the page cache reads.
#include <cpl_conv.h>
#include <gdal_priv.h>

#include <memory>

#include <strata/crs.hpp>
#include <strata/host/output_file.hpp>
#include <strata/host/tiling.hpp>

#include "block_range_scan.hpp"
#include "cog_writing.hpp"
#include "healpix_tiling.hpp"
#include "pipeline/files_gdal_reads.hpp"
#include "tile_target.hpp"

namespace strata {
namespace {

using tiling::Dataset;

// Of a reprojected raster's time, warping takes the most; writing it again, without warping, the rest.
constexpr double kWarpedShare = 0.7;

Dataset openInput(const std::filesystem::path& file, const SourceLocation& where) {
  CPLErrorReset();
  Dataset dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!dataset)
    throw Error(where, "GDAL cannot open '" + file.string() + "' as a raster: " + CPLGetLastErrorMsg(),
                "check the path, and that `gdalinfo " + file.string() + "` reads it");
  return dataset;
}

// 1 to 4 bands of the sample types the page cache decodes.
void checkBands(GDALDataset& dataset, const SourceLocation& where) {
  const int bands = dataset.GetRasterCount();
  if (bands < 1 || bands > 4)
    throw Error(where, "'" + std::string(dataset.GetDescription()) + "' has " + std::to_string(bands) + " bands",
                "give 1 band (heights, scalars) or 3-4 (colour); pick them with gdal_translate -b");
  const GDALDataType type = dataset.GetRasterBand(1)->GetRasterDataType();
  if (GDALDataTypeIsComplex(type) || (GDALGetDataTypeSizeBits(type) > 32 && type != GDT_Float64))
    throw Error(where,
                "'" + std::string(dataset.GetDescription()) + "' holds " + GDALGetDataTypeName(type) + " samples",
                "convert to 8/16/32-bit integers or floats: gdal_translate -ot Float32");
}

// The COG of `input` in `target` (empty: its own CRS). A one-channel raster carries its blocks' ranges
// (strata/plugin/block_ranges.hpp), which bound a patch's heights by its data at any size; they are those of the
// texels written, so a reprojected raster is written twice: warped, then again with the ranges of what was
// warped.
Dataset writePyramid(GDALDataset& input, const std::filesystem::path& partial, const std::string& target,
                     const std::function<void(double)>& progress, const SourceLocation& where) {
  if (input.GetRasterCount() != 1) return tiling::writeCog(input, partial, target, progress, where);
  if (target.empty()) return tiling::writeCog(input, partial, "", progress, where, tiling::blockRangeItems(input));
  Dataset warped = tiling::writeCog(input, partial.parent_path() / "reprojected.tif", target,
                                    tiling::progressShare(progress, 0.0, kWarpedShare), where);
  return tiling::writeCog(*warped, partial, "", tiling::progressShare(progress, kWarpedShare, 1.0), where,
                          tiling::blockRangeItems(*warped));
}

// The pyramid, written into `partial` (in the scratch folder beside the output).
TilingResult tileInto(const PluginRegistry& plugins, GDALDataset& input, TilingRequest request,
                      const std::filesystem::path& partial) {
  const SourceLocation where{request.input.string()};
  const OGRSpatialReference* crs = input.GetSpatialRef();
  std::array<double, 6> geotransform{};
  if (!crs || input.GetGeoTransform(geotransform.data()) != CE_None)
    throw Error(where, "'" + request.input.string() + "' has no CRS or no geotransform, so where it lies is unknown",
                "assign them: gdal_translate -a_srs <CRS> -a_ullr ulx uly lrx lry in.tif out.tif");
  request.output = partial;
  if (request.target == tiling::kHealpixPyramid) return tiling::tileHealpix(plugins, input, request);
  if (request.nside != 0)
    throw Error({"--nside"}, "--nside is the resolution of a HEALPix pyramid, but the target is not one",
                "add --to " + std::string(tiling::kHealpixPyramid) + ", or leave --nside out");
  const std::string target = tiling::tileTarget(plugins, *crs, geotransform.data(), input.GetRasterXSize(),
                                                input.GetRasterYSize(), request.target, {"--to"});
  Dataset output = writePyramid(input, partial, target, request.progress, where);
  return {projStringOf(*output->GetSpatialRef()), !target.empty(), output->GetRasterXSize(), output->GetRasterYSize(),
          output->GetRasterBand(1)->GetOverviewCount()};
}

}  // namespace

// Written under a scratch name beside the output and renamed into place when whole and closed, so that an
// interrupted or failed run leaves the finished file or nothing (strata/host/output_file.hpp).
TilingResult tileRaster(const PluginRegistry& plugins, const TilingRequest& request) {
  const SourceLocation where{request.input.string()}, output{request.output.string()};
  checkOutputTarget(request.output, {request.overwrite, {request.input}}, output);
  Dataset input = openInput(request.input, where);
  // Every file GDAL reads for the input (a VRT's sources too): none may be the output.
  checkOutputTarget(request.output, {request.overwrite, filesGdalReads(*input)}, output);
  checkBands(*input, where);
  const ScratchDirectory scratch(request.output);
  const std::filesystem::path partial = scratch.path() / request.output.filename();
  const TilingResult result = tileInto(plugins, *input, request, partial);
  scratch.publish(partial, request.output, request.overwrite);
  return result;
}

}  // namespace strata
