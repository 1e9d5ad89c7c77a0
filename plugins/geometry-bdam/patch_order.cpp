#include "patch_order.hpp"

#include <meshoptimizer.h>

namespace strata::bdam {

DisplacedPatch orderedForDrawing(const DisplacedPatch& patch) {
  checkPatch(patch);
  DisplacedPatch ordered{patch.vertices, std::vector<std::uint32_t>(patch.indices.size())};
  meshopt_optimizeVertexCache(ordered.indices.data(), patch.indices.data(), patch.indices.size(),
                              patch.vertices.size());
  const std::size_t used =
      meshopt_optimizeVertexFetch(ordered.vertices.data(), ordered.indices.data(), ordered.indices.size(),
                                  patch.vertices.data(), patch.vertices.size(), sizeof(DisplacedVertex));
  ordered.vertices.resize(used);
  return ordered;
}

}  // namespace strata::bdam
