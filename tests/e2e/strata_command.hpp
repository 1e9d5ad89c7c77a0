#pragma once
// Running the built strata command as a user would, for the end-to-end tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "temporary_directory.hpp"

namespace strata::test {

// What one run of the command did.
struct CommandResult {
  int exitCode = -1;  // a crash shows as 128 + the signal (the shell's way), -1 if the shell itself failed
  std::string out;
  std::string err;
};

std::string readText(const std::filesystem::path& file);
bool contains(const std::string& text, const std::string& part);
// The names in a folder, sorted: what a test sees of scratch folders or partial files left behind.
std::vector<std::string> namesIn(const std::filesystem::path& folder);

// Each test gets a scratch directory, removed with its files afterwards, and runs strata with only the
// built-in plugins beside the binary unless it names a plugin directory: plugins found through a
// STRATA_PLUGIN_PATH of the person running the tests must not change the results.
class StrataCommandTest : public ::testing::Test {
 protected:
  // Runs strata from the source tree (where pipelines/ is) with `arguments`.
  CommandResult run(const std::vector<std::string>& arguments, const std::string& pluginPath = {}) const;
  // Renders `pipeline` to a tiny frame in the scratch directory (x.png, replaced by each call), for tests
  // that expect it to be refused or compare it with the frame of another pipeline.
  CommandResult renderTiny(const std::filesystem::path& pipeline, const std::string& pluginPath = {}) const;

  std::filesystem::path file(const std::string& name) const { return scratch_.path() / name; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    return scratch_.write(name, text);
  }

  TemporaryDirectory scratch_;
};

}  // namespace strata::test
