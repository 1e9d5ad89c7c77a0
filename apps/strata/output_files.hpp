#pragma once
// Where a command writes (render's frames and videos, bench's tables and plots): every file it will write
// checked before any work, and each written under a scratch name and renamed into place when whole
// (strata/host/output_file.hpp).
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include <strata/host/output_file.hpp>

namespace strata::cli {

class OutputFiles {
 public:
  // `targets`: every file the command will write. Each is checked now against `rules`; throws
  // strata::Error at `option` (-o, --plot) naming the file and what to do.
  OutputFiles(std::vector<std::filesystem::path> targets, OutputRules rules, SourceLocation option);

  // Checks the targets not yet written again, now also against `inputs` (a loaded pipeline's files).
  void refuse(const std::vector<std::filesystem::path>& inputs);
  // Writes `target` through `write`, which is given a file in the scratch folder to write, then renames
  // that into place. `target` is checked once more first: a file may have appeared since.
  void write(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write);
  // Moves a finished file of `target`'s scratch folder onto `target`.
  void publish(const std::filesystem::path& file, const std::filesystem::path& target);
  // The scratch folder beside `target` (in its directory, so that the rename is atomic), made when first
  // asked for.
  ScratchDirectory& scratchFor(const std::filesystem::path& target);

 private:
  std::vector<std::filesystem::path> targets_;
  std::set<std::filesystem::path> written_;  // by this command: its own, no longer checked
  OutputRules rules_;
  SourceLocation option_;
  std::map<std::filesystem::path, ScratchDirectory> scratch_;  // by the targets' directories
};

}  // namespace strata::cli
