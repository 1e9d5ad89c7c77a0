#include "stored_block_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <strata/log.hpp>

#include "drawn_window.hpp"

namespace strata::gdal {
namespace {

// An average computed and stored in the band's type strays beyond the range of what it averages by rounding
// alone: a ten-thousandth of its size is far beyond that, and far below what a rescaling changes.
constexpr double kAverageRounding = 1e-4;

// The block containing level-0 texel position `texel`, within the `blocks` there are.
int blockAt(double texel, int side, int blocks) { return std::clamp(int(std::floor(texel / side)), 0, blocks - 1); }

// Whether `value` lies within the ranges of the blocks under level-0 texels [low, high), widened by a texel
// for the rounding of GDAL's averaging window. Where some of them hold no data somewhere it cannot be told:
// an average may have taken in what fills those texels (0 under an alpha band), so it is let be.
bool heldByBlocks(const BlockRanges& ranges, double value, glm::dvec2 low, glm::dvec2 high) {
  const int side = ranges.blockTexels();
  double least = std::numeric_limits<double>::infinity(), greatest = -least;
  for (int row = blockAt(low.y - 1.0, side, ranges.rows()); row <= blockAt(high.y + 1.0, side, ranges.rows()); ++row)
    for (int column = blockAt(low.x - 1.0, side, ranges.columns());
         column <= blockAt(high.x + 1.0, side, ranges.columns()); ++column) {
      if (ranges.holdsGaps(column, row)) return true;
      const BlockRanges::Block& block = ranges.at(column, row);
      least = std::min(least, block.least);
      greatest = std::max(greatest, block.greatest);
    }
  const double slack = kAverageRounding * std::max(1.0, std::abs(value));
  return value >= least - slack && value <= greatest + slack;
}

// Whether every texel of the band's coarsest overview that holds data lies within the blocks it averages.
bool agreesWithOverview(GDALRasterBand& band, const BlockRanges& ranges) {
  if (band.GetOverviewCount() == 0) return false;
  GDALRasterBand& overview = *band.GetOverview(band.GetOverviewCount() - 1);
  const int width = overview.GetXSize(), height = overview.GetYSize();
  const std::optional<std::vector<double>> values = readDrawnWindow(overview, 0, 0, width, height);
  if (!values) return false;
  const glm::dvec2 texels(double(band.GetXSize()) / width, double(band.GetYSize()) / height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double value = (*values)[std::size_t(y) * width + x];
      if (std::isnan(value)) continue;
      if (!heldByBlocks(ranges, value, glm::dvec2(x, y) * texels, glm::dvec2(x + 1, y + 1) * texels)) return false;
    }
  return true;
}

void warnOfIgnored(GDALDataset& dataset, const char* why) {
  logWarning(std::string("'") + dataset.GetDescription() + "' carries block ranges that " + why +
                 ": it was changed after `strata tile` wrote it, so its heights are not known region by region and "
                 "its patches are measured on the sphere",
             "run `strata tile` on it again");
}

}  // namespace

std::shared_ptr<BlockRanges> storedBlockRanges(GDALDataset& dataset) {
  const auto item = [&](const std::string& name) { return dataset.GetMetadataItem(name.c_str()); };
  const std::optional<BlockRanges> ranges =
      BlockRanges::fromMetadata(dataset.GetRasterXSize(), dataset.GetRasterYSize(), item);
  if (!ranges) {
    if (BlockRanges::inMetadata(item)) warnOfIgnored(dataset, "do not fit its size");
    return nullptr;
  }
  if (!agreesWithOverview(*dataset.GetRasterBand(1), *ranges)) {
    warnOfIgnored(dataset, "its coarsest overview contradicts");
    return nullptr;
  }
  return std::make_shared<BlockRanges>(*ranges);
}

}  // namespace strata::gdal
