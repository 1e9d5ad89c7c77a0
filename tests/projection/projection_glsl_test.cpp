// The GLSL form of each built-in projection against PROJ: the function compiled into a fragment shader that
// evaluates it at one longitude/latitude per pixel, read from a float texture so that the inputs are known
// exactly, into a GL_RGBA32F target that is read back. The reference is PROJ at the same (float) inputs, over
// the windows and samples of the double-precision comparison (projection_cases.hpp).
//
// Tolerance, from single-precision arithmetic, per sample: 16 ulps of the result (in GLSL units, map /
// glslMapScale(), values near 1), for the rounding of a chain of some 30 operations on values of at most a few
// units, which the formulas keep free of cancellation (t of the stereographic, 1 - sin of HEALPix's caps, the
// haversine of perspective views); plus 16 * 2^-24 rad times the map's magnification |d(x, y) / d(lon, lat)|
// there (GLSL units per radian), for sin, cos, pow and sqrt, good to a few ulps of 1 on llvmpipe and to 2^-21
// absolute in GPU hardware approximations, and for the few-ulp errors of the angles formed from the inputs
// (lon - lon_0, 2 lon / pi). The magnification matters where the map stretches: a tilted camera's view far
// off its axis, the far side of a polar stereographic map. Points within 1e-5 rad of the rim of the visible
// hemisphere, of the horizon or of a seam of HEALPix's polar triangles are left out: float rounding may put
// them on the other side. The output reports the worst error in texels of a raster 40000 texels across the
// full x range, and its share of the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <strata/gl/framebuffer.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/gl/texture.hpp>
#include <strata/plugin/healpix_pyramid.hpp>

#include "projection_cases.hpp"
#include "rendering.hpp"

namespace strata::test {
namespace {

constexpr int kWidth = 512;
constexpr double kEdgeMargin = 1e-5;  // radians
constexpr double kResultUlps = 16.0;
constexpr double kAngleError = 16.0 * 0x1p-24;  // radians

double ulpOf(double value) {
  const float magnitude = float(std::abs(value));
  return double(std::nextafter(magnitude, std::numeric_limits<float>::infinity()) - magnitude);
}

// The tolerance at `lonlat`, in map units (see above).
double glslTolerance(const Projection& projection, glm::dvec2 lonlat, glm::dvec2 glsl) {
  const double scale = projection.glslMapScale(), step = 1e-6;
  double magnification = 0.0;
  for (glm::dvec2 direction : {glm::dvec2(step, 0.0), glm::dvec2(0.0, step)}) {
    const glm::dvec2 ahead = lonlat + direction, behind = lonlat - direction;
    const auto a = projection.forward({ahead.x, std::min(ahead.y, 0.5 * std::numbers::pi)});
    const auto b = projection.forward({behind.x, std::max(behind.y, -0.5 * std::numbers::pi)});
    if (a && b) magnification = std::max(magnification, glm::length(*a - *b) / (2.0 * step) / scale);
  }
  const double resultUlp = std::max(ulpOf(glsl.x / scale), ulpOf(glsl.y / scale));
  return (kResultUlps * resultUlp + kAngleError * magnification) * scale;
}

// One projection's GLSL function, evaluated on the headless context at many points.
class GlslProjection {
 public:
  explicit GlslProjection(const Projection& projection) : parameters_(projection.glslParameters()) {
    const ShaderLibrary library;
    const std::string fragment =
        "#version 450 core\n"
        "#include \"" +
        projection.glslInclude() +
        "\"\n"
        "layout(binding = 0) uniform sampler2D lonlats;\n"
        "uniform vec4 projectionA;\n"
        "uniform vec4 projectionB;\n"
        "layout(location = 0) out vec4 result;\n"
        "void main() {\n"
        "  vec2 lonlat = texelFetch(lonlats, ivec2(gl_FragCoord.xy), 0).xy;\n"
        "  result = vec4(" +
        projection.glslFunction() +
        "(lonlat, projectionA, projectionB), 0.0);\n"
        "}\n";
    program_ = ShaderProgram(
        {{GL_VERTEX_SHADER, "strata/fullscreen.vert", library.expand("strata/fullscreen.vert")},
         {GL_FRAGMENT_SHADER, "projection_glsl_test.frag", library.expandText(fragment, "projection_glsl_test.frag")}});
  }

  std::vector<glm::vec3> evaluate(std::vector<glm::vec2> lonlats) const {
    const int count = int(lonlats.size());
    const int height = (count + kWidth - 1) / kWidth;
    lonlats.resize(std::size_t(kWidth) * height, glm::vec2(0.0f));
    const Texture input(GL_RG32F, kWidth, height);
    glTextureSubImage2D(input.id(), 0, 0, 0, kWidth, height, GL_RG, GL_FLOAT, lonlats.data());
    const Framebuffer target(kWidth, height, {GL_RGBA32F});
    target.bind();
    program_.use();
    program_.set("projectionA", glm::vec4(parameters_[0]));
    program_.set("projectionB", glm::vec4(parameters_[1]));
    glBindTextureUnit(0, input.id());
    const FullscreenTriangle triangle;
    triangle.draw();
    std::vector<glm::vec4> pixels(lonlats.size());
    glGetTextureImage(target.color(0).id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(glm::vec4)),
                      pixels.data());
    std::vector<glm::vec3> results;
    for (int i = 0; i < count; ++i) results.emplace_back(pixels[i]);
    return results;
  }

 private:
  std::array<glm::dvec4, 2> parameters_;
  ShaderProgram program_;
};

// The float nearest `lonlat`, kept on the body: the float nearest pi/2 lies beyond the pole.
glm::vec2 floatLonlat(glm::dvec2 lonlat) {
  glm::vec2 rounded(lonlat);
  if (std::abs(double(rounded.y)) > 0.5 * std::numbers::pi) rounded.y = std::nextafter(rounded.y, 0.0f);
  return rounded;
}

class GlslAgainstProj : public testing::TestWithParam<ProjectionCase> {};

TEST_P(GlslAgainstProj, MatchesProjAndIsUndefinedWhereForwardIs) {
  headlessContext();
  const auto projection = makeProjection(GetParam());
  const ProjReference proj(referenceDefinition(GetParam()));
  const MapWindow window = mapWindow(GetParam(), *projection, proj);
  std::vector<glm::vec2> lonlats;
  for (glm::dvec2 lonlat : lonlatSamples(proj, window, 360, 181, 256)) lonlats.push_back(floatLonlat(lonlat));
  const std::vector<glm::vec3> results = GlslProjection(*projection).evaluate(lonlats);

  double worst = 0.0, worstShare = 0.0;
  int compared = 0, wrongZ = 0;
  for (std::size_t i = 0; i < lonlats.size(); ++i) {
    const glm::dvec2 lonlat(lonlats[i]);
    if (nearRim(*projection, lonlat, kEdgeMargin) ||
        nearSeam(*projection, lonlat, kEdgeMargin, 0.01 * window.fullRangeX))
      continue;
    const auto mine = projection->forward(lonlat);
    if (results[i].z != (mine ? 1.0f : 0.0f) && wrongZ++ < 5)
      ADD_FAILURE() << ".z = " << results[i].z << " at (" << lonlat.x << ", " << lonlat.y << ")";
    const auto theirs = proj.forward(lonlat);
    if (!mine || !theirs || !window.contains(*theirs)) continue;
    const glm::dvec2 glsl = glm::dvec2(results[i]) * projection->glslMapScale();
    const double error = mapDistance(*projection, glsl, *theirs);
    worst = std::max(worst, error);
    worstShare = std::max(worstShare, error / glslTolerance(*projection, lonlat, glsl));
    ++compared;
  }
  std::cout << GetParam().name << " GLSL: worst " << worst << " map units = " << worst / window.texel() << " texels of "
            << window.texel() << "; worst error / tolerance " << worstShare << " (" << compared << " samples)\n";
  RecordProperty("worst_texels", std::to_string(worst / window.texel()));
  EXPECT_LE(worstShare, 1.0);
  EXPECT_EQ(wrongZ, 0);
  EXPECT_GT(compared, 10000);
}

// The GLSL side wraps longitudes around the raster's centre as forward() does: geographic, eqc and HEALPix
// rasters spanning [0, 360) degrees.
TEST(GlslLongitudeWrap, RastersFrom0To360Degrees) {
  headlessContext();
  for (const std::string terms : {"+proj=longlat", "+proj=eqc +lat_ts=20 +lon_0=30", "+proj=healpix +lon_0=-45"}) {
    const auto projection = makeProjection(terms, kMars);
    projection->setLongitudeCentre(std::numbers::pi);
    std::vector<glm::vec2> lonlats;
    for (int i = 0; i < 720; ++i)
      for (double lat : {-80.0, -30.0, 0.0, 45.0, 70.0})
        lonlats.push_back(floatLonlat(glm::radians(glm::dvec2(-179.75 + 0.5 * i, lat))));
    const std::vector<glm::vec3> results = GlslProjection(*projection).evaluate(lonlats);
    for (std::size_t i = 0; i < lonlats.size(); ++i) {
      const glm::dvec2 lonlat(lonlats[i]);
      const glm::dvec2 expected = *projection->forward(lonlat);
      const glm::dvec2 glsl = glm::dvec2(results[i]) * projection->glslMapScale();
      ASSERT_LE(glm::length(glsl - expected), glslTolerance(*projection, lonlat, glsl))
          << terms << " at " << glm::degrees(lonlat.x) << ", " << glm::degrees(lonlat.y);
    }
  }
}

// The strip of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp), on a sphere and an ellipsoid, against its
// C++ form over random places, leaving out those within kEdgeMargin of a face's edge, which float rounding
// may put on the other face. Tolerance as above, in strip units (a face is one unit across).
TEST(GlslHealpixStrip, MatchesTheStripProjection) {
  headlessContext();
  for (const Ellipsoid& figure : {kMars, Ellipsoid{6378137.0, 298.257223563}}) {
    const auto projection = healpix::stripProjection(makeProjection("+proj=healpix", figure));
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::vec2> lonlats;
    for (int i = 0; i < 100000; ++i)
      lonlats.push_back(
          floatLonlat({std::numbers::pi * (2.0 * unit(random) - 1.0), std::asin(2.0 * unit(random) - 1.0)}));
    const std::vector<glm::vec3> results = GlslProjection(*projection).evaluate(lonlats);
    double worstShare = 0.0;
    int compared = 0;
    for (std::size_t i = 0; i < lonlats.size(); ++i) {
      const glm::dvec2 lonlat(lonlats[i]), expected = *projection->forward(lonlat);
      const double x = expected.x - std::floor(expected.x);
      if (std::min({x, 1.0 - x, expected.y, 1.0 - expected.y}) < kEdgeMargin) continue;
      const glm::dvec2 glsl(results[i]);
      worstShare = std::max(worstShare, glm::length(glsl - expected) / glslTolerance(*projection, lonlat, glsl));
      ++compared;
    }
    std::cout << "HEALPix strip GLSL, a = " << figure.semiMajorAxis << ": worst error / tolerance " << worstShare
              << " (" << compared << " samples)\n";
    EXPECT_LE(worstShare, 1.0);
    EXPECT_GT(compared, 99000);
  }
}

std::string caseName(const testing::TestParamInfo<ProjectionCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Builtin, GlslAgainstProj, testing::ValuesIn(projectionCases()), caseName);

}  // namespace
}  // namespace strata::test
