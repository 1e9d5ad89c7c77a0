#include "cog_writing.hpp"

#include <cpl_conv.h>
#include <gdal_utils.h>

namespace strata::tiling {
namespace {

// GDAL's command-line style options for the COG driver.
std::vector<std::string> translateArguments(const std::string& targetCrs, const MetadataItems& metadata) {
  std::vector<std::string> arguments{
      "-of", "COG",
      "-co", "BLOCKSIZE=512",     // the page size of [Kooima 2008, §4.3.1]
      "-co", "COMPRESS=DEFLATE",  // lossless: heights must come back bit for bit
      "-co", "OVERVIEWS=IGNORE_EXISTING",
      "-co", "RESAMPLING=AVERAGE",    // overviews are the mean of what they cover, as the GPU's mips are
      "-co", "NUM_THREADS=ALL_CPUS",  // compression on every core
      "-co", "BIGTIFF=IF_SAFER",
      "-co", "SPARSE_OK=TRUE"};
  if (!targetCrs.empty()) {
    arguments.insert(arguments.end(), {"-co", "TARGET_SRS=" + targetCrs, "-co", "WARP_RESAMPLING=BILINEAR"});
  }
  for (const auto& [name, value] : metadata) arguments.insert(arguments.end(), {"-mo", name + "=" + value});
  return arguments;
}

}  // namespace

AllCpusForWarping::AllCpusForWarping() : previous_(CPLGetThreadLocalConfigOption("GDAL_NUM_THREADS", "")) {
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", "ALL_CPUS");
}

AllCpusForWarping::~AllCpusForWarping() {
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", previous_.empty() ? nullptr : previous_.c_str());
}

std::vector<char*> argvOf(std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  return argv;
}

std::function<void(double)> progressShare(const std::function<void(double)>& progress, double from, double to) {
  if (!progress) return {};
  return [=](double fraction) { progress(from + (to - from) * fraction); };
}

int reportProgress(double fraction, const char*, void* progress) {
  (*static_cast<std::function<void(double)>*>(progress))(fraction);
  return 1;
}

Dataset writeCog(GDALDataset& source, const std::filesystem::path& output, const std::string& targetCrs,
                 std::function<void(double)> progress, const SourceLocation& where, const MetadataItems& metadata) {
  std::vector<std::string> arguments = translateArguments(targetCrs, metadata);
  std::unique_ptr<GDALTranslateOptions, void (*)(GDALTranslateOptions*)> options(
      GDALTranslateOptionsNew(argvOf(arguments).data(), nullptr), GDALTranslateOptionsFree);
  if (progress) GDALTranslateOptionsSetProgress(options.get(), reportProgress, &progress);
  const AllCpusForWarping threads;  // the COG driver warps before it tiles
  CPLErrorReset();
  Dataset written(
      GDALDataset::FromHandle(GDALTranslate(output.c_str(), GDALDataset::ToHandle(&source), options.get(), nullptr)));
  if (!written)
    throw Error(where, "GDAL could not write '" + output.string() + "': " + CPLGetLastErrorMsg(),
                "check that the output's folder exists and is writable, and that the disk has room");
  return written;
}

}  // namespace strata::tiling
