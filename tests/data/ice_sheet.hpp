#pragma once
#include <filesystem>

namespace strata::testdata {

// An ice sheet over the test planet's north pole, for composite.layer_peel (pipelines/layer_peel.yaml): its
// surface, ice-height.tif, is the north cap's bedrock (north-height.tif) plus Vialov's steady-state profile
// of thickness, 3000 m at the pole thinning to nothing 1200 km from it, nodata beyond; its colours,
// ice-color.tif, blue-white, paler where the ice is thicker, alpha 0 beyond. Both on the north cap's polar
// stereographic grid. Throws std::runtime_error naming a file it cannot read or write.
void writeIceSheet(const std::filesystem::path& directory);

}  // namespace strata::testdata
