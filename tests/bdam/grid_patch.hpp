#pragma once
// A regular patch for geometry.bdam's tests.
#include <cstdint>
#include <vector>

#include "displaced_patch.hpp"

namespace strata::bdam {

// The right triangle's grid of `divisions` steps a side, row by row (the order the triangles first name its
// vertices), displaced by `height` (m) at the barycentrics; two triangles a grid square, one along the diagonal.
template <class Height>
DisplacedPatch gridPatch(int divisions, Height height) {
  DisplacedPatch patch;
  std::vector<std::vector<std::uint32_t>> rows;
  for (int j = 0; j <= divisions; ++j) {
    rows.emplace_back();
    for (int i = 0; i + j <= divisions; ++i) {
      const double b1 = double(i) / divisions, b2 = double(j) / divisions;
      rows.back().push_back(std::uint32_t(patch.vertices.size()));
      patch.vertices.push_back(displacedVertex(b1, b2, height(b1, b2)));
    }
  }
  for (int j = 0; j < divisions; ++j)
    for (int i = 0; i + j < divisions; ++i) {
      patch.indices.insert(patch.indices.end(), {rows[j][i], rows[j][i + 1], rows[j + 1][i]});
      if (i + j + 1 < divisions)
        patch.indices.insert(patch.indices.end(), {rows[j][i + 1], rows[j + 1][i + 1], rows[j + 1][i]});
    }
  return patch;
}

}  // namespace strata::bdam
