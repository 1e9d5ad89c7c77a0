#pragma once
#include <cstddef>
#include <span>
#include <strata/export.hpp>

#include <strata/plugin/page_source.hpp>

// Not part of the SDK: exported from libstrata_core for Strata's own tests and tools.
STRATA_EXPORTS_BEGIN
namespace strata::paging {

// Fills one atlas slot (kPageSide x kPageSide texels) with page `key` of `source`: slot texel (i, j)
// holds level texel (512 column + i - 1, 512 row + j - 1). Rows are clamped to the edges of the page's grid
// (the level, unless PageSource::gridOf says otherwise), and so are columns unless `wrapX`, where the column
// west of the first is the level's last and the one east of the last is its first, so that filtering runs
// on across the seam; a texel one beyond the grid's edge that PageSource::texelBeside places elsewhere in
// the level is read from there. Where the neighbours' texels
// cannot be read, the border repeats the page's own edge; where the page's own texels cannot be read,
// throws what source.read throws.
void assemblePage(const PageSource& source, const PageKey& key, bool wrapX, std::span<std::byte> slot);

}  // namespace strata::paging
STRATA_EXPORTS_END
