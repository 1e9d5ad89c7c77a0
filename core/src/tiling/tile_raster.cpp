// strata tile: any GDAL raster to the Cloud Optimized GeoTIFF pyramid the page cache reads.
#include <cpl_conv.h>
#include <gdal_priv.h>
#include <gdal_utils.h>

#include <memory>
#include <vector>

#include <strata/crs.hpp>
#include <strata/tiling.hpp>

#include "tiling/tile_target.hpp"

namespace strata {
namespace {

using Dataset = std::unique_ptr<GDALDataset>;

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
    throw Error(where, "'" + std::string(dataset.GetDescription()) + "' holds " + GDALGetDataTypeName(type) + " samples",
                "convert to 8/16/32-bit integers or floats: gdal_translate -ot Float32");
}

// GDAL's command-line style options for the COG driver.
std::vector<std::string> translateArguments(const std::string& targetCrs) {
  std::vector<std::string> arguments{"-of", "COG",
      "-co", "BLOCKSIZE=512",          // the page size of seed 000 section 4.3.1
      "-co", "COMPRESS=DEFLATE",       // lossless: heights must come back bit for bit
      "-co", "OVERVIEWS=IGNORE_EXISTING",
      "-co", "RESAMPLING=AVERAGE",     // overviews are the mean of what they cover, as the GPU's mips are
      "-co", "NUM_THREADS=ALL_CPUS",   // compression on every core
      "-co", "BIGTIFF=IF_SAFER"};
  if (!targetCrs.empty()) {
    arguments.insert(arguments.end(), {"-co", "TARGET_SRS=" + targetCrs, "-co", "WARP_RESAMPLING=BILINEAR"});
  }
  return arguments;
}

int progressThunk(double fraction, const char*, void* data) {
  (*static_cast<std::function<void(double)>*>(data))(fraction);
  return 1;
}

Dataset translate(GDALDataset& input, const TilingRequest& request, const std::string& targetCrs,
                  const SourceLocation& where) {
  std::vector<std::string> arguments = translateArguments(targetCrs);
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::unique_ptr<GDALTranslateOptions, void (*)(GDALTranslateOptions*)> options(
      GDALTranslateOptionsNew(argv.data(), nullptr), GDALTranslateOptionsFree);
  std::function<void(double)> progress = request.progress;
  if (progress) GDALTranslateOptionsSetProgress(options.get(), progressThunk, &progress);
  // The warper's own threads (the COG driver warps before it tiles).
  const std::string previousThreads = CPLGetThreadLocalConfigOption("GDAL_NUM_THREADS", "");
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", "ALL_CPUS");
  CPLErrorReset();
  Dataset output(GDALDataset::FromHandle(
      GDALTranslate(request.output.c_str(), GDALDataset::ToHandle(&input), options.get(), nullptr)));
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", previousThreads.empty() ? nullptr : previousThreads.c_str());
  if (!output)
    throw Error(where, "GDAL could not write '" + request.output.string() + "': " + CPLGetLastErrorMsg(),
                "check that the output's folder exists and is writable, and that the disk has room");
  return output;
}

}  // namespace

TilingResult tileRaster(const PluginRegistry& plugins, const TilingRequest& request) {
  const SourceLocation where{request.input.string()};
  if (!request.overwrite && std::filesystem::exists(request.output))
    throw Error({request.output.string()}, "the output exists already", "choose another name, or pass --overwrite");
  Dataset input = openInput(request.input, where);
  checkBands(*input, where);
  const OGRSpatialReference* crs = input->GetSpatialRef();
  std::array<double, 6> geotransform{};
  if (!crs || input->GetGeoTransform(geotransform.data()) != CE_None)
    throw Error(where, "'" + request.input.string() + "' has no CRS or no geotransform, so where it lies is unknown",
                "assign them: gdal_translate -a_srs <CRS> -a_ullr ulx uly lrx lry in.tif out.tif");
  const std::string target = tiling::tileTarget(plugins, *crs, geotransform.data(), input->GetRasterXSize(),
                                                input->GetRasterYSize(), request.target, {"--to"});
  Dataset output = translate(*input, request, target, where);
  return {projStringOf(*output->GetSpatialRef()), !target.empty(), output->GetRasterXSize(),
          output->GetRasterYSize(), output->GetRasterBand(1)->GetOverviewCount()};
}

}  // namespace strata
