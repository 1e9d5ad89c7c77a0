#include "output_files.hpp"

namespace strata::cli {

namespace fs = std::filesystem;

OutputFiles::OutputFiles(std::vector<fs::path> targets, OutputRules rules, SourceLocation option)
    : targets_(std::move(targets)), rules_(std::move(rules)), option_(std::move(option)) {
  refuse({});
}

void OutputFiles::refuse(const std::vector<fs::path>& inputs) {
  rules_.inputs.insert(rules_.inputs.end(), inputs.begin(), inputs.end());
  for (const fs::path& target : targets_)
    if (!written_.contains(target)) checkOutputTarget(target, rules_, option_);
}

ScratchDirectory& OutputFiles::scratchFor(const fs::path& target) {
  return scratch_.try_emplace(fs::absolute(target).parent_path(), target).first->second;
}

void OutputFiles::write(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  checkOutputTarget(target, rules_, option_);
  const fs::path partial = scratchFor(target).path() / target.filename();
  write(partial);
  publish(partial, target);
}

void OutputFiles::publish(const fs::path& file, const fs::path& target) {
  scratchFor(target).publish(file, target, rules_.overwrite);
  written_.insert(target);
}

}  // namespace strata::cli
