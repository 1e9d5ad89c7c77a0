#pragma once
// A node of geometry.healpix's twelve quadtrees [Westerteiger et al. 2011, §3.2]: a dyadic square of a base face's
// coordinates, with what the traversal and the balancing pass ask of it.
#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include <strata/plugin/healpix.hpp>
#include <strata/plugin/spherical_cap.hpp>

namespace strata::healpix {

// The node covering face coordinates [ix, ix + 1] / 2^level by [iy, iy + 1] / 2^level of base face `face`:
// at level L it is the NESTED pixel (ix, iy) of that face at nside 2^L. Its corners are numbered as the
// face's: 0 south (x, y low), 1 east (x high), 2 north (both high), 3 west (y high); edge e runs from corner e
// to corner e + 1, so edge 0 lies at y = iy / 2^L, 1 at x = (ix + 1) / 2^L, 2 at y = (iy + 1) / 2^L and 3 at
// x = ix / 2^L.
struct NodeKey {
  int face = 0;
  int level = 0;
  std::int64_t ix = 0, iy = 0;

  friend bool operator==(const NodeKey&, const NodeKey&) = default;

  // The node's side in face coordinates, 2^-level.
  double size() const;
  // The four children, in the order (ix, iy) low-low, high-low, low-high, high-high.
  std::array<NodeKey, 4> children() const;
  NodeKey parent() const;
  // The face point at (u, v) in [0, 1]^2 across the node.
  FacePoint at(double u, double v) const;
  FacePoint centre() const { return at(0.5, 0.5); }
  FacePoint corner(int corner) const;
  // Whether the node holds a point of its face: half open like a pixel, except that the face's own north
  // and east edges (x or y = 1) belong to the nodes along them.
  bool holds(const FacePoint& point) const;
};

struct NodeKeyHash {
  std::size_t operator()(const NodeKey& key) const;
};

// The node of `level` holding a face point.
NodeKey nodeAt(const FacePoint& point, int level);

// A point just beyond the middle of edge `edge`, a 64th of the node's size outward, in whichever face holds
// it: the place to look for the neighbour across that edge (docs/healpix.md, "Selection"). Across a base-face
// boundary the step is taken on the sphere, mirroring a point as far inside through the edge's midpoint.
// Neighbours at one level meet edge to edge across face boundaries too, so a neighbour of any coarser
// level holds the point.
FacePoint acrossEdge(const NodeKey& key, int edge);

// The node's cone from the body's centre: the cap holding every direction of the node, around its centre's unit
// vector, kConeMargin times as wide as the largest angle from it to the node's corners and edge midpoints (the
// edges are curves, so the farthest point may lie between those; node_selection_test checks the margin against
// dense samples of whole faces down to deep nodes).
using NodeCone = SphericalCap;
constexpr double kConeMargin = 1.1;
NodeCone coneOf(const NodeKey& key);
// The unit vectors of the node's boundary samples: corner 0, the middle of edge 0, corner 1, ..., the middle
// of edge 3; and the cone around `axis` they give.
std::array<glm::dvec3, 8> boundarySamples(const NodeKey& key);
NodeCone coneAround(const glm::dvec3& axis, const std::array<glm::dvec3, 8>& boundary);

}  // namespace strata::healpix
