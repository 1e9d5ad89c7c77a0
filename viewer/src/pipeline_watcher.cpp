#include <strata/viewer/pipeline_watcher.hpp>

#include <system_error>

namespace strata::viewer {
namespace {

std::vector<std::filesystem::path> filesOf(const Pipeline& pipeline) {
  std::vector<std::filesystem::path> files{pipeline.file};
  for (const SceneBody& body : pipeline.bodies) files.push_back(body.pipeline.file);
  return files;
}

}  // namespace

PipelineWatcher::PipelineWatcher(std::vector<std::filesystem::path> files) {
  for (std::filesystem::path& file : files) {
    std::error_code error;
    const auto seen = std::filesystem::last_write_time(file, error);
    files_.emplace_back(std::move(file), seen);
  }
}

PipelineWatcher::PipelineWatcher(const Pipeline& pipeline) : PipelineWatcher(filesOf(pipeline)) {}

bool PipelineWatcher::changed() {
  bool any = false;
  for (auto& [file, seen] : files_) {
    std::error_code error;
    const auto now = std::filesystem::last_write_time(file, error);
    if (error || now == seen) continue;
    seen = now;
    any = true;
  }
  return any;
}

}  // namespace strata::viewer
