// Strata's OpenColorIO config (ocio/strata.ocio) and the GLSL OCIO writes for it, run on the headless context:
// every 8-bit sRGB level goes to scene-linear as IEC 61966-2-1 defines it, and back through the sRGB display's
// Standard view to the level it came from (issue 8: known colours round-trip within 1/255). Tolerances: the
// linear values within 1e-4 of the standard's formula (OCIO's curve meets the linear segment at 0.0393 where
// the standard says 0.04045, measured 7.5e-7 apart at worst on llvmpipe; float adds 1e-6); the round trip to the
// same level after rounding, which is within half of 1/255.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <strata/colour_config.hpp>
#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>

#include "compute_each.hpp"
#include "rendering.hpp"
#include "srgb.hpp"
#include "temporary_directory.hpp"

namespace strata {
namespace {

const SourceLocation kWhere{"colour test"};

// Each value v: toLinear(v) and toDisplay(toLinear(v)), from the two generated functions.
std::vector<std::array<float, 2>> evaluate(const std::string& toLinear, const std::string& toDisplay,
                                           const std::vector<float>& values) {
  test::headlessContext();
  const std::string source = test::eachElementShader(toLinear + toDisplay, "float", "vec2", R"(
  vec4 linear = toLinear(vec4(vec3(arguments[i]), 1.0));
  results[i] = vec2(linear.g, toDisplay(linear).g);
)");
  const ShaderLibrary library;
  const ShaderProgram program(
      {{GL_COMPUTE_SHADER, "colour_test.comp", library.expandText(source, "colour_test.comp")}});
  return test::computeEach<std::array<float, 2>>(program, values);
}

std::vector<float> everyLevel() {
  std::vector<float> levels;
  for (int level = 0; level < 256; ++level) levels.push_back(float(level) / 255.0f);
  return levels;
}

TEST(ColourConfig, SrgbLevelsRoundTripThroughSceneLinear) {
  const ColourConfig config = ColourConfig::load({}, kWhere);
  EXPECT_EQ(config.defaultDisplay(), "sRGB");
  EXPECT_EQ(config.defaultView("sRGB"), "Standard");
  const auto results = evaluate(config.toSceneLinear("srgb", "toLinear", kWhere),
                                config.toDisplay("sRGB", "Standard", "toDisplay", kWhere), everyLevel());
  double worstLinear = 0.0;
  int worstLevels = 0;
  for (int level = 0; level < 256; ++level) {
    worstLinear = std::max(worstLinear, std::abs(results[level][0] - test::srgbDecode(level / 255.0)));
    worstLevels = std::max(worstLevels, std::abs(int(std::lround(results[level][1] * 255.0)) - level));
  }
  std::printf("worst: %.2e from the sRGB formula in linear light, %d levels after the round trip\n", worstLinear,
              worstLevels);
  EXPECT_LE(worstLinear, 1e-4);
  EXPECT_EQ(worstLevels, 0);
}

TEST(ColourConfig, Gamma22IsAPurePower) {
  const ColourConfig config = ColourConfig::load({}, kWhere);
  const auto results = evaluate(config.toSceneLinear("gamma22", "toLinear", kWhere),
                                config.toDisplay("sRGB", "Raw", "toDisplay", kWhere), everyLevel());
  for (int level = 0; level < 256; level += 15) {
    EXPECT_NEAR(results[level][0], std::pow(level / 255.0, 2.2), 1e-5) << level;
    EXPECT_NEAR(results[level][1], results[level][0], 1e-7) << "the Raw view changes nothing";
  }
}

TEST(ColourConfig, SaysWhichSpacesNeedNoConversion) {
  const ColourConfig config = ColourConfig::load({}, kWhere);
  EXPECT_TRUE(config.isSceneLinear("linear", kWhere));
  EXPECT_TRUE(config.isSceneLinear("raw", kWhere)) << "data is never converted";
  EXPECT_FALSE(config.isSceneLinear("srgb", kWhere));
  EXPECT_FALSE(config.isSceneLinear("gamma22", kWhere));
  EXPECT_THROW(config.isSceneLinear("acescg", kWhere), Error);
}

TEST(ColourConfig, NamesWhatTheConfigLacks) {
  const ColourConfig config = ColourConfig::load({}, kWhere);
  try {
    config.toSceneLinear("acescg", "f", kWhere);
    ADD_FAILURE() << "an unknown colour space was accepted";
  } catch (const Error& error) {
    EXPECT_EQ(error.problem(), "the colour space 'acescg' is not in Strata's built-in config");
    EXPECT_EQ(error.fix(), "choose one of 'linear', 'srgb', 'gamma22', 'raw'");
  }
  EXPECT_THROW(config.toDisplay("P3", "Standard", "f", kWhere), Error);
  EXPECT_THROW(config.toDisplay("sRGB", "Filmic", "f", kWhere), Error);
}

TEST(ColourConfig, TakesTheConfigOcioNamesAndSaysWhatIsWrongWithIt) {
  test::TemporaryDirectory directory;
  const auto broken = directory.write("broken.ocio", "ocio_profile_version: 2\nroles: [\n");
  setenv("OCIO", broken.c_str(), 1);
  try {
    ColourConfig::load({}, kWhere);
    ADD_FAILURE() << "a broken config was accepted";
  } catch (const Error& error) {
    EXPECT_NE(error.problem().find(broken.string() + "' ($OCIO)"), std::string::npos) << error.problem();
    EXPECT_NE(error.fix().find("unset OCIO"), std::string::npos);
  }
  unsetenv("OCIO");
  EXPECT_EQ(ColourConfig::load({}, kWhere).origin(), "Strata's built-in config");
}

// A folder given as the config (the folder a config came in) is named as a folder, with the file to give.
TEST(ColourConfig, RefusesAFolderAsTheConfig) {
  test::TemporaryDirectory directory;
  try {
    ColourConfig::load(directory.path(), kWhere);
    ADD_FAILURE() << "a folder was taken for a config";
  } catch (const Error& error) {
    EXPECT_EQ(error.problem(), "'" + directory.path().string() + "' is a folder, not an OpenColorIO config");
    EXPECT_NE(error.fix().find("config.ocio"), std::string::npos) << error.fix();
  }
}

}  // namespace
}  // namespace strata
