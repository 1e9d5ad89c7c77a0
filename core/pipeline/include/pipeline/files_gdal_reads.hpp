#pragma once
// What GDAL reads for a dataset it opened: the file itself, a VRT's sources, overviews, side-cars. No
// output may be one of them (strata/host/output_file.hpp): pipelineInputFiles and strata tile ask it.
#include <filesystem>
#include <vector>

#include <gdal_priv.h>

namespace strata {

std::vector<std::filesystem::path> filesGdalReads(GDALDataset& dataset);

}  // namespace strata
