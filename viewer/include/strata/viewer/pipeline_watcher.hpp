#pragma once
#include <filesystem>

namespace strata::viewer {

// Whether a pipeline file changed on disk since it was last looked at (its modification time), so that the
// viewer loads it again, keeping the camera (Engine::reload). A file that cannot be read now (being
// rewritten) counts as unchanged and is looked at again the next time.
class PipelineWatcher {
 public:
  explicit PipelineWatcher(std::filesystem::path file);

  // Since the last call, or since construction.
  bool changed();

 private:
  std::filesystem::path file_;
  std::filesystem::file_time_type seen_;
};

}  // namespace strata::viewer
