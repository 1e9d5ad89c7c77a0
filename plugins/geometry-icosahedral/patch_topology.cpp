#include "patch_topology.hpp"

#include <algorithm>
#include <limits>

namespace strata::icosahedral {
namespace {

constexpr std::uint64_t kNoEdge = std::numeric_limits<std::uint64_t>::max();

// An undirected edge's key, and which side of it a patch running from a to b lies on.
std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}
std::size_t sideOf(std::uint32_t a, std::uint32_t b) { return a < b ? 0 : 1; }

}  // namespace

PatchTopology::PatchTopology() {
  for (const SphericalTriangle& face : icosahedronFaces()) {
    std::array<std::uint32_t, 3> corners{};
    for (std::size_t i = 0; i < 3; ++i) {
      const auto shared = std::ranges::find_if(vertices_, [&](const Vertex& v) { return v.normal == face[i]; });
      corners[i] =
          shared != vertices_.end() ? std::uint32_t(shared - vertices_.begin()) : addVertex(face[i], kNoEdge, 0);
    }
    addNode(corners, -1, 0);
  }
}

SphericalTriangle PatchTopology::cornersOf(std::int32_t id) const {
  const PatchNode& node = (*this)[id];
  return {vertices_[node.corners[0]].normal, vertices_[node.corners[1]].normal, vertices_[node.corners[2]].normal};
}

std::int32_t PatchTopology::across(std::int32_t id, int edge) const {
  const PatchNode& node = (*this)[id];
  const std::uint32_t a = node.corners[std::size_t(edge)], b = node.corners[std::size_t(edge + 1) % 3];
  const auto found = sides_.find(edgeKey(a, b));
  return found == sides_.end() ? -1 : found->second[1 - sideOf(a, b)];
}

std::int32_t PatchTopology::coarserNeighbour(std::int32_t id, int edge) const {
  const PatchNode& node = (*this)[id];
  if (node.parent < 0) return -1;
  const std::uint32_t a = node.corners[std::size_t(edge)], b = node.corners[std::size_t(edge + 1) % 3];
  const PatchNode& parent = (*this)[node.parent];
  // The parent's edge that this one is half of.
  for (int e = 0; e < 3; ++e) {
    const std::uint32_t p = parent.corners[std::size_t(e)], q = parent.corners[std::size_t(e + 1) % 3];
    const auto middle = midpoints_.find(edgeKey(p, q));
    if (middle == midpoints_.end()) continue;
    const std::uint32_t m = middle->second;
    if ((a == p && b == m) || (a == m && b == q)) return across(node.parent, e);
  }
  return -1;
}

std::array<std::uint32_t, 2> PatchTopology::parentsOf(std::uint32_t vertex) const {
  const std::uint64_t edge = vertices_[vertex].splitEdge;
  if (edge == kNoEdge) return {vertex, vertex};
  return {std::uint32_t(edge >> 32), std::uint32_t(edge & 0xffffffffu)};
}

void PatchTopology::split(std::int32_t leaf) {
  const std::array<std::uint32_t, 3> c = (*this)[leaf].corners;
  const int level = (*this)[leaf].level + 1;
  const std::uint32_t m01 = midpoint(c[0], c[1], level), m12 = midpoint(c[1], c[2], level),
                      m20 = midpoint(c[2], c[0], level);
  const std::array<std::array<std::uint32_t, 3>, 4> quarters{
      {{c[0], m01, m20}, {m01, c[1], m12}, {m20, m12, c[2]}, {m01, m12, m20}}};
  std::array<std::int32_t, 4> children{};
  for (std::size_t i = 0; i < 4; ++i) children[i] = addNode(quarters[i], leaf, level);
  (*this)[leaf].children = children;  // after addNode, which may move the nodes
}

void PatchTopology::merge(std::int32_t parent) {
  for (const std::int32_t child : (*this)[parent].children) removeNode(child);
  (*this)[parent].children = {-1, -1, -1, -1};
}

std::int32_t PatchTopology::addNode(const std::array<std::uint32_t, 3>& corners, std::int32_t parent, int level) {
  std::int32_t id = std::int32_t(nodes_.size());
  if (freeNodes_.empty()) {
    nodes_.emplace_back();
  } else {
    id = freeNodes_.back();
    freeNodes_.pop_back();
  }
  PatchNode& node = (*this)[id];
  node = {.corners = corners, .parent = parent, .level = level, .alive = true};
  for (std::size_t e = 0; e < 3; ++e) {
    const std::uint32_t a = corners[e], b = corners[(e + 1) % 3];
    sides_.try_emplace(edgeKey(a, b), std::array<std::int32_t, 2>{-1, -1}).first->second[sideOf(a, b)] = id;
    ++vertices_[a].users;
  }
  return id;
}

void PatchTopology::removeNode(std::int32_t id) {
  PatchNode& node = (*this)[id];
  for (std::size_t e = 0; e < 3; ++e) {
    const std::uint32_t a = node.corners[e], b = node.corners[(e + 1) % 3];
    const auto found = sides_.find(edgeKey(a, b));
    found->second[sideOf(a, b)] = -1;
    if (found->second[1 - sideOf(a, b)] < 0) sides_.erase(found);
  }
  for (const std::uint32_t corner : node.corners) release(corner);
  node.alive = false;
  freeNodes_.push_back(id);
}

std::uint32_t PatchTopology::addVertex(const glm::dvec3& normal, std::uint64_t splitEdge, int level) {
  const Vertex vertex{normal, splitEdge, 0, level};
  if (freeVertices_.empty()) {
    vertices_.push_back(vertex);
    return std::uint32_t(vertices_.size() - 1);
  }
  const std::uint32_t index = freeVertices_.back();
  freeVertices_.pop_back();
  vertices_[index] = vertex;
  return index;
}

std::uint32_t PatchTopology::midpoint(std::uint32_t a, std::uint32_t b, int level) {
  const std::uint64_t key = edgeKey(a, b);
  if (const auto found = midpoints_.find(key); found != midpoints_.end()) return found->second;
  const std::uint32_t vertex = addVertex(greatCircleMidpoint(vertices_[a].normal, vertices_[b].normal), key, level);
  midpoints_.emplace(key, vertex);
  return vertex;
}

// A vertex no patch uses any more is forgotten, so that the tree's memory follows its size, not its history.
void PatchTopology::release(std::uint32_t vertex) {
  Vertex& v = vertices_[vertex];
  if (--v.users > 0) return;
  if (v.splitEdge != kNoEdge) midpoints_.erase(v.splitEdge);
  freeVertices_.push_back(vertex);
}

}  // namespace strata::icosahedral
