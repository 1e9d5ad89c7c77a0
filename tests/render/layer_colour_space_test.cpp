// A colour space per layer (issue 8; docs/colour.md): source.gdal's `colorspace` names how a colour raster is
// encoded, its pages hold the encoded values, and the page cache converts each page to scene-linear on the GPU
// with OpenColorIO's GLSL right after uploading it.
//
// EveryEncodingRendersTheSameColours: one pattern of linear colours (the checkerboard's cells decoded from sRGB)
// written as 16-bit rasters encoded as `srgb`, `gamma22` and `linear`, and rendered on a globe. Each frame is
// compared with the `srgb` one pixel by pixel, and its judged pixels (away from cell edges, poles and the limb)
// with the cells' 8-bit sRGB colours. Tolerances: between encodings 1 level, where two conversions that agree
// within 1e-4 in linear light (16-bit steps are 1.5e-5 of full scale, half floats keep 11 bits, OpenColorIO's
// curves are exact to 1e-6) round to neighbouring 8-bit levels; against the cells 2 levels, as in
// surface_colour_test.cpp. Measured on llvmpipe: 1 level between encodings, 0 from the cells.
// HealpixPyramidsAreConvertedAlike: the same for the gamma22 cells tiled as a HEALPix pyramid (measured: 0).
//
// FilteringMixesLinearLight: columns alternately black and light (8-bit sRGB; red white, green mid-grey 128),
// each about 21 pixels wide, seen from 100 km. Between two texel centres the bilinear filter mixes linear light,
// so a pixel a fraction f of the way from a black texel's centre to a light one's shows the sRGB encoding of f
// times the light's linear value: at the column edge red 188 and green 92, where filtering the encoded values
// would give 128 and 64 (and not converting at all 188 and 137). Every pixel of 10 rows across the stripes is
// judged against the analytic ray's longitude. Tolerance: 2 levels, the output's rounding (half a level) with
// room for where the mesh's chords put a sample (0.01 texel moves the expected level by up to 1.7 at the edges,
// and more on the steep linear segment near black); the column edges' means within 2 levels. Measured on
// llvmpipe: 3200 pixels, worst 0.51 levels off; the edges' means red 187.5, green 92.3 (160 pixels).
// Coarser levels are GDAL's averages of encoded values (docs/colour.md), so this is seen magnified, at level 0.
//
// The errors: an unknown space at its `colorspace` line, listing the config's; the pipeline's own config
// (`colour: {config}`) is the one asked; a `colorspace` on a layer of values is refused at its line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <strata/error.hpp>
#include <strata/host/tiling.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "srgb.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr double kRadius = 6371000.0;  // m: Earth's, as the pipelines say
// 12000 km above 20N 10E: the whole disc, most of its cells seen nearly head-on.
const Camera kGlobeCamera{.lon = 10, .lat = 20, .altitude = 1.2e7, .fov = 45};

double linearToSrgb(double linear) {
  return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// The linear colour of the checkerboard's cell (column, row), written in `space`'s encoding at 16 bits.
Rgb16 encodedCell(int column, int row, const std::string& space) {
  Rgb16 encoded{};
  for (int c = 0; c < 3; ++c) {
    const double srgb = cellColour(column, row)[std::size_t(c)] / 255.0, linear = srgbDecode(srgb);
    const double value = space == "srgb" ? srgb : space == "gamma22" ? std::pow(linear, 1.0 / 2.2) : linear;
    encoded[std::size_t(c)] = std::uint16_t(std::lround(value * 65535.0));
  }
  return encoded;
}

std::string globePipeline(const std::filesystem::path& raster, const std::string& space) {
  return "strata: 1\n"
         "body: {name: Earth, radius: 6371000}\n"
         "camera: {lon: " +
         std::to_string(kGlobeCamera.lon) + ", lat: " + std::to_string(kGlobeCamera.lat) +
         ", altitude: " + std::to_string(kGlobeCamera.altitude) + ", fov: " + std::to_string(kGlobeCamera.fov) +
         "}\n"
         "nodes:\n"
         "  cells: {type: source.gdal, path: " +
         raster.string() + ", kind: color, colorspace: " + space +
         "}\n"
         "  globe: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: globe, surface: [cells], shading: none}\n";
}

// The cells' raster in `space`'s encoding, as space.tif in `directory`.
std::filesystem::path writeCells(TemporaryDirectory& directory, const std::string& space) {
  const auto raster = directory.path() / (space + ".tif");
  writeColourRaster16(raster, 256, 128, {-180, -90, 180, 90},
                      [&space](int x, int y) { return encodedCell(x / 32, y / 32, space); });
  return raster;
}

Image renderGlobe(TemporaryDirectory& directory, const std::filesystem::path& raster, const std::string& space) {
  auto engine = makeEngine();
  return renderFrame(*engine, directory.write("globe.yaml", globePipeline(raster, space)), 320, 240);
}

double distanceToCellEdge(double value) { return std::abs(value - 45.0 * std::round(value / 45.0)); }

// The most any channel of any pixel of `image` differs from `reference`'s.
int largestDifference(const Image& image, const Image& reference) {
  int largest = 0;
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    largest = std::max(largest, std::abs(int(image.rgba[i]) - int(reference.rgba[i])));
  return largest;
}

// The most a judged pixel (away from cell edges, poles and the limb) differs from its cell's sRGB colour.
int largestCellDifference(const Image& image) {
  const View view = makeView(Body{"Earth", kRadius}, kGlobeCamera, image.width, image.height);
  int largest = 0, judged = 0;
  for (int y = 1; y < image.height; y += 3)
    for (int x = 1; x < image.width; x += 3) {
      const auto hit = raycastSphere(view, kRadius, x, y);
      if (!hit || hit->incidence < 0.3 || std::abs(hit->lat) > 80.0) continue;
      if (distanceToCellEdge(hit->lon) < 2.0 || distanceToCellEdge(hit->lat) < 2.0) continue;
      const Rgb8 cell =
          cellColour(int(std::floor((hit->lon + 180.0) / 45.0)) % 8, int(std::floor((90.0 - hit->lat) / 45.0)));
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(image.at(x, y)[c] - int(cell[std::size_t(c)])));
      ++judged;
    }
  EXPECT_GT(judged, 600) << "too few pixels were judged for the test to mean anything";
  return largest;
}

TEST(LayerColourSpace, EveryEncodingRendersTheSameColours) {
  TemporaryDirectory directory;
  const Image srgb = renderGlobe(directory, writeCells(directory, "srgb"), "srgb");
  EXPECT_LE(largestCellDifference(srgb), 2);
  for (const std::string space : {"gamma22", "linear"}) {
    const Image image = renderGlobe(directory, writeCells(directory, space), space);
    const int fromSrgb = largestDifference(image, srgb), fromCells = largestCellDifference(image);
    std::printf("%s: %d levels from the srgb frame, %d from the cells\n", space.c_str(), fromSrgb, fromCells);
    EXPECT_LE(fromSrgb, 1) << space;
    EXPECT_LE(fromCells, 2) << space;
  }
}

// HEALPix pyramids (plugins/source-gdal/healpix_page_source.cpp) take their colour space as other rasters do:
// the gamma22 cells as `strata tile --to healpix` writes them (UInt16 kept, each texel the bilinear value at its
// pixel's centre, so the cells' insides are unchanged).
TEST(LayerColourSpace, HealpixPyramidsAreConvertedAlike) {
  TemporaryDirectory directory;
  const auto pyramid = directory.path() / "pyramid.tif";
  const PluginRegistry plugins;
  tileRaster(plugins,
             {.input = writeCells(directory, "gamma22"), .output = pyramid, .target = "healpix", .nside = 512});
  const int fromCells = largestCellDifference(renderGlobe(directory, pyramid, "gamma22"));
  std::printf("a HEALPix pyramid of gamma22: %d levels from the cells\n", fromCells);
  EXPECT_LE(fromCells, 2);
}

// kStripes columns of texels, alternately black (even) and light (odd), from longitude -kStripeHalfWidth. Red
// is black and white, which every transfer function leaves as they are; green is black and mid-grey, which tells
// converting before filtering from converting after it, and from not converting at all.
constexpr int kStripes = 64;
constexpr double kStripeHalfWidth = 1.6, kTexel = 2.0 * kStripeHalfWidth / kStripes;  // deg
constexpr Rgb8 kLight{255, 128, 255};

// The light column's weight in the bilinear filter at longitude `lon`, and the fraction of a texel from the
// nearest centre westward.
double lightWeight(double lon, double& fraction) {
  const double s = (lon + kStripeHalfWidth) / kTexel - 0.5;
  const double west = std::floor(s);
  fraction = s - west;
  const bool westIsLight = int(west) % 2 != 0;
  return westIsLight ? 1.0 - fraction : fraction;
}

// The 8-bit sRGB level of channel `c` where the light column weighs `weight`, mixed in linear light.
double mixedLevel(double weight, int c) {
  return 255.0 * linearToSrgb(weight * srgbDecode(kLight[std::size_t(c)] / 255.0));
}

Image renderStripes(TemporaryDirectory& directory, const Camera& camera) {
  const auto raster = directory.path() / "stripes.tif";
  writeColourRaster(raster, kStripes, 16, {-kStripeHalfWidth, -0.4, kStripeHalfWidth, 0.4}, [](int x, int) {
    return x % 2 ? kLight : Rgb8{0, 0, 0};
  });
  const std::string pipeline =
      "strata: 1\nbody: {name: Earth, radius: 6371000}\ncamera: {lon: " + std::to_string(camera.lon) +
      ", lat: " + std::to_string(camera.lat) + ", altitude: " + std::to_string(camera.altitude) +
      ", fov: " + std::to_string(camera.fov) + "}\nnodes:\n  stripes: {type: source.gdal, path: " + raster.string() +
      "}\n  globe: {type: geometry.icosahedral}\n"
      "  frame: {type: output.image, geometry: globe, surface: [stripes], shading: none}\n";
  auto engine = makeEngine();
  return renderFrame(*engine, directory.write("stripes.yaml", pipeline), 320, 240);
}

TEST(LayerColourSpace, FilteringMixesLinearLight) {
  TemporaryDirectory directory;
  const Camera camera{.lon = 0, .lat = 0, .altitude = 100000, .fov = 45};
  const Image image = renderStripes(directory, camera);
  const View view = makeView(Body{"Earth", kRadius}, camera, image.width, image.height);
  double worst = 0.0;
  std::string worstPixel;  // one line for all pixels, so that a failure reads at a glance
  std::array<double, 2> edgeSum{};
  int judged = 0, edges = 0, over = 0;
  for (int y = 100; y < 140; y += 4)
    for (int x = 0; x < image.width; ++x) {
      const auto hit = raycastSphere(view, kRadius, x, y);
      if (!hit || std::abs(hit->lon) > kStripeHalfWidth - kTexel) continue;
      double fraction = 0.0;
      const double weight = lightWeight(hit->lon, fraction);
      for (int c = 0; c < 2; ++c) {
        const double error = std::abs(image.at(x, y)[c] - mixedLevel(weight, c));
        over += error > 2.0;
        if (error <= worst) continue;
        worst = error;
        worstPixel = std::to_string(x) + "," + std::to_string(y) + " channel " + std::to_string(c) + " lon " +
                     std::to_string(hit->lon) + " weight " + std::to_string(weight) + ": " +
                     std::to_string(image.at(x, y)[c]) + ", not " + std::to_string(mixedLevel(weight, c));
      }
      ++judged;
      if (std::abs(fraction - 0.5) >= 0.02) continue;
      for (int c = 0; c < 2; ++c) edgeSum[std::size_t(c)] += image.at(x, y)[c];
      ++edges;
    }
  const double red = edgeSum[0] / std::max(edges, 1), green = edgeSum[1] / std::max(edges, 1);
  std::printf("%d pixels judged, worst %.2f levels off; at column edges red %.1f, green %.1f (%d pixels)\n", judged,
              worst, red, green, edges);
  EXPECT_EQ(over, 0) << "channels over 2 levels off; the worst at " << worstPixel;
  EXPECT_GT(judged, 2000);
  EXPECT_GT(edges, 20);
  EXPECT_NEAR(red, mixedLevel(0.5, 0), 2.0) << "midway between black and white in linear light: 188, not 128";
  EXPECT_NEAR(green, mixedLevel(0.5, 1), 2.0) << "midway between black and grey 128 in linear light: 92, not 64";
}

// The error loading `pipeline` throws, written beside cells.tif (the checkerboard) and `extraFile`, if any.
Error loadError(const std::string& pipeline, const std::string& extraFile = {}, const std::string& extraText = {}) {
  TemporaryDirectory directory;
  writeCheckerboard(directory.path() / "cells.tif");
  if (!extraFile.empty()) directory.write(extraFile, extraText);
  auto engine = makeEngine();
  try {
    engine->load(directory.write("p.yaml", pipeline));
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "the pipeline loaded:\n" << pipeline;
  return Error({}, "");
}

std::string cellsPipeline(const std::string& cells, const std::string& colour = {}) {
  return "strata: 1\n" + colour + "nodes:\n  cells:\n    type: source.gdal\n    path: cells.tif\n" + cells +
         "  globe: {type: geometry.icosahedral}\n  frame: {type: output.image, geometry: globe, surface: [cells]}\n";
}

TEST(LayerColourSpace, AnUnknownColourSpaceIsRefusedAtItsLineListingThoseThereAre) {
  const Error error = loadError(cellsPipeline("    colorspace: acescg\n"));
  EXPECT_EQ(error.where().line, 6);
  EXPECT_NE(error.where().file.find("p.yaml"), std::string::npos) << error.where().str();
  EXPECT_EQ(error.problem(), "the colour space 'acescg' is not in Strata's built-in config");
  EXPECT_EQ(error.fix(), "choose one of 'linear', 'srgb', 'gamma22', 'raw'");
}

TEST(LayerColourSpace, TheSpacesAreThePipelinesConfigs) {
  const std::string config =
      "ocio_profile_version: 2\n"
      "roles: {default: linear, scene_linear: linear, data: raw}\n"
      "displays: {sRGB: [!<View> {name: Raw, colorspace: raw}]}\n"
      "colorspaces:\n"
      "  - !<ColorSpace> {name: linear}\n"
      "  - !<ColorSpace> {name: raw, isdata: true}\n";
  const Error error = loadError(cellsPipeline("", "colour: {config: mine.ocio}\n"), "mine.ocio", config);
  EXPECT_EQ(error.where().line, 4) << "the node, whose `colorspace` is the default";
  EXPECT_NE(error.problem().find("the colour space 'srgb' is not in /"), std::string::npos) << error.problem();
  EXPECT_TRUE(error.problem().ends_with("/mine.ocio")) << error.problem();
  EXPECT_EQ(error.fix(), "choose one of 'linear', 'raw'");
}

TEST(LayerColourSpace, ALayerOfValuesTakesNoColourSpace) {
  const Error error = loadError(cellsPipeline("    kind: scalar\n    colorspace: srgb\n"));
  EXPECT_EQ(error.where().line, 7);
  EXPECT_EQ(error.problem(), "a scalar layer holds values, which have no colour space");
  EXPECT_EQ(error.fix(), "remove `colorspace`, or read the raster as colours with `kind: color`");
}

}  // namespace
}  // namespace strata::test
