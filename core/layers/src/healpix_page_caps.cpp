#include "layers/healpix_page_caps.hpp"

#include <vector>

#include <strata/plugin/page_pyramid.hpp>

namespace strata {

std::shared_ptr<const BlockCaps> pageCapsOf(const healpix::PageRanges& ranges, const RasterGeoreference& georeference,
                                            int nside) {
  std::vector<BlockValues> values;
  for (const healpix::PageRanges::Range& page : ranges.finestStoredRanges())
    values.push_back(page.least <= page.greatest ? BlockValues{page.least, page.greatest, page.uncovered}
                                                 : BlockValues{.gaps = page.uncovered});
  const BlockLayout layout{12 * nside, nside, kPagePayload << ranges.finestStoredLevel()};
  return std::make_shared<const BlockCaps>(layout, std::move(values), georeference, false, true);
}

}  // namespace strata
