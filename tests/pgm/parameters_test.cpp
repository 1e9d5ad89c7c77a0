// geometry.pgm's own parameters, refused at load with the place and the fix when they make no grid.
#include <gtest/gtest.h>

#include <string>

#include <strata/error.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::pgm::test {
namespace {

TEST(PgmParameters, AGridThatIsNoGridNamesItsLineAndTheForm) {
  strata::test::TemporaryDirectory directory;
  auto engine = strata::test::makeEngine();
  const auto pipeline = directory.write("grid.yaml",
                                        "strata: 1\nnodes:\n"
                                        "  terrain: {type: geometry.pgm, grid: 512}\n"
                                        "  frame: {type: output.image, geometry: terrain}\n");
  try {
    engine->load(pipeline);
    FAIL() << "a grid of '512' loaded";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("grid.yaml:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("grid '512' is not a grid size"), std::string::npos) << message;
    EXPECT_NE(message.find("e.g. grid: 1024x1024"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace strata::pgm::test
