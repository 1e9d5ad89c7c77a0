#include <dlfcn.h>

#include <cstdlib>
#include <sstream>

#include <strata/plugin/plugin_registry.hpp>

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

// Adds `directory` unless it is one already listed under another spelling (an installed strata's program
// and its libstrata_core name the same <prefix>/lib/strata/plugins), so that no module loads twice.
void addDirectory(std::vector<std::filesystem::path>& directories, const std::filesystem::path& directory) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(directory, error);
  for (const std::filesystem::path& listed : directories) {
    std::error_code listedError;
    if (!error && std::filesystem::weakly_canonical(listed, listedError) == canonical && !listedError) return;
  }
  directories.push_back(directory);
}

}  // namespace

std::vector<std::filesystem::path> defaultPluginDirectories() {
  std::vector<std::filesystem::path> directories;
  if (const char* path = std::getenv("STRATA_PLUGIN_PATH")) {
    std::istringstream entries(path);
    std::string entry;
    while (std::getline(entries, entry, ':'))
      if (!entry.empty()) addDirectory(directories, entry);
  }
  std::error_code error;
  auto program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) addDirectory(directories, program.parent_path().parent_path() / STRATA_RELATIVE_PLUGIN_DIR);
  // The plugins lie in strata/plugins beside libstrata_core, in an install (STRATA_PLUGIN_SUBDIR) as in
  // the build tree.
  if (const std::filesystem::path core = coreLibraryFile(); !core.empty())
    addDirectory(directories, core.parent_path() / "strata" / "plugins");
  addDirectory(directories, STRATA_INSTALL_PLUGIN_DIR);
  return directories;
}

}  // namespace strata
