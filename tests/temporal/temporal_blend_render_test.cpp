// composite.temporal_blend (issue 7; [Kooima 2008, §1.1, ch. 6], time-varying data): a series of synthetic
// months, each one colour over the whole planet, rendered day by day through the scene's date with no reload.
// The mean colour of a frame follows the blend of the bracketing months linearly in time in scene-linear
// light, then sRGB-encoded as output.image writes it, to within 1 level (8-bit output rounding, 0.5, plus
// the half floats the pages hold, under 0.2): it is continuous in the date, with no step where one month
// gives way to the next. And of a year of months the page cache wants only the pages of the bracketing two
// and one month beyond each side, in GPU memory of the budget's size, however long the series. Heights blend
// in the geometry alike: the planet's outline follows the blended height, to within a quarter of the
// outline's pixels (a 2.5-day step moves about 240 of them). Measured on llvmpipe: worst 0.49 levels from
// the blend; largest change from one day to the next 19.00 levels where the blend's own is 18.92 (early in
// January's fade, where sRGB is steep); outlines 0 to 22 pixels off of 255 to 278. Frames are drawn without
// antialiasing: the mean is over the pixels whose centre shows the body, and the outline is judged at pixel
// centres, where the edge's pixels would otherwise mix the body with the sky.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <strata/date.hpp>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "srgb.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 96;
const std::vector<Rgb8> kMonthColours{{200, 40, 40}, {40, 200, 40}, {40, 40, 200}, {220, 220, 60}};
const std::vector<std::string> kMonthDates{"2004-01-15", "2004-02-15", "2004-03-15", "2004-04-15"};

double linearToSrgb(double linear) {
  return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// The steps' colours blended as the compositor blends them, in 8-bit levels.
std::array<double, 3> expectedColour(DayNumber date) {
  std::size_t later = 0;
  while (later < kMonthDates.size() && *parseIsoDate(kMonthDates[later]) <= date) ++later;
  const std::size_t earlier = later == 0 ? 0 : later - 1;
  later = std::min(later, kMonthDates.size() - 1);
  const double from = *parseIsoDate(kMonthDates[earlier]), to = *parseIsoDate(kMonthDates[later]);
  const double t = later == earlier ? 0.0 : std::clamp((date - from) / (to - from), 0.0, 1.0);
  std::array<double, 3> colour{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double a = srgbDecode(kMonthColours[earlier][c] / 255.0), b = srgbDecode(kMonthColours[later][c] / 255.0);
    colour[c] = 255.0 * linearToSrgb(a + (b - a) * t);
  }
  return colour;
}

// A series of `months` global rasters of `width` texels across, one colour each, as a temporal blend.
std::filesystem::path writeSeries(const std::filesystem::path& directory, const std::vector<Rgb8>& colours,
                                  const std::vector<std::string>& dates, int width, const std::string& camera) {
  std::string steps, nodes;
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const std::filesystem::path file = directory / ("month" + std::to_string(i) + ".tif");
    writeColourRaster(file, width, width / 2, {-180, -90, 180, 90}, [&](int, int) { return colours[i]; });
    nodes += "  month" + std::to_string(i) + ": {type: source.gdal, path: " + file.string() + "}\n";
    steps += std::string(i ? ", " : "") + "month" + std::to_string(i);
  }
  std::string list;
  for (const std::string& date : dates) list += (list.empty() ? "" : ", ") + date;
  const std::filesystem::path pipeline = directory / "series.yaml";
  std::ofstream(pipeline)
      << "strata: 1\nbody: {name: Mars, radius: 3396190}\ndate: " << dates.front() << "\ncamera: " << camera
      << "\nnodes:\n"
      << nodes << "  series: {type: composite.temporal_blend, steps: [" << steps << "], dates: [" << list
      << "]}\n  globe: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: globe, surface: [series], shading: none, antialiasing: none}\n";
  return pipeline;
}

std::array<double, 3> meanColour(const Image& image) {
  std::array<double, 3> sum{};
  int counted = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (covered(image, x, y)) {
        for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += image.at(x, y)[std::size_t(c)];
        ++counted;
      }
  EXPECT_GT(counted, kSize * kSize / 4);
  for (double& channel : sum) channel /= std::max(counted, 1);
  return sum;
}

TEST(TemporalBlend, MeanColourFollowsTheDateContinuously) {
  TemporaryDirectory directory;
  const auto pipeline = writeSeries(directory.path(), kMonthColours, kMonthDates, 64,
                                    "{lon: 0, lat: 0, altitude: 1.2e7, tilt: 0, fov: 30}");
  auto engine = makeEngine();
  engine->load(pipeline);
  double worst = 0.0, largestStep = 0.0, largestExpectedStep = 0.0;
  std::array<double, 3> previous{}, previousExpected{};
  const DayNumber first = *parseIsoDate("2004-01-01"), last = *parseIsoDate("2004-05-01");
  for (DayNumber date = first; date <= last; date += 1.0) {
    engine->date() = date;
    const std::array<double, 3> mean =
        meanColour(Image{kSize, kSize, readPixels(engine->renderComplete(kSize, kSize).frame())});
    const std::array<double, 3> expected = expectedColour(date);
    for (std::size_t c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(mean[c] - expected[c]));
      if (date > first) {
        largestStep = std::max(largestStep, std::abs(mean[c] - previous[c]));
        largestExpectedStep = std::max(largestExpectedStep, std::abs(expected[c] - previousExpected[c]));
      }
    }
    previous = mean;
    previousExpected = expected;
  }
  std::printf("worst %.2f levels from the blend; largest change a day %.2f, the blend's %.2f\n", worst, largestStep,
              largestExpectedStep);
  EXPECT_LE(worst, 1.0);
  EXPECT_LE(largestStep, largestExpectedStep + 1.0);  // no pop: no day changes more than the blend does
}

TEST(TemporalBlend, PagesOnlyTheBracketingStepsAndOneBeyondEachSide) {
  TemporaryDirectory directory;
  const std::string near = "{lon: 0, lat: 0, altitude: 500000, tilt: 0, fov: 45}";  // wants level-0 pages
  const std::vector<Rgb8> colours(12, Rgb8{90, 120, 150});
  std::vector<std::string> months;
  for (int m = 1; m <= 12; ++m) months.push_back("2004-" + std::string(m < 10 ? "0" : "") + std::to_string(m) + "-15");
  auto engine = makeEngine();
  engine->load(writeSeries(directory.path(), {colours.front()}, {months.front()}, 1024, near));
  engine->renderComplete(kSize, kSize);
  const PageCacheStatistics one = engine->pageCacheStatistics();
  ASSERT_GT(one.wanted, 1) << "the view must want more than the pinned coarsest page for this to say anything";

  engine->load(writeSeries(directory.path(), colours, months, 1024, near));
  // Within the year two months show and one beyond each is prefetched; at its end there is no month beyond.
  for (const auto& [date, steps] :
       {std::pair{"2004-06-01", 4}, {"2004-06-20", 4}, {"2004-11-30", 3}, {"2004-12-20", 2}}) {
    engine->date() = *parseIsoDate(date);
    engine->renderComplete(kSize, kSize);
    const PageCacheStatistics series = engine->pageCacheStatistics();
    EXPECT_EQ(series.wanted, steps * one.wanted) << date;
    EXPECT_EQ(series.gpuBytes, one.gpuBytes) << date << ": the budget's, however long the series";
  }
}

// Heights blend as imagery does: two steps of the whole planet raised 0 and 300 km, ten days apart, make a
// sphere that grows with the date; its outline is the analytic sphere's of the blended height.
TEST(TemporalBlend, HeightsBlendInTheGeometry) {
  TemporaryDirectory directory;
  std::string nodes;
  for (const auto& [name, height] : {std::pair{"low", 0.0f}, {"high", 300000.0f}}) {
    const std::filesystem::path file = directory.path() / (std::string(name) + ".tif");
    writeFloatRaster(file, 64, 32, {-180, -90, 180, 90}, [h = height](int, int) { return h; });
    nodes += "  " + std::string(name) + ": {type: source.gdal, path: " + file.string() + ", kind: height}\n";
  }
  const Camera camera{.lon = 0, .lat = 0, .altitude = 1.2e7, .heading = 0, .tilt = 0, .fov = 30};
  std::ofstream(directory.path() / "heights.yaml")
      << "strata: 1\nbody: {name: Mars, radius: 3396190}\ndate: 2004-01-01\nnodes:\n"
      << nodes
      << "  series: {type: composite.temporal_blend, steps: [low, high], dates: [2004-01-01, 2004-01-11]}\n"
         "  globe: {type: geometry.icosahedral, height: series, lowest: 0, highest: 300000}\n"
         "  frame: {type: output.image, geometry: globe, shading: none, antialiasing: none}\n";
  auto engine = makeEngine();
  engine->load(directory.path() / "heights.yaml");
  const Body body{"Mars", 3396190.0};
  const View view = makeView(body, camera, kSize, kSize);
  for (double day = 0.0; day <= 10.0; day += 2.5) {
    engine->date() = *parseIsoDate("2004-01-01") + day;
    const Image image = renderFrames(*engine, camera, kSize, kSize, 1);
    const double radius = body.radius + 30000.0 * day;
    int differing = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        differing += covered(image, x, y) != raycastSphere(view, radius, x, y).has_value();
    const double outline = 2.0 * 3.14159265 * discRadiusPixels(view, radius, body.radius + camera.altitude);
    std::printf("day %.1f: %d pixels differ from the sphere's outline of %.0f\n", day, differing, outline);
    EXPECT_LE(differing, 0.25 * outline) << "day " << day;
  }
}

}  // namespace
}  // namespace strata::test
