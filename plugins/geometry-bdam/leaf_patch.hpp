#pragma once
#include <functional>

#include <glm/glm.hpp>

#include "cube_bintree.hpp"
#include "displaced_patch.hpp"

namespace strata::bdam {

// Heights of the terrain, m above the body's radius, at a planet-fixed unit direction.
using HeightAt = std::function<double(const glm::dvec3& direction)>;

// A bintree leaf's patch before simplification [Cignoni et al. 2003, §5: "recursively subdivide each cube face,
// placing new vertices on the planet surface"]: the node's triangle cut into `divisions` steps a side, each grid
// point displaced along the interpolated normal to the terrain of `heights` (the height where the displaced point
// lies: found step by step, the height at the last step's point, to a millimetre),
// ordered for drawing (patch_order.hpp). divisions^2 triangles: 16 gives 256, a few hundred as the paper's patches.
DisplacedPatch leafPatch(const BintreeNode& node, double radius, const HeightAt& heights, int divisions);

}  // namespace strata::bdam
