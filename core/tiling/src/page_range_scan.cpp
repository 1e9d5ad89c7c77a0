#include "page_range_scan.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "texel_windows.hpp"

namespace strata::tiling {
namespace {

using Range = healpix::PageRanges::Range;

Range rangeOf(const TexelWindow& window) {
  Range range{INFINITY, -INFINITY, false};
  for (std::size_t i = 0; i < window.values.size(); ++i) {
    if (window.mask[i] == 0 || std::isnan(window.values[i])) {
      range.uncovered = true;
      continue;
    }
    range.least = std::min(range.least, float(window.values[i]));
    range.greatest = std::max(range.greatest, float(window.values[i]));
  }
  return range;
}

}  // namespace

// The strip's sides are whole pages (healpix::kLeastNside), so its windows are its pages, row by row.
healpix::PageRanges scanPageRanges(GDALDataset& strip, std::int64_t nside) {
  std::vector<Range> finest;
  finest.reserve(std::size_t(12 * nside / kPagePayload) * std::size_t(nside / kPagePayload));
  visitTexelWindows(strip, [&](const TexelWindow& window) { finest.push_back(rangeOf(window)); });
  return healpix::PageRanges(nside, finest);
}

}  // namespace strata::tiling
