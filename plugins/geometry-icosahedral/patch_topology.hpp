#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include <strata/body.hpp>

#include "icosahedron.hpp"

namespace strata::icosahedral {

// One patch of the tree: a face of the icosahedron or a quarter of its parent.
struct PatchNode {
  std::array<std::uint32_t, 3> corners{};  // vertices, counter-clockwise from outside
  std::int32_t parent = -1;
  std::array<std::int32_t, 4> children{-1, -1, -1, -1};  // corner 0's, 1's, 2's, then the middle one
  int level = 0;
  bool alive = false;
  bool visible = false;                // set by the tree's visibility test
  double distance = 0.0;               // m: the least face-on distance (patch_shell.hpp) from an eye that sees it
  std::optional<HeightRange> heights;  // the terrain's within it, once the tree asked (PatchHeights)
  double terrainError = 0.0;           // m: the relief a vertex spacing may hide, set with heights (PatchTree::errorOf)
  bool leaf() const { return children[0] < 0; }
};

// The shape of the patch tree: patches, their shared vertices and who lies across each edge. A split
// makes four children from the edge midpoints; vertices are shared by every patch that touches them,
// so neighbours hold the same corners bit for bit [Kooima 2008, §3.2.5]. Edge e of a patch runs
// from corner e to corner e + 1.
class PatchTopology {
 public:
  static constexpr std::int32_t kFaces = 20;
  PatchTopology();  // the icosahedron's faces, ids 0 to kFaces - 1

  std::size_t capacity() const { return nodes_.size(); }  // ids are below this; some are not alive
  const PatchNode& operator[](std::int32_t id) const { return nodes_[std::size_t(id)]; }
  PatchNode& operator[](std::int32_t id) { return nodes_[std::size_t(id)]; }
  SphericalTriangle cornersOf(std::int32_t id) const;

  // The patch of the same level across an edge, or -1 where the neighbour there is coarser.
  std::int32_t across(std::int32_t id, int edge) const;
  // The coarser patch across an edge that has no patch of the same level across it.
  std::int32_t coarserNeighbour(std::int32_t id, int edge) const;

  // A vertex's direction, its level (the split that made it, plus one; 0 for the icosahedron's own), and the two
  // whose edge it is the midpoint of (itself twice for the icosahedron's own).
  const glm::dvec3& normalOf(std::uint32_t vertex) const { return vertices_[vertex].normal; }
  int levelOf(std::uint32_t vertex) const { return vertices_[vertex].level; }
  std::array<std::uint32_t, 2> parentsOf(std::uint32_t vertex) const;

  void split(std::int32_t leaf);
  void merge(std::int32_t parent);  // the four children must be leaves

 private:
  struct Vertex {
    glm::dvec3 normal;
    std::uint64_t splitEdge;  // the edge it is the midpoint of, or kNoEdge for the icosahedron's own
    int users;
    int level;
  };

  std::int32_t addNode(const std::array<std::uint32_t, 3>& corners, std::int32_t parent, int level);
  void removeNode(std::int32_t id);
  std::uint32_t addVertex(const glm::dvec3& normal, std::uint64_t splitEdge, int level);
  std::uint32_t midpoint(std::uint32_t a, std::uint32_t b, int level);
  void release(std::uint32_t vertex);

  std::vector<PatchNode> nodes_;
  std::vector<std::int32_t> freeNodes_;
  std::vector<Vertex> vertices_;
  std::vector<std::uint32_t> freeVertices_;
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints_;            // edge -> its midpoint
  std::unordered_map<std::uint64_t, std::array<std::int32_t, 2>> sides_;  // edge -> the patch on each side
};

}  // namespace strata::icosahedral
