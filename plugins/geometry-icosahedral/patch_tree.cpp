#include "patch_tree.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>

namespace strata::icosahedral {
namespace {

constexpr double kFollowingStep = 0.02;  // a frame's change of the detail scale: morphs move 6 % of their way
constexpr double kSettlingStep = 1.0;    // settle(): the scale may double or halve per round
constexpr int kSettlingRounds = 40;      // enough for the scale to cross its whole range and settle
constexpr double kRestingShare = 0.8;    // the count may fall to this share of `patches` before the scale grows

}  // namespace

PatchTree::PatchTree(double radius, HeightRange heights, PatchTreeSettings settings, PatchHeights patchHeights)
    : radius_(radius), heights_(heights), settings_(settings), patchHeights_(std::move(patchHeights)) {}

int PatchTree::update(std::span<const ViewVolume> views, int operations) {
  views_ = views;
  const int made = refine(operations);
  if (made < operations) followCount(kFollowingStep);  // the count means something once the tree kept up
  views_ = {};                                         // the views are the caller's: only this call may look at them
  return made;
}

void PatchTree::settle(std::span<const ViewVolume> views) {
  views_ = views;
  for (int round = 0; round < kSettlingRounds; ++round) {
    const double before = detail_;
    const int made = refine(std::numeric_limits<int>::max());
    followCount(kSettlingStep);
    if (made == 0 && detail_ == before) break;
  }
  views_ = {};
}

// Reclassifies the leaves, then merges and splits until the tree is what the detail scale asks for, or
// `operations` were made; returns how many were.
int PatchTree::refine(int operations) {
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id)
    if (topology_[id].alive && topology_[id].leaf()) classify(id);
  int made = 0;
  while (made < operations) {
    const int merged = mergeFar(operations - made);
    const int split = splitNear(operations - made - merged);
    if (merged + split == 0) break;
    made += merged + split;
  }
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
    patches.push_back({topology_.cornersOf(id), node.level, coarse});
  };
  for (std::int32_t face = 0; face < PatchTopology::kFaces; ++face) visit(face);
  return patches;
}

double PatchTree::splitDistance(int level) const { return splitDistance(level, detail_); }

double PatchTree::splitDistance(int level, double detail) const {
  return std::ldexp(detail * radius_ * kFaceEdgeAngle, -level);
}

PatchShell PatchTree::shellOf(std::int32_t id) {
  const SphericalTriangle corners = topology_.cornersOf(id);
  if (!topology_[id].heights) topology_[id].heights = heightsOf(id, corners);
  return {corners, radius_ + topology_[id].heights->lowest, radius_ + topology_[id].heights->highest};
}

// A patch's heights within its parent's: what a child samples lies within what its parent samples, so both
// bound the child's terrain, and nested shells keep a split patch's children no nearer than itself can be (bounds
// such as source.procedural's, from the value at each cap's centre, need not nest by themselves).
HeightRange PatchTree::heightsOf(std::int32_t id, const SphericalTriangle& corners) {
  if (!patchHeights_) return heights_;
  const HeightRange own = patchHeights_(corners);
  const std::int32_t parent = topology_[id].parent;
  if (parent < 0) return own;
  const PatchShell outer = shellOf(parent);
  const HeightRange nested{std::max(own.lowest, outer.innerRadius - radius_),
                           std::min(own.highest, outer.outerRadius - radius_)};
  return nested.lowest <= nested.highest ? nested : own;
}

// A shell is seen by a view when it rises above the view's horizon and reaches into its frustum. Its
// distance is the least face-on distance of any point of the shell, which bounds from below that of every
// vertex the compute pass displaces into it: so a split brings its vertices in at their parents' midpoints.
// Without each patch's heights, both measure on the sphere: an eye inside the whole terrain's range would
// lie at no distance from every shell near it, and the tree would split beneath it to the deepest level.
std::optional<double> PatchTree::viewedDistance(const PatchShell& shell) const {
  const double occluder = radius_ + heights_.lowest;
  std::optional<double> distance;
  for (const ViewVolume& view : views_)
    if (!belowHorizon(shell, view.eye(), occluder) && view.mayHold(shell))
      distance = std::min(
          distance.value_or(std::numeric_limits<double>::infinity()),
          leastFaceOnDistance(measuresOnTerrain() ? shell : PatchShell{shell.corners, radius_, radius_}, view.eye()));
  return distance;
}

void PatchTree::classify(std::int32_t id) {
  const std::optional<double> distance = viewedDistance(shellOf(id));
  PatchNode& node = topology_[id];
  visibleCount_ += int(distance.has_value()) - int(node.visible);
  node.visible = distance.has_value();
  node.distance = distance.value_or(std::numeric_limits<double>::infinity());
}

bool PatchTree::wantsSplit(std::int32_t id, double distance) const {
  const PatchNode& node = topology_[id];
  return node.level < kDeepestLevel && distance < splitDistance(node.level);
}

// Folds every family whose parent would not be split (out of every view, or far enough); returns the
// merges made, at most `operations`.
int PatchTree::mergeFar(int operations) {
  int made = 0;
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()) && made < operations; ++id) {
    if (!mergeable(id)) continue;
    const std::optional<double> distance = viewedDistance(shellOf(id));
    if (distance && wantsSplit(id, *distance)) continue;
    merge(id);
    ++made;
  }
  return made;
}

// Splits the visible leaves nearer than their split distance, the nearest (in split distances) first;
// returns the splits made, at most `operations`.
int PatchTree::splitNear(int operations) {
  std::vector<std::pair<double, std::int32_t>> near;
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id) {
    const PatchNode& node = topology_[id];
    if (node.alive && node.leaf() && node.visible && wantsSplit(id, node.distance))
      near.emplace_back(node.distance / splitDistance(node.level), id);
  }
  std::ranges::sort(near);
  int made = 0;
  for (const auto& [ratio, id] : near) {
    if (made == operations) break;
    if (!topology_[id].alive || !topology_[id].leaf()) continue;  // split already, to keep one level
    splitKeepingOneLevel(id);
    ++made;
  }
  return made;
}

// Moves the detail scale toward `patches` visible patches by at most the factor 1 + largestStep. The count
// grows about as the square of the scale (each level's ring of patches does), hence the square root. Over
// `patches` it shrinks; under kRestingShare of them it grows, unless the splits that would bring would
// pass `patches`: seen from afar, a whole level splits at once, and the count would swing between a
// quarter and four times the aim.
void PatchTree::followCount(double largestStep) {
  const double count = std::max(visibleCount_, 1);
  if (count > settings_.patches)
    detail_ *= std::max(std::sqrt(settings_.patches / count), 1.0 / (1.0 + largestStep));
  else if (count < kRestingShare * settings_.patches) {
    const double grown = detail_ * std::min(std::sqrt(settings_.patches / count), 1.0 + largestStep);
    if (visibleCount_ + 3 * splitsAt(grown) <= settings_.patches) detail_ = grown;
  }
  detail_ = std::clamp(detail_, kLeastDetail, kMostDetail);
}

// The visible leaves that would split at the detail scale `detail`.
int PatchTree::splitsAt(double detail) const {
  int splits = 0;
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id) {
    const PatchNode& node = topology_[id];
    splits += int(node.alive && node.leaf() && node.visible && node.level < kDeepestLevel &&
                  node.distance < splitDistance(node.level, detail));
  }
  return splits;
}

void PatchTree::splitKeepingOneLevel(std::int32_t leaf) {
  for (int e = 0; e < 3; ++e)
    if (topology_.across(leaf, e) < 0)
      if (const std::int32_t coarser = topology_.coarserNeighbour(leaf, e); coarser >= 0) splitKeepingOneLevel(coarser);
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

}  // namespace strata::icosahedral
