#include "patch_tree.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>

namespace strata::icosahedral {

PatchTree::PatchTree(double radius, HeightRange heights, PatchTreeSettings settings)
    : radius_(radius), heights_(heights), settings_(settings) {}

int PatchTree::update(std::span<const ViewVolume> views, int operations) {
  views_ = views;
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id)
    if (topology_[id].alive && topology_[id].leaf()) classify(id);
  int made = 0;
  while (made < operations && improve()) ++made;
  views_ = {};  // the views are the caller's: only this call may look at them
  return made;
}

std::vector<Patch> PatchTree::visiblePatches() const {
  std::vector<Patch> patches;
  const std::function<void(std::int32_t)> visit = [&](std::int32_t id) {
    const PatchNode& node = topology_[id];
    if (!node.leaf()) {
      for (const std::int32_t child : node.children) visit(child);
      return;
    }
    if (!node.visible) return;
    unsigned coarse = 0;
    for (int e = 0; e < 3; ++e)
      if (topology_.across(id, e) < 0) coarse |= 1u << e;
    patches.push_back({topology_.cornersOf(id), node.level, coarse, node.solidAngle});
  };
  for (std::int32_t face = 0; face < PatchTopology::kFaces; ++face) visit(face);
  return patches;
}

PatchShell PatchTree::shellOf(std::int32_t id) const {
  return {topology_.cornersOf(id), radius_ + heights_.lowest, radius_ + heights_.highest};
}

// A shell is seen by a view when it rises above the view's horizon and reaches into its frustum. The
// solid angle is measured on the datum sphere (the body's radius, moved into the height range if it lies
// outside): heights vary within a patch, and per-patch height ranges would place it better.
std::optional<double> PatchTree::viewedAngle(const PatchShell& shell) const {
  const double occluder = radius_ + heights_.lowest;
  const double datum = radius_ + std::clamp(0.0, heights_.lowest, heights_.highest);
  std::optional<double> angle;
  for (const ViewVolume& view : views_)
    if (!belowHorizon(shell, view.eye(), occluder) && view.mayHold(shell))
      angle = std::max(angle.value_or(0.0), solidAngle(shell.corners, datum, view.eye()));
  return angle;
}

void PatchTree::classify(std::int32_t id) {
  const std::optional<double> angle = viewedAngle(shellOf(id));
  PatchNode& node = topology_[id];
  visibleCount_ += int(angle.has_value()) - int(node.visible);
  node.visible = angle.has_value();
  node.solidAngle = angle.value_or(0.0);
}

// One step toward `patches` visible patches of equal solid angle; false when none would help.
bool PatchTree::improve() {
  if (const std::int32_t hidden = smallestFamily(true); hidden >= 0) {
    merge(hidden);  // out of every view: folded back, so that the tree follows the view
    return true;
  }
  if (visibleCount_ > settings_.patches) {
    const std::int32_t family = smallestFamily(false);
    if (family >= 0) merge(family);
    return family >= 0;
  }
  const std::int32_t largest = largestLeaf();
  if (largest < 0) return false;
  if (visibleCount_ + 3 <= settings_.patches) {
    splitKeepingOneLevel(largest);
    return true;
  }
  // Full: trade the smallest family for the largest patch where that evens their sizes out. Halving
  // the largest's angle is the margin that keeps a trade from being undone by the next one.
  const std::int32_t family = smallestFamily(false);
  if (family < 0 || family == topology_[largest].parent ||
      familyAngle(family) >= 0.5 * topology_[largest].solidAngle)
    return false;
  merge(family);
  splitKeepingOneLevel(largest);
  return true;
}

void PatchTree::splitKeepingOneLevel(std::int32_t leaf) {
  for (int e = 0; e < 3; ++e)
    if (topology_.across(leaf, e) < 0)
      if (const std::int32_t coarser = topology_.coarserNeighbour(leaf, e); coarser >= 0)
        splitKeepingOneLevel(coarser);
  PatchNode& node = topology_[leaf];
  visibleCount_ -= int(node.visible);
  node.visible = false;
  topology_.split(leaf);
  for (const std::int32_t child : topology_[leaf].children) classify(child);
}

// Four leaf siblings can fold into their parent unless a neighbour of theirs outside the family is
// split: its children would then lie two levels below the parent.
bool PatchTree::mergeable(std::int32_t parent) const {
  const PatchNode& node = topology_[parent];
  if (!node.alive || node.leaf()) return false;
  for (const std::int32_t child : node.children) {
    if (!topology_[child].leaf()) return false;
    for (int e = 0; e < 3; ++e) {
      const std::int32_t neighbour = topology_.across(child, e);
      if (neighbour >= 0 && topology_[neighbour].parent != parent && !topology_[neighbour].leaf()) return false;
    }
  }
  return true;
}

void PatchTree::merge(std::int32_t parent) {
  for (const std::int32_t child : topology_[parent].children) visibleCount_ -= int(topology_[child].visible);
  topology_.merge(parent);
  topology_[parent].visible = false;
  classify(parent);
}

double PatchTree::familyAngle(std::int32_t parent) const {
  double sum = 0.0;
  for (const std::int32_t child : topology_[parent].children) sum += topology_[child].solidAngle;
  return sum;
}

std::int32_t PatchTree::largestLeaf() const {
  std::int32_t largest = -1;
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id) {
    const PatchNode& node = topology_[id];
    if (node.alive && node.leaf() && node.visible && node.level < kDeepestLevel &&
        (largest < 0 || node.solidAngle > topology_[largest].solidAngle))
      largest = id;
  }
  return largest;
}

// The mergeable family of least solid angle: among families out of every view when `hiddenOnly`
// (their parent's shell too), else among families whose four patches are all visible.
std::int32_t PatchTree::smallestFamily(bool hiddenOnly) const {
  std::int32_t smallest = -1;
  double smallestAngle = std::numeric_limits<double>::infinity();
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id) {
    if (!mergeable(id)) continue;
    const auto& children = topology_[id].children;
    const int visible = int(std::ranges::count_if(children, [&](std::int32_t c) { return topology_[c].visible; }));
    if (hiddenOnly ? visible > 0 || viewedAngle(shellOf(id)) : visible < 4) continue;
    const double angle = familyAngle(id);
    if (angle < smallestAngle) smallest = id, smallestAngle = angle;
  }
  return smallest;
}

}  // namespace strata::icosahedral
