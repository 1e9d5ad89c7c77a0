#pragma once
#include <string>
#include <vector>

#include <strata/camera.hpp>
#include <strata/gl/context.hpp>
#include <strata/gl/shader_program.hpp>

#include "patch_buffers.hpp"

namespace strata::icosahedral::test {

// geometry.icosahedral's compute pass (subdivide_patches.comp) on the headless context, as the node runs
// it, for tests that read the subdivided vertices back: on an Earth-sized body, at depth 5.
class GpuPatches {
 public:
  static constexpr double kRadius = 6371000.0;  // m
  static constexpr int kDepth = 5;

  // Without a height layer, or with `heightFunction` (GLSL taking a SurfacePoint, returning height in r
  // and coverage in a) defined by `heightGlsl`.
  GpuPatches(const std::string& heightFunction = "", const std::string& heightGlsl = "");

  struct Subdivided {
    PatchBatch batch;
    std::vector<PatchBuffers::Vertex> vertices;  // kDepth's vertices of each patch in turn
  };
  // `onTerrain`: vertices measure their distances at their displaced points (PatchBatch::onTerrain).
  Subdivided subdivide(const std::vector<Patch>& patches, const View& view, double splitDistanceUnit,
                       bool onTerrain = false);
  const SubdivisionTable& table() const { return table_; }

 private:
  GlContext& context_;  // first: the buffers need it
  SubdivisionTable table_;
  EdgeWindings windings_;
  PatchBuffers buffers_;
  ShaderProgram program_;
};

}  // namespace strata::icosahedral::test
