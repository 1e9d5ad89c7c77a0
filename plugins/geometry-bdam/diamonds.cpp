#include "diamonds.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>

namespace strata::bdam {
HypotenuseKey hypotenuseOf(const BintreeNode& node) {
  const FaceTriangle triangle = faceTriangle(node);
  std::array<glm::dvec3, 2> ends = {cubeDirection(faceOf(node), triangle.left),
                                    cubeDirection(faceOf(node), triangle.right)};
  const auto bits = [](const glm::dvec3& v) {
    return std::array<std::uint64_t, 3>{std::bit_cast<std::uint64_t>(v.x), std::bit_cast<std::uint64_t>(v.y),
                                        std::bit_cast<std::uint64_t>(v.z)};
  };
  auto a = bits(ends[0]), b = bits(ends[1]);
  if (std::tie(b[0], b[1], b[2]) < std::tie(a[0], a[1], a[2])) std::swap(a, b);
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}

std::array<BintreeNode, 4> Diamond::children() const {
  const auto first = bdam::children(halves[0]), second = bdam::children(halves[1]);
  return {first[0], first[1], second[0], second[1]};
}

std::vector<Diamond> diamondsOf(int level) {
  if (level < 0 || level > 40) throw std::invalid_argument("no diamonds of level " + std::to_string(level));
  std::vector<std::pair<HypotenuseKey, BintreeNode>> nodes;
  const std::uint64_t perRoot = std::uint64_t(1) << level;
  nodes.reserve(std::size_t(kBintreeRoots * perRoot));
  for (int root = 0; root < kBintreeRoots; ++root)
    for (std::uint64_t path = 0; path < perRoot; ++path) {
      const BintreeNode node{root, level, path};
      nodes.emplace_back(hypotenuseOf(node), node);
    }
  std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Diamond> diamonds;
  for (std::size_t i = 0; i + 1 < nodes.size(); i += 2) {
    if (nodes[i].first != nodes[i + 1].first) throw std::logic_error("a bintree node without a hypotenuse partner");
    const auto& [a, b] = std::minmax(nodes[i].second, nodes[i + 1].second, [](const auto& x, const auto& y) {
      return std::tie(x.root, x.path) < std::tie(y.root, y.path);
    });
    diamonds.push_back({{a, b}});
  }
  std::sort(diamonds.begin(), diamonds.end(), [](const Diamond& x, const Diamond& y) {
    return std::tie(x.halves[0].root, x.halves[0].path) < std::tie(y.halves[0].root, y.halves[0].path);
  });
  return diamonds;
}

}  // namespace strata::bdam
