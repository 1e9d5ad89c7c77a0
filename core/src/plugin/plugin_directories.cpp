#include <cstdlib>
#include <sstream>

#include <strata/plugin_registry.hpp>

namespace strata {

std::vector<std::filesystem::path> defaultPluginDirectories() {
  std::vector<std::filesystem::path> directories;
  if (const char* path = std::getenv("STRATA_PLUGIN_PATH")) {
    std::istringstream entries(path);
    std::string entry;
    while (std::getline(entries, entry, ':'))
      if (!entry.empty()) directories.emplace_back(entry);
  }
  std::error_code error;
  auto program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) directories.push_back(program.parent_path().parent_path() / STRATA_RELATIVE_PLUGIN_DIR);
  directories.emplace_back(STRATA_INSTALL_PLUGIN_DIR);
  return directories;
}

}  // namespace strata
