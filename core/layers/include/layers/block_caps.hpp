#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <strata/plugin/block_ranges.hpp>
#include <strata/plugin/raster_georeference.hpp>
#include <strata/plugin/spherical_cap.hpp>

namespace strata {

// What a raster's blocks hold within a cap (BlockCaps::within): raw values, whether no data shows there, and the
// relief and curvature of the blocks themselves (BlockRelief).
struct BlockValues {
  double least = std::numeric_limits<double>::infinity();
  double greatest = -std::numeric_limits<double>::infinity();
  bool gaps = false;        // some texel there holds no data, or the cap reaches beyond the raster: the sphere shows
  double blockRange = 0.0;  // the largest greatest - least of one block
  double blockWidth = std::numeric_limits<double>::infinity();  // rad: that block's cap's diameter
  // One block's second differences, raw per texel squared (BlockRanges::Block): row, column, twist; < 0 unknown.
  std::array<double, 3> bends{-1.0, -1.0, -1.0};
  double curvature = 0.0;  // the largest second derivative along the ground, raw per rad squared, a block's bends
                           // show; infinite where some block's are unknown, or its data end (gaps)
  double texel = 0.0;      // rad: the largest a texel spans in those blocks
  bool counted() const { return least <= greatest; }
};

// Square blocks of `blockTexels` level-0 texels a side over a raster of width x height texels.
struct BlockLayout {
  int width = 0;
  int height = 0;
  int blockTexels = 0;
  int columns() const { return int((std::int64_t(width) + blockTexels - 1) / blockTexels); }
  int rows() const { return int((std::int64_t(height) + blockTexels - 1) / blockTexels); }
};

// What a raster's blocks hold placed on the body: each block bounded by a cap through the raster's
// georeference, and the blocks grouped 2 x 2 level by level into a quadtree of caps, so that a query visits
// the blocks near its cap only. Built once, when the layer is placed.
class BlockCaps {
 public:
  // `values`: each block's, row by row. `coversBody`: the raster covers the whole body (a HEALPix pyramid's
  // strip of faces), so that no cap reaches beyond it, though its texels' rectangle says otherwise.
  BlockCaps(BlockLayout layout, std::vector<BlockValues> values, RasterGeoreference georeference, bool repeatX,
            bool coversBody);
  // The blocks of a raster's BlockRanges.
  BlockCaps(std::shared_ptr<const BlockRanges> ranges, RasterGeoreference georeference, bool repeatX);

  // The values of every block whose cap meets `cap`, and gaps where the cap is not wholly inside the raster.
  BlockValues within(const SphericalCap& cap) const;

 private:
  struct Group {
    SphericalCap cap;
    BlockValues values;
  };
  using Level = std::vector<Group>;  // row by row, columnsAt(level) across

  struct Placement {
    SphericalCap cap;
    // rad: the least a texel spans along the block's rows and along its columns, and the largest either way
    double leastAlongRows = 0.0, leastAlongColumns = 0.0, largestTexel = 0.0;
  };
  Placement placementOf(int blockColumn, int blockRow) const;
  void addCoarserLevel();
  int columnsAt(std::size_t level) const;
  int rowsAt(std::size_t level) const;
  void gather(std::size_t level, int column, int row, const SphericalCap& cap, BlockValues& found) const;
  bool holdsWhole(const SphericalCap& cap) const;

  BlockLayout layout_;
  RasterGeoreference georeference_;
  bool repeatX_;
  bool coversBody_;
  std::vector<Level> levels_;  // blocks first, then groups of 2 x 2 up to one
};

}  // namespace strata
