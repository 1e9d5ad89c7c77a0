// The files a loaded pipeline reads, which no output may replace (strata/host/output_file.hpp).
#include <gdal_priv.h>

#include <memory>
#include <string>
#include <variant>

#include <strata/host/pipeline.hpp>

#include "pipeline/files_gdal_reads.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;

// What GDAL itself reads for `file`: a VRT's sources, overviews, side-cars; nothing if GDAL cannot open it.
void addFilesGdalReads(const fs::path& file, std::vector<fs::path>& files) {
  CPLPushErrorHandler(CPLQuietErrorHandler);  // not a raster (a vector file, a path list): only the file itself
  std::unique_ptr<GDALDataset> dataset(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  CPLPopErrorHandler();
  if (!dataset) return;
  const std::vector<fs::path> read = filesGdalReads(*dataset);
  files.insert(files.end(), read.begin(), read.end());
}

}  // namespace

std::vector<fs::path> filesGdalReads(GDALDataset& dataset) {
  std::vector<fs::path> files;
  char** list = dataset.GetFileList();
  for (char** name = list; name && *name; ++name) files.emplace_back(*name);
  CSLDestroy(list);
  return files;
}

std::vector<fs::path> pipelineInputFiles(const Pipeline& pipeline) {
  std::vector<fs::path> files;
  if (!pipeline.file.empty()) files.push_back(pipeline.file);
  // Any text value that names a file is taken as read: a path parameter of any plugin's node type.
  for (const NodeDescription& node : pipeline.nodes)
    for (const std::string& name : node.parameters.names()) {
      const auto* text = std::get_if<std::string>(&node.parameters.value(name));
      std::error_code error;
      if (!text || text->empty() || !fs::is_regular_file(*text, error)) continue;
      files.emplace_back(*text);
      addFilesGdalReads(*text, files);
    }
  for (const SceneBody& body : pipeline.bodies) {
    const std::vector<fs::path> read = pipelineInputFiles(body.pipeline);
    files.insert(files.end(), read.begin(), read.end());
  }
  return files;
}

}  // namespace strata
