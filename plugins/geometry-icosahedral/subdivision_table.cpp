#include "subdivision_table.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace strata::icosahedral {
namespace {

constexpr std::uint32_t kNotAVertex = std::numeric_limits<std::uint32_t>::max();

// The direction, from its lower-numbered corner, of the patch edge that a new vertex's parents lie
// parallel to (our breadth-first numbering for [Kooima 2008, §3.3.1]): along a when only a/s is odd,
// along b when only b/s is, and along the edge from v1 to v2 when both are.
GridPoint parentDirection(GridPoint point, int step) {
  const bool oddA = (point.a / step) % 2 != 0, oddB = (point.b / step) % 2 != 0;
  if (oddA && oddB) return {-1, 1};
  return oddA ? GridPoint{1, 0} : GridPoint{0, 1};
}

}  // namespace

int verticesPerPatch(int depth) {
  const int segments = 1 << depth;
  return (segments + 1) * (segments + 2) / 2;
}

SubdivisionTable::SubdivisionTable(int depth) : depth_(depth) {
  if (depth < 0 || depth > kDeepestSubdivision)
    throw std::invalid_argument("subdivision depth " + std::to_string(depth) + " is outside 0 to " +
                                std::to_string(kDeepestSubdivision));
  const int n = segments();
  indexOfPoint_.assign(std::size_t((n + 1) * (n + 1)), kNotAVertex);
  for (GridPoint corner : {GridPoint{0, 0}, GridPoint{n, 0}, GridPoint{0, n}}) {
    const auto index = std::uint32_t(grid_.size());
    indexOfPoint_[std::size_t(corner.b * (n + 1) + corner.a)] = index;
    grid_.push_back(corner);
    parentPairs_.insert(parentPairs_.end(), {index, index});
  }
  for (int level = 1; level <= depth; ++level) addLevel(level);
}

void SubdivisionTable::addLevel(int level) {
  const int n = segments(), step = 1 << (depth_ - level);
  for (int b = 0; b <= n; b += step)
    for (int a = 0; a + b <= n; a += step) {
      const GridPoint point{a, b};
      if ((a / step) % 2 == 0 && (b / step) % 2 == 0) continue;  // made by an earlier level
      const GridPoint d = parentDirection(point, step);
      const std::uint32_t first = indexOf({a - step * d.a, b - step * d.b});
      const std::uint32_t second = indexOf({a + step * d.a, b + step * d.b});
      indexOfPoint_[std::size_t(b * (n + 1) + a)] = std::uint32_t(grid_.size());
      grid_.push_back(point);
      parentPairs_.insert(parentPairs_.end(), {first, second});
    }
}

std::array<std::uint32_t, 2> SubdivisionTable::parents(std::uint32_t vertex) const {
  return {parentPairs_[2 * std::size_t(vertex)], parentPairs_[2 * std::size_t(vertex) + 1]};
}

std::uint32_t SubdivisionTable::indexOf(GridPoint point) const {
  const int n = segments();
  if (point.a < 0 || point.b < 0 || point.a + point.b > n)
    throw std::out_of_range("grid point (" + std::to_string(point.a) + ", " + std::to_string(point.b) +
                            ") lies outside the patch of " + std::to_string(n) + " segments");
  return indexOfPoint_[std::size_t(point.b * (n + 1) + point.a)];
}

}  // namespace strata::icosahedral
