// composite.chroma_fusion (issue 8; [Kooima 2008, §1.1], HiRISE luminance with Viking chroma, and §3.4.3,
// colour-space transformations): one known colour image made into a high-resolution luminance layer and a
// low-resolution colour layer, fused, against the image itself.
//
// The image: 2048 x 2048 texels over 2.4 x 2.4 degrees of Mars (69.5 m a texel), scene-linear colour C x d,
// a hue C that turns slowly (periods of 160 and 230 texels: 40 and 58 texels of the colour layer) times a
// fine pattern of brightness d within 1 +- 0.25 (periods of 4.7 to 9 texels), written as 8-bit sRGB. The
// luminance layer is the relative luminance of those 8-bit colours (Float32, kind: luminance); the colour
// layer their average over 4 x 4 texels in linear light, 512 x 512, 8-bit sRGB. The luminance layer's
// pyramid reaches the colour layer's resolution (its level 2, 512 texels, is its coarsest), as the detail
// matching's low-pass needs. Seen straight down from 16 km (a pixel some 55 m, 0.8 texel, so that both the
// image and the luminance are sampled at their finest level, and a colour texel spans 5 pixels), each
// frame is compared with the image's own, pixel by pixel, in 8-bit levels of each channel.
//
// Tolerance. The method assumes the chroma varies slowly, as the image's hue does, and carries the
// luminance's detail alone: the colour layer's chroma, an average over 4 x 4 texels (bilinear between them),
// stands for each texel's. But the brightness pattern moves the chroma channels too (a* and b* grow about as
// d^(1/3); Cb and Cr of encoded values as d^(1/2.4)), so a texel darker than its block keeps the block's
// chroma, too much of it: up to 10 levels in a channel where the channel is dark (an encoded channel is
// steep there), about 1 on average. That is the method's, not the rendering's: the test predicts it by
// fusing every texel within the frame's reach in double (fusion_reference.hpp, written from the standards),
// from its own luminance and the colour layer's bilinear colour at its centre, against the image: Lab mean
// 1.03 levels, largest 10; Y'CbCr 1.16 and 9. A render may differ from the image by that plus 8-bit
// rounding (of the frame, and of the half-float colour pages): 0.5 on the mean, 1 on the largest. Measured on
// llvmpipe (mean / largest, levels): Lab 0.87 / 8, Y'CbCr 0.97 / 9 (the render samples between texels, which
// smooths the error a little); matching none with the image's own luminance 0.86 / 9; the image itself (a
// colour layer) as the luminance 0.90 / 8. The colour layer alone, without the detail, differs by 4.13 / 20:
// the fusion must at least halve its mean.
//
// Strength 0 is the colour layer alone, to within the opponent spaces' round trip in float: at most 1 level
// (measured: 1, in either space, mean 0.00). Luminance matching: with the luminance layer at 0.7 of the
// image's luminance (a gain between the two data sets) the detail's ratio to its own low-pass cancels the
// gain: the same tolerance (measured 0.87 / 8), with the frame's mean level, its brightness, within 0.5 of the
// image's (measured +0.03); taken as it is (matching none) it darkens the frame by more than 10 levels on
// average (measured -21.3).
//
// Coverage: beyond the luminance layer's extent the colour layer shows exactly as alone (measured: 0 levels);
// beyond the colour layer's, the luminance as grey, within 1.5 levels of the grey of the image's pixel (its
// three channels' rounding carried into their luminance, and the grey's own; measured 0.29 / 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <strata/error.hpp>

#include "fusion_reference.hpp"
#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 240;
constexpr int kTexels = 2048;        // the image's and the luminance layer's, a side
constexpr int kReduction = 4;        // a colour layer texel spans 4 x 4 of them
constexpr double kHalfExtent = 1.2;  // deg
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr int kReach = 96;  // texels from the middle to the frame's edge, 16 km up: 95.4
// Levels beyond the predicted error that rendering may add: see the header.
constexpr double kMeanMargin = 0.5;
constexpr double kLargestMargin = 1.0;
constexpr std::array<double, 4> kExtent{-kHalfExtent, -kHalfExtent, kHalfExtent, kHalfExtent};

using Linear = LinearColour;

Rgb8 encode(const Linear& linear) {
  Rgb8 levels{};
  for (std::size_t c = 0; c < 3; ++c)
    levels[c] = static_cast<unsigned char>(std::lround(255.0 * srgbEncode(std::clamp(linear[c], 0.0, 1.0))));
  return levels;
}

Linear decode(const Rgb8& levels) {
  return {srgbDecode(levels[0] / 255.0), srgbDecode(levels[1] / 255.0), srgbDecode(levels[2] / 255.0)};
}

// The known image at texel (column, row), scene-linear: a slowly turning hue times fine brightness detail.
Linear knownColour(int column, int row) {
  const double hue = kTwoPi * (column / 160.0 + row / 230.0);
  const double detail = 1.0 + 0.15 * std::sin(kTwoPi * column / 6.3) * std::cos(kTwoPi * row / 4.7) +
                        0.1 * std::sin(kTwoPi * (column + 2 * row) / 9.0);
  Linear colour{};
  for (std::size_t c = 0; c < 3; ++c) colour[c] = (0.25 + 0.18 * std::cos(hue - double(c) * kTwoPi / 3.0)) * detail;
  return colour;
}

// The image as 8-bit sRGB, row by row.
std::vector<Rgb8> knownImage() {
  std::vector<Rgb8> image(std::size_t(kTexels) * kTexels);
  for (int row = 0; row < kTexels; ++row)
    for (int column = 0; column < kTexels; ++column)
      image[std::size_t(row) * kTexels + column] = encode(knownColour(column, row));
  return image;
}

// The image's colours averaged over kReduction x kReduction texels in linear light: the colour layer.
std::vector<Rgb8> reducedImage(const std::vector<Rgb8>& image) {
  constexpr int side = kTexels / kReduction;
  std::vector<Rgb8> reduced(std::size_t(side) * side);
  for (int row = 0; row < side; ++row)
    for (int column = 0; column < side; ++column) {
      Linear sum{};
      for (int y = 0; y < kReduction; ++y)
        for (int x = 0; x < kReduction; ++x) {
          const Linear c = decode(image[std::size_t(row * kReduction + y) * kTexels + column * kReduction + x]);
          for (std::size_t i = 0; i < 3; ++i) sum[i] += c[i] / (kReduction * kReduction);
        }
      reduced[std::size_t(row) * side + column] = encode(sum);
    }
  return reduced;
}

struct Difference {
  double mean = 0.0;     // levels, over every channel of every pixel
  double largest = 0.0;  // levels
  double bias = 0.0;     // the frame's mean level less the reference's: its brightness
  int count = 0;

  void add(double d) {
    mean += std::abs(d);
    bias += d;
    largest = std::max(largest, std::abs(d));
    ++count;
  }
  Difference& averaged() {
    mean /= std::max(count, 1);
    bias /= std::max(count, 1);
    return *this;
  }
};

Difference differenceOf(const Image& frame, const Image& reference) {
  Difference difference;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (std::size_t c = 0; c < 3; ++c) difference.add(frame.at(x, y)[c] - reference.at(x, y)[c]);
  return difference.averaged();
}

// The colour layer bilinearly at (u, v), in its texels with centres at whole numbers, in linear light.
Linear bilinearColour(const std::vector<Rgb8>& colour, double u, double v) {
  const int i = int(std::floor(u)), j = int(std::floor(v));
  const double fu = u - i, fv = v - j;
  const auto at = [&](int x, int y) { return decode(colour[std::size_t(y) * (kTexels / kReduction) + x]); };
  const Linear a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
  Linear mixed{};
  for (std::size_t k = 0; k < 3; ++k)
    mixed[k] = (a[k] * (1.0 - fu) + b[k] * fu) * (1.0 - fv) + (c[k] * (1.0 - fu) + d[k] * fu) * fv;
  return mixed;
}

// What the method itself makes of the image, apart from rendering: every texel within the frame's reach
// fused in double (fusion_reference.hpp) from its own luminance and the colour layer's bilinear colour at its
// centre, against the image, in 8-bit levels.
Difference predicted(const std::vector<Rgb8>& image, const std::vector<Rgb8>& colour, OpponentSpace space) {
  Difference difference;
  for (int row = kTexels / 2 - kReach; row < kTexels / 2 + kReach; ++row)
    for (int column = kTexels / 2 - kReach; column < kTexels / 2 + kReach; ++column) {
      const Rgb8 truth = image[std::size_t(row) * kTexels + column];
      const Linear chroma = bilinearColour(colour, (column + 0.5) / kReduction - 0.5, (row + 0.5) / kReduction - 0.5);
      const Rgb8 fused = encode(fuse(chroma, relativeLuminance(decode(truth)), space));
      for (std::size_t c = 0; c < 3; ++c) difference.add(double(fused[c]) - double(truth[c]));
    }
  return difference.averaged();
}

class ChromaFusion : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = std::make_unique<TemporaryDirectory>();
    image_ = knownImage();
    colour_ = reducedImage(image_);
    const auto texel = [](int column, int row) { return image_[std::size_t(row) * kTexels + column]; };
    writeColourRaster(file("image.tif"), kTexels, kTexels, kExtent, texel);
    writeColourRaster(file("colour.tif"), kTexels / kReduction, kTexels / kReduction, kExtent,
                      [](int column, int row) { return colour_[std::size_t(row) * (kTexels / kReduction) + column]; });
    for (const double gain : {1.0, 0.7})
      writeFloatRaster(
          file(gain == 1.0 ? "luminance.tif" : "dim.tif"), kTexels, kTexels, kExtent,
          [&](int column, int row) { return float(gain * relativeLuminance(decode(texel(column, row)))); });
    writeHalves();
  }

  // The luminance layer's west half and the colour layer's east half, the edge at longitude 0 in the middle.
  static void writeHalves() {
    constexpr int side = kTexels / kReduction;
    writeFloatRaster(file("west-luminance.tif"), kTexels / 2, kTexels, {-kHalfExtent, -kHalfExtent, 0.0, kHalfExtent},
                     [](int column, int row) {
                       return float(relativeLuminance(decode(image_[std::size_t(row) * kTexels + column])));
                     });
    writeColourRaster(file("east-colour.tif"), side / 2, side, {0.0, -kHalfExtent, kHalfExtent, kHalfExtent},
                      [](int column, int row) { return colour_[std::size_t(row) * side + side / 2 + column]; });
  }
  static void TearDownTestSuite() {
    directory_.reset();
    image_ = {};
    colour_ = {};
  }

  static std::filesystem::path file(const std::string& name) { return directory_->path() / name; }

  // The frame of `nodes` with `shown` as its one surface, straight down from 16 km over the image's middle.
  Image render(const std::string& nodes, const std::string& shown) {
    const std::string text =
        "strata: 1\nbody: {name: Mars, radius: 3396190}\n"
        "camera: {lon: 0, lat: 0, altitude: 16000, fov: 45}\n"
        "nodes:\n" +
        nodes +
        "  globe: {type: geometry.icosahedral}\n"
        "  frame: {type: output.image, geometry: globe, surface: [" +
        shown + "], shading: none}\n";
    return renderFrame(*engine_, directory_->write("chroma_fusion.yaml", text), kSize, kSize);
  }

  static std::string source(const std::string& id, const std::string& name, const std::string& kind) {
    return "  " + id + ": {type: source.gdal, path: " + file(name).string() + ", kind: " + kind + "}\n";
  }

  // The fusion of `luminanceFile` with the colour layer, with `parameters` said of it.
  Image fused(const std::string& parameters, const std::string& luminanceFile = "luminance.tif",
              const std::string& colourFile = "colour.tif") {
    return render(source("pan", luminanceFile, "luminance") + source("colour", colourFile, "color") +
                      "  fused: {type: composite.chroma_fusion, luminance: pan, colour: colour" + parameters + "}\n",
                  "fused");
  }

  Image image() { return render(source("image", "image.tif", "color"), "image"); }
  Image colourAlone() { return render(source("colour", "colour.tif", "color"), "colour"); }

  static Difference report(const std::string& what, const Difference& difference) {
    std::printf("%s: mean %.2f levels, largest %.0f, brightness %+.2f\n", what.c_str(), difference.mean,
                difference.largest, difference.bias);
    return difference;
  }

  // The render of a fusion in `space` is what the method predicts, within 8-bit rounding.
  static void expectPredicted(const Difference& fusion, OpponentSpace space) {
    const Difference prediction = predicted(image_, colour_, space);
    std::printf("  predicted: mean %.2f levels, largest %.0f\n", prediction.mean, prediction.largest);
    EXPECT_LE(fusion.mean, prediction.mean + kMeanMargin);
    EXPECT_LE(fusion.largest, prediction.largest + kLargestMargin);
  }

  static std::unique_ptr<TemporaryDirectory> directory_;
  static std::vector<Rgb8> image_, colour_;
  std::unique_ptr<Engine> engine_ = makeEngine();
};

std::unique_ptr<TemporaryDirectory> ChromaFusion::directory_;
std::vector<Rgb8> ChromaFusion::image_, ChromaFusion::colour_;

TEST_F(ChromaFusion, ReproducesTheImageInEitherSpace) {
  const Image reference = image();
  const Difference alone = report("colour layer alone", differenceOf(colourAlone(), reference));
  for (const std::string space : {"lab", "ycbcr"}) {
    const Difference fusion = report(space, differenceOf(fused(", space: " + space), reference));
    expectPredicted(fusion, space == "lab" ? OpponentSpace::Lab : OpponentSpace::YCbCr);
    EXPECT_LT(fusion.mean, 0.5 * alone.mean) << space << ": the fusion brings back the luminance's detail";
  }
}

// Without matching, the luminance layer's own luminance, here the image's.
TEST_F(ChromaFusion, ReproducesTheImageWithoutMatching) {
  const Difference fusion = report("matching none", differenceOf(fused(", matching: none"), image()));
  expectPredicted(fusion, OpponentSpace::Lab);
}

// A colour layer as the luminance: its relative luminance, here the image's own colours'.
TEST_F(ChromaFusion, TakesAColourLayersLuminance) {
  const Image reference = image();
  const Image frame = render(source("image", "image.tif", "color") + source("colour", "colour.tif", "color") +
                                 "  fused: {type: composite.chroma_fusion, luminance: image, colour: colour}\n",
                             "fused");
  const Difference fusion = report("colour layer as luminance", differenceOf(frame, reference));
  expectPredicted(fusion, OpponentSpace::Lab);
}

TEST_F(ChromaFusion, StrengthZeroIsTheColourLayerAlone) {
  for (const std::string space : {"lab", "ycbcr"}) {
    const Difference difference =
        report("strength 0, " + space, differenceOf(fused(", strength: 0, space: " + space), colourAlone()));
    EXPECT_LE(difference.largest, 1.0) << space;
  }
}

// A luminance layer uniformly darker than the colour layer (a gain between the data sets) keeps the colour
// layer's brightness and hue when matched; taken as it is, it darkens the colour.
TEST_F(ChromaFusion, MatchingKeepsTheColourLayersBrightness) {
  const Image reference = image();
  const Difference matched = report("0.7 x luminance, matched", differenceOf(fused("", "dim.tif"), reference));
  expectPredicted(matched, OpponentSpace::Lab);
  EXPECT_LE(std::abs(matched.bias), 0.5);
  const Difference unmatched =
      report("0.7 x luminance, matching none", differenceOf(fused(", matching: none", "dim.tif"), reference));
  EXPECT_LT(unmatched.bias, -10.0);
}

// An 8-bit frame's grey of the relative luminance of its pixel's colour.
double greyLevel(const std::array<int, 4>& pixel) {
  return 255.0 * srgbEncode(relativeLuminance(
                     decode(Rgb8{static_cast<unsigned char>(pixel[0]), static_cast<unsigned char>(pixel[1]),
                                 static_cast<unsigned char>(pixel[2])})));
}

// Where the luminance layer has no data the colour layer shows alone; where the colour layer has none, the
// luminance as grey. Judged from 4 pixels either side of the edge (longitude 0, the middle column) on.
TEST_F(ChromaFusion, EachLayerAloneWhereTheOtherHasNoData) {
  const Image colour = colourAlone(), reference = image();
  const Image westLuminance = fused("", "west-luminance.tif");
  const Image eastColour = fused("", "luminance.tif", "east-colour.tif");
  Difference east, west;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (std::size_t c = 0; c < 3; ++c) {
        if (x > kSize / 2 + 3) east.add(westLuminance.at(x, y)[c] - colour.at(x, y)[c]);
        if (x < kSize / 2 - 3) west.add(eastColour.at(x, y)[c] - greyLevel(reference.at(x, y)));
      }
  report("east of the luminance layer, against the colour layer", east.averaged());
  report("west of the colour layer, against the image's grey", west.averaged());
  EXPECT_LE(east.largest, 0.0) << "the colour layer exactly";
  EXPECT_LE(west.largest, 1.5) << "the frame's rounding of each channel, carried into their luminance, and the grey's";
}

// The message of loading `nodes` (with a globe and a frame showing `fused`), or "" where it loads.
std::string refusal(Engine& engine, const TemporaryDirectory& directory, const std::string& nodes) {
  const std::string text = "strata: 1\nnodes:\n" + nodes +
                           "  globe: {type: geometry.icosahedral}\n"
                           "  frame: {type: output.image, geometry: globe, surface: [fused]}\n";
  try {
    engine.load(directory.write("refused.yaml", text));
  } catch (const Error& error) {
    std::printf("%s\n", error.what());
    return error.what();
  }
  return {};
}

// The luminance port takes luminance and colour layers, the colour port colour layers: the graph refuses
// others at the node. One node on both ports is refused, and matching against a colour layer without texels.
TEST_F(ChromaFusion, RefusesWhatItCannotFuse) {
  const std::string colour = source("colour", "colour.tif", "color");
  const std::string heights =
      refusal(*engine_, *directory_,
              source("heights", "luminance.tif", "height") + colour +
                  "  fused: {type: composite.chroma_fusion, luminance: heights, colour: colour}\n");
  EXPECT_NE(heights.find("input 'luminance' takes a luminance or color layer"), std::string::npos) << heights;
  const std::string same = refusal(
      *engine_, *directory_, colour + "  fused: {type: composite.chroma_fusion, luminance: colour, colour: colour}\n");
  EXPECT_NE(same.find("the same node"), std::string::npos) << same;
  const std::string procedural =
      refusal(*engine_, *directory_,
              source("pan", "luminance.tif", "luminance") + "  colour: {type: source.procedural, kind: color}\n" +
                  "  fused: {type: composite.chroma_fusion, luminance: pan, colour: colour, matching: detail}\n");
  EXPECT_NE(procedural.find("no texels"), std::string::npos) << procedural;
  EXPECT_NE(procedural.find("matching: none"), std::string::npos) << procedural;
}

}  // namespace
}  // namespace strata::test
