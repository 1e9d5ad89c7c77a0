// Multisample antialiasing (output.image's `antialiasing`) across the body's edge. A bare grey sphere on black,
// unlit, is drawn with and without it; each pixel's coverage is read back from its light (the sRGB level decoded
// and divided by that of a pixel inside the disc) and judged against the share of the pixel the sphere truly
// covers: 16 x 16 rays through each pixel met with the sphere in double. The mesh is refined to a twentieth
// of a pixel (pixel_error 0.05), so what differs is the sampling, not the chords.
//
// Four samples resolve a pixel's coverage to quarters; one gives all or nothing. Measured on llvmpipe over
// the 636 pixels the edge crosses: with 4x off by 0.084 on average and 0.263 at worst, without by 0.236 and
// 0.504. Tolerances: with 4x a mean under 0.12 (an eighth, half a quarter's step: what quarters give for edges
// crossing pixels at random) and no pixel off by 0.4 or more (a step of the unsmoothed edge shows as 0.5);
// without antialiasing the mean is at least twice that with it, so the test sees the steps it removes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rendering.hpp"
#include "sphere_raycast.hpp"
#include "srgb.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

constexpr int kSize = 256;
constexpr int kRays = 16;  // per pixel side, for the true coverage
constexpr double kEarth = 6371000.0;
const Camera kCamera{.lon = 137.4, .lat = -4.6, .altitude = 1.0e7, .fov = 60};

// The share of pixel (x, y) the sphere covers: rays through a kRays x kRays grid over the pixel.
double trueCoverage(const View& view, int x, int y) {
  int inside = 0;
  for (int i = 0; i < kRays; ++i)
    for (int j = 0; j < kRays; ++j)
      inside += raycastSphere(view, kEarth, x - 0.5 + (i + 0.5) / kRays, y - 0.5 + (j + 0.5) / kRays).has_value();
  return double(inside) / (kRays * kRays);
}

struct EdgeErrors {
  int pixels = 0;  // those the edge crosses: true coverage between 2% and 98%
  double mean = 0.0;
  double worst = 0.0;
};

EdgeErrors edgeErrors(const Image& image, const View& view) {
  const double inside = linearLightOf(image.at(kSize / 2, kSize / 2)[1]);
  EdgeErrors errors;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double truth = trueCoverage(view, x, y);
      if (truth < 0.02 || truth > 0.98) continue;
      const double error = std::abs(linearLightOf(image.at(x, y)[1]) / inside - truth);
      ++errors.pixels;
      errors.mean += error;
      errors.worst = std::max(errors.worst, error);
    }
  errors.mean /= std::max(errors.pixels, 1);
  return errors;
}

std::string greySphere(const std::string& antialiasing) {
  return "strata: 1\nbody: {name: Earth, radius: 6371000}\nnodes:\n"
         "  globe: {type: geometry.icosahedral, pixel_error: 0.05, patches: 20000}\n"
         "  frame: {type: output.image, geometry: globe, shading: none, antialiasing: " +
         antialiasing + "}\n";
}

EdgeErrors limbErrors(Engine& engine, const TemporaryDirectory& directory, const std::string& antialiasing) {
  engine.load(directory.write("sphere.yaml", greySphere(antialiasing)));
  const Image image = renderFrames(engine, kCamera, kSize, kSize, 1);
  const EdgeErrors errors = edgeErrors(image, engine.view(kSize, kSize));
  std::printf("antialiasing %s: %d edge pixels, coverage off by %.3f on average, %.3f at worst\n", antialiasing.c_str(),
              errors.pixels, errors.mean, errors.worst);
  return errors;
}

TEST(Antialiasing, TheLimbHasNoSteps) {
  TemporaryDirectory directory;
  auto engine = makeEngine();
  const EdgeErrors smoothed = limbErrors(*engine, directory, "4x");
  const EdgeErrors stepped = limbErrors(*engine, directory, "none");
  EXPECT_GT(smoothed.pixels, 300);  // the disc's radius is about 94 pixels
  EXPECT_LT(smoothed.mean, 0.12);
  EXPECT_LT(smoothed.worst, 0.4);
  EXPECT_GT(stepped.mean, 2.0 * smoothed.mean);
}

}  // namespace
}  // namespace strata::test
