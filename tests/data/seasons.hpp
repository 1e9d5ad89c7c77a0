#pragma once
#include <filesystem>

namespace strata::testdata {

// Twelve monthly views of the global colour observation, as a time series for composite.temporal_blend
// (pipelines/temporal_blend.yaml): season-200401-color.tif to season-200412-color.tif, at half its resolution, with
// snow that reaches 40 degrees from the equator in each hemisphere's midwinter and draws back to 85 degrees in
// its midsummer. Reads <directory>/global-color.tif; throws std::runtime_error naming a file it cannot use.
void writeSeasons(const std::filesystem::path& directory);

}  // namespace strata::testdata
