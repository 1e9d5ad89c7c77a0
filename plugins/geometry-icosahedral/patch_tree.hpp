#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include <strata/plugin/height_input.hpp>

#include "detail_field.hpp"
#include "patch_topology.hpp"
#include "view_volume.hpp"

namespace strata::icosahedral {

struct PatchTreeSettings {
  int patches = 300;            // the most visible patches: [Kooima 2008, §2.4.1] sets np to about 300
  int operationsPerFrame = 64;  // splits and merges one frame may make: bounds the CPU's share of it
  double pixelError = 1.0;      // px: the geometric error a patch may show; one pixel is what the eye cannot resolve
  int depth = 5;                // the subdivisions each patch is drawn with: its vertex spacing sets its error
};

// The heights of the terrain within a patch (HeightInput::within), asked once per patch.
using PatchHeights = std::function<RegionalHeights(const SphericalTriangle& corners)>;

// A visible leaf, as the geometry generation takes it [Kooima 2008, §3.2.4].
struct Patch {
  SphericalTriangle corners;
  int level = 0;             // splits from the icosahedron's face
  unsigned coarseEdges = 0;  // bit e: the neighbour across the edge from corner e to corner e + 1 is coarser
  // The detail scale at its first nv(max(DetailField::kLevel - level, 0)) vertices in SubdivisionTable's order
  // (its corners, and where it is coarser than the field's lattice, the lattice's vertices within it), as float:
  // the compute pass takes every other vertex's as its parents' mean (DetailField).
  std::array<float, DetailField::kPatchValues> details{};
};

// The frame-coherent patch tree of [Kooima 2008, §3.2.1], computed once for all views: the faces of
// the icosahedron split 1-to-4. A visible patch is split while its face-on distance from an eye
// (patch_shell.hpp: the least over the patch's shell, between its own lowest and highest heights, where
// they are known; else on the sphere) is below its split distance, the detail scale there times the level's
// nominal size, and four siblings are merged when their parent would not be split: the largest patches in solid
// angle split first, as in [Kooima 2008], but by a threshold on a measure each vertex also has, which is what
// geomorphing needs (docs/geometry.md; the split distances are CDLOD's, Strugar 2009, on the sphere).
// The detail scale is a field over the body (DetailField), the largest of it over a patch that patch's; it
// follows, slowly, the least that keeps every visible patch's projected error under `pixelError` pixels (level of
// detail by screen-space error, [Cignoni et al. 2003, §4.3]), region by region, with `patches` as a cap on the
// count of visible patches. A patch is visible when its shell
// [Kooima 2008, §3.2.3] rises above the horizon and reaches into a view's frustum. Neighbouring leaves differ
// by at most one level [Kooima 2008, §3.4.1]: a split first splits coarser neighbours, and a merge that would
// break the rule is not made (how the tree of [Kooima 2008, §3.2.1] keeps the rule is left unsaid there).
class PatchTree {
 public:
  // `heights`: the whole terrain's, below which the body hides what lies behind; `patchHeights`: each patch's
  // own, within them (none: every patch takes `heights`).
  PatchTree(double radius, HeightRange heights, PatchTreeSettings settings = {}, PatchHeights patchHeights = {});

  // Reclassifies the leaves for the views, merges and splits at most `operations` times, and, when that
  // was enough to follow the views, moves the detail scale a step toward the one the pixel error asks for.
  // Returns the splits and merges made.
  int update(std::span<const ViewVolume> views, int operations);
  int update(std::span<const ViewVolume> views) { return update(views, settings_.operationsPerFrame); }
  // Updates without bounds and lets the detail scale jump, until the tree is what the pixel error asks for:
  // for a first frame, or a still image.
  void settle(std::span<const ViewVolume> views);

  // The visible leaves, depth first from the icosahedron's faces.
  std::vector<Patch> visiblePatches() const;
  int visibleCount() const { return visibleCount_; }
  const PatchTopology& topology() const { return topology_; }
  // Whether distances are measured to each patch's own shell, which the compute pass must then match by
  // measuring its vertices' displaced points (PatchBatch::onTerrain); else both measure on the sphere.
  bool measuresOnTerrain() const { return bool(patchHeights_); }

  // A face of the icosahedron's split distance where the detail scale is 1, m: a patch of level L is split while
  // its face-on distance from an eye is below this halved L times, times the largest detail scale over it.
  double splitDistanceUnit() const;
  double splitDistanceOf(const Patch& patch) const;
  const DetailField& detailField() const { return field_; }
  // The geometric error of a patch drawn with `depth` subdivisions, m: the larger of the sphere's error (the
  // chords' sagitta, grown toward a pole where longitude bends fastest) and the terrain's (its relief over
  // the patch scaled down to one vertex spacing as the relief's own roughness scales it).
  double errorOf(std::int32_t id);

  // Splits below this level would make patches narrower than about 7 mm (the icosahedron's 7054 km
  // edges on Earth halved 30 times): finer than depth 5's vertices need for a 1 cm pattern seen from
  // 2 m, and well within what double normals resolve.
  static constexpr int kDeepestLevel = 30;
  // The detail scale's bounds, in nominal patch sizes: a patch nearest the eye is about 1 / scale rad
  // across. Below 1 it would fill a view (so the bare sphere rests at 1: about 20 patches, whatever the
  // view); beyond 64 it would cover under 2 percent of one, finer than 300 patches can cover a view with.
  static constexpr double kLeastDetail = 1.0, kMostDetail = 64.0;

  using Details = std::vector<double>;  // a detail field's values (DetailField::values)

 private:
  PatchShell shellOf(std::int32_t id);
  RegionalHeights heightsOf(std::int32_t id, const SphericalTriangle& corners);
  std::optional<double> viewedDistance(const PatchShell& shell) const;
  double nearestSeen(const PatchShell& shell) const;
  bool errorShows(std::int32_t id, double faceOn, double pixelsPerRadian);
  double spacingOf(std::int32_t id) const;
  bool sees(const ViewVolume& view, const PatchShell& shell) const;
  PatchShell measured(const PatchShell& shell) const;
  void classify(std::int32_t id);
  int refine(int operations);
  bool wantsSplit(std::int32_t id, double distance) const;
  void splitKeepingOneLevel(std::int32_t leaf);
  bool mergeable(std::int32_t parent) const;
  void merge(std::int32_t parent);
  int mergeFar(int operations);
  int splitNear(int operations);
  void followError(double largestStep);
  Details wantedDetail();
  const std::vector<int>& latticeVerticesOf(std::int32_t id) const;
  double pixelsPerRadian() const;
  int splitsAt(const Details& details) const;
  double splitDistance(std::int32_t id, const Details& details) const;
  double splitDistance(std::int32_t id) const { return splitDistance(id, field_.values()); }
  double detailOver(std::int32_t id, const Details& details) const;
  float detailAt(std::uint32_t vertex, const Details& details, std::unordered_map<std::uint32_t, float>& known) const;
  void fillDetails(std::int32_t id, Patch& patch) const;

  double radius_;
  HeightRange heights_;
  PatchTreeSettings settings_;
  PatchHeights patchHeights_;
  PatchTopology topology_;
  std::span<const ViewVolume> views_;  // during update() only
  int visibleCount_ = 0;
  DetailField field_{16.0};  // the detail scale: a start between the bounds that settle() moves from
};

}  // namespace strata::icosahedral
