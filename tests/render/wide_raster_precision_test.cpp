// Issue 27: a raster wider than float addresses is as crisp as a small one. Its level-0 texel address is a
// whole texel from the CPU's double and a small float part (strata/texel_address.glsl): through float texture
// coordinates times the width, a texel position resolves 2^-24 of the width, 4 texels of a raster 2^26 wide.
// A checkerboard of 1 cm texels in cells of 64, 2^26 texels (671 km) along the parallels of Gale crater's place
// and of a place beside the antimeridian, and once around the body 1 degree from the south pole (2^26 texels)
// and 0.1 degree from it (2^24), is seen from 2 m straight down and tilted 60 degrees, and judged as
// raster_precision_test.cpp judges its boards. Through float addresses 8 to 827 judged pixels of each view at
// Gale, the antimeridian and the polar cap were wrong. 0.1 degree from the pole the texels are 4 mm by 1 cm: there a
// hundredth of a texel is a far smaller share of the board's width than of its height, and checked against the one
// share, the fit about the eye (LocalTextureFrame) shrank to 0.6 m, beyond which the board was grey (11,868 of
// 28,059 judged pixels wrong straight down, all tilted).
// Its pages come from a page source of the test's own, which makes any window of any level (each level texel
// the average of the level-0 texels under it), since no file that wide could be written here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <tuple>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/packing.hpp>

#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/paged_raster_layer.hpp>
#include <strata/plugin/plugin_registry.hpp>
#include <strata/plugin/raster_georeference.hpp>
#include <strata/plugin/srgb.hpp>

#include "board_judging.hpp"
#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 192;
constexpr double kRadius = 6371000.0;  // m: the pipeline's body
constexpr double kTexel = 0.01;        // m, along each meridian
constexpr int kRows = 8192;            // 82 m from north to south: all a view tilted 60 degrees judges
// 64 texels a cell: cells of 64 cm north to south, and 27 cm east to west 0.1 degree from the pole, where the
// board's 2^24 texels around the body are 4 mm wide; mip levels 1 to 6 stay inside cells.
constexpr int kCellTexels = 64;
constexpr int kLight = 231, kDark = 48;

// Where a board lies: the camera's place (degrees), the board's width in texels, and where along it the camera
// is (a share of the width: far from column 0, where float addresses are coarsest); a board once around the
// body starts at longitude -180.
struct Place {
  const char* name;
  double lon, lat;
  int columns;
  double along;
  bool aroundBody;
};

void PrintTo(const Place& place, std::ostream* out) { *out << place.name; }

BoardGrid boardAt(const Place& place) {
  BoardGrid board;
  board.columns = place.columns;
  board.rows = kRows;
  board.cellTexels = kCellTexels;
  board.latStep = glm::degrees(kTexel / kRadius);
  board.north = place.lat + board.latStep * kRows * 0.5;
  board.lonStep =
      place.aroundBody ? 360.0 / place.columns : glm::degrees(kTexel / (kRadius * std::cos(glm::radians(place.lat))));
  board.west = place.aroundBody ? -180.0 : place.lon - board.lonStep * place.columns * place.along;
  if (board.west < -180.0) board.west += 360.0;  // its east edge then lies beyond 180
  return board;
}

// Level-0 texels in [from, to) of one axis that lie in even cells.
std::int64_t evenCellTexels(std::int64_t from, std::int64_t to) {
  const auto below = [](std::int64_t end) {
    const std::int64_t cells = end / kCellTexels, rest = end % kCellTexels;
    return (cells + 1) / 2 * kCellTexels + (cells % 2 == 0 ? rest : 0);
  };
  return below(to) - below(from);
}

// The board's texels at every level, made for each window asked: the average colour of the level-0 texels under
// each level texel, in linear light, as half floats (PageFormat::Colour, coverage 1).
class BoardSource : public PageSource {
 public:
  explicit BoardSource(const BoardGrid& board) : pyramid_(board.columns, board.rows) {}

  const PagePyramid& pyramid() const override { return pyramid_; }
  PageFormat format() const override { return PageFormat::Colour; }
  std::string name() const override { return "the wide board"; }

  void read(const LevelWindow& window, std::span<std::byte> texels) const override {
    const std::int64_t side = std::int64_t{1} << window.level;
    auto* halves = reinterpret_cast<std::uint16_t*>(texels.data());
    for (int y = 0; y < window.height; ++y) {
      const std::int64_t top = (window.y + y) * side, bottom = std::min(top + side, std::int64_t(pyramid_.height()));
      const std::int64_t evenRows = evenCellTexels(top, bottom), rows = bottom - top;
      for (int x = 0; x < window.width; ++x) {
        const std::int64_t left = (window.x + x) * side, right = std::min(left + side, std::int64_t(pyramid_.width()));
        const std::int64_t evenColumns = evenCellTexels(left, right), columns = right - left;
        const double light =
            double(evenColumns * evenRows + (columns - evenColumns) * (rows - evenRows)) / double(columns * rows);
        const float grey = float(light * kLinearLight + (1.0 - light) * kLinearDark);
        std::uint16_t* texel = halves + 4 * (std::size_t(y) * window.width + x);
        texel[0] = texel[1] = texel[2] = glm::packHalf1x16(grey);
        texel[3] = glm::packHalf1x16(1.0f);
      }
    }
  }

 private:
  static inline const double kLinearLight = srgbToSceneLinear(kLight / 255.0, 0.0, 0.0).r;
  static inline const double kLinearDark = srgbToSceneLinear(kDark / 255.0, 0.0, 0.0).r;
  PagePyramid pyramid_;
};

// The board as a source node, sampled relative to the point below the eye as source.gdal samples rasters.
class BoardNode : public Node {
 public:
  BoardNode(const NodeSetup& setup, const BoardGrid& board)
      : board_(board), plugins_(*setup.plugins), layer_(setup.id, LayerKind::Color) {}

  void createResources(GpuContext& gpu) override {
    const GeographicExtent extent{board_.west, board_.north - board_.latStep * board_.rows,
                                  board_.west + board_.lonStep * board_.columns, board_.north};
    layer_.attach(*gpu.pages, std::make_shared<BoardSource>(board_),
                  geographicGeoreference(plugins_, extent, board_.columns, board_.rows));
  }
  void prepare(const FrameState& frame) override { layer_.setReference(frame.view.reference); }
  Layer* layer() override { return &layer_; }

 private:
  BoardGrid board_;
  const PluginRegistry& plugins_;
  PagedRasterLayer layer_;
};

NodeTypeDeclaration boardType(const BoardGrid& board) {
  NodeTypeDeclaration type;
  type.type = "test.wide_board";
  type.category = NodeCategory::Source;
  type.summary = "a checkerboard of 1 cm texels wider than float addresses";
  type.output = PortType::Layer;
  type.create = [board](const NodeSetup& setup) { return std::make_unique<BoardNode>(setup, board); };
  return type;
}

class WideRasterPrecision : public ::testing::TestWithParam<std::tuple<Place, double>> {};

TEST_P(WideRasterPrecision, OneCentimetreTexelsOfARasterWiderThanFloatAddressesAreCrisp) {
  const auto& [place, tilt] = GetParam();
  const BoardGrid board = boardAt(place);
  TemporaryDirectory directory;
  const auto pipeline =
      directory.write("board.yaml",
                      "strata: 1\nbody: {name: sphere, radius: 6371000}\n"
                      "camera: {lon: " +
                          pipelineDegrees(place.lon) + ", lat: " + pipelineDegrees(place.lat) +
                          ", altitude: 2, heading: 30, tilt: " + std::to_string(tilt) +
                          ", fov: 40}\nnodes:\n"
                          "  board: {type: test.wide_board}\n"
                          "  globe: {type: geometry.icosahedral}\n"
                          "  frame: {type: output.image, geometry: globe, surface: [board], shading: none}\n");
  auto engine = makeEngine();
  engine->plugins().add(boardType(board));
  const Image image = renderFrame(*engine, pipeline, kSize, kSize);
  const Judgement judgement = judgeBoard(image, engine->view(kSize, kSize), kRadius, board, false, kLight, kDark);
  EXPECT_GT(judgement.judged, kSize * kSize / 5);
  EXPECT_EQ(judgement.wrong, 0) << "of " << judgement.judged << " pixels";
}

// The camera's place is off every texel's centre and corner, so that no symmetry hides an offset.
const Place kPlaces[] = {
    {"gale", 137.4000123, -4.6000045, 1 << 26, 0.7312345, false},
    {"antimeridian", -179.9999877, 10.0000045, 1 << 26, 0.6, false},
    {"south_polar_cap", 33.0123, -89.0000045, 1 << 26, 0.0, true},
    {"near_south_pole", 33.0123, -89.9000045, 1 << 24, 0.0, true},
};

INSTANTIATE_TEST_SUITE_P(PlacesAndTilts, WideRasterPrecision,
                         ::testing::Combine(::testing::ValuesIn(kPlaces), ::testing::Values(0.0, 60.0)),
                         [](const ::testing::TestParamInfo<std::tuple<Place, double>>& param) {
                           return std::string(std::get<0>(param.param).name) + "_tilt" +
                                  std::to_string(int(std::get<1>(param.param)));
                         });

}  // namespace
}  // namespace strata::test
