// Shader sources: includes expand once, and a compile failure names the shader, quotes the driver's log
// and shows the numbered source.
#include <gtest/gtest.h>

#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>

#include "rendering.hpp"

namespace strata::test {
namespace {

TEST(ShaderLibrary, ExpandsEachIncludeOnce) {
  ShaderLibrary library;
  library.add("a.glsl", "#include \"strata/constants.glsl\"\nfloat a() { return PI; }\n");
  std::string text = library.expandText("#include \"a.glsl\"\n#include \"strata/constants.glsl\"\n", "test");
  EXPECT_NE(text.find("float a()"), std::string::npos);
  EXPECT_EQ(text.find("const float PI"), text.rfind("const float PI")) << text;
}

// libstrata_core holds the SDK's shared GLSL only; each plugin's own comes from its module, through its
// node declarations, as an out-of-tree plugin's does.
TEST(ShaderLibrary, PluginsGlslComesFromTheirModulesNotTheCore) {
  const ShaderLibrary core;
  EXPECT_TRUE(core.has("strata/surface_point.glsl"));
  EXPECT_TRUE(core.has("strata/surface_buffer.frag"));
  for (const char* name :
       {"composite-relief/relief.glsl", "geometry-pgm/pgm_cast.comp", "geometry-icosahedral/subdivide_patches.comp",
        "output-image/composite.frag", "source-procedural/planet.glsl"}) {
    EXPECT_FALSE(core.has(name)) << name;
    EXPECT_TRUE(pluginShaderLibrary().has(name)) << name;
  }
}

TEST(ShaderLibrary, UnknownIncludeNamesTheIncludingSource) {
  ShaderLibrary library;
  try {
    library.expandText("#include \"nowhere.glsl\"\n", "mine.frag");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("mine.frag"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("nowhere.glsl"), std::string::npos);
  }
}

TEST(ShaderProgram, CompileErrorQuotesTheLogAndTheSource) {
  headlessContext();
  try {
    ShaderProgram program(
        {{GL_FRAGMENT_SHADER, "broken.frag", "#version 450 core\nout vec4 c;\nvoid main() { c = nope; }\n"}});
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("broken.frag"), std::string::npos) << message;
    EXPECT_NE(message.find("failed to compile"), std::string::npos) << message;
    EXPECT_NE(message.find("nope"), std::string::npos) << message;
    EXPECT_NE(message.find("3: void main() { c = nope; }"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace strata::test
