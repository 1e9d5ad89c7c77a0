#include "patch_loader.hpp"

#include <utility>

#include <strata/log.hpp>

namespace strata::bdam {
namespace {

std::tuple<int, int, std::uint64_t> keyOf(const BintreeNode& node) { return {node.root, node.level, node.path}; }

}  // namespace

PatchLoader::PatchLoader(const BdamData& data, std::size_t slots)
    : data_(data), slots_(slots), indices_(slots, 0), vertices_(slots, 0) {}

bool PatchLoader::resident(const BintreeNode& node) const { return slots_.slotOf(node).has_value(); }

void PatchLoader::load(const std::vector<BintreeNode>& nodes, std::size_t budget, std::uint64_t frame) {
  for (const BintreeNode& node : nodes) {
    if (budget == 0) return;
    if (resident(node) || failed_.contains(keyOf(node))) continue;
    DisplacedPatch patch;
    try {
      patch = data_.faceOf(node).patch(node);
    } catch (const FaceFileError& error) {
      failed_.insert(keyOf(node));
      logWarning(std::string(error.what()) + "; the coarser patch above it is drawn instead",
                 "build the folder again with `strata build-bdam`");
      continue;
    }
    const std::optional<std::size_t> slot = slots_.take(node, frame);
    if (!slot) return;  // every slot holds a patch of this frame: the rest wait
    indices_[*slot] = std::uint32_t(patch.indices.size());
    vertices_[*slot] = std::uint32_t(patch.vertices.size());
    pending_.push_back({*slot, std::move(patch)});
    ++loaded_;
    --budget;
  }
}

std::pair<std::size_t, std::uint32_t> PatchLoader::drawn(const BintreeNode& node, std::uint64_t frame) {
  slots_.touch(node, frame);
  const std::size_t slot = *slots_.slotOf(node);
  return {slot, indices_[slot]};
}

std::uint64_t PatchLoader::vertices(const BintreeNode& node) const { return vertices_[*slots_.slotOf(node)]; }

std::vector<PendingPatch> PatchLoader::takePending() { return std::exchange(pending_, {}); }

void PatchLoader::prefetch(const std::vector<BintreeNode>& nodes) const {
  for (const BintreeNode& node : nodes)
    if (!resident(node) && !failed_.contains(keyOf(node))) try {
        data_.faceOf(node).prefetch(node);
      } catch (const FaceFileError&) {  // reported when it is loaded
      }
}

}  // namespace strata::bdam
