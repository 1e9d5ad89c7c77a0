// The settings a pipeline may write, as users read them: `strata plugins --describe scene` and the
// parameter reference in docs/reference/, both generated from the declarations the code reads them with.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "strata_command.hpp"

namespace {

namespace fs = std::filesystem;

using strata::test::CommandResult;
using strata::test::contains;
using strata::test::readText;
using strata::test::StrataCommandTest;

TEST_F(StrataCommandTest, PluginsDescribesTheScenesSettings) {
  const CommandResult result = run({"plugins", "--describe", "scene"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  for (const char* line : {"\nbody: ", "\n  radius ", "\ncamera: ", "\n  altitude ", "\ncache: ", "\n  budget ",
                           "\ndate (a value, not a map): ", "\ncolour: ", "\n  config "})
    EXPECT_TRUE(contains(result.out, line)) << line << " in\n" << result.out;
  EXPECT_TRUE(contains(result.out, "(0, inf]")) << "the altitude lies above 0, not at it\n" << result.out;
}

// docs/reference/ is what `strata plugins --reference` writes from the built-in plugins' declarations and
// the scene's: a parameter added, renamed or documented anew without regenerating it fails here.
TEST_F(StrataCommandTest, ParameterReferenceMatchesTheDeclarations) {
  const fs::path generated = file("reference"), committed = fs::path(STRATA_SOURCE_DIR) / "docs" / "reference";
  const CommandResult result = run({"plugins", "--reference", generated.string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string fix = "\nregenerate it: build/bin/strata plugins --reference docs/reference, and commit it";
  EXPECT_EQ(strata::test::namesIn(generated), strata::test::namesIn(committed)) << fix;
  for (const auto& page : fs::directory_iterator(generated))
    EXPECT_EQ(readText(page.path()), readText(committed / page.path().filename()))
        << page.path().filename() << " differs from the declarations" << fix;
}

TEST_F(StrataCommandTest, ParameterReferenceLeavesAFolderOfOtherFilesAlone) {
  fs::create_directories(file("docs"));
  const fs::path notes = write("docs/notes.md", "my notes\n");
  const CommandResult result = run({"plugins", "--reference", notes.parent_path().string()});
  EXPECT_EQ(result.exitCode, 1) << result.out;
  EXPECT_TRUE(contains(result.err, "notes.md")) << result.err;
  EXPECT_EQ(readText(notes), "my notes\n");
  EXPECT_FALSE(fs::exists(notes.parent_path() / "README.md")) << "nothing written";
}

}  // namespace
