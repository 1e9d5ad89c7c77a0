#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "patch_topology.hpp"
#include "view_volume.hpp"

namespace strata::icosahedral {

// Heights of the terrain, m above the body's radius, that the patches' shells must enclose.
struct HeightRange {
  double lowest = 0.0;
  double highest = 0.0;
};

struct PatchTreeSettings {
  int patches = 300;            // visible patches to keep: seed 000 section 2.4.1 sets np to about 300
  int operationsPerFrame = 64;  // splits and merges one frame may make: bounds the CPU's share of it
};

// A visible leaf, as the geometry generation takes it (seed 000 section 3.2.4).
struct Patch {
  SphericalTriangle corners;
  int level = 0;             // splits from the icosahedron's face
  unsigned coarseEdges = 0;  // bit e: the neighbour across the edge from corner e to corner e + 1 is coarser
  double solidAngle = 0.0;   // sr, the largest any view sees
};

// The frame-coherent patch tree of seed 000 section 3.2.1, computed once for all views: the faces of
// the icosahedron split 1-to-4, kept near `patches` visible patches of about equal solid angle by
// splitting the largest and merging the smallest four siblings. A patch is visible when its shell
// (section 3.2.3) rises above the horizon and reaches into a view's frustum. Neighbouring leaves differ
// by at most one level (section 3.4.1): a split first splits coarser neighbours, and a merge that would
// break the rule is not made (digest 000 section 2.1).
class PatchTree {
 public:
  PatchTree(double radius, HeightRange heights, PatchTreeSettings settings = {});

  // Reclassifies the leaves for the views, then splits or merges at most `operations` times; returns
  // how many it made.
  int update(std::span<const ViewVolume> views, int operations);
  int update(std::span<const ViewVolume> views) { return update(views, settings_.operationsPerFrame); }

  // The visible leaves, depth first from the icosahedron's faces.
  std::vector<Patch> visiblePatches() const;
  int visibleCount() const { return visibleCount_; }
  const PatchTopology& topology() const { return topology_; }

  // Splits below this level would make patches narrower than about 7 mm (the icosahedron's 7054 km
  // edges on Earth halved 30 times): finer than depth 5's vertices need for a 1 cm pattern seen from
  // 2 m, and well within what double normals resolve.
  static constexpr int kDeepestLevel = 30;

 private:
  PatchShell shellOf(std::int32_t id) const;
  std::optional<double> viewedAngle(const PatchShell& shell) const;
  void classify(std::int32_t id);
  void splitKeepingOneLevel(std::int32_t leaf);
  bool mergeable(std::int32_t parent) const;
  void merge(std::int32_t parent);
  double familyAngle(std::int32_t parent) const;
  std::int32_t largestLeaf() const;
  std::int32_t smallestFamily(bool hiddenOnly) const;
  bool improve();

  double radius_;
  HeightRange heights_;
  PatchTreeSettings settings_;
  PatchTopology topology_;
  std::span<const ViewVolume> views_;  // during update() only
  int visibleCount_ = 0;
};

}  // namespace strata::icosahedral
