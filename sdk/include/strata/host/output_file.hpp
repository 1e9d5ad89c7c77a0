#pragma once
// The files Strata writes for its user (frames, videos, tables, plots, pyramids): nothing the user has is
// replaced without asking, no file the work reads is replaced whatever is asked, no file is written through
// a link, and nothing unfinished ever carries the final name (docs/robustness.md, "Outputs").
#include <filesystem>
#include <strata/export.hpp>
#include <vector>

#include <strata/error.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// What may become of an output's target.
struct OutputRules {
  bool overwrite = false;  // an existing regular file may be replaced (--overwrite)
  // Files the work reads (the pipeline, its rasters, a camera path): never replaced, whatever `overwrite`
  // says. Compared by identity (device and inode), not by spelling.
  std::vector<std::filesystem::path> inputs;
};

// Throws strata::Error at `where`, naming `target` and what to do, when `target` may not be written under
// `rules`: it is a symbolic link (dangling or not), exists as something other than a regular file, exists
// and `rules.overwrite` is false, or is the same file as one of `rules.inputs`.
void checkOutputTarget(const std::filesystem::path& target, const OutputRules& rules, const SourceLocation& where);

// A fresh folder beside an output (.NAME.strata-XXXXXX in the target's directory, so that a rename out of it
// is atomic) where the work in progress is written, and removed with all it holds when this is destroyed or
// when the process is interrupted (removeScratchDirectories). Nothing in it is ever under a final name.
class ScratchDirectory {
 public:
  // Creates the target's directory if need be; throws strata::Error naming `target` if it cannot.
  explicit ScratchDirectory(const std::filesystem::path& target);
  ~ScratchDirectory();
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Moves the finished, closed `file` (inside this folder) onto `target` in one rename, and GDAL's side-car
  // `file`.aux.xml, if there is one, onto `target`.aux.xml before it. Without `replace`, an existing target
  // (one that appeared since it was checked) is left alone and this throws.
  void publish(const std::filesystem::path& file, const std::filesystem::path& target, bool replace) const;
  // Leaves the folder and what it holds for the user (the frames of a video ffmpeg could not encode, say)
  // and returns its path; it is no longer removed.
  std::filesystem::path keep();

 private:
  std::filesystem::path path_;
  bool kept_ = false;
};

// Removes every ScratchDirectory still alive, and what it holds; for a signal watcher just before the
// process ends on SIGINT, SIGTERM or SIGHUP. Safe to call from any thread, at any time.
void removeScratchDirectories() noexcept;

}  // namespace strata
STRATA_EXPORTS_END
