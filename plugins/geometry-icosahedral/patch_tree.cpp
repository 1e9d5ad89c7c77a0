#include "patch_tree.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>

#include <strata/plugin/geometric_error.hpp>

#include "subdivision_table.hpp"

namespace strata::icosahedral {
namespace {

constexpr double kFollowingStep = 0.02;  // a frame's change of the detail scale: morphs move 6 % of their way
constexpr double kSettlingStep = 1.0;    // settle(): the scale may double or halve per round
constexpr int kSettlingRounds = 60;      // enough for the scale to cross its whole range, then close in
constexpr double kSplitMargin = 1.25;    // a patch whose error shows is split this far inside its split distance,
                                         // so that a frame's small step of the scale does not merge it again

}  // namespace

PatchTree::PatchTree(double radius, HeightRange heights, PatchTreeSettings settings, PatchHeights patchHeights)
    : radius_(radius), heights_(heights), settings_(settings), patchHeights_(std::move(patchHeights)) {}

int PatchTree::update(std::span<const ViewVolume> views, int operations) {
  views_ = views;
  const int made = refine(operations);
  if (made < operations) followError(kFollowingStep);  // the errors mean something once the tree kept up
  views_ = {};                                         // the views are the caller's: only this call may look at them
  return made;
}

// Large steps of the detail scale first; where they stop (the splits of a large step would pass `patches`),
// ever smaller ones, down to update()'s, so that a still view's updates find nothing left to do.
void PatchTree::settle(std::span<const ViewVolume> views) {
  views_ = views;
  double step = kSettlingStep;
  for (int round = 0; round < kSettlingRounds; ++round) {
    const Details before = field_.values();
    const int made = refine(std::numeric_limits<int>::max());
    followError(step);
    if (made > 0 || field_.values() != before) continue;
    if (step == kFollowingStep) break;
    step = std::max(step / 4.0, kFollowingStep);
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
    fillDetails(id, patches.back());
  };
  for (std::int32_t face = 0; face < PatchTopology::kFaces; ++face) visit(face);
  return patches;
}

double PatchTree::splitDistanceUnit() const { return radius_ * kFaceEdgeAngle; }

double PatchTree::splitDistanceOf(const Patch& patch) const {
  const int held = verticesPerPatch(std::max(DetailField::kLevel - patch.level, 0));
  return std::ldexp(splitDistanceUnit() * *std::max_element(patch.details.begin(), patch.details.begin() + held),
                    -patch.level);
}

double PatchTree::splitDistance(std::int32_t id, const Details& details) const {
  return std::ldexp(splitDistanceUnit() * detailOver(id, details), -topology_[id].level);
}

// The largest detail scale over a patch: the field is linear in the lattice's triangles, so at its corners where it
// lies within one, else at the lattice's vertices within it.
double PatchTree::detailOver(std::int32_t id, const Details& details) const {
  const PatchNode& node = topology_[id];
  double largest = 0.0;
  if (node.level < DetailField::kLevel) {
    for (const int v : field_.gridOf(topology_.cornersOf(id), node.level))
      largest = std::max(largest, details[std::size_t(v)]);
    return largest;
  }
  std::unordered_map<std::uint32_t, float> known;
  for (const std::uint32_t corner : node.corners) largest = std::max(largest, double(detailAt(corner, details, known)));
  return largest;
}

// The detail scale at a vertex of the tree, as the compute pass finds it: the lattice's value at a vertex of its
// levels, else the float mean of its parents' (`known`: those found so far).
float PatchTree::detailAt(std::uint32_t vertex, const Details& details,
                          std::unordered_map<std::uint32_t, float>& known) const {
  if (topology_.levelOf(vertex) <= DetailField::kLevel)
    return float(details[std::size_t(field_.vertexAt(topology_.normalOf(vertex)))]);
  if (const auto found = known.find(vertex); found != known.end()) return found->second;
  const auto [a, b] = topology_.parentsOf(vertex);
  const float detail = 0.5f * (detailAt(a, details, known) + detailAt(b, details, known));
  known.emplace(vertex, detail);
  return detail;
}

void PatchTree::fillDetails(std::int32_t id, Patch& patch) const {
  const PatchNode& node = topology_[id];
  if (node.level < DetailField::kLevel) {
    const std::vector<int>& grid = field_.gridOf(patch.corners, node.level);
    for (std::size_t i = 0; i < grid.size(); ++i) patch.details[i] = float(field_.values()[std::size_t(grid[i])]);
    return;
  }
  std::unordered_map<std::uint32_t, float> known;
  for (std::size_t c = 0; c < 3; ++c) patch.details[c] = detailAt(node.corners[c], field_.values(), known);
}

// The shell and, the first time, the terrain's error over the patch's cap, its spacings in the same measure: the
// relief a spacing may hide (reliefWithinSpacing), which stays the patch's while its heights do.
PatchShell PatchTree::shellOf(std::int32_t id) {
  const SphericalTriangle corners = topology_.cornersOf(id);
  if (!topology_[id].heights) {
    const RegionalHeights heights = heightsOf(id, corners);
    const double width = 2.0 * capAround(corners).angle;
    topology_[id].heights = heights.range;
    topology_[id].terrainError = reliefWithinSpacing(heights.range.highest - heights.range.lowest, heights.finest,
                                                     width, std::ldexp(width, -settings_.depth));
  }
  return {corners, radius_ + topology_[id].heights->lowest, radius_ + topology_[id].heights->highest};
}

// A patch's heights within its parent's: what a child samples lies within what its parent samples, so both
// bound the child's terrain, and nested shells keep a split patch's children no nearer than itself can be (bounds
// such as source.procedural's, from the value at each cap's centre, need not nest by themselves).
RegionalHeights PatchTree::heightsOf(std::int32_t id, const SphericalTriangle& corners) {
  if (!patchHeights_) return {heights_};
  const auto [own, finest] = patchHeights_(corners);
  const std::int32_t parent = topology_[id].parent;
  if (parent < 0) return {own, finest};
  const PatchShell outer = shellOf(parent);
  const HeightRange nested{std::max(own.lowest, outer.innerRadius - radius_),
                           std::min(own.highest, outer.outerRadius - radius_)};
  return {nested.lowest <= nested.highest ? nested : own, finest};
}

// A shell is seen by a view when it rises above the view's horizon and reaches into its frustum. Its
// distance is the least face-on distance of any point of the shell, which bounds from below that of every
// vertex the compute pass displaces into it: so a split brings its vertices in at their parents' midpoints.
// Without each patch's heights, both measure on the sphere (measured()): an eye inside the whole terrain's range
// would lie at no distance from every shell near it, and the tree would split beneath it to the deepest level.
std::optional<double> PatchTree::viewedDistance(const PatchShell& shell) const {
  std::optional<double> distance;
  for (const ViewVolume& view : views_)
    if (sees(view, shell))
      distance = std::min(distance.value_or(std::numeric_limits<double>::infinity()),
                          leastFaceOnDistance(measured(shell), view.eye()));
  return distance;
}

// The least distance of the shell from an eye that sees it, m (infinite where none does): where its error shows
// most, since the errors are heights' and the sphere's chords', radial, and show in full where the ground is seen
// edge on, which the face-on distance discounts up to four times (a mountain's top 150 km away stood three pixels
// low where the pixel error was one).
double PatchTree::nearestSeen(const PatchShell& shell) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (const ViewVolume& view : views_)
    if (sees(view, shell)) nearest = std::min(nearest, leastDistance(measured(shell), view.eye()));
  return nearest;
}

bool PatchTree::sees(const ViewVolume& view, const PatchShell& shell) const {
  return !belowHorizon(shell, view.eye(), radius_ + heights_.lowest) && view.mayHold(shell);
}

PatchShell PatchTree::measured(const PatchShell& shell) const {
  return measuresOnTerrain() ? shell : PatchShell{shell.corners, radius_, radius_};
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
  return node.level < kDeepestLevel && distance < splitDistance(id);
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
      near.emplace_back(node.distance / splitDistance(id), id);
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

// Moves the detail field toward the one the pixel error asks for by at most the factor 1 + largestStep at each
// lattice vertex. Over `patches` visible patches it shrinks everywhere instead (the count grows about as the
// square of the scale, each level's ring of patches does, hence the square root); it grows only while the splits
// that would bring keep within `patches`: seen from afar, a whole level splits at once, and the count would swing
// across the cap. Each step (a common factor, clamps, the least of two fields) keeps neighbouring values within
// DetailField::kNeighbourRatio, as the asked field and the field before are.
void PatchTree::followError(double largestStep) {
  const double count = std::max(visibleCount_, 1);
  Details next = field_.values();
  if (count > settings_.patches) {
    const double shrink = std::max(std::sqrt(settings_.patches / count), 1.0 / (1.0 + largestStep));
    for (double& value : next) value = std::max(value * shrink, kLeastDetail);
    field_.assign(std::move(next));
    return;
  }
  const Details wanted = wantedDetail();
  bool grows = false;
  for (std::size_t v = 0; v < next.size(); ++v) {
    next[v] = std::clamp(wanted[v], next[v] / (1.0 + largestStep), next[v] * (1.0 + largestStep));
    grows = grows || next[v] > field_.values()[v];
  }
  if (grows && visibleCount_ + 3 * splitsAt(next) > settings_.patches)
    for (std::size_t v = 0; v < next.size(); ++v) next[v] = std::min(next[v], field_.values()[v]);
  for (double& value : next) value = std::clamp(value, kLeastDetail, kMostDetail);
  field_.assign(std::move(next));
}

// The least detail field at which every visible patch whose error would show more than the pixel error is
// split, each asking at the lattice vertices that decide its split distance (latticeVerticesOf), the field then
// smoothed (DetailField::smoothed): the visible leaves and every split patch seen. A split patch's children may be
// split only by the scale it asks for, so leaving it out once they were would let the scale fall and merge them, and
// take it back up: the tree swung by a split a frame. Its error seen from the patch, ε·ppr/d, is the screen-space error
// of [Cignoni et al. 2003, §4.3] (errorShows); the detail it asks for, the face-on distance the split measures.
PatchTree::Details PatchTree::wantedDetail() {
  const double finest = pixelsPerRadian();
  Details wanted(std::size_t(field_.vertexCount()), kLeastDetail);
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id) {
    const PatchNode& node = topology_[id];
    if (!node.alive || node.level >= kDeepestLevel) continue;
    std::optional<double> distance;
    if (node.leaf() && node.visible)
      distance = node.distance;
    else if (!node.leaf())
      distance = viewedDistance(shellOf(id));
    if (!distance || !errorShows(id, *distance, finest)) continue;
    const double asked = std::min(kSplitMargin * std::ldexp(*distance / splitDistanceUnit(), node.level), kMostDetail);
    for (const int v : latticeVerticesOf(id)) wanted[std::size_t(v)] = std::max(wanted[std::size_t(v)], asked);
  }
  return field_.smoothed(std::move(wanted));
}

// The lattice vertices whose values decide a patch's largest detail scale: those within it, or where it lies within
// a triangle of the lattice, that triangle's corners.
const std::vector<int>& PatchTree::latticeVerticesOf(std::int32_t id) const {
  std::int32_t within = id;
  while (topology_[within].level > DetailField::kLevel) within = topology_[within].parent;
  return field_.gridOf(topology_.cornersOf(within), topology_[within].level);
}

// Whether the patch's error shows more than the pixel error: the whole of it seen from the face-on distance
// (`faceOn`), and its radial part, the terrain's and the chords' sagitta, from the least distance (nearestSeen),
// where it shows in full seen edge on. `pixelsPerRadian`: the views' finest.
bool PatchTree::errorShows(std::int32_t id, double faceOn, double pixelsPerRadian) {
  const double radial = std::max(chordSagitta(radius_, spacingOf(id)), topology_[id].terrainError);
  return errorOf(id) * pixelsPerRadian > settings_.pixelError * faceOn ||
         radial * pixelsPerRadian > settings_.pixelError * nearestSeen(shellOf(id));
}

// The views' finest angular resolution.
double PatchTree::pixelsPerRadian() const {
  double finest = 0.0;
  for (const ViewVolume& view : views_) finest = std::max(finest, view.pixelsPerRadian());
  return finest;
}

// The sphere's error: the chords' (chordError), from the patch's point nearest a pole. The terrain's: shellOf's. It
// shrinks as the patch does on smooth terrain and stays large on rough, and keeps the vertices, whose normals shade
// the relief, within a pixel or two of each other where relief shows.
double PatchTree::errorOf(std::int32_t id) {
  const PatchShell shell = shellOf(id);
  const double patchAngle = std::ldexp(kFaceEdgeAngle, -topology_[id].level);
  const double spacing = spacingOf(id);
  double fromPole = std::numbers::pi;
  for (const glm::dvec3& corner : shell.corners)
    fromPole = std::min(fromPole, std::acos(std::min(std::abs(corner.z), 1.0)));
  return std::max(chordError(radius_, spacing, fromPole - patchAngle), topology_[id].terrainError);
}

double PatchTree::spacingOf(std::int32_t id) const {
  return std::ldexp(kFaceEdgeAngle, -topology_[id].level - settings_.depth);
}

// The visible leaves that would split were the detail field `details`.
int PatchTree::splitsAt(const Details& details) const {
  int splits = 0;
  for (std::int32_t id = 0; id < std::int32_t(topology_.capacity()); ++id) {
    const PatchNode& node = topology_[id];
    splits += int(node.alive && node.leaf() && node.visible && node.level < kDeepestLevel &&
                  node.distance < splitDistance(id, details));
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
