#pragma once
#include "displaced_patch.hpp"

namespace strata::bdam {

// The patch's triangles reordered for the GPU's post-transform vertex cache, and its vertices in the order those
// triangles first name them, the vertices no triangle names left out: the paper's "generalised triangle strip",
// ordered for the cache (§3), and "strip occurrence order" (§4.4), which keeps consecutive vertices near each other
// and their stored differences small. By meshoptimizer (meshopt_optimizeVertexCache, meshopt_optimizeVertexFetch);
// each triangle keeps its vertices' winding.
DisplacedPatch orderedForDrawing(const DisplacedPatch& patch);

}  // namespace strata::bdam
