#pragma once
#include <functional>
#include <optional>
// The CPU half of geometry.healpix's traversal ([Westerteiger et al. 2011, §3.2, §3.2.2]; docs/healpix.md,
// "Selection"): which nodes of the twelve quadtrees a view draws, in double.
#include <array>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <strata/camera.hpp>
#include <strata/plugin/height_input.hpp>

#include "healpix_node.hpp"

namespace strata::healpix {

// A node to draw. Bit e of coarserEdges is set when the node across edge e (healpix_node.hpp's numbering)
// is drawn one level coarser: the edge then skips its odd vertices. Drawn neighbours never differ by more.
struct SelectedNode {
  NodeKey key;
  unsigned coarserEdges = 0;
};

struct SelectionSettings {
  // The paper's user factor, desired vertices per pixel [Westerteiger et al. 2011, §3.2.2]: a node is drawn when its
  // projected area in pixels times this needs no more vertices than its grid has. 0.2 recommended, 0.005
  // to 1.0 in the paper's figure 7.
  double threshold = 0.2;
  // Cells along a node's proxy grid: (gridCells + 1)^2 vertices. 64: 4225 vertices a node, so a few hundred
  // nodes cover a view (the paper's 254 is its data tiles' size, for 16-bit indices).
  int gridCells = 64;
  // px: a node whose geometric error seen from its shell shows no more than this is drawn, however many vertices
  // its area asks for, so that the threshold caps the density where the terrain is rough and a smooth sphere takes
  // few nodes (level of detail by screen-space error, as geometry.icosahedral's pixel_error; 0: the paper's
  // density alone). One pixel is what the eye cannot resolve.
  double pixelError = 1.0;
  int maxLevel = 26;  // 2^-26 of a face, about 10 cm on Earth
  double gridVertices() const { return double(gridCells + 1) * double(gridCells + 1); }
};

// What a node's terrain can occupy: its directions (a NodeCone) between the radii of the lowest and highest
// heights, and a box around that, planet-fixed, whose projection bounds the terrain's on screen.
struct NodeShell {
  NodeCone cone;
  double innerRadius = 0.0, outerRadius = 0.0;  // m
  std::array<glm::dvec3, 8> box;                // corners, m
  std::optional<BlockRelief> finest;            // the height layer's finest relief within it, where known
};

// The heights over one node, of the cone given, where they are known more closely than the body's range (a
// HEALPix pyramid's pages' true ranges, HealpixFaceLayer::faceNodeValues, or another raster's over the cone,
// RegionalValueLayer::valuesWithin; the paper's per-node boxes, [Westerteiger et al. 2011, §3.2.1]; docs/references.md,
// Errata); empty: the body's range.
using NodeHeights = std::function<std::optional<RegionalHeights>(const NodeKey&, const NodeCone&)>;

// One view's tests of node shells. Culling is exact for the cone's shell, so never removes what the cone
// holds; the area is the paper's, the projection of a bounding box [Westerteiger et al. 2011, §3.2.2].
class ShellView {
 public:
  ShellView(const View& view, double radius, HeightRange heights, NodeHeights nodeHeights = {});

  NodeShell shellOf(const NodeKey& key) const;
  // Whether the shell lies wholly outside one plane of the frustum (far plane at infinity) or wholly behind
  // the body, taken as the sphere of the body's lowest height: a point at radius r is hidden when its angle from
  // the eye's direction exceeds acos(r_low / |eye|) + acos(r_low / r) (the tangent rays).
  bool culled(const NodeShell& shell) const;
  // A bound on the pixels the node's terrain covers [Westerteiger et al. 2011, §3.2.2], the lesser of two:
  // - boxArea: the box's projection, the convex hull of its projected corners (what the paper's sum over
  //   front faces gives) clipped to the screen, since only pixels on it ask for vertices; infinite when a
  //   corner lies at or behind the near plane, which forces refinement (the paper does not say what such a
  //   box projects to). Tight from afar and edge on, but a global height range makes boxes tens of km tall
  //   that near the ground cover the screen however narrow they are.
  // - faceOnArea: the node's surface seen face on from its shell's nearest point, at the densest pixels of
  //   the screen (its corners, f^2 / cos^3 per steradian): its area (HEALPix is equal area, 4 pi r^2 / (12
  //   4^level) at the outer radius) times kSlopeAllowance over the nearest distance squared. Infinite when
  //   the shell holds the eye. Tight near the ground, where the box is not.
  double projectedArea(const NodeShell& shell, const NodeKey& key) const;
  double boxArea(const NodeShell& shell) const;
  double faceOnArea(const NodeShell& shell, const NodeKey& key) const;
  // The most the node's grid of `gridCells` cells a side may misplace its terrain on screen, px: the larger of the
  // sphere's error (chordError) and the relief a vertex spacing may hide (reliefWithinSpacing), seen from the
  // shell's nearest point at the screen's densest pixels. Infinite when the shell holds the eye.
  double screenError(const NodeShell& shell, const NodeKey& key, int gridCells) const;
  // Terrain may hold more area than its patch of the sphere: twice as much, slopes of 60 degrees throughout.
  static constexpr double kSlopeAllowance = 2.0;

 private:
  struct Plane {
    glm::dvec3 normal;  // unit, toward the inside
    double offset;      // inside where dot(normal, p - eye) + offset >= 0
  };
  double nearestDistanceSquared(const NodeShell& shell) const;

  glm::dvec3 eye_;
  glm::dmat3 planetToEye_;
  double near_, focal_;        // focal length in pixels
  glm::dvec2 halfScreen_;      // pixels
  double pixelsPerSteradian_;  // at the screen's corners, the most
  double radius_;
  HeightRange heights_;
  NodeHeights nodeHeights_;
  std::array<Plane, 5> planes_;
};

// The nodes a view draws of a body of `radius` (m) whose heights lie in `heights`: stateless, top down from
// the twelve faces [Westerteiger et al. 2011, §3.2]; a node is culled by ShellView::culled, drawn when its projected
// area times the threshold is at most its grid's vertices, when its screen error is at most the pixel error, or at
// maxLevel, else refined. Then coarser
// neighbours are split until drawn neighbours differ by at most one level, across face edges too, keeping
// only the visible children of a split node; last the coarser edges are marked. Depth first from face 0.
std::vector<SelectedNode> selectNodes(const View& view, double radius, HeightRange heights,
                                      const SelectionSettings& settings, const NodeHeights& nodeHeights = {});

}  // namespace strata::healpix
