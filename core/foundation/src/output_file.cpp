#include <strata/host/output_file.hpp>

#include <fcntl.h>  // AT_FDCWD, for renameat2

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <string>

namespace strata {
namespace {

namespace fs = std::filesystem;

// The scratch folders alive in this process, for removeScratchDirectories. Leaked on purpose: a signal
// watcher may call it while static destructors run at exit.
struct ScratchRegistry {
  std::mutex mutex;
  std::set<fs::path> directories;
};

ScratchRegistry& scratchRegistry() {
  static auto* registry = new ScratchRegistry;
  return *registry;
}

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

void refuseInput(const fs::path& target, const OutputRules& rules, const SourceLocation& where) {
  for (const fs::path& input : rules.inputs) {
    std::error_code error;
    if (fs::equivalent(target, input, error))
      throw Error(where, quoted(target) + " is " + quoted(input) + ", a file this work reads; it is never overwritten",
                  "choose another output name");
  }
}

// The folder a target's scratch folder is made in: its own directory, created if need be.
fs::path directoryOf(const fs::path& target) {
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw Error(SourceLocation{target.string()},
                "cannot create the folder " + quoted(directory) + ": " + error.message(),
                "choose an output in a folder you can write to");
  return directory;
}

// Moves `from` onto `to` in one rename; without `replace`, an existing `to` is left alone and this throws.
void rename(const fs::path& from, const fs::path& to, bool replace) {
  const int status = replace ? std::rename(from.c_str(), to.c_str())
                             : renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE);
  if (status != 0)
    throw Error(SourceLocation{to.string()},
                "cannot move the finished file into place: " + std::string(std::strerror(errno)),
                errno == EEXIST ? "a file of that name appeared while it was written: choose another name, or pass "
                                  "--overwrite"
                                : "check that the folder is writable");
}

}  // namespace

void checkOutputTarget(const fs::path& target, const OutputRules& rules, const SourceLocation& where) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(target, error);
  if (fs::is_symlink(status))
    throw Error(where, quoted(target) + " is a symbolic link; Strata writes no file through a link",
                "give the path of the file itself, or a new name");
  if (!fs::exists(status)) return;
  if (!fs::is_regular_file(status))
    throw Error(where, quoted(target) + " exists and is not a regular file (a folder, FIFO or device)",
                "give the name of a file to write");
  refuseInput(target, rules, where);
  if (!rules.overwrite)
    throw Error(where, quoted(target) + " exists already", "choose another name, or pass --overwrite to replace it");
}

ScratchDirectory::ScratchDirectory(const fs::path& target) {
  // The target's name (cut to stay within a file name's 255 bytes), so that a folder left by a crash says
  // what it was for.
  const std::string name = "." + target.filename().string().substr(0, 200) + ".strata-XXXXXX";
  std::string pattern = (directoryOf(target) / name).string();
  if (!mkdtemp(pattern.data()))
    throw Error(
        SourceLocation{target.string()},
        "cannot write " + quoted(target) + ": no scratch folder can be made beside it (" + std::strerror(errno) + ")",
        "choose an output in a folder you can write to");
  path_ = pattern;
  const std::lock_guard lock(scratchRegistry().mutex);
  scratchRegistry().directories.insert(path_);
}

ScratchDirectory::~ScratchDirectory() {
  if (kept_) return;
  const std::lock_guard lock(scratchRegistry().mutex);
  std::error_code ignored;  // nothing to do about a folder that cannot be removed while unwinding
  fs::remove_all(path_, ignored);
  scratchRegistry().directories.erase(path_);
}

void ScratchDirectory::publish(const fs::path& file, const fs::path& target, bool replace) const {
  // GDAL's side-car first (the CRS of a GeoTIFF that cannot encode it), so that the file is whole when it
  // appears.
  const fs::path sideCar = file.string() + ".aux.xml";
  if (fs::exists(sideCar)) rename(sideCar, target.string() + ".aux.xml", replace);
  rename(file, target, replace);
}

fs::path ScratchDirectory::keep() {
  const std::lock_guard lock(scratchRegistry().mutex);
  scratchRegistry().directories.erase(path_);
  kept_ = true;
  return path_;
}

void removeScratchDirectories() noexcept {
  ScratchRegistry& registry = scratchRegistry();
  const std::lock_guard lock(registry.mutex);
  for (const fs::path& directory : registry.directories) {
    std::error_code ignored;  // the process is ending: what cannot be removed stays, under no final name
    fs::remove_all(directory, ignored);
  }
  registry.directories.clear();
}

}  // namespace strata
