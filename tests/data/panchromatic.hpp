#pragma once
#include <filesystem>

namespace strata::testdata {

// A panchromatic view of the strip, for composite.chroma_fusion (pipelines/chroma_fusion.yaml): the relative
// luminance of strip-color.tif's colours (sRGB decoded to linear light, Rec. 709 weights) times kPanchromaticGain,
// as strip-luminance.tif (Float32, nodata -1 outside the track), on the strip's grid. Reads
// <directory>/strip-color.tif; throws std::runtime_error naming a file it cannot use.
void writePanchromatic(const std::filesystem::path& directory);

// 0.8: darker than the colours, as another camera's exposure would be, so that the fusion's luminance
// matching has a difference of brightness to take out.
inline constexpr double kPanchromaticGain = 0.8;

}  // namespace strata::testdata
