#include "strata_command.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace strata::test {
namespace {

// Single quotes for /bin/sh; a quote inside is closed, escaped and reopened.
std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> namesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

CommandResult StrataCommandTest::run(const std::vector<std::string>& arguments, const std::string& pluginPath) const {
  const std::filesystem::path out = scratch_.path() / "stdout.txt", err = scratch_.path() / "stderr.txt";
  const std::string environment =
      pluginPath.empty() ? "-u STRATA_PLUGIN_PATH" : "STRATA_PLUGIN_PATH=" + shellQuoted(pluginPath);
  std::string command =
      "cd " + shellQuoted(STRATA_SOURCE_DIR) + " && env " + environment + " " + shellQuoted(STRATA_EXECUTABLE);
  for (const std::string& argument : arguments) command += " " + shellQuoted(argument);
  command += " >" + shellQuoted(out.string()) + " 2>" + shellQuoted(err.string());
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readText(out), readText(err)};
}

CommandResult StrataCommandTest::renderTiny(const std::filesystem::path& pipeline,
                                            const std::string& pluginPath) const {
  return run({"render", pipeline.string(), "--size", "32x18", "-o", file("x.png").string(), "--overwrite"}, pluginPath);
}

}  // namespace strata::test
