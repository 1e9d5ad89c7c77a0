#pragma once
#include <functional>
#include <optional>
#include <vector>

#include <strata/camera.hpp>

#include "cube_bintree.hpp"
#include "face_file.hpp"

namespace strata::bdam {

// What the refinement reads of a node: its error and sphere (FaceFile::node), and whether its patch is on the GPU.
struct NodeLookup {
  std::function<std::optional<NodeRecord>(const BintreeNode&)> record;  // empty: damaged, never split nor drawn
  std::function<bool(const BintreeNode&)> resident;
};

struct Cut {
  std::vector<BintreeNode> drawn;    // the patches to draw: a conforming bintree cut's visible nodes
  std::vector<BintreeNode> missing;  // not resident, wanted for a visible node's split (or a root, to be drawn)
  std::size_t visited = 0;           // nodes looked at
};

// P-BDAM's stateless top-down refinement [Cignoni et al. 2003, §4.3], level by level from the twelve roots: a
// diamond splits, both halves together, when its error seen from the eye over its sphere exceeds `pixelError`
// pixels (error times the focal length in pixels over the distance to the sphere; the paper prints no formula) and
// both halves' children are resident (a culled half needs none). Errors and spheres nest and are shared across the
// hypotenuse (docs/bdam.md), so the halves decide alike and the nodes left form a conforming cut; a diamond whose
// other half its parent did not reach cannot split. Nodes whose sphere lies outside the frustum or behind the body
// (the sphere of `lowestRadius`) are not drawn but still split, so that a visible neighbour across their legs can.
Cut refine(const View& view, int leafLevel, double pixelError, double lowestRadius, const NodeLookup& nodes);

// Whether a sphere lies wholly outside the view's frustum (the far plane at infinity) or wholly behind the body,
// taken as the sphere of `lowestRadius`: a point at radius r is hidden when its angle from the eye's direction
// exceeds acos(lowestRadius / |eye|) + acos(lowestRadius / r), the tangent rays'.
bool culled(const View& view, const BoundingSphere& sphere, double lowestRadius);

}  // namespace strata::bdam
