#pragma once
#include <filesystem>
#include <utility>
#include <vector>

#include <strata/host/pipeline.hpp>

namespace strata::viewer {

// Whether a pipeline's files changed on disk since they were last looked at (their modification times), so that
// the viewer loads the pipeline again, keeping the camera (Engine::reload). A file that cannot be read now (being
// rewritten) counts as unchanged and is looked at again the next time.
class PipelineWatcher {
 public:
  explicit PipelineWatcher(std::vector<std::filesystem::path> files);
  // The pipeline's own file and, in a scene of several bodies, each body's pipeline file.
  explicit PipelineWatcher(const Pipeline& pipeline);
  // Whether any changed since the last call, or since construction.
  bool changed();

 private:
  std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> files_;  // each as last seen
};

}  // namespace strata::viewer
