#include "layers/block_caps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/glm.hpp>

namespace strata {
namespace {

// Samples along each edge of a block, corners included: the cap from them holds the block's image with the
// margin below for any projection smooth at the scale of a block (8 texels or more, at most about a degree of a
// global map: BlockRanges::kMostBlocks).
constexpr int kEdgeSamples = 8;
// The bilinear filter reads the texels whose centres lie within a texel each way of a point: a texel's diagonal
// beyond the block's outer texel centres. Caps are widened by that, then by a tenth, for the bulge of the
// edges between their samples.
constexpr double kFilterReach = std::numbers::sqrt2;
constexpr double kCapMargin = 1.1;
// Points on a cap's rim a query tests to lie inside the raster, a twentieth beyond the rim.
constexpr int kRimSamples = 32;
constexpr double kRimMargin = 1.05;

std::vector<BlockValues> valuesOf(const BlockRanges& ranges) {
  std::vector<BlockValues> values;
  for (int row = 0; row < ranges.rows(); ++row)
    for (int column = 0; column < ranges.columns(); ++column) {
      const BlockRanges::Block& block = ranges.at(column, row);
      values.push_back({.least = block.least,
                        .greatest = block.greatest,
                        .gaps = ranges.holdsGaps(column, row),
                        .bends = {block.rowBend, block.columnBend, block.twist}});
    }
  return values;
}

// Both blocks' values; of their blocks' relief, the larger's (a real block's range and width, which a block
// flattened to a point at a pole does not take the width of); the larger curvature and texel.
BlockValues spanning(const BlockValues& a, const BlockValues& b) {
  const BlockValues& rougher = a.blockRange >= b.blockRange ? a : b;
  return {.least = std::min(a.least, b.least),
          .greatest = std::max(a.greatest, b.greatest),
          .gaps = a.gaps || b.gaps,
          .blockRange = rougher.blockRange,
          .blockWidth = rougher.blockWidth,
          .curvature = std::max(a.curvature, b.curvature),
          .texel = std::max(a.texel, b.texel)};
}

// Spans below this, rad, are a pole's row of texels, all at one point.
constexpr double kDegenerateSpan = 1e-12;

// A block's curvature (BlockValues): the largest of its second differences along rows and columns, each over the
// least its texels span that way, squared, plus the twist over both (the Hessian's largest eigenvalue is at most
// the larger of its diagonal's magnitudes plus the off-diagonal's), so that it bounds the values' second
// derivative along the ground whichever way the texels are stretched. Unknown where the bends are, where the
// block holds gaps, or where its texels span nothing one way (a pole, or a single row or column).
double curvatureOf(const BlockValues& block, double alongRows, double alongColumns) {
  const auto [row, column, twist] = block.bends;
  if (row < 0.0 || block.gaps) return std::numeric_limits<double>::infinity();
  if (row == 0.0 && column == 0.0 && twist == 0.0) return 0.0;
  if (!(alongRows > kDegenerateSpan && alongColumns > kDegenerateSpan) || !std::isfinite(alongRows + alongColumns))
    return std::numeric_limits<double>::infinity();
  return std::max(row / (alongRows * alongRows), column / (alongColumns * alongColumns)) +
         twist / (alongRows * alongColumns);
}

// Whether `outer` holds every direction of `inner`.
bool holds(const SphericalCap& outer, const SphericalCap& inner) {
  return angleBetween(outer.centre, inner.centre) + inner.angle <= outer.angle;
}

// The point `angle` from the cap's centre in direction `turn` (rad about the centre).
glm::dvec3 rimPoint(const SphericalCap& cap, double angle, double turn) {
  const glm::dvec3 c = cap.centre;
  const glm::dvec3 helper = std::abs(c.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(helper, c)), e2 = glm::cross(c, e1);
  return std::cos(angle) * c + std::sin(angle) * (std::cos(turn) * e1 + std::sin(turn) * e2);
}

}  // namespace

BlockCaps::BlockCaps(BlockLayout layout, std::vector<BlockValues> values, RasterGeoreference georeference, bool repeatX,
                     bool coversBody)
    : layout_(layout), georeference_(std::move(georeference)), repeatX_(repeatX), coversBody_(coversBody) {
  Level blocks;
  for (int row = 0; row < layout_.rows(); ++row)
    for (int column = 0; column < layout_.columns(); ++column) {
      const Placement placement = placementOf(column, row);
      Group block{placement.cap, values[std::size_t(row) * layout_.columns() + column]};
      if (block.values.counted()) {
        block.values.blockRange = block.values.greatest - block.values.least;
        block.values.blockWidth = 2.0 * block.cap.angle;
      }
      block.values.curvature = curvatureOf(block.values, placement.leastAlongRows, placement.leastAlongColumns);
      block.values.texel = placement.largestTexel;
      blocks.push_back(block);
    }
  levels_.push_back(std::move(blocks));
  while (columnsAt(levels_.size() - 1) > 1 || rowsAt(levels_.size() - 1) > 1) addCoarserLevel();
}

BlockCaps::BlockCaps(std::shared_ptr<const BlockRanges> ranges, RasterGeoreference georeference, bool repeatX)
    : BlockCaps({ranges->width(), ranges->height(), ranges->blockTexels()}, valuesOf(*ranges), std::move(georeference),
                repeatX, false) {}

int BlockCaps::columnsAt(std::size_t level) const { return ((layout_.columns() - 1) >> level) + 1; }

int BlockCaps::rowsAt(std::size_t level) const { return ((layout_.rows() - 1) >> level) + 1; }

// The cap around the centres of the block's outer texels as the georeference places them, widened by the
// filter's reach; the whole sphere where some lies outside the projection's domain. Texel centres, not the
// block's edges: a global map's edges may lie half a texel beyond a pole, where no projection is defined, and
// a HEALPix strip's grids meet in the raster though not on the body. With it, the least and largest angle a texel
// spans along the edges.
BlockCaps::Placement BlockCaps::placementOf(int blockColumn, int blockRow) const {
  const double side = layout_.blockTexels;
  const double x0 = blockColumn * side + 0.5, y0 = blockRow * side + 0.5;
  const double x1 = std::min(blockColumn * side + side, double(layout_.width)) - 0.5;
  const double y1 = std::min(blockRow * side + side, double(layout_.height)) - 0.5;
  const std::array<double, 6>& t = georeference_.geotransform;
  std::vector<glm::dvec3> edge;  // sample i of the four edges at 4 i to 4 i + 3
  for (int i = 0; i < kEdgeSamples; ++i) {
    const double s = double(i) / kEdgeSamples;
    for (const glm::dvec2 texel : {glm::dvec2(x0 + s * (x1 - x0), y0), glm::dvec2(x1, y0 + s * (y1 - y0)),
                                   glm::dvec2(x1 - s * (x1 - x0), y1), glm::dvec2(x0, y1 - s * (y1 - y0))}) {
      const glm::dvec2 map(t[0] + texel.x * t[1] + texel.y * t[2], t[3] + texel.x * t[4] + texel.y * t[5]);
      const std::optional<glm::dvec2> lonlat = georeference_.projection->inverse(map);
      if (!lonlat) return {{glm::dvec3(0, 0, 1), std::numbers::pi}};
      edge.push_back(directionOf(*lonlat));
    }
  }
  // The angles a texel spans along the edges: the samples of an edge lie (its texels) / kEdgeSamples apart.
  const std::array<double, 2> step{(x1 - x0) / kEdgeSamples, (y1 - y0) / kEdgeSamples};
  std::array<double, 2> least{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double largest = 0.0;
  for (std::size_t k = 0; k + 4 < edge.size(); ++k)
    if (step[k % 2] > 0.0) {
      const double texel = angleBetween(edge[k], edge[k + 4]) / step[k % 2];
      least[k % 2] = std::min(least[k % 2], texel);
      largest = std::max(largest, texel);
    }
  const SphericalCap cap = capAround(edge);
  return {{cap.centre, std::min((cap.angle + kFilterReach * largest) * kCapMargin, std::numbers::pi)},
          least[0],
          least[1],
          largest};
}

void BlockCaps::addCoarserLevel() {
  const std::size_t finer = levels_.size() - 1;
  const int finerColumns = columnsAt(finer), finerRows = rowsAt(finer);
  Level coarser;
  for (int row = 0; row < rowsAt(finer + 1); ++row)
    for (int column = 0; column < columnsAt(finer + 1); ++column) {
      std::optional<Group> group;
      for (int y = 2 * row; y < std::min(2 * row + 2, finerRows); ++y)
        for (int x = 2 * column; x < std::min(2 * column + 2, finerColumns); ++x) {
          const Group& child = levels_[finer][std::size_t(y) * finerColumns + x];
          group = group ? Group{joined(group->cap, child.cap), spanning(group->values, child.values)} : child;
        }
      coarser.push_back(*group);
    }
  levels_.push_back(std::move(coarser));
}

void BlockCaps::gather(std::size_t level, int column, int row, const SphericalCap& cap, BlockValues& found) const {
  const Group& group = levels_[level][std::size_t(row) * columnsAt(level) + column];
  if (!group.cap.meets(cap)) return;
  if (level == 0 || holds(cap, group.cap)) {  // every block below meets the cap: their values are the group's
    found = spanning(found, group.values);
    return;
  }
  for (int y = 2 * row; y < std::min(2 * row + 2, rowsAt(level - 1)); ++y)
    for (int x = 2 * column; x < std::min(2 * column + 2, columnsAt(level - 1)); ++x)
      gather(level - 1, x, y, cap, found);
}

BlockValues BlockCaps::within(const SphericalCap& cap) const {
  BlockValues found;
  gather(levels_.size() - 1, 0, 0, cap, found);
  found.gaps = found.gaps || !holdsWhole(cap);
  return found;
}

// Whether the cap lies inside the raster, a texel from its edges: its centre and points a little beyond its
// rim all map into it. The image of a cap that small through a smooth projection is a smooth, nearly
// elliptic blob, which the rim points bound with that margin.
bool BlockCaps::holdsWhole(const SphericalCap& cap) const {
  if (coversBody_) return true;
  if (cap.angle >= 0.5 * std::numbers::pi) return false;  // a hemisphere: its image is no small blob
  const std::array<double, 6>& t = georeference_.geotransform;
  const glm::dmat2 toTexels = glm::inverse(glm::dmat2(t[1], t[4], t[2], t[5]));
  const auto inside = [&](const glm::dvec3& unit) {
    const std::optional<glm::dvec2> map = georeference_.projection->forward(lonlatOf(unit));
    if (!map) return false;
    const glm::dvec2 texel = toTexels * (*map - glm::dvec2(t[0], t[3]));
    const bool across = repeatX_ || (texel.x >= 1.0 && texel.x <= layout_.width - 1.0);
    return across && texel.y >= 1.0 && texel.y <= layout_.height - 1.0;
  };
  if (!inside(cap.centre)) return false;
  for (int i = 0; i < kRimSamples; ++i)
    if (!inside(rimPoint(cap, std::min(cap.angle * kRimMargin, std::numbers::pi),
                         2.0 * std::numbers::pi * i / kRimSamples)))
      return false;
  return true;
}

}  // namespace strata
