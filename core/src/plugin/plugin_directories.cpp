#include <dlfcn.h>

#include <cstdlib>
#include <sstream>

#include <strata/plugin_registry.hpp>

namespace strata {
namespace {

// The file libstrata_core was loaded from, or empty: a host application linking an installed Strata finds
// that install's plugins from it, wherever the install was moved.
std::filesystem::path coreLibraryFile() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&defaultPluginDirectories), &info) == 0 || !info.dli_fname) return {};
  std::error_code error;
  std::filesystem::path file = std::filesystem::canonical(info.dli_fname, error);
  return error ? std::filesystem::path() : file;
}

}  // namespace

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
  // The plugins lie in strata/plugins beside libstrata_core, in an install (STRATA_PLUGIN_SUBDIR) as in
  // the build tree.
  if (const std::filesystem::path core = coreLibraryFile(); !core.empty())
    directories.push_back(core.parent_path() / "strata" / "plugins");
  directories.emplace_back(STRATA_INSTALL_PLUGIN_DIR);
  return directories;
}

}  // namespace strata
