#pragma once
#include <array>

#include "diamonds.hpp"
#include "displaced_patch.hpp"

namespace strata::bdam {

// One step of the builder's bottom-up simplification [Cignoni et al. 2003, §5, "mark, distribute, simplify,
// merge"]: a diamond's four child patches (in Diamond::children()'s order) joined into one mesh, simplified to half
// its triangles by quadric-error edge collapse [Garland & Heckbert 1997] (Debian's meshoptimizer) with the children's
// hypotenuses, the diamond's outline, frozen, and split at the diagonal into the two halves' patches, ordered for
// drawing. The diagonal, the halves' shared hypotenuse, keeps a subset of its vertices, the same from either half:
// each half's copy of a diagonal vertex is its own vertex at one position, which meshoptimizer keeps as a seam
// (it collapses a seam only along itself, both copies together), so no triangle crosses the diagonal. Its vertices
// are then stored on each half from the diagonal's ends alone, so that the halves share them to the bit; the outline
// is stored on the halves' legs exactly as the children had it on their hypotenuses, so that the finer patches
// across it still meet it.
std::array<DisplacedPatch, 2> simplifiedDiamond(const Diamond& diamond, const std::array<DisplacedPatch, 4>& children,
                                                double radius);

}  // namespace strata::bdam
