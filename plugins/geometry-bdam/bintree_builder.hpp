#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "cube_bintree.hpp"
#include "leaf_patch.hpp"
#include "level_patches.hpp"

namespace strata::bdam {

// The smallest sphere found that holds a node's patch, its partner's across the hypotenuse and every descendant's
// sphere [Cignoni et al. 2003, §3: nested bounding volumes, shared by patches adjacent along their hypotenuse].
struct BoundingSphere {
  glm::dvec3 centre{0.0};  // planetocentric, m
  double radius = 0.0;     // m
};

struct BuiltNode {
  std::uint64_t offset = 0;  // where encodePatch's bytes lie among its level's (BuiltBintrees::stored)
  std::uint32_t bytes = 0;
  double error = 0.0;  // m along the line from the centre; nested and shared with the partner, as the sphere
  BoundingSphere sphere;
  // m above the body's radius: how near the body's centre and how far from it the patch's triangles reach.
  double lowest = 0.0, highest = 0.0;
  std::uint32_t vertices = 0, indices = 0;  // the patch's
};

struct BuildOptions {
  double radius = 0.0;   // the body's, m: displacements are heights above it
  int leafLevel = 10;    // where the terrain is sampled
  int divisions = 16;    // leaf grid steps a side: 256 triangles, a few hundred as the paper's patches
  unsigned threads = 0;  // 0: every core
  // A folder for each level's patches while the build goes on (LevelPatches): the built bintrees read them from there
  // until they are destroyed. Beside the output, on a disk with room for as much again as the face files.
  std::filesystem::path scratch;
};

// What one level took, for progress on stderr.
struct LevelReport {
  int level = 0;
  std::size_t diamonds = 0, storedBytes = 0, triangles = 0;
  double seconds = 0.0;
};

// Every node's patch, error and sphere, from the leaves up.
class BuiltBintrees {
 public:
  explicit BuiltBintrees(const BuildOptions& options);
  const BuildOptions& options() const { return options_; }
  int leafLevel() const { return options_.leafLevel; }
  const BuiltNode& at(const BintreeNode& node) const;
  BuiltNode& at(const BintreeNode& node);
  // A node's patch, encodePatch's bytes, once its level is finished.
  std::span<const std::byte> stored(const BintreeNode& node) const;
  LevelPatches& patchesOf(int level) { return *patches_.at(std::size_t(level)); }

 private:
  BuildOptions options_;
  std::vector<std::vector<BuiltNode>> levels_;          // per level, by root << level | path
  std::vector<std::unique_ptr<LevelPatches>> patches_;  // per level
};

// A source of heights for one worker thread: each gets its own, so samplers need not be thread-safe.
using HeightsForThread = std::function<HeightAt()>;

// P-BDAM's construction [Cignoni et al. 2003, §5]: every leaf made from the terrain (leaf_patch.hpp), its error
// measured at its triangles' centroids; then level by level upwards each diamond simplified (diamond_simplification
// .hpp) into its halves, their error measured against the children's vertices plus the children's own (so errors
// nest), shared by the halves, and a sphere holding both and their children's. The diamonds of a level are
// independent, as the paper's distributed build has them, and shared among `threads` workers; a level waits for
// the one below. Patches go to the scratch folder as they are made, a few thousand diamonds at a time.
BuiltBintrees buildBintrees(const HeightsForThread& heights, const BuildOptions& options,
                            const std::function<void(const LevelReport&)>& progress);

}  // namespace strata::bdam
