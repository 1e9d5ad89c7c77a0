#include <strata/viewer/pipeline_watcher.hpp>

#include <system_error>
#include <utility>

namespace strata::viewer {

PipelineWatcher::PipelineWatcher(std::filesystem::path file) : file_(std::move(file)) {
  std::error_code error;
  seen_ = std::filesystem::last_write_time(file_, error);
}

bool PipelineWatcher::changed() {
  std::error_code error;
  const auto now = std::filesystem::last_write_time(file_, error);
  if (error || now == seen_) return false;
  seen_ = now;
  return true;
}

}  // namespace strata::viewer
